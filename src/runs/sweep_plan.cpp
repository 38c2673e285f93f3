#include "runs/sweep_plan.hpp"

#include "config/text_lines.hpp"
#include "config/units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <set>
#include <stdexcept>

namespace geartrib::io {

namespace {

// "40mm" -> (40, "mm"); throws when the text does not start with a number.
std::pair<double, std::string> number_and_unit(const std::string& text, const std::string& whole) {
  double v = 0.0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc{} || end == text.data() || !std::isfinite(v))
    throw std::invalid_argument("'" + whole + "': range ends must be numbers with an optional unit, got '" + text +
                                "'");
  return {v, trim(std::string(end, text.data() + text.size()))};
}

bool is_integer_text(const std::string& t) {
  return !t.empty() && t.find_first_not_of("+-0123456789") == std::string::npos;
}

// The values of an axis on a declared key, checked against the parameter table before any
// point runs (unit, kind, choices, range). Keys the table does not know are left to the points,
// which report them as unknown.
void check_axis_values(const SweepAxis& axis, const std::string& text) {
  for (const std::string& key : resolve_case_key(axis.key)) {
    const ParameterLookup found = find_parameter(key);
    if (!found.parameter || found.parameter->kind == ParameterKind::model_constants) continue;
    for (const std::string& v : axis.values)
      if (const std::string rule = parameter_text_error(*found.parameter, v); !rule.empty())
        throw std::invalid_argument("'" + text + "': value '" + v + "' for " + key + ": " + rule);
  }
}

// Whether two dotted keys name the same value: equal, or one a table holding the other.
bool overlap(const std::string& a, const std::string& b) {
  const std::string& shorter = a.size() <= b.size() ? a : b;
  const std::string& longer = a.size() <= b.size() ? b : a;
  return longer.compare(0, shorter.size(), shorter) == 0 &&
         (longer.size() == shorter.size() || longer[shorter.size()] == '.');
}

// The same key reached by two axes (an alias and a dotted key it stands for: `teeth` and
// `pinion.teeth`), or one axis replacing what another sets (`torque` and `fzg_load_stage`, `rq`
// and `pinion.flank.ra`): the point would run with whichever is applied last while the table
// records both axes' values. Refused, naming both.
void check_overlaps(const std::vector<SweepAxis>& axes) {
  struct Reach {
    std::vector<std::string> sets, replaces;
  };
  std::vector<Reach> reach;
  for (const auto& a : axes) {
    Reach r;
    r.sets = resolve_case_key(a.key);
    for (const auto& k : r.sets)
      for (const auto& v : a.values)
        for (auto& gone : keys_replaced_by(k, v)) r.replaces.push_back(std::move(gone));
    reach.push_back(std::move(r));
  }
  auto named = [](const SweepAxis& a) {
    const std::vector<std::string> keys = resolve_case_key(a.key);
    std::string s = "--set " + a.key;
    if (keys.size() != 1 || keys.front() != a.key) {
      s += " (";
      for (std::size_t i = 0; i < keys.size(); ++i) s += (i ? ", " : "") + keys[i];
      s += ")";
    }
    return s;
  };
  for (std::size_t i = 0; i < axes.size(); ++i)
    for (std::size_t j = i + 1; j < axes.size(); ++j)
      for (int pass = 0; pass < 2; ++pass) {
        const std::size_t a = pass == 0 ? i : j, b = pass == 0 ? j : i;
        for (const auto& key : reach[a].sets) {
          for (const auto& other : reach[b].sets)
            if (overlap(key, other))
              throw std::invalid_argument(
                  fmt::format("{} and {} set the same key {}: a key given twice (a point would run with the later "
                              "value while the table records both); give it once",
                              named(axes[i]), named(axes[j]), key));
          for (const auto& gone : reach[b].replaces)
            if (overlap(key, gone))
              throw std::invalid_argument(
                  fmt::format("{} and {} change the same key: {} replaces {} (another form of the same value, "
                              "as a case file gives one); give one of them",
                              named(axes[i]), named(axes[j]), named(axes[b]), key));
        }
      }
}

}  // namespace

SweepAxis parse_sweep_axis(const std::string& text) {
  const CaseChange c = parse_case_change(text);
  SweepAxis axis{c.key, {}};
  const std::vector<std::string> parts = split_csv(c.value);
  if (parts.size() == 1 && std::count(c.value.begin(), c.value.end(), ':') == 2) {
    const auto a = c.value.find(':'), b = c.value.rfind(':');
    const std::string lo = trim(c.value.substr(0, a)), hi = trim(c.value.substr(a + 1, b - a - 1));
    const std::string count = trim(c.value.substr(b + 1));
    long n = 0;
    const auto [end, ec] = std::from_chars(count.data(), count.data() + count.size(), n);
    if (ec != std::errc{} || end != count.data() + count.size() || n < 2 || n > 100000)
      throw std::invalid_argument("'" + text + "': lo:hi:n needs an integer count n in [2, 100000], got '" + count +
                                  "'");
    const auto [v0, u0] = number_and_unit(lo, text);
    const auto [v1, u1] = number_and_unit(hi, text);
    if (u0 != u1)
      throw std::invalid_argument("'" + text + "': both range ends need the same unit ('" + u0 + "', '" + u1 + "')");
    const bool integers =
        is_integer_text(lo) && is_integer_text(hi) && std::fmod(std::abs(v1 - v0), static_cast<double>(n - 1)) == 0.0;
    for (long i = 0; i < n; ++i) {
      const double v = v0 + (v1 - v0) * static_cast<double>(i) / static_cast<double>(n - 1);
      axis.values.push_back(integers ? fmt::format("{}", std::llround(v)) : fmt::format("{:.10g}{}", v, u0));
    }
    check_axis_values(axis, text);
    return axis;
  }
  for (const auto& p : parts) {
    const std::string v = trim(p);
    if (v.empty()) throw std::invalid_argument("'" + text + "': empty value in the list");
    axis.values.push_back(v);
  }
  check_axis_values(axis, text);
  return axis;
}

void SweepPlan::validate() const {
  if (axes.empty()) throw std::invalid_argument("a sweep needs at least one --set key=values");
  // The factorial's size, checked axis by axis before anything is built from it (no wrapping).
  std::size_t points = 1;
  for (const auto& a : axes) {
    if (a.values.empty()) throw std::invalid_argument("--set " + a.key + " has no values");
    if (!zip && points > kMaxSweepPoints / a.values.size())
      throw std::invalid_argument(
          fmt::format("the sweep has more than {} points (--set {} multiplies it by {}): "
                      "run it as several sweeps",
                      kMaxSweepPoints, a.key, a.values.size()));
    points = zip ? std::max(points, a.values.size()) : points * a.values.size();
  }
  std::set<std::string> keys;
  for (const auto& a : axes)
    if (!keys.insert(a.key).second) throw std::invalid_argument("--set " + a.key + " given twice");
  check_overlaps(axes);
  for (const auto& a : axes) {
    if (zip && a.values.size() != 1 && a.values.size() != size())
      throw std::invalid_argument(
          fmt::format("--zip: --set {} has {} values, another axis {}: zipped axes need equal lengths "
                      "(or one value, used at every point)",
                      a.key, a.values.size(), size()));
  }
}

std::size_t SweepPlan::size() const {
  if (axes.empty()) return 0;
  if (zip) {
    std::size_t n = 1;
    for (const auto& a : axes) n = std::max(n, a.values.size());
    return n;
  }
  std::size_t n = 1;
  for (const auto& a : axes) n *= a.values.size();
  return n;
}

std::vector<CaseChange> SweepPlan::point(std::size_t i) const {
  if (i >= size()) throw std::out_of_range("sweep point index");
  std::vector<CaseChange> out(axes.size());
  for (std::size_t k = axes.size(); k-- > 0;) {  // last axis fastest
    const auto& a = axes[k];
    const std::size_t j = zip ? (a.values.size() == 1 ? 0 : i) : i % a.values.size();
    if (!zip) i /= a.values.size();
    out[k] = {a.key, a.values[j]};
  }
  return out;
}

std::string SweepPlan::describe() const {
  std::string s;
  for (const auto& a : axes) {
    s += (s.empty() ? "" : ";") + a.key + "=";
    for (std::size_t j = 0; j < a.values.size(); ++j) s += (j ? "," : "") + a.values[j];
  }
  return s + (zip ? " (zip)" : " (factorial)");
}

std::optional<std::size_t> whole_number(std::string_view text) {
  std::size_t v = 0;
  if (text.empty() || text.find_first_not_of("0123456789") != std::string_view::npos) return std::nullopt;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (ec != std::errc{} || end != text.data() + text.size()) return std::nullopt;  // too large for std::size_t
  return v;
}

std::optional<Shard> shard_from_text(std::string_view text) {
  const auto slash = text.find('/');
  if (slash == std::string_view::npos) return std::nullopt;
  const auto index = whole_number(text.substr(0, slash)), count = whole_number(text.substr(slash + 1));
  if (!index || !count || *index >= *count || *count > kMaxSweepPoints) return std::nullopt;  // --merge's rule too
  return Shard{*index, *count};
}

Shard parse_shard(const std::string& text) {
  if (const auto s = shard_from_text(text)) return *s;
  throw std::invalid_argument("--shard '" + text + "': expected i/n with 0 <= i < n <= " +
                              std::to_string(kMaxSweepPoints) + " (e.g. 0/4 .. 3/4)");
}

std::optional<SiValue> si_quantity(const std::string& text) {
  const auto q = parse_any_quantity(text);
  if (!q) return std::nullopt;
  return SiValue{q->si, std::string(si_symbol(q->dimension))};
}

}  // namespace geartrib::io
