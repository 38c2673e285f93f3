// The flanks' keys, declared beside surface::FlankSpec and RoughnessSettings (surface/flank_spec.hpp).
#include "config/parameters/declare.hpp"

#include "surface/flank_profile.hpp"
#include "surface/flank_spec.hpp"

namespace geartrib::io::parameters {

// {gear}.flank: one roughness form, a measured topography or a generated profile.
void declare_flanks(ParameterRows& table) {
  auto add = [&](Parameter p) -> Row& { return table.add(std::move(p)); };
  using D = Dimension;
  using K = ParameterKind;
  auto gear = gear_of;
  auto rough = [gear](auto& c, int g) -> auto& { return gear(c, g).flank.roughness; };
  add(quantity(
          "{gear}.flank.ra", D::length, [rough](auto& c, int g) -> auto& { return rough(c, g).ra; }))
      .range(1e-10, 1e-3)
      .plausible(1e-9, 25.0 * kUm)
      .no_default()
      .alias({"ra"})
      .field("{gear}.flank.roughness.ra")
      .doc("Form Ra: arithmetic mean roughness (profile)");
  add(quantity(
          "{gear}.flank.rq", D::length, [rough](auto& c, int g) -> auto& { return rough(c, g).rq; }))
      .range(1e-10, 1e-3)
      .plausible(1e-9, 25.0 * kUm)
      .no_default()
      .alias({"rq"})
      .field("{gear}.flank.roughness.rq")
      .doc("Form Rq: root-mean-square roughness (profile)");
  add(quantity(
          "{gear}.flank.summit_density",
          D::areal_density, [rough](auto& c, int g) -> auto& { return rough(c, g).summit_density; }))
      .range(1.0, 1e20)
      .no_default()
      .field("{gear}.flank.roughness.summit_density")
      .doc("Form summits: summit density eta (with summit_sigma)");
  add(quantity(
          "{gear}.flank.summit_sigma",
          D::length, [rough](auto& c, int g) -> auto& { return rough(c, g).summit_sigma; }))
      .range(1e-10, 1e-3)
      .plausible(1e-9, 25.0 * kUm)
      .no_default()
      .field("{gear}.flank.roughness.summit_sigma")
      .doc("Form summits: standard deviation of summit heights");
  add(quantity(
          "{gear}.flank.m0", D::area, [rough](auto& c, int g) -> auto& { return rough(c, g).m0; }))
      .range(1e-20, 1e-6)
      .no_default()
      .field("{gear}.flank.roughness.m0")
      .doc("Form spectral: profile moment m0 = Rq^2 (with m2, m4; McCool 1986)");
  add(quantity(
          "{gear}.flank.m2", D::dimensionless, [rough](auto& c, int g) -> auto& { return rough(c, g).m2; }))
      .range(1e-12, 100.0)
      .no_default()
      .field("{gear}.flank.roughness.m2")
      .doc("Form spectral: slope moment m2");
  add(quantity(
          "{gear}.flank.m4", D::areal_density, [rough](auto& c, int g) -> auto& { return rough(c, g).m4; }))
      .range(1.0, 1e26)
      .no_default()
      .field("{gear}.flank.roughness.m4")
      .doc("Form spectral: curvature moment m4");
  add(quantity(
          "{gear}.flank.summit_radius",
          D::length, [rough](auto& c, int g) -> auto& { return rough(c, g).summit_radius; }))
      .range(1e-9, 1.0)
      .plausible(0.1 * kUm, 10.0 * kMm)
      .no_default()
      .alias({"summit_radius"})
      .field("{gear}.flank.roughness.summit_radius")
      .doc(
          "Mean summit radius beta of the flank's asperities: required with ra, rq or summit_density + summit_sigma, "
          "no default (it sets the plasticity index and depends on the finish and the sampling interval). Measured: "
          "`geartrib surface stats FILE` (summit_radius_m, mccool_summit_radius_m); from a profile, McCool's beta = "
          "0.375 sqrt(pi/m4) with m4 = bandwidth x (rms slope)^4/Rq^2 (Rq 0.4 um, slope 0.05, bandwidth 5: 48 um). "
          "Typical: ground flanks tens of um; the thesis's hobbed, run-in flanks 1.65 and 1.75 um. Given with a "
          "measured flank, it overrides the measured radius");
  auto topo = [gear](auto& c, int g) -> auto& { return gear(c, g).flank.topography; };
  // A measured flank: the rows fill the topography spec (created on first use).
  auto topo_spec = [topo](Case& c, int g) -> surface::TopographySpec& {
    auto& t = topo(c, g);
    if (!t) t.emplace();
    return *t;
  };
  auto topo_get = [topo](const Case& c, int g) -> const surface::TopographySpec& {
    static const surface::TopographySpec kDefault;
    const auto& t = topo(c, g);
    return t ? *t : kDefault;
  };
  auto topo_ref = [topo_spec, topo_get](auto member) {
    return [=](auto& c, int g) -> auto& {
      if constexpr (std::is_const_v<std::remove_reference_t<decltype(c)>>) return member(topo_get(c, g));
      else return member(topo_spec(c, g));
    };
  };
  add(text("{gear}.flank.topography.file", K::text, topo_ref([](auto& t) -> auto& { return t.file; })))
      .doc(
          "Form measured: a profiler export, HDF5 or X3P surface (geartrib surface); its summits give the "
          "roughness");
  add(quantity("{gear}.flank.topography.unit", D::length, topo_ref([](auto& t) -> auto& { return t.unit; })))
      .range(1e-12, 1.0)
      .doc("Length unit of a file that does not state one");
  add(quantity("{gear}.flank.topography.spacing", D::length, topo_ref([](auto& t) -> auto& { return t.spacing; })))
      .range(0.0, 1.0)
      .doc("Grid spacing of files without one; 0: from the file");
  add(quantity("{gear}.flank.topography.resample", D::length, topo_ref([](auto& t) -> auto& { return t.resample; })))
      .range(0.0, 1.0)
      .doc("Regrid spacing; 0: as measured");
  add(integer("{gear}.flank.topography.form", topo_ref([](auto& t) -> auto& { return t.clean.form_degree; })))
      .range(0, 6)
      .field("{gear}.flank.topography.clean.form_degree")
      .doc("Degree of the polynomial form removed");
  add(quantity("{gear}.flank.topography.cutoff", D::length,
               topo_ref([](auto& t) -> auto& { return t.clean.waviness_cutoff; })))
      .range(0.0, 1.0)
      .field("{gear}.flank.topography.clean.waviness_cutoff")
      .doc("Gaussian waviness cut-off (ISO 16610-61); 0: no waviness filter");
  add(number("{gear}.flank.topography.outliers", topo_ref([](auto& t) -> auto& { return t.clean.outlier_limit; })))
      .range(0.0, 1000.0)
      .field("{gear}.flank.topography.clean.outlier_limit")
      .doc("Outlier limit in robust standard deviations: 0 (off) or at least 2");
  {
    Parameter fill = numeric("{gear}.flank.topography.fill", K::flag, D::dimensionless,
                             topo_ref([](auto& t) -> auto& { return t.clean.fill; }));
    add(std::move(fill)).field("{gear}.flank.topography.clean.fill").doc("Fill missing points from their neighbours");
  }
  add(mapped_choice(
          "{gear}.flank.topography.profile_axis", {"x", "y"},
          topo_ref([](auto& t) -> auto& { return t.profile_along_x; }), [](const std::string& t) { return t == "x"; },
          [](bool x) { return std::string(x ? "x" : "y"); }))
      .field("{gear}.flank.topography.profile_along_x")
      .doc("Deterministic: the surface's axis along the involute (root to tip), the profile's direction");
  add(number("{gear}.flank.topography.profile_at", topo_ref([](auto& t) -> auto& { return t.profile_at; })))
      .range(0.0, 1.0)
      .doc("Deterministic: where across the other axis the profile is taken (fraction of its length)");
  add(mapped_choice(
          "{gear}.flank.topography.synthesis", {"none", "psd", "iaaft"},
          topo_ref([](auto& t) -> auto& { return t.synthesis; }),
          [](const std::string& t) { return surface::synthesis_method(t); },
          [](surface::SynthesisMethod m) { return std::string(surface::synthesis_method_name(m)); }))
      .doc(
          "Deterministic: none (the line at profile_at, which must cover the flank), or a flank-long profile "
          "synthesised from the surface's profile spectrum along profile_axis (all its lines; nothing at wavelengths "
          "longer than the surface): random phases (psd), or also its height distribution kept (iaaft)");
  add(integer("{gear}.flank.topography.synthesis_seed", topo_ref([](auto& t) -> auto& { return t.synthesis_seed; })))
      .range(0, 4294967295.0)
      .doc(
          "Synthesis: random seed of the phases (tooth t of the hunting order: seed + t); give the two flanks "
          "different seeds");
  add(quantity("{gear}.flank.topography.synthesis_length", D::length,
               topo_ref([](auto& t) -> auto& { return t.synthesis_length; })))
      .range(0.0, 1.0)
      .doc(
          "Synthesis: the profile's length, centred on the active flank; 0: a module below the base circle to a "
          "module beyond the tip (as a generated profile)");
  // A generated profile along the involute (a roughness form; the deterministic fidelity's flank).
  auto prof = [gear](auto& c, int g) -> auto& { return gear(c, g).flank.profile; };
  auto prof_spec = [prof](Case& c, int g) -> surface::GeneratedProfileSpec& {
    auto& t = prof(c, g);
    if (!t) t.emplace();
    return *t;
  };
  auto prof_get = [prof](const Case& c, int g) -> const surface::GeneratedProfileSpec& {
    static const surface::GeneratedProfileSpec kDefault;
    const auto& t = prof(c, g);
    return t ? *t : kDefault;
  };
  auto prof_ref = [prof_spec, prof_get](auto member) {
    return [=](auto& c, int g) -> auto& {
      if constexpr (std::is_const_v<std::remove_reference_t<decltype(c)>>) return member(prof_get(c, g));
      else return member(prof_spec(c, g));
    };
  };
  add(mapped_choice(
          "{gear}.flank.profile.kind", {"smooth", "ground", "hobbed"},
          prof_ref([](auto& t) -> auto& { return t.kind; }),
          [](const std::string& t) { return surface::profile_kind(t); },
          [](surface::ProfileKind k) { return std::string(surface::profile_kind_name(k)); }))
      .doc(
          "Form generated profile: smooth, ground (Gaussian random, Gaussian autocorrelation) or hobbed "
          "(parabolic ridges meeting in sharp valleys, plus a ground-like random part)");
  add(quantity("{gear}.flank.profile.spacing", D::length, prof_ref([](auto& t) -> auto& { return t.spacing; })))
      .range(1e-9, 1e-4)
      .doc("Generated profile: point spacing along the involute");
  add(quantity("{gear}.flank.profile.rq", D::length, prof_ref([](auto& t) -> auto& { return t.rq; })))
      .range(0.0, 1e-4)
      .plausible(0.0, 25.0 * kUm)
      .doc("Generated profile: Rq of the random part (ground: of the profile)");
  add(quantity("{gear}.flank.profile.correlation_length", D::length,
               prof_ref([](auto& t) -> auto& { return t.correlation_length; })))
      .range(1e-9, 1e-2)
      .doc("Generated profile: lambda of the random part's autocorrelation exp(-tau^2/lambda^2)");
  add(quantity("{gear}.flank.profile.ridge_spacing", D::length,
               prof_ref([](auto& t) -> auto& { return t.ridge_spacing; })))
      .range(1e-8, 1e-2)
      .doc("Hobbed profile: distance between the ridges");
  add(quantity("{gear}.flank.profile.ridge_radius", D::length,
               prof_ref([](auto& t) -> auto& { return t.ridge_radius; })))
      .range(1e-8, 1.0)
      .doc("Hobbed profile: the ridges' tip radius");
  add(integer("{gear}.flank.profile.seed", prof_ref([](auto& t) -> auto& { return t.seed; })))
      .range(0, 4294967295.0)
      .doc("Generated profile: random seed");
}

// [roughness]: both flanks.
void declare_roughness(ParameterRows& table) {
  auto add = [&](Parameter p) -> Row& { return table.add(std::move(p)); };
  // [roughness]: both flanks.
  add(mapped_choice(
          "roughness.distribution", {"gaussian", "exponential"},
          [](auto& c, int) -> auto& { return c.roughness.distribution; },
          [](const std::string& t) {
            return t == "gaussian" ? surface::HeightDistribution::gaussian : surface::HeightDistribution::exponential;
          },
          [](surface::HeightDistribution d) {
            return std::string(d == surface::HeightDistribution::gaussian ? "gaussian" : "exponential");
          }))
      .doc("Summit height distribution");
  add(number(
          "roughness.eta_sigma_beta", [](auto& c, int) -> auto& { return c.roughness.eta_sigma_beta; }))
      .range(0.0, 10.0, true, true)
      .plausible(0.01, 0.2)
      .doc("Summit parameter eta sigma beta for flanks given by Ra or Rq");
}

}  // namespace geartrib::io::parameters
