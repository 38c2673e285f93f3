#include "runs/sweep_points.hpp"

#include "runs/mesh_cycle.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <optional>

namespace geartrib::runs {

SweepPoint run_sweep_point(const CaseLoader& load, const std::vector<io::CaseChange>& changes, std::size_t index) {
  SweepPoint p;
  p.index = index;
  const auto start = std::chrono::steady_clock::now();
  try {
    const Case c = load(changes);
    for (const auto& w : c.warnings) p.message += (p.message.empty() ? "" : "; ") + w;
    const contact::MeshContactResult r = run_mesh_cycle(c);
    for (const auto& w : r.warnings) p.message += (p.message.empty() ? "warning: " : "; warning: ") + w;
    p.contact_ratio = r.path.contact_ratio;
    p.plasticity_index = r.plasticity_index;
    p.regime = r.regime;
    p.verdict = r.verdict;
    p.flag_counts = r.flag_counts;
    for (const auto* group : r.groups())
      for (const auto& q : *group) {
        if (q.name == "s_m" || q.name == "roll_angle_rad") continue;                  // the path itself
        if (q.name.rfind("flag_", 0) == 0 || q.name == "plasticity_index") continue;  // counted below / a column
        const auto [lo, hi] = std::minmax_element(q.values.begin(), q.values.end());
        p.quantities.push_back({q.name, q.unit, *lo, contact::path_mean(q.values), *hi});
      }
    p.ok = true;
  } catch (const std::exception& e) {
    p.message = e.what();
  }
  p.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return p;
}

io::ColumnTable sweep_table(const io::SweepPlan& plan, const std::vector<SweepPoint>& points) {
  io::ColumnTable t;
  io::Column index{"point", "1", false, {}, {}};
  for (const auto& p : points) index.numbers.push_back(static_cast<double>(p.index));
  t.columns.push_back(std::move(index));
  for (std::size_t k = 0; k < plan.axes.size(); ++k) {
    const auto& axis = plan.axes[k];
    std::vector<std::optional<io::SiValue>> si;
    for (const auto& v : axis.values) si.push_back(io::si_quantity(v));
    const bool numeric =
        std::all_of(si.begin(), si.end(), [&](const auto& s) { return s && s->unit == si.front()->unit; });
    io::Column col{axis.key, numeric ? si.front()->unit : "", !numeric, {}, {}};
    for (const auto& p : points) {
      const std::string value = plan.point(p.index)[k].value;
      if (numeric) col.numbers.push_back(io::si_quantity(value)->value);
      else col.texts.push_back(value);
    }
    t.columns.push_back(std::move(col));
  }
  io::Column status{"status", "", true, {}, {}}, message{"message", "", true, {}, {}};
  io::Column seconds{"seconds", "s", false, {}, {}}, ratio{"contact_ratio", "1", false, {}, {}},
      psi{"plasticity_index", "1", false, {}, {}};
  for (const auto& p : points) {
    status.texts.emplace_back(p.ok ? "ok" : "error");
    message.texts.push_back(p.message);
    seconds.numbers.push_back(p.seconds);
    ratio.numbers.push_back(p.ok ? p.contact_ratio : std::nan(""));
    psi.numbers.push_back(p.ok ? p.plasticity_index : std::nan(""));
  }
  for (auto* c : {&status, &message, &seconds, &ratio, &psi}) t.columns.push_back(std::move(*c));
  // The validity verdict and, per flag, at how many positions it is set.
  io::Column regime{"regime", "", true, {}, {}}, verdict{"validity", "", true, {}, {}};
  for (const auto& p : points) {
    regime.texts.push_back(p.ok ? p.regime : "");
    verdict.texts.push_back(p.ok ? p.verdict : "");
  }
  t.columns.push_back(std::move(regime));
  t.columns.push_back(std::move(verdict));
  std::vector<std::string> flags;
  for (const auto& p : points)
    for (const auto& f : p.flag_counts)
      if (std::find(flags.begin(), flags.end(), f.name) == flags.end()) flags.push_back(f.name);
  for (const auto& name : flags) {
    io::Column col{"positions_" + name, "1", false, {}, {}};
    for (const auto& p : points) {
      const auto f =
          std::find_if(p.flag_counts.begin(), p.flag_counts.end(), [&](const auto& x) { return x.name == name; });
      col.numbers.push_back(p.ok && f != p.flag_counts.end() ? f->positions : std::nan(""));
    }
    t.columns.push_back(std::move(col));
  }
  // Quantities in order of first appearance (a swept key may add one, e.g. mesh.dynamics).
  std::vector<std::pair<std::string, std::string>> names;
  for (const auto& p : points)
    for (std::size_t k = 0; k < p.quantities.size(); ++k) {
      const QuantitySummary& q = p.quantities[k];
      if (k < names.size() && names[k].first == q.name) continue;  // where the points before had it
      if (std::none_of(names.begin(), names.end(), [&](const auto& n) { return n.first == q.name; }))
        names.emplace_back(q.name, q.unit);
    }
  // Points list their quantities in one order as a rule: the k-th name is looked for at k first
  // (a search only when a point's list differs), so the table costs points x quantities.
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto& [name, unit] = names[k];
    io::Column lo{name + "_min", unit, false, {}, {}}, mean{name + "_mean", unit, false, {}, {}},
        hi{name + "_max", unit, false, {}, {}};
    for (const auto& p : points) {
      const QuantitySummary* q = k < p.quantities.size() && p.quantities[k].name == name ? &p.quantities[k] : nullptr;
      if (!q) {
        const auto it = std::find_if(p.quantities.begin(), p.quantities.end(),
                                     [&key = name](const QuantitySummary& s) { return s.name == key; });
        q = it != p.quantities.end() ? &*it : nullptr;
      }
      lo.numbers.push_back(q ? q->min : std::nan(""));
      mean.numbers.push_back(q ? q->mean : std::nan(""));
      hi.numbers.push_back(q ? q->max : std::nan(""));
    }
    for (auto* c : {&lo, &mean, &hi}) t.columns.push_back(std::move(*c));
  }
  return t;
}

}  // namespace geartrib::runs
