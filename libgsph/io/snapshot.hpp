// SPDX-License-Identifier: MIT
// Snapshot files of a run (DESIGN §1): the state at one time, for gsph-post and the user.
// HDF5, format "gsph-snapshot" 0.4 (layout in
// docs/formats.md). Written atomically (io/atomic_file.hpp).
//
//   /time, /step                 (1 element each)
//   /particles/X, x, v           N×3 reference position, position, velocity
//   /particles/stress            N×9 Cauchy stress, row-major
//   /particles/F                 N×9 deformation gradient, row-major
//   /particles/volume            N reference quadrature volume ω det M [m³]
//   /particles/body, space       N int32
//   /particles/plastic_strain, temperature, damage   N float64
//   /particles/transient         N int8: 1 if the particle has an overset entry (since 0.3;
//                                absent in older files, read as 0)
//   /particles/bond_damage       N float64: the share of the particle's bonds that broke (since
//                                0.4; absent in older files, read as 0)
//   /bonds/broken                M×2 int32 particle pairs (a < b) whose bond broke (M may be 0)
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <vector>

#include "io/provenance.hpp"
#include "particles/reference.hpp"
#include "particles/state.hpp"

namespace gsph {

inline constexpr const char* kSnapshotFormat = "gsph-snapshot";
inline constexpr int kSnapshotFormatMajor = 0;
inline constexpr int kSnapshotFormatMinor = 4;

/// What a snapshot holds, read back as plain arrays.
struct Snapshot {
    double time = 0.0;
    long step = 0;
    std::vector<Vec3> X, x, v;
    std::vector<Mat3> stress, F;
    std::vector<double> volume;
    std::vector<Index> body, space;
    std::vector<double> plasticStrain, temperature, damage;
    /// 1 if the particle is transient in another space (Reference::overset), else 0.
    std::vector<std::uint8_t> transient;
    /// Broken bonds / bonds of each particle (the peridynamic damage index; 0 without bonds).
    std::vector<double> bondDamage;
    std::vector<std::array<Index, 2>> brokenBonds;  ///< (a, b), a < b
    Provenance provenance;
    Index size() const { return static_cast<Index>(x.size()); }
};

/// 3×3 tensors as N×9 rows, row-major (σ_xx, σ_xy, σ_xz, σ_yx, …), the files' layout (Eigen
/// stores column-major); and back. Exact copies, no arithmetic.
std::vector<double> rowMajor(const std::vector<Mat3>& m);
std::vector<Mat3> fromRowMajor(const std::vector<double>& rows);

/// The broken bonds of a state as particle pairs (a, b) with a < b, in CSR order.
std::vector<std::array<Index, 2>> brokenBonds(const PairList& pairs,
                                              const std::vector<std::uint8_t>& bondIntact);

/// Per particle, the share of its bonds (its entries in `pairs`) that broke: the damage index of
/// peridynamics, in which a crack shows as a line of particles near ½ (one face's bonds gone).
/// All zero when no bond is tracked (bondIntact empty) and for a particle without neighbours.
std::vector<double> brokenBondFraction(const PairList& pairs,
                                       const std::vector<std::uint8_t>& bondIntact);

/// Writes the state of a run. Throws IoError naming the file on failure (nothing left behind).
void writeSnapshot(const std::filesystem::path& path, const Reference& ref, const State& state,
                   const Provenance& provenance);

/// Reads a snapshot. Throws IoError naming the file if it is missing, of another format or
/// major version, or inconsistent.
Snapshot readSnapshot(const std::filesystem::path& path);

/// readSnapshot in a child process (io/child_process.hpp), as readParticleFileIsolated: a damaged
/// or crafted file that crashes or hangs HDF5's own parser (`deadlineSeconds`, 0: 60 s plus 1 s
/// per 20 MB) is an IoError naming the file instead of a crash of the caller. Same results and
/// errors otherwise. The caller's threads may run; the child uses none.
Snapshot readSnapshotIsolated(const std::filesystem::path& path, unsigned deadlineSeconds = 0);

}  // namespace gsph
