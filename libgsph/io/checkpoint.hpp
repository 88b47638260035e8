// SPDX-License-Identifier: MIT
// Checkpoint files (DESIGN §1): the whole State of a run, so that a restart continues it bit
// for bit, plus what the run's driver needs to resume its own schedule. HDF5, format
// "gsph-checkpoint" 3.3 (layout in docs/formats.md). Written atomically (io/atomic_file.hpp).
//
//   /state/NAME            every array of State::forEachArray under its field's name
//                          (particles/fields.hpp), with its `units` attribute (Vec3: N×3,
//                          Mat3: N×9 row-major, double: N, uint8: per pair), stored exactly
//   /state/scalars/NAME    every scalar of State::forEachScalar (float64 or int64, 1 element)
//   /run/inputs/{role,file,sha256}   the files the run was built from and their SHA-256
//   /run/counters/NAME     int64 counters of the driver (next output index, ...)
//   /run/texts/NAME        strings of the driver (the history rows written so far, ...)
//
// Contract: the State goes through its visitors only, so a field added to State is saved and
// restored without a change here. A restart must also rebuild the same Reference (same case,
// same particle file: the inputs' hashes say so) and must not recompute what the state holds
// (a_n, Δt_n, the ledger's powers): VelocityVerlet::resume.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "io/provenance.hpp"
#include "particles/state.hpp"

namespace gsph {

inline constexpr const char* kCheckpointFormat = "gsph-checkpoint";
/// 3.0: the contact force between each pair of bodies (/state/contact_force). 3.1: the arrays
/// carry `units`, the stress is /state/stress as in snapshots (3.0's /state/cauchy is read), and
/// /state/damage_driver holds nonlocal damage's driver (a 3.0 file reads it as zeros). 3.2:
/// /state/contact_separation of self-contact (an older file has none: read as empty). 3.3:
/// /state/cohesive_traction, /state/cohesive_stretch and the ledger's cohesive work and power of
/// softening bonds (an older file has none: read as empty and 0).
inline constexpr int kCheckpointFormatMajor = 3;
inline constexpr int kCheckpointFormatMinor = 3;

/// A file the run was built from: a restart refuses to continue if its bytes changed.
struct CheckpointInput {
    std::string role;    ///< what the file is to the run ("case", "particles")
    std::string file;    ///< as the run named it
    std::string sha256;  ///< SHA-256 of its bytes when the run started (lower-case hex)
};

/// What the driver of a run keeps beyond the State to resume its schedule exactly.
struct RunRecord {
    std::vector<CheckpointInput> inputs;
    std::map<std::string, std::int64_t> counters;
    std::map<std::string, std::string> texts;
};

struct Checkpoint {
    State state;
    RunRecord run;
    Provenance provenance;
};

/// Writes a checkpoint. Throws IoError naming the file on failure (nothing left behind).
void writeCheckpoint(const std::filesystem::path& path, const State& state, const RunRecord& run,
                     const Provenance& provenance);

/// Reads a checkpoint. Throws IoError naming the file if it is missing, of another format or
/// major version, or lacks an object the State or the record needs.
Checkpoint readCheckpoint(const std::filesystem::path& path);

/// Throws InputError naming `file` and the array if an array of `loaded` has another length
/// than the same array of `expected` (e.g. State::atRest of the run's reference).
void checkStateShape(const State& loaded, const State& expected, const std::string& file);

}  // namespace gsph
