// `geartrib surface`: measured topography (seed section 4) - synthetic surfaces, statistics,
// the equivalent surface of two flanks, and the reduction to summits or parabolic cylinders.
#include "app/cli_options.hpp"
#include "app/commands.hpp"
#include "app/surface_input.hpp"

#include "output/table_writer.hpp"
#include "runs/surface_statistics_table.hpp"
#include "surface/cylinder_reduction.hpp"
#include "surface/surface_statistics.hpp"
#include "surface/synthetic_surface.hpp"
#include "topography/topography_files.hpp"

#include <fmt/format.h>

#include <memory>

namespace geartrib::app {

namespace {

double length(const std::string& option, const std::string& text) {
  return quantity_option(option, text, io::Dimension::length);
}

// A length option within (lo, hi] metres (lo itself allowed when `closed`), the option named.
double bounded_length(const std::string& option, const std::string& text, double lo, double hi, bool closed) {
  const double v = length(option, text);
  if (!(closed ? v >= lo : v > lo) || !(v <= hi))
    throw std::invalid_argument(
        fmt::format("{} '{}': must lie in {}{:g} m, {:g} m]", option, text, closed ? "[" : "(", lo, hi));
  return v;
}
// A grid spacing option: within the limits of every grid (surface/height_grid.hpp).
double spacing_option(const std::string& option, const std::string& text) {
  return bounded_length(option, text, surface::kMinSpacing, surface::kMaxSpacing, true);
}

// The surface file -o names, checked before any work: its format (by extension) and its target.
void reserve_surface(const std::string& file, io::OutputSet& outputs) {
  io::topography_format(file);
  outputs.reserve(file);
}

}  // namespace

void add_surface_input_options(CLI::App* cmd, SurfaceInputOptions& o) {
  cmd->add_option("--unit", o.unit, "Length unit of ASCII files that do not state one in '# units:' (default um)");
  cmd->add_option("--grid-spacing", o.spacing,
                  "Spacing of height-grid files without a '# spacing:' line (e.g. \"0.5 um\")");
  cmd->add_option("--resample", o.resample,
                  "Regrid at this spacing: point clouds off a lattice are binned, grids interpolated");
  cmd->add_option("--form", o.form_degree,
                  "Form removed: least-squares polynomial of this degree (0 none, 1 plane, default 2)")
      ->check(CLI::Range(0, 6));
  cmd->add_option("--cutoff", o.cutoff,
                  "Gaussian cut-off separating waviness from roughness (e.g. \"0.25 mm\"; default: no filter)");
  cmd->add_option("--outliers", o.outliers,
                  "Mask points beyond K robust standard deviations (1.4826 MAD) of the form-free surface");
  cmd->add_flag("--fill", o.fill, "Fill missing points from their neighbours (default: leave them masked)");
}

namespace {

struct GenerateOptions {
  std::string kind = "self-affine";
  std::string output;
  int nx = 0, ny = 0;
  std::string spacing, rq = "0.3 um", rolloff = "30 um", short_cutoff, wavelength = "5 um", tip_radius = "6.6 um",
                       noise = "0 um", lay_angle = "0 deg", unit = "um", correlation = "10 um", fine_rq = "0.02 um",
                       fine_correlation = "2 um";
  double hurst = 0.8, anisotropy = 0.0, plateau = 0.8;
  std::uint64_t seed = 1;
};

void generate(const GenerateOptions& o) {
  io::OutputSet outputs;
  reserve_surface(o.output, outputs);
  surface::HeightGrid g;
  auto check_size = [](int nx, int ny) {
    if (static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny) > surface::kMaxGridPoints)
      throw std::invalid_argument(
          fmt::format("--nx {} --ny {}: more than the {} points a grid may hold", nx, ny, surface::kMaxGridPoints));
  };
  if (o.kind == "self-affine") {
    surface::SelfAffineSpec s;
    if (o.nx) s.nx = o.nx;
    if (o.ny) s.ny = o.ny;
    check_size(s.nx, s.ny);
    if (!o.spacing.empty()) s.spacing = spacing_option("--spacing", o.spacing);
    s.rq = bounded_length("--rq", o.rq, 0.0, surface::kMaxHeight, false);
    s.hurst = o.hurst;
    s.rolloff_wavelength = length("--rolloff", o.rolloff);
    s.cutoff_wavelength = o.short_cutoff.empty() ? 4.0 * s.spacing : length("--short-cutoff", o.short_cutoff);
    s.anisotropy = o.anisotropy > 0.0 ? o.anisotropy : 1.0;
    s.lay_angle = quantity_option("--lay-angle", o.lay_angle, io::Dimension::angle);
    s.seed = o.seed;
    g = surface::self_affine_surface(s);
  } else if (o.kind == "ground" || o.kind == "superfinished") {
    surface::GaussianSurfaceSpec s;
    if (o.nx) s.nx = o.nx;
    if (o.ny) s.ny = o.ny;
    if (!o.nx) s.nx = 256;
    if (!o.ny) s.ny = 256;
    check_size(s.nx, s.ny);
    if (!o.spacing.empty()) s.dx = s.dy = spacing_option("--spacing", o.spacing);
    s.rq = bounded_length("--rq", o.rq, 0.0, surface::kMaxHeight, false);
    s.correlation_length = length("--correlation", o.correlation);
    const double ratio = o.anisotropy > 0.0 ? o.anisotropy : 8.0;
    if (!(ratio >= 1.0 && ratio <= 1000.0))
      throw std::invalid_argument(fmt::format("--anisotropy {:g}: the ratio must lie in [1, 1000]", ratio));
    s.correlation_length_y = ratio * s.correlation_length;
    s.seed = o.seed;
    if (o.kind == "ground") {
      g = surface::gaussian_surface(s);
    } else {
      if (!(o.plateau > 0.0 && o.plateau < 1.0))
        throw std::invalid_argument(fmt::format("--plateau {:g}: the area cut flat must lie in (0, 1)", o.plateau));
      surface::SuperfinishedSpec f;
      f.ground = s;
      f.plateau = o.plateau;
      f.fine_rq = bounded_length("--fine-rq", o.fine_rq, 0.0, surface::kMaxHeight, true);
      f.fine_correlation = length("--fine-correlation", o.fine_correlation);
      g = surface::superfinished_surface(f);
    }
  } else {
    surface::HobbedSpec s;
    if (o.nx) s.nx = o.nx;
    if (o.ny) s.ny = o.ny;
    check_size(s.nx, s.ny);
    if (!o.spacing.empty()) s.spacing = spacing_option("--spacing", o.spacing);
    s.wavelength = length("--wavelength", o.wavelength);
    s.tip_radius = length("--tip-radius", o.tip_radius);
    s.noise_rq = length("--noise", o.noise);
    s.seed = o.seed;
    g = surface::hobbed_surface(s);
  }
  io::add_topography(outputs, o.output, g, quantity_option("--out-unit", "1 " + o.unit, io::Dimension::length));
  outputs.commit();
}

struct StatsOptions {
  SurfaceInputOptions input;
  std::string file;
  TableOptions table;
};

struct EquivalentOptions {
  SurfaceInputOptions input;
  std::string upper, lower, output, unit = "um", mirror = "x";
  TableOptions table;  // the statistics (standard output or --csv FILE); -o is the surface
};

void equivalent(const EquivalentOptions& o) {
  io::OutputSet outputs;  // the surface and the statistics' files, all or none
  reserve_surface(o.output, outputs);
  reserve_table(o.table, outputs);
  const io::LoadedSurface u = load_surface_reporting(o.upper, o.input), d = load_surface_reporting(o.lower, o.input);
  surface::HeightGrid e;
  try {
    const auto mirror = o.mirror == "x"   ? surface::Mirror::x
                        : o.mirror == "y" ? surface::Mirror::y
                                          : surface::Mirror::none;
    e = surface::equivalent_surface(u.grid, d.grid, mirror);
  } catch (const std::invalid_argument& ex) {
    throw std::invalid_argument(fmt::format("{} and {}: {}", o.upper, o.lower, ex.what()));
  }
  // The statistics before the surface is written: a surface they refuse leaves no file behind.
  const auto stats = about_surface(o.upper + " + " + o.lower, [&] { return surface::surface_statistics(e); });
  io::add_topography(outputs, o.output, e, quantity_option("--out-unit", "1 " + o.unit, io::Dimension::length));
  emit_table(runs::surface_statistics_table(stats, nullptr), o.table, outputs);
}

struct AsperityOptions {
  SurfaceInputOptions input;
  std::string file;
  bool cylinders = false;
  double prominence = 0.5, cap = 0.3;
  TableOptions table;
};

void asperities(const AsperityOptions& o) {
  io::OutputSet outputs;
  reserve_table(o.table, outputs);
  const io::LoadedSurface in = load_surface_reporting(o.file, o.input);
  const surface::SurfaceStatistics s = about_surface(o.file, [&] { return surface::surface_statistics(in.grid); });
  io::Table t;
  if (!o.cylinders) {
    double mean = 0.0;
    std::size_t n = 0;
    for (std::size_t k = 0; k < in.grid.size(); ++k)
      if (in.grid.valid[k]) mean += in.grid.z[k], ++n;
    mean /= static_cast<double>(n);
    t.header = {"x_m", "y_m", "height_m", "radius_m"};
    for (const auto& p : surface::find_summits(in.grid, mean)) t.rows.push_back({p.x, p.y, p.height, p.radius});
    fmt::print(
        stderr,
        "{} summits: density {:.4g} /mm^2 (McCool {:.4g}), radius {:.4g} um (McCool {:.4g}), height mean {:.4g} um, "
        "sigma {:.4g} um (McCool {:.4g})\n",
        s.summits, s.summit_density * 1e-6, s.mccool_density * 1e-6, s.summit_radius * 1e6, s.mccool_radius * 1e6,
        s.summit_mean_height * 1e6, s.summit_sigma * 1e6, s.mccool_summit_sigma * 1e6);
  } else {
    const surface::CylinderReduction r =
        about_surface(o.file, [&] { return surface::reduce_to_cylinders(in.grid, s.lay_angle, o.prominence, o.cap); });
    t.header = {"centre_m", "height_m", "tip_radius_m", "spacing_m"};
    for (const auto& a : r.asperities) t.rows.push_back({a.centre, a.height, a.tip_radius, a.spacing});
    fmt::print(
        stderr,
        "{} cylinder asperities across the lay ({}): tip radius R_m {:.4g} +- {:.3g} um, spacing {:.4g} +- {:.3g} um, "
        "height {:.4g} +- {:.3g} um\n",
        r.asperities.size(), r.lay_along_y ? "lay along y, profile along x" : "lay along x, profile along y",
        r.mean_tip_radius * 1e6, r.sd_tip_radius * 1e6, r.mean_spacing * 1e6, r.sd_spacing * 1e6, r.mean_height * 1e6,
        r.sd_height * 1e6);
  }
  emit_table(t, o.table, outputs);
}

}  // namespace

io::LoadedSurface load_surface_reporting(const std::string& file, const SurfaceInputOptions& o) {
  io::TopographyReadOptions read;
  read.unit = quantity_option("--unit", "1 " + o.unit, io::Dimension::length);
  if (!(read.unit > 0.0)) throw std::invalid_argument("--unit '" + o.unit + "': must be a positive length unit");
  if (!o.spacing.empty()) read.spacing = spacing_option("--grid-spacing", o.spacing) / read.unit;
  if (!o.resample.empty()) read.resample = spacing_option("--resample", o.resample);
  surface::CleanupOptions clean;
  clean.form_degree = o.form_degree;
  // The cut-off against the grid (two spacings to the surface's length) once the file is read.
  if (!o.cutoff.empty()) clean.waviness_cutoff = bounded_length("--cutoff", o.cutoff, 0.0, surface::kMaxSpacing, false);
  clean.outlier_limit = o.outliers;
  clean.fill = o.fill;
  try {
    clean.validate();
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string("surface clean-up options: ") + e.what());
  }
  io::LoadedSurface s = io::load_surface(file, read, clean);
  for (const auto& w : s.warnings) fmt::print(stderr, "{}\n", w);
  fmt::print(
      stderr,
      "{}: {} x {} points at {:.4g} x {:.4g} um; {} missing in the file, {} outliers masked, {} filled, {} missing\n",
      file, s.grid.nx, s.grid.ny, s.grid.dx * 1e6, s.grid.dy * 1e6, s.cleanup.missing_in, s.cleanup.outliers,
      s.cleanup.filled, s.cleanup.missing_out);
  return s;
}

void add_surface_command(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "surface",
      "Measured topography: generate synthetic surfaces, clean profiler exports, compute Ra, Rq, Rsk,\n"
      "Rku, Rz, spectral moments along and across the lay, summits beside McCool's predictions, the equivalent surface\n"
      "of two flanks, and the reduction to parabolic-cylinder asperities.\n"
      "Formats by extension: .xyz/.asc point clouds (x y z, header lines skipped, 'Bad' or NaN missing), .csv/.txt/.grd\n"
      "height grids ('# spacing: 0.5 um' and '# units: um' lines), .h5/.hdf5 (/z with attributes dx, dy in m),\n"
      ".x3p (ISO 25178-72 open surface format: areal or profile, incremental axes, lengths in m).\n"
      "Clean-up order: outliers masked, missing filled (--fill), polynomial form removed (--form), waviness filtered (--cutoff).");
  cmd->require_subcommand(1);

  auto g = std::make_shared<GenerateOptions>();
  auto* gen = cmd->add_subcommand(
      "generate", "Write a seeded synthetic surface: the test data (no measured flank ships with geartrib)");
  gen->add_option("kind", g->kind,
                  "self-affine (random-phase, Hurst exponent, roll-off), ground (Gaussian correlation, a lay along "
                  "y), superfinished (a ground surface's peaks cut to a plateau, a fine texture on it) or hobbed "
                  "(parallel parabolic ridges)")
      ->check(CLI::IsMember({"self-affine", "ground", "superfinished", "hobbed"}));
  add_output_option(gen, g->output, "the surface to write (format by extension; required)");
  gen->get_option("--output")->required();
  gen->add_option("--nx", g->nx, "Points along x (self-affine, ground, superfinished 256; hobbed 512)")
      ->check(CLI::Range(3, 1 << 14));
  gen->add_option("--ny", g->ny, "Points along y (self-affine, ground, superfinished 256; hobbed 64)")
      ->check(CLI::Range(3, 1 << 14));
  gen->add_option("--spacing", g->spacing, "Grid spacing (self-affine, ground, superfinished 0.5 um; hobbed 0.1 um)");
  gen->add_option("--rq", g->rq,
                  "self-affine, ground: root-mean-square height; superfinished: the ground surface's before the cut "
                  "(default 0.3 um)");
  gen->add_option("--hurst", g->hurst, "self-affine: Hurst exponent H in (0, 1) (default 0.8)");
  gen->add_option("--rolloff", g->rolloff, "self-affine: roll-off wavelength (default 30 um)");
  gen->add_option("--short-cutoff", g->short_cutoff, "self-affine: shortest wavelength (default 4 spacings)");
  gen->add_option("--anisotropy", g->anisotropy,
                  "self-affine, ground, superfinished: correlation length ratio along/across the lay (default 1; "
                  "ground and superfinished 8)");
  gen->add_option("--correlation", g->correlation,
                  "ground, superfinished: correlation length across the lay, along x (default 10 um)");
  gen->add_option("--plateau", g->plateau,
                  "superfinished: the area cut flat, the material ratio at the cut (default 0.8)");
  gen->add_option("--fine-rq", g->fine_rq,
                  "superfinished: Rq of the finishing's fine isotropic texture (default 0.02 um)");
  gen->add_option("--fine-correlation", g->fine_correlation,
                  "superfinished: correlation length of the fine texture (default 2 um)");
  gen->add_option("--lay-angle", g->lay_angle, "self-affine: lay direction from the x axis (default \"0 deg\")");
  gen->add_option("--wavelength", g->wavelength, "hobbed: ridge spacing (default 5 um)");
  gen->add_option("--tip-radius", g->tip_radius, "hobbed: ridge tip radius (default 6.6 um)");
  gen->add_option("--noise", g->noise, "hobbed: Rq of added Gaussian noise (default 0)");
  gen->add_option("--seed", g->seed, "Random seed (default 1)");
  gen->add_option("--out-unit", g->unit, "Length unit of ASCII output (m, mm, um, nm; default um)");
  gen->callback([g] { generate(*g); });

  auto s = std::make_shared<StatsOptions>();
  auto* st = cmd->add_subcommand("stats", "Clean a surface and print its statistics");
  st->add_option("file", s->file, "Surface file")->required();
  add_surface_input_options(st, s->input);
  add_table_options(st, s->table);
  st->callback([s] {
    io::OutputSet outputs;
    reserve_table(s->table, outputs);
    const io::LoadedSurface in = load_surface_reporting(s->file, s->input);
    emit_table(runs::surface_statistics_table(
                   about_surface(s->file, [&] { return surface::surface_statistics(in.grid); }), &in.cleanup),
               s->table, outputs);
  });

  auto cl = std::make_shared<EquivalentOptions>();  // upper: the input; unit: of the output
  auto* clean = cmd->add_subcommand("clean", "Clean a surface and write it (any format: also a format converter)");
  clean->add_option("file", cl->upper, "Surface file")->required();
  add_output_option(clean, cl->output, "the cleaned surface to write (format by extension; required)");
  clean->get_option("--output")->required();
  clean->add_option("--out-unit", cl->unit, "Length unit of ASCII output (default um)");
  add_surface_input_options(clean, cl->input);
  clean->callback([cl] {
    io::OutputSet outputs;
    reserve_surface(cl->output, outputs);
    const io::LoadedSurface in = load_surface_reporting(cl->upper, cl->input);
    io::add_topography(outputs, cl->output, in.grid,
                       quantity_option("--out-unit", "1 " + cl->unit, io::Dimension::length));
    outputs.commit();
  });

  auto e = std::make_shared<EquivalentOptions>();
  auto* eq = cmd->add_subcommand(
      "equivalent",
      "Equivalent rough surface y_e = y_u + y_d of two facing flanks (upper mirrored, in x by default; grids\n"
      "must align): "
      "each is cleaned, the sum written to -o and its statistics printed");
  eq->add_option("upper", e->upper, "Upper flank surface file")->required();
  eq->add_option("lower", e->lower, "Lower flank surface file")->required();
  add_output_option(eq, e->output, "the equivalent surface to write (format by extension; required)");
  eq->get_option("--output")->required();
  eq->add_option("--out-unit", e->unit, "Length unit of ASCII output (default um)");
  eq->add_option("--mirror", e->mirror,
                 "Axis the upper flank is mirrored about: x (default), y, or none (already in the lower's frame)")
      ->check(CLI::IsMember({"x", "y", "none"}));
  add_csv_option(eq, e->table.csv,
                 "the statistics as CSV: to FILE, or without one to standard output in place\n"
                 "of the aligned table");
  add_surface_input_options(eq, e->input);
  eq->callback([e] { equivalent(*e); });

  auto a = std::make_shared<AsperityOptions>();
  auto* as = cmd->add_subcommand(
      "asperities",
      "Reduce a surface to asperities: its summits (eight-neighbour peaks: position, height, radius), or with\n"
      "--cylinders the profile across the lay cut into parabolic cylinders (the thesis's hobbed-flank model: centre, tip\n"
      "height, tip radius R_m, spacing). A summary with the distributions goes to stderr.");
  as->add_option("file", a->file, "Surface file")->required();
  as->add_flag("--cylinders", a->cylinders, "Parabolic-cylinder asperities across the lay instead of summits");
  as->add_option("--prominence", a->prominence,
                 "Cylinders: least peak prominence in units of the profile's Rq (default 0.5)")
      ->check(CLI::Range(0.0, 100.0));
  as->add_option("--cap", a->cap, "Cylinders: fit each parabola over the top fraction of its prominence (default 0.3)")
      ->check(CLI::Range(0.05, 1.0));
  add_surface_input_options(as, a->input);
  add_table_options(as, a->table);
  as->callback([a] { asperities(*a); });
}

}  // namespace geartrib::app
