// /parameters is written from the Case as it runs (io::current_parameters: each recorded key read
// through its row), with the origins recorded at load: a Case changed in code after loading, as
// examples/custom_sweep.cpp teaches, records the values it ran with, not the file's.
#include "config/case_file.hpp"
#include "config/case_prepare.hpp"
#include "config/case_records.hpp"
#include "config/input_error.hpp"
#include "output/hdf5_handles.hpp"
#include "output/hdf5_results.hpp"
#include "runs/mesh_cycle.hpp"
#include "test_support.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <map>
#include <string>
#include <utility>

namespace geartrib {
namespace {

namespace fs = std::filesystem;

// /parameters as key -> (value, origin).
std::map<std::string, std::pair<std::string, std::string>> parameters_of(const fs::path& file) {
  using io::hdf5::Handle;
  Handle f(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, "file");
  Handle g(H5Gopen2(f, "/parameters", H5P_DEFAULT), H5Gclose, "/parameters");
  const auto keys = io::hdf5::read_strings(g, "key");
  const auto values = io::hdf5::read_strings(g, "value");
  const auto origins = io::hdf5::read_strings(g, "origin");
  std::map<std::string, std::pair<std::string, std::string>> out;
  for (std::size_t i = 0; i < keys.size(); ++i) out[keys[i]] = {values.at(i), origins.at(i)};
  return out;
}

TEST(ParameterRecords, ACaseChangedInCodeRecordsItsValues) {
  const fs::path file = test::source_dir() / "gears/m6z30-dry.toml";
  Case c = io::prepare_case(io::load_case(file, {{"positions", "5"}}));
  c.operating.pinion_torque = 1234.0;  // the file's key, changed in code
  c.contact.strip.strip_points = 32;   // a key of the file, changed in code
  c.dynamics.backlash = 2e-5;          // a default, changed in code
  io::prepare_case(c);
  const contact::MeshContactResult r = runs::run_mesh_cycle(c);
  const fs::path out = fs::temp_directory_path() / "geartrib_parameter_records.h5";
  io::write_mesh_contact_hdf5(out, r, file.string(), c);
  const auto p = parameters_of(out);
  fs::remove(out);
  EXPECT_EQ(p.at("operating.pinion_torque").first, "1234 N m");
  EXPECT_NE(p.at("operating.pinion_torque").second.find("m6z30-dry.toml:"), std::string::npos);
  EXPECT_EQ(p.at("contact.strip_points").first, "32");
  EXPECT_NE(p.at("contact.strip_points").second.find("m6z30-dry.toml:"), std::string::npos);
  EXPECT_EQ(p.at("dynamics.backlash"), std::make_pair(std::string("2e-05 m"), std::string("default")));
  EXPECT_EQ(p.at("contact.positions"), std::make_pair(std::string("5"), std::string("--set")));
  // The load-time record itself is unchanged: what the file said.
  EXPECT_NE(io::find_record(c, "operating.pinion_torque")->value, "1234 N m");
}

// The message of the error a run of `c` throws (empty: none).
std::string run_error(const Case& c) {
  try {
    runs::run_mesh_cycle(c);
  } catch (const io::InputError& e) {
    return e.what();
  }
  return "";
}

// A physics refusal of an option value the table's range let through (a Case changed in code):
// the option struct's validate() names its field (contact::StripOptions' strip_points, the boundary
// elements' element_size), the table maps the field's path to its case key, and the message names
// the file and line the key came from, the key, the value the Case holds and the rule.
TEST(ParameterRecords, APhysicsRefusalIsLocatedAtItsKey) {
  const fs::path dry = test::source_dir() / "gears/m6z30-dry.toml";
  Case c = io::prepare_case(io::load_case(dry, {{"positions", "5"}}));
  c.contact.strip.strip_points = 4;  // below contact::StripOptions::kMinStripPoints
  EXPECT_EQ(run_error(c), dry.string() + ":50: key 'contact.strip_points' = 4: strip_points must lie in [8, 100000]");

  const fs::path deterministic = test::source_dir() / "gears/m6z30-deterministic.toml";
  Case d = io::prepare_case(io::load_case(deterministic, {{"positions", "5"}}));
  d.contact.boundary_elements.element_size = -1e-6;
  EXPECT_EQ(run_error(d),
            deterministic.string() + ":58: key 'contact.element_size' = -1e-06 m: element size must be positive");
  // The boundary elements' plastic_overlap is the key running_in.tolerance (a field of another
  // table's struct): its line in [running_in].
  d = io::prepare_case(io::load_case(deterministic, {{"positions", "5"}}));
  d.contact.boundary_elements.plastic_overlap = 0.0;
  EXPECT_EQ(run_error(d),
            deterministic.string() +
                ":65: key 'running_in.tolerance' = 0 m: plastic overlap threshold outside [1e-15, 1e-3] m");
  // A key the file leaves to its default: its table's line ([contact], line 54).
  d = io::prepare_case(io::load_case(deterministic, {{"positions", "5"}}));
  d.contact.strip.coupled_nodes = 5;
  EXPECT_EQ(run_error(d),
            deterministic.string() + ":54: key 'contact.coupled_nodes' = 5: coupled_nodes must lie in [16, 4000]");
}

}  // namespace
}  // namespace geartrib
