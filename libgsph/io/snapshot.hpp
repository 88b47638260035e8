// SPDX-License-Identifier: MIT
// Snapshot files of a run (DESIGN §1): the state at one time, for gsph-post and the user.
// HDF5, format "gsph-snapshot" 0.6 (layout in docs/formats.md). Written atomically
// (io/atomic_file.hpp).
//
//   /time, /step                 (1 element each)
//   /dimension, /axisymmetric    (1 int32: 3 or 2; 1 int8: 1 for an axisymmetric run's section;
//                                since 0.6)
//   /particles/NAME              one dataset per field of Snapshot::forEachField, with its
//                                `units` attribute: N×3 (vectors), N×9 row-major (tensors), N
//   /bonds/broken                M×2 int32 particle pairs (a < b) whose bond broke (M may be 0)
//
// Snapshot::forEachField is the one list of the per-particle fields, derived from the field
// registry (particles/fields.hpp): the reference's fields and every state array flagged
// kSnapshot. The writer, both readers and gsph-post's .vtu arrays iterate it, so a state field
// flagged there is written, read and shown.
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
/// 0.5: internal_energy, plastic_work, damage_driver (older files read them as zeros);
/// 0.6: /dimension and /axisymmetric (older files: 3 and 0).
inline constexpr int kSnapshotFormatMinor = 6;

/// What a snapshot holds, read back as plain arrays.
struct Snapshot {
    /// The state at the snapshot's time: time, step and the arrays whose field is saved in
    /// snapshots (Field::isSavedIn(kSnapshot): x, v, σ, F, ε̄p, T, D, e, plastic work and the
    /// damage driver); the others are empty.
    State state;
    // The reference's fields.
    std::vector<Vec3> X;
    std::vector<double> volume;  ///< ω det M [m³]
    std::vector<Index> body, space;
    /// 1 if the particle is transient in another space (Reference::overset), else 0.
    std::vector<std::uint8_t> transient;
    /// Broken bonds / bonds of each particle (the peridynamic damage index; 0 without bonds).
    std::vector<double> bondDamage;
    std::vector<std::array<Index, 2>> brokenBonds;  ///< (a, b), a < b
    Provenance provenance;
    /// The run was axisymmetric (a 2-D section whose particles are rings; its volumes are the
    /// rings' volumes).
    bool axisymmetric = false;
    int dimension = 3;  ///< 2 for a run of a 2-D particle file (plane strain or axisymmetric)
    Index size() const { return static_cast<Index>(X.size()); }

    /// Calls visit(field, array) for every per-particle array, in the files' order, with its
    /// entry of the field registry. Array types: std::vector of Vec3, Mat3, double, Index or
    /// std::uint8_t (int8 on file).
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
        visit(fields::kReferencePosition, s.X);
        s.state.forEachArray([&](const Field& field, auto& array) {
            if (field.isSavedIn(kSnapshot)) visit(field, array);
        });
        visit(fields::kVolume, s.volume);
        visit(fields::kBody, s.body);
        visit(fields::kSpace, s.space);
        visit(fields::kTransient, s.transient);
        visit(fields::kBondDamage, s.bondDamage);
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
