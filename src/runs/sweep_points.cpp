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
    p.flag_counts = contact::validity_summary(r).values;
    if (r.tooth_contact) p.summary = contact::tooth_contact_summary(*r.tooth_contact).values;
    if (r.rating)
      for (auto& v : contact::rating_summary(*r.rating).values) p.summary.push_back(std::move(v));
    if (r.lubrication_summary)
      for (auto& v : contact::lubrication_summary(*r.lubrication_summary).values) p.summary.push_back(std::move(v));
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

namespace {

// The items of a per-point list (validity flags, mesh-level values, quantities), one per name in
// order of first appearance over the points (a swept key may add some: mesh.dynamics, a lubricant,
// a scuffing temperature); each the first point's of that name (it gives the unit).
template <class Item>
std::vector<const Item*> first_appearance(const std::vector<SweepPoint>& points, std::vector<Item> SweepPoint::*list) {
  std::vector<const Item*> items;
  for (const auto& p : points) {
    const std::vector<Item>& own = p.*list;
    for (std::size_t k = 0; k < own.size(); ++k) {
      if (k < items.size() && items[k]->name == own[k].name) continue;  // where the points before had it
      if (std::none_of(items.begin(), items.end(), [&](const Item* i) { return i->name == own[k].name; }))
        items.push_back(&own[k]);
    }
  }
  return items;
}

// A point's item of that name. Points list their items in one order as a rule: the table's k-th
// name is looked for at k first (a search only when a point's list differs), so the table costs
// points x items.
template <class Item>
const Item* item_named(const std::vector<Item>& own, std::size_t k, const std::string& name) {
  if (k < own.size() && own[k].name == name) return &own[k];
  const auto it = std::find_if(own.begin(), own.end(), [&](const Item& i) { return i.name == name; });
  return it != own.end() ? &*it : nullptr;
}

}  // namespace

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
  // The validity verdict.
  io::Column regime{"regime", "", true, {}, {}}, verdict{"validity", "", true, {}, {}};
  for (const auto& p : points) {
    regime.texts.push_back(p.ok ? p.regime : "");
    verdict.texts.push_back(p.ok ? p.verdict : "");
  }
  t.columns.push_back(std::move(regime));
  t.columns.push_back(std::move(verdict));
  // Per point lists by name, one column per name (NaN where a point lacks it): positions per
  // validity flag, the lubricated runs' mesh-level values, the quantities' _min, _mean, _max.
  for (auto list : {&SweepPoint::flag_counts, &SweepPoint::summary}) {
    const auto items = first_appearance(points, list);
    for (std::size_t k = 0; k < items.size(); ++k) {
      io::Column col{items[k]->name, items[k]->unit, false, {}, {}};
      for (const auto& p : points) {
        const auto* v = p.ok ? item_named(p.*list, k, items[k]->name) : nullptr;
        col.numbers.push_back(v ? v->value : std::nan(""));
      }
      t.columns.push_back(std::move(col));
    }
  }
  const auto quantities = first_appearance(points, &SweepPoint::quantities);
  for (std::size_t k = 0; k < quantities.size(); ++k) {
    const std::string &name = quantities[k]->name, &unit = quantities[k]->unit;
    io::Column lo{name + "_min", unit, false, {}, {}}, mean{name + "_mean", unit, false, {}, {}},
        hi{name + "_max", unit, false, {}, {}};
    for (const auto& p : points) {
      const auto* q = item_named(p.quantities, k, name);
      lo.numbers.push_back(q ? q->min : std::nan(""));
      mean.numbers.push_back(q ? q->mean : std::nan(""));
      hi.numbers.push_back(q ? q->max : std::nan(""));
    }
    for (auto* c : {&lo, &mean, &hi}) t.columns.push_back(std::move(*c));
  }
  return t;
}

}  // namespace geartrib::runs
