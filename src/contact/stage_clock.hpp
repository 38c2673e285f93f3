// The mesh cycle's stage timings, lap by lap: what the cycle and the fidelities record in
// MeshContactResult::stages (internal: the library's sources only).
#pragma once

#include "contact/mesh_contact.hpp"
#include "core/stopwatch.hpp"

#include <string>
#include <utility>
#include <vector>

namespace geartrib::contact {

struct StageClock {
  std::vector<StageTiming>& stages;
  Stopwatch watch;
  void lap(std::string name) { stages.push_back({std::move(name), watch.lap()}); }  // [s] since the last
};

}  // namespace geartrib::contact
