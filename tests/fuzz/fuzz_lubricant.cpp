// libFuzzer harness: a lubricant file (lubricants/*.toml), structure-aware. The input is the file's
// TOML; a custom mutator parses it (toml++) and changes it as a lubricant file can change: a key's
// value (numbers at and around each law's limits, extremes, NaN and inf, scaled), its unit (the
// dimension's own, another dimension's, none), its type; a key removed or an unknown one added;
// the traction curves' grid (a curve copied to another pressure or temperature, removed, its
// pressure or temperature moved onto another's) and their arrays (an element changed, inserted,
// removed, the lengths made to differ). Text that does not parse is mutated byte by byte.
//
// The property (docs/theory/lubrication.md#where-the-laws-hold): the file is refused with a located
// error (io::InputError), or every law evaluated across its stated range is finite and sound:
// data range inside the operating range inside the law range; at 129 temperatures across the law
// range, both ends included, viscosity, density, alpha, beta and the whole oil state finite and
// positive, the density above half its 15 degC value, viscosity, density and alpha falling with
// temperature; each law refusing a temperature beyond the range (OutsideLawRange, never a NaN);
// the traction curves' coefficient finite and in [0, 1] at, between and beyond their grid.
#include "config/case_file.hpp"
#include "fuzz_support.hpp"
#include "lubrication/lubricant.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace geartrib;
namespace lub = lubrication;

extern "C" std::size_t LLVMFuzzerMutate(std::uint8_t* data, std::size_t size, std::size_t max_size);

namespace {

void finding(const std::string& what) {
  std::fprintf(stderr, "finding: %s\n", what.c_str());
  std::abort();
}

// Libm's log10 and pow are accurate to about an ulp, not monotone to the last bit: a law flat to
// the double's resolution (nu40 a hair above nu100) may wobble by a few ulps between neighbours.
constexpr double kMonotoneSlack = 1e-14;  // relative

void check_laws(const lub::Lubricant& l) {
  if (l.fixed()) finding("a lubricant file gave the fixed form");
  const lub::TemperatureRange data = lub::data_range(l), operating = lub::operating_range(l), law = lub::law_range(l);
  if (!(law.lo <= operating.lo && operating.lo <= data.lo && data.lo < data.hi && data.hi <= operating.hi &&
        operating.hi <= law.hi))
    finding("ranges not nested: law [" + std::to_string(law.lo) + ", " + std::to_string(law.hi) + "], operating [" +
            std::to_string(operating.lo) + ", " + std::to_string(operating.hi) + "], data [" + std::to_string(data.lo) +
            ", " + std::to_string(data.hi) + "]");
  fuzz::expect_finite(l.lubricant_factor(), "X_L");
  double last_nu = std::numeric_limits<double>::infinity(), last_rho = last_nu, last_alpha = last_nu;
  constexpr int kSteps = 128;
  for (int i = 0; i <= kSteps; ++i) {
    const double t = i == kSteps ? law.hi : law.lo + (law.hi - law.lo) * i / kSteps;
    const std::string at = " at " + std::to_string(t) + " K";
    const double nu = lub::kinematic_viscosity(l, t), rho = lub::density(l, t);
    const double alpha = lub::pressure_viscosity_coefficient(l, t);
    const lub::OilState s = lub::oil_state(l, t);
    for (const auto& [what, v] : {std::pair{"nu", nu}, std::pair{"rho", rho}, std::pair{"alpha", alpha},
                                  std::pair{"eta", s.dynamic_viscosity}, std::pair{"beta", s.temperature_viscosity}})
      if (!(std::isfinite(v) && v > 0.0)) finding(std::string(what) + " = " + std::to_string(v) + at);
    if (!(rho >= 0.5 * l.density_15)) finding("density below half its 15 degC value" + at);
    if (nu > last_nu * (1.0 + kMonotoneSlack)) finding("viscosity rises with temperature" + at);
    if (rho > last_rho * (1.0 + kMonotoneSlack)) finding("density rises with temperature" + at);
    if (alpha > last_alpha * (1.0 + kMonotoneSlack)) finding("alpha rises with temperature" + at);
    last_nu = nu, last_rho = rho, last_alpha = alpha;
  }
  for (double t : {law.hi * (1.0 + 1e-9) + 1e-9, law.lo * (1.0 - 1e-9) - 1e-9}) {
    try {
      (void)lub::oil_state(l, t);
      finding("oil_state answered at " + std::to_string(t) + " K, outside the law range");
    } catch (const lub::OutsideLawRange&) {
    }
  }
  // Traction curves: at, between and beyond every grid point.
  if (l.traction.empty()) return;
  std::vector<double> pressures, temperatures;
  for (const auto& c : l.traction.curves())
    pressures.push_back(c.hertz_pressure), temperatures.push_back(c.temperature);
  auto around = [](std::vector<double> axis) {
    std::sort(axis.begin(), axis.end());
    std::vector<double> out = {0.0, 0.5 * axis.front(), 2.0 * axis.back(), 1e300};
    for (std::size_t i = 0; i < axis.size(); ++i) {
      out.push_back(axis[i]);
      if (i + 1 < axis.size()) out.push_back(0.5 * (axis[i] + axis[i + 1]));
    }
    return out;
  };
  for (double p : around(pressures))
    for (double t : around(temperatures))
      for (double srr : {0.0, 0.013, 0.5, 2.0, -0.3, 50.0}) {
        const lub::TractionValue v = l.traction.at(srr, p, t);
        if (!(v.coefficient >= 0.0 && v.coefficient <= 1.0))
          finding("traction coefficient " + std::to_string(v.coefficient) + " at SRR " + std::to_string(srr));
      }
}

// -- the structure-aware mutator ------------------------------------------------------------------

struct KeySpec {
  const char* key;
  std::array<const char*, 3> units;  // the dimension's own symbols ("" : a bare number)
  double typical;                    // in the first unit
};
constexpr KeySpec kKeys[] = {
    {"kinematic_viscosity_40C", {"mm^2/s", "cSt", "m^2/s"}, 220.0},
    {"kinematic_viscosity_100C", {"mm^2/s", "cSt", "m^2/s"}, 18.75},
    {"density_15C", {"kg/m^3", "g/cm^3", "kg/m3"}, 895.0},
    {"density_temperature_coefficient", {"1/K", "1/K", "1/K"}, 6.7e-4},
    {"pressure_viscosity_coefficient", {"1/GPa", "1/Pa", "m^2/N"}, 20.0},
    {"pressure_viscosity_temperature", {"degC", "K", "degC"}, 40.0},
    {"thermal_conductivity", {"W/(m K)", "W/m/K", "W/(m K)"}, 0.13},
    {"specific_heat", {"J/(kg K)", "kJ/(kg K)", "J/kg/K"}, 2000.0},
    {"eyring_stress", {"MPa", "Pa", "GPa"}, 5.0},
    {"limiting_shear_coefficient", {"", "1", "%"}, 0.075},
    {"min_temperature", {"degC", "K", "degC"}, 0.0},
    {"max_temperature", {"degC", "K", "degC"}, 120.0},
    {"iso_lubricant_factor", {"", "1", ""}, 1.0},
};
constexpr KeySpec kCurveKeys[] = {
    {"hertz_pressure", {"GPa", "MPa", "Pa"}, 1.5},
    {"temperature", {"degC", "K", "degC"}, 80.0},
    {"entrainment_speed", {"m/s", "mm/s", "m/s"}, 4.0},
};
// The laws' limits in the units above, and the extremes of a double.
constexpr double kEdges[] = {0.0,
                             -0.0,
                             1.0,
                             -1.0,
                             2.0,
                             1.999999,
                             2e7,
                             2.0000001e7,
                             100.0,
                             99.999,
                             1000.0,
                             1000.01,
                             673.15,
                             673.16,
                             400.0,
                             400.01,
                             782.8,
                             509.7,
                             311.15,
                             38.0,
                             313.15,
                             373.15,
                             1e-7,
                             1.0000001,
                             2e-3,
                             1.9999e-3,
                             5e-4,
                             1e-300,
                             1e300,
                             5e-324,
                             1.7976931348623157e308,
                             -273.15,
                             -273.16,
                             0.5,
                             1e-12,
                             1e-6};
constexpr const char* kForeignUnits[] = {"furlong", "m", "N m", "rpm", "K", "1/K", "Pa s", "", "degF", "mm^2/s"};

std::string number(double v) {
  char b[64];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

template <class Rng>
double draw_number(Rng& rng, double typical) {
  switch (rng() % 6) {
    case 0:
      return kEdges[rng() % std::size(kEdges)];
    case 1:
      return typical * std::pow(10.0, static_cast<double>(static_cast<int>(rng() % 25) - 12));
    case 2:
      return -typical;
    case 3:
      return rng() % 2 ? std::numeric_limits<double>::infinity() : std::numeric_limits<double>::quiet_NaN();
    case 4:
      return typical * (1.0 + (static_cast<double>(rng() % 2001) - 1000.0) * 1e-3);
    default:
      return kEdges[rng() % std::size(kEdges)] * (1.0 + 1e-12 * (static_cast<double>(rng() % 3) - 1.0));
  }
}

// A quantity as the files write it: "<number> <unit>" (or a bare number).
template <class Rng>
void set_quantity(toml::table& t, const KeySpec& k, Rng& rng) {
  const double v = draw_number(rng, k.typical);
  const char* unit = rng() % 8 == 0 ? kForeignUnits[rng() % std::size(kForeignUnits)] : k.units[rng() % 3];
  if (*unit == '\0' && rng() % 2 && std::isfinite(v)) t.insert_or_assign(k.key, v);
  else t.insert_or_assign(k.key, number(v) + (*unit ? " " : "") + unit);
}

// The number of an existing "<number> <unit>" kept, its unit changed (or the reverse).
template <class Rng>
void change_unit_or_scale(toml::table& t, const KeySpec& k, Rng& rng) {
  const toml::node* n = t.get(k.key);
  if (!n || !n->is_string()) return set_quantity(t, k, rng);
  const std::string s = n->as_string()->get();
  const auto space = s.find(' ');
  const std::string num = s.substr(0, space), unit = space == std::string::npos ? "" : s.substr(space + 1);
  if (rng() % 2) {
    const char* u = rng() % 3 ? k.units[rng() % 3] : kForeignUnits[rng() % std::size(kForeignUnits)];
    t.insert_or_assign(k.key, num + (*u ? " " : "") + u);
  } else {
    const double v =
        std::strtod(num.c_str(), nullptr) * std::pow(10.0, static_cast<double>(static_cast<int>(rng() % 9) - 4));
    t.insert_or_assign(k.key, number(v) + (unit.empty() ? "" : " " + unit));
  }
}

template <class Rng>
void confuse_type(toml::table& t, const char* key, Rng& rng) {
  switch (rng() % 5) {
    case 0:
      t.insert_or_assign(key, true);
      return;
    case 1:
      t.insert_or_assign(key, toml::array{1.0, 2.0});
      return;
    case 2:
      t.insert_or_assign(key, toml::table{{"x", 1}});
      return;
    case 3:
      t.insert_or_assign(key, static_cast<std::int64_t>(rng() % 2 ? 9223372036854775807LL : -3));
      return;
    default:
      t.insert_or_assign(key, "");
  }
}

toml::table fresh_curve(double p_gpa, double t_degc) {
  return toml::table{{"source", "fuzz"},
                     {"hertz_pressure", number(p_gpa) + " GPa"},
                     {"temperature", number(t_degc) + " degC"},
                     {"entrainment_speed", "4 m/s"},
                     {"slide_to_roll", toml::array{0.0, 0.02, 0.1, 0.5}},
                     {"coefficient", toml::array{0.0, 0.04, 0.05, 0.045}}};
}

template <class Rng>
void mutate_array(toml::array& a, Rng& rng) {
  const double v = rng() % 3 ? static_cast<double>(rng() % 2001) * 1e-3 : draw_number(rng, 0.05);
  switch (rng() % 6) {
    case 0:
      if (!a.empty()) a.replace(a.begin() + static_cast<std::ptrdiff_t>(rng() % a.size()), v);
      return;
    case 1:
      a.insert(a.begin() + static_cast<std::ptrdiff_t>(rng() % (a.size() + 1)), v);
      return;
    case 2:
      if (!a.empty()) a.erase(a.begin() + static_cast<std::ptrdiff_t>(rng() % a.size()));
      return;
    case 3:
      a.push_back(v);
      return;
    case 4: {
      const std::size_t n = 1 + rng() % 300;  // a long table
      for (std::size_t i = 0; i < n; ++i) a.push_back(static_cast<double>(a.size()) * 1e-3);
      return;
    }
    default:
      if (!a.empty()) a.replace(a.begin() + static_cast<std::ptrdiff_t>(rng() % a.size()), number(v) + " 1");
  }
}

template <class Rng>
void mutate_curves(toml::table& root, Rng& rng) {
  toml::table* curves = root["traction_curves"].as_table();
  if (!curves || curves->empty() || rng() % 6 == 0) {
    if (!curves) {
      root.insert_or_assign("traction_curves", toml::table{});
      curves = root["traction_curves"].as_table();
    }
    curves->insert_or_assign("c" + std::to_string(rng() % 1000),
                             fresh_curve(1.0 + rng() % 3, 40.0 + 40.0 * (rng() % 3)));
    return;
  }
  std::vector<std::string> names;
  for (auto&& [k, v] : *curves) names.emplace_back(k.str());
  const std::string name = names[rng() % names.size()];
  toml::table* c = (*curves)[name].as_table();
  if (!c) {
    curves->insert_or_assign(name, fresh_curve(1.0, 40.0));
    return;
  }
  switch (rng() % 7) {
    case 0: {  // a copy at another pressure or temperature (grows or breaks the grid)
      toml::table copy = *c;
      if (rng() % 2) copy.insert_or_assign("hertz_pressure", number(0.5 + rng() % 4) + " GPa");
      else copy.insert_or_assign("temperature", number(20.0 + 20.0 * (rng() % 6)) + " degC");
      curves->insert_or_assign(name + "x" + std::to_string(rng() % 100), std::move(copy));
      return;
    }
    case 1:
      curves->erase(name);
      return;
    case 2: {  // its pressure or temperature onto another curve's
      const toml::table* other = (*curves)[names[rng() % names.size()]].as_table();
      const char* key = rng() % 2 ? "hertz_pressure" : "temperature";
      if (other && other->contains(key)) c->insert_or_assign(key, *other->get(key));
      return;
    }
    case 3:
      set_quantity(*c, kCurveKeys[rng() % std::size(kCurveKeys)], rng);
      return;
    case 4: {
      const char* key = rng() % 2 ? "slide_to_roll" : "coefficient";
      if (toml::array* a = (*c)[key].as_array()) mutate_array(*a, rng);
      else c->insert_or_assign(key, toml::array{0.0, 0.1});
      return;
    }
    case 5: {
      static constexpr const char* kKeysOfCurve[] = {
          "source", "hertz_pressure", "temperature", "entrainment_speed", "slide_to_roll", "coefficient"};
      const char* key = kKeysOfCurve[rng() % std::size(kKeysOfCurve)];
      if (rng() % 2) c->erase(key);
      else confuse_type(*c, key, rng);
      return;
    }
    default:
      c->insert_or_assign("colour", "blue");  // unknown key
  }
}

template <class Rng>
void mutate(toml::table& root, Rng& rng) {
  const KeySpec& k = kKeys[rng() % std::size(kKeys)];
  switch (rng() % 9) {
    case 0:
    case 1:
      set_quantity(root, k, rng);
      return;
    case 2:
      change_unit_or_scale(root, k, rng);
      return;
    case 3:
      root.erase(k.key);
      return;
    case 4:
      confuse_type(root, k.key, rng);
      return;
    case 5: {
      static constexpr const char* kBaseOils[] = {
          "mineral",        "pao",    "ester", "polyglycol-insoluble", "polyglycol-water-soluble", "phosphate-ester",
          "traction-fluid", "castor", ""};
      root.insert_or_assign("base_oil", kBaseOils[rng() % std::size(kBaseOils)]);
      return;
    }
    case 6:
      root.insert_or_assign(rng() % 2 ? "viscosity_index" : "name", rng() % 2 ? "x" : "");
      return;
    default:
      mutate_curves(root, rng);
  }
}

}  // namespace

extern "C" std::size_t LLVMFuzzerCustomMutator(std::uint8_t* data, std::size_t size, std::size_t max_size,
                                               unsigned int seed) {
  std::minstd_rand rng(seed);
  toml::table root;
  try {
    root = toml::parse(std::string_view(reinterpret_cast<const char*>(data), size));
  } catch (const toml::parse_error&) {
    return LLVMFuzzerMutate(data, size, max_size);
  }
  if (rng() % 16 == 0) return LLVMFuzzerMutate(data, size, max_size);  // now and then a byte-level change
  const int rounds = 1 + static_cast<int>(rng() % 3);
  for (int i = 0; i < rounds; ++i) mutate(root, rng);
  std::ostringstream out;
  out << root << '\n';
  const std::string text = out.str();
  if (text.size() > max_size) return LLVMFuzzerMutate(data, size, max_size);
  std::copy(text.begin(), text.end(), data);
  return text.size();
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const auto path = fuzz::write_input("lubricant.toml", data, size);
  // Stricter than expect_accepted_or_refused: a lubricant file is refused only with a located
  // error (io::InputError naming the file and a line or key), never a bare std::invalid_argument.
  try {
    check_laws(io::load_lubricant(path));
  } catch (const io::InputError& e) {
    if (e.file().empty() || (e.line() <= 0 && e.key().empty())) finding(std::string("unlocated refusal: ") + e.what());
  } catch (const std::exception& e) {
    finding(std::string("an exception other than a located input error: ") + e.what());
  }
  return 0;
}
