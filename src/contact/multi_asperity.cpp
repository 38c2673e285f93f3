#include "contact/multi_asperity.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace geartrib::contact {

void MultiAsperitySpec::validate() const {
  if (!profile.empty()) {
    double top = -std::numeric_limits<double>::infinity(), low = -top;
    for (std::size_t k = 0; k < profile.size(); ++k) {
      const auto& a = profile[k];
      if (!(a.tip_radius > 0.0) || !std::isfinite(a.tip_radius) || !std::isfinite(a.height) || !std::isfinite(a.centre))
        throw std::invalid_argument("profile asperities need finite centres and heights and positive tip radii");
      if (k > 0 && !(a.centre > profile[k - 1].centre))
        throw std::invalid_argument("profile asperities must be ordered by centre");
      top = std::max(top, a.height), low = std::min(low, a.height);
    }
    if (!(asperity_height > top - low))
      throw std::invalid_argument("asperity height must exceed the spread of the profile's tip heights");
  } else if (layout.empty() || layout.find_first_not_of("HL") != std::string::npos ||
             layout.find('H') == std::string::npos)
    throw std::invalid_argument("layout must be letters H and L with at least one H (e.g. LLH, HLH, H)");
  if (profile.empty() && !(tip_radius > 0.0)) throw std::invalid_argument("tip radius must be positive");
  if (!(height_step >= 0.0)) throw std::invalid_argument("height step must be >= 0");
  if (!(spacing >= 0.0)) throw std::invalid_argument("spacing must be >= 0");
  if (!(asperity_height > height_step)) throw std::invalid_argument("asperity height must exceed the height step");
  if (!(length > 0.0)) throw std::invalid_argument("length must be positive");
  if (!(modulus > 0.0)) throw std::invalid_argument("modulus must be positive");
  if (!(pressure_cap > 0.0)) throw std::invalid_argument("pressure cap must be positive");
  if (elements < 64 || elements > (1 << 22)) throw std::invalid_argument("elements must lie in [64, 4194304]");
  if (!(reference_length > 0.0)) throw std::invalid_argument("reference length must be positive");
  if (coarse_elements < 0) throw std::invalid_argument("coarse elements must be >= 0");
  if (line_load && !(*line_load > 0.0)) throw std::invalid_argument("line load must be positive");
  if (!line_load && !(approach > 0.0)) throw std::invalid_argument("approach must be positive");
  if (!line_load && approach >= asperity_height)
    throw std::invalid_argument("approach must stay below the asperity height");
}

MultiAsperityResult solve_multi_asperity(const MultiAsperitySpec& spec) {
  const auto start = std::chrono::steady_clock::now();
  spec.validate();
  const bool measured = !spec.profile.empty();
  const int count = static_cast<int>(measured ? spec.profile.size() : spec.layout.size());
  const double base = -spec.asperity_height;
  // Tips relative to the highest (at 0), axes, radii and kinds.
  std::vector<double> tip(static_cast<std::size_t>(count)), centre(tip), radius(tip);
  std::string kind(static_cast<std::size_t>(count), 'H');
  double top = -std::numeric_limits<double>::infinity();
  for (const auto& a : spec.profile) top = std::max(top, a.height);
  for (int k = 0; k < count; ++k) {
    if (measured) {
      const auto& a = spec.profile[static_cast<std::size_t>(k)];
      tip[k] = a.height - top;
      centre[k] = a.centre - 0.5 * (spec.profile.front().centre + spec.profile.back().centre);
      radius[k] = a.tip_radius;
      kind[k] = tip[k] == 0.0 ? 'H' : 'L';
    } else {
      tip[k] = spec.layout[static_cast<std::size_t>(k)] == 'H' ? 0.0 : -spec.height_step;
      centre[k] = (k - 0.5 * (count - 1)) * spec.spacing;
      radius[k] = spec.tip_radius;
      kind[k] = spec.layout[static_cast<std::size_t>(k)];
    }
  }
  const double mean_spacing = count > 1 ? (centre.back() - centre.front()) / (count - 1) : spec.spacing;
  // Beyond the outer axes: a spacing, at least 2 um (contacts at the seed's scale are ~0.2 um wide).
  const double margin = std::max(mean_spacing, 2e-6);
  const double left = centre.front() - margin, right = centre.back() + margin;
  HalfPlaneGrid grid{left, (right - left) / spec.elements, spec.elements};
  // Undeformed surface: the highest of the parabolas, never below the base plane; gap to the flat at the high tips.
  std::vector<double> gap0(static_cast<std::size_t>(grid.size));
  for (int i = 0; i < grid.size; ++i) {
    double y = base;
    for (int k = 0; k < count; ++k) y = std::max(y, tip[k] - std::pow(grid.x(i) - centre[k], 2) / (2.0 * radius[k]));
    gap0[static_cast<std::size_t>(i)] = -y;
  }
  BemOptions opt;
  opt.tolerance = spec.tolerance;
  opt.pressure_cap = spec.pressure_cap;
  opt.reference_length = spec.reference_length;
  opt.precondition = spec.precondition;
  opt.coarse_elements = spec.coarse_elements;
  opt.overlap_start = spec.overlap_start;
  const HalfPlaneBem bem(grid, spec.modulus, opt);
  const BemSolution s =
      spec.line_load ? bem.solve_load(gap0, *spec.line_load) : bem.solve_approach(gap0, spec.approach);

  MultiAsperityResult out;
  out.grid = grid;
  out.pressure = s.pressure;
  out.approach = s.approach;
  out.line_load = s.line_load;
  out.iterations = s.iterations;
  out.coarse_iterations = s.coarse_iterations;
  out.complementarity_error = s.complementarity_error;
  out.transforms = s.transforms;
  out.transform_seconds = s.transform_seconds;
  out.solve_seconds = s.seconds;
  // Per asperity: its share of the domain runs to the midpoints of the gaps.
  const double nu = spec.poisson_ratio, h = grid.spacing;
  const SubsurfaceStressField field(grid, s.pressure);
  for (int k = 0; k < count; ++k) {
    AsperityLoad a;
    a.kind = kind[static_cast<std::size_t>(k)];
    a.centre = centre[k];
    const double lo = k == 0 ? left : 0.5 * (centre[k - 1] + centre[k]);
    const double hi = k == count - 1 ? right : 0.5 * (centre[k] + centre[k + 1]);
    double contact_lo = std::numeric_limits<double>::infinity(), contact_hi = -contact_lo;
    for (int i = 0; i < grid.size; ++i) {
      const double x = grid.x(i);
      if (x < lo || x >= hi) continue;
      const std::size_t u = static_cast<std::size_t>(i);
      const double p = s.pressure[u];
      a.load += p * h;
      if (p > 0.0) {
        a.contact_width += h;
        contact_lo = std::min(contact_lo, x);
        contact_hi = std::max(contact_hi, x);
      }
      a.max_pressure = std::max(a.max_pressure, p);
      a.max_deformation = std::max(a.max_deformation, s.displacement[u] + std::max(0.0, -s.gap[u]));
    }
    // Surface von Mises half an element below the surface, over the contact and one contact width around it.
    if (a.contact_width > 0.0) {
      const double span = contact_hi - contact_lo + a.contact_width;
      for (double x = contact_lo - 0.5 * span; x <= contact_hi + 0.5 * span; x += std::max(h, span / 400.0))
        a.max_surface_von_mises = std::max(a.max_surface_von_mises, field.at(x, 0.5 * h, nu).von_mises());
    }
    out.total_contact_area += a.contact_width * spec.length;
    out.asperities.push_back(a);
  }
  for (int k = 0; k + 1 < count; ++k) {
    const double x = 0.5 * (centre[k] + centre[k + 1]);
    out.midpoint_von_mises.push_back(field.at(x, 0.5 * h, nu).von_mises());
  }
  // Below the middle asperity: the von Mises profile, its maximum, and the inflection point
  // beyond it (second difference changing sign from negative to positive).
  const double xm = centre[static_cast<std::size_t>(count / 2)];
  const AsperityLoad& mid = out.asperities[static_cast<std::size_t>(count / 2)];
  const double depth_max = 3.0 * std::max(mean_spacing, mid.contact_width);
  const int samples = 1500;
  std::vector<double> z(samples), v(samples);
  for (int j = 0; j < samples; ++j) {
    z[j] = depth_max * (j + 1) / samples;
    v[j] = field.at(xm, z[j], nu).von_mises();
  }
  const int jmax = static_cast<int>(std::max_element(v.begin(), v.end()) - v.begin());
  for (int j = std::max(jmax, 1); j + 1 < samples; ++j) {
    const double c0 = v[j - 1] - 2.0 * v[j] + v[j + 1];
    const double c1 = v[j] - 2.0 * v[j + 1] + (j + 2 < samples ? v[j + 2] : v[j + 1]);
    if (c0 < 0.0 && c1 >= 0.0) {
      out.inflection_depth = z[j + 1];
      out.inflection_von_mises = v[j + 1];
      break;
    }
  }
  out.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return out;
}

}  // namespace geartrib::contact
