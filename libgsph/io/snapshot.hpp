// SPDX-License-Identifier: MIT
// Snapshot files of a run (DESIGN §1): the state at one time, for gsph-post and the user.
// HDF5, format "gsph-snapshot" 0.4 (layout in docs/formats.md). Written atomically
// (io/atomic_file.hpp).
//
//   /time, /step                 (1 element each)
//   /particles/NAME              one dataset per field of Snapshot::forEachField, with its
//                                `units` attribute: N×3 (vectors), N×9 row-major (tensors), N
//   /bonds/broken                M×2 int32 particle pairs (a < b) whose bond broke (M may be 0)
//
// Snapshot::forEachField is the one list of the per-particle fields: the writer, both readers
// and gsph-post's .vtu arrays iterate it, so a field added there is written, read and shown.
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

/// A per-particle field of a snapshot.
struct SnapshotField {
    const char* name;  ///< dataset /particles/NAME
    const char* unit;  ///< SI unit ("1": a number), the dataset's `units` attribute
    int sinceMinor;    ///< the format 0.N that added it: older files read as zeros
    /// The point-data array gsph-post writes for it in the .vtu (nullptr: none; the positions
    /// are the points, and post derives displacement, J, von Mises and pressure).
    const char* vtuName;
};

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

    /// Calls visit(field, array) for every per-particle array, in the files' order. Array types:
    /// std::vector of Vec3, Mat3, double, Index or std::uint8_t (int8 on file).
    template <class Visitor>
    void forEachField(Visitor&& visit) {
        visitFields(*this, visit);
    }
    template <class Visitor>
    void forEachField(Visitor&& visit) const {
        visitFields(*this, visit);
    }

  private:
    template <class Self, class Visitor>
    static void visitFields(Self& s, Visitor& visit) {
        visit(SnapshotField{"X", "m", 0, nullptr}, s.X);
        visit(SnapshotField{"x", "m", 0, nullptr}, s.x);
        visit(SnapshotField{"v", "m/s", 0, "velocity"}, s.v);
        visit(SnapshotField{"stress", "Pa", 0, "stress"}, s.stress);
        visit(SnapshotField{"F", "1", 0, nullptr}, s.F);
        visit(SnapshotField{"volume", "m^3", 0, "reference_volume"}, s.volume);
        visit(SnapshotField{"body", "1", 0, "body"}, s.body);
        visit(SnapshotField{"space", "1", 0, "space"}, s.space);
        visit(SnapshotField{"plastic_strain", "1", 0, "plastic_strain"}, s.plasticStrain);
        visit(SnapshotField{"temperature", "K", 0, "temperature"}, s.temperature);
        visit(SnapshotField{"damage", "1", 0, "damage"}, s.damage);
        visit(SnapshotField{"transient", "1", 3, "transient"}, s.transient);
        visit(SnapshotField{"bond_damage", "1", 4, "bond_damage"}, s.bondDamage);
    }
};

/// The snapshot of a run's state: the per-particle fields from the reference (X, volume ω det M,
/// body, space, transient) and the state, the bonds' damage and the broken bonds.
Snapshot snapshotOf(const Reference& ref, const State& state);

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
