#pragma once
// Checkpoint files: the whole scene, so that a run continued from one takes
// the same steps, bit for bit, as one that never stopped.
//
// Layout (little-endian): an 8-byte magic, the format version (u32), a byte
// order mark (u32), the payload's size (u64) and CRC-32 (u32), then the
// payload: the Manager's state and the caller's own part (the Tcl session's
// settings, as text). Written whole or not at all (atomic_files.hpp).
#include <memory>
#include <string>

#include "sandflow/sim/manager.hpp"

namespace sf::io {

// 2: each warning keeps its remedy (sf::Remedy) beside its sentence.
// 5: outflow sides; velocity sides' profile, ramp and expressions.
inline constexpr int kCheckpointVersion = 5;

void saveCheckpoint(const std::string& path, const sim::Manager& manager,
                    const std::string& session);

struct Checkpoint {
  std::unique_ptr<sim::Manager> manager;
  std::string session;
  int version = 0;
  long long bytes = 0;
};
// Reads a checkpoint into a fresh Manager with `threads` threads. Any fault
// (missing, empty, truncated, corrupted, foreign, a later version, a scene
// the kernel refuses) throws sf::Error naming the file and the fault; nothing
// outside the returned value is touched.
Checkpoint loadCheckpoint(const std::string& path, int threads);

}  // namespace sf::io
