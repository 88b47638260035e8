// SPDX-License-Identifier: MIT
// The field registry: every array of a run's state and of its snapshots, with the name it has
// in every file, its unit, what it is kept per (particle, pair, wall, pair of bodies) and where
// it is saved. One entry per field, used by everything that names a field:
//   - State::forEachArray visits the state's arrays with their entries: checkpoints save every
//     one (io/checkpoint.hpp), snapshots the ones flagged kSnapshot (io/snapshot.hpp);
//   - snapshots add the reference's fields below (X, volume, body, space, ...);
//   - gsph-post writes a field's .vtu array under its vtuName;
//   - a material model names its history variables by their entries (materials/history.hpp).
// A field added to State with an entry here is saved, restored, written, read back and shown
// wherever its flags say, without another list to extend.
#pragma once

namespace gsph {

/// What a field's array has one entry per.
enum class Extent {
    Particle,  ///< N entries, in particle order
    Pair,      ///< one per CSR pair of the reference's pair list
    Wall,      ///< one per rigid wall, in the order added
    BodyPair,  ///< one per ordered pair of bodies (i, j), at i·B + j
};

/// Where a field is saved (bit flags of Field::savedIn). Every state field is in checkpoints.
enum SavedIn : unsigned {
    kCheckpoint = 1u,  ///< /state/NAME of checkpoint files: a restart needs it
    kSnapshot = 2u,    ///< /particles/NAME of snapshot files (and so gsph-post)
};

struct Field {
    const char* name;  ///< the dataset name: /state/NAME, /particles/NAME
    const char* unit;  ///< SI unit, "1" for a number: the datasets' and arrays' `units`
    Extent extent;
    unsigned savedIn;  ///< SavedIn flags
    /// gsph-post's point-data array for it in the .vtu (nullptr: none; the positions are the
    /// points, and post derives displacement, J, von Mises and pressure from x, X, F, σ).
    const char* vtuName = nullptr;
    /// The snapshot format 0.N that added it: older snapshots read it as zeros.
    int snapshotSinceMinor = 0;
    /// Its dataset name in checkpoints of format 3.0, which are still read (nullptr: the same).
    const char* checkpoint30Name = nullptr;
    /// The checkpoint format 3.N that added it: an older checkpoint reads it as zeros.
    int checkpointSinceMinor = 0;

    constexpr bool isSavedIn(SavedIn where) const { return (savedIn & where) != 0; }
};

namespace fields {

// The state's arrays (particles/state.hpp), in its order.
inline constexpr Field kPosition{"x", "m", Extent::Particle, kCheckpoint | kSnapshot};
inline constexpr Field kVelocity{"v", "m/s", Extent::Particle, kCheckpoint | kSnapshot, "velocity"};
inline constexpr Field kAcceleration{"acceleration", "m/s^2", Extent::Particle, kCheckpoint};
inline constexpr Field kDeformationGradient{"F", "1", Extent::Particle, kCheckpoint | kSnapshot};
inline constexpr Field kStress{.name = "stress",
                               .unit = "Pa",
                               .extent = Extent::Particle,
                               .savedIn = kCheckpoint | kSnapshot,
                               .vtuName = "stress",
                               .checkpoint30Name = "cauchy"};
inline constexpr Field kPlasticStrain{"plastic_strain", "1", Extent::Particle,
                                      kCheckpoint | kSnapshot, "plastic_strain"};
inline constexpr Field kTemperature{"temperature", "K", Extent::Particle, kCheckpoint | kSnapshot,
                                    "temperature"};
inline constexpr Field kDamage{"damage", "1", Extent::Particle, kCheckpoint | kSnapshot, "damage"};
inline constexpr Field kInternalEnergy{
    "internal_energy", "J/kg", Extent::Particle, kCheckpoint | kSnapshot, "internal_energy", 5};
/// ω = Σ Δε̄p/εf, the local driver of a nonlocal damage (failure/nonlocal_damage.hpp).
inline constexpr Field kDamageDriver{.name = "damage_driver",
                                     .unit = "1",
                                     .extent = Extent::Particle,
                                     .savedIn = kCheckpoint | kSnapshot,
                                     .vtuName = "damage_driver",
                                     .snapshotSinceMinor = 5,
                                     .checkpointSinceMinor = 1};
inline constexpr Field kPlasticWork{"plastic_work", "J", Extent::Particle, kCheckpoint | kSnapshot,
                                    "plastic_work", 5};
inline constexpr Field kBondIntact{"bond_intact", "1", Extent::Pair, kCheckpoint};
inline constexpr Field kWallForce{"wall_force", "N", Extent::Wall, kCheckpoint};
inline constexpr Field kContactForce{"contact_force", "N", Extent::BodyPair, kCheckpoint};
/// Per CSR pair of a broken bond in a run with self-contact: the largest distance the pair has
/// had since the bond broke, capped at its reference distance (contact/penalty_contact.hpp).
inline constexpr Field kContactSeparation{.name = "contact_separation",
                                          .unit = "m",
                                          .extent = Extent::Pair,
                                          .savedIn = kCheckpoint,
                                          .checkpointSinceMinor = 2};
/// Per CSR pair, in bodies with a fracture energy: the normal stress across a bond when it broke
/// by stretch (> 0: it softens), and the largest stretch it has had since
/// (forces/cohesive_bonds.hpp).
inline constexpr Field kCohesiveTraction{.name = "cohesive_traction",
                                         .unit = "Pa",
                                         .extent = Extent::Pair,
                                         .savedIn = kCheckpoint,
                                         .checkpointSinceMinor = 3};
inline constexpr Field kCohesiveStretch{.name = "cohesive_stretch",
                                        .unit = "1",
                                        .extent = Extent::Pair,
                                        .savedIn = kCheckpoint,
                                        .checkpointSinceMinor = 3};

// The reference's fields a snapshot adds (io/snapshot.hpp).
inline constexpr Field kReferencePosition{"X", "m", Extent::Particle, kSnapshot};
inline constexpr Field kVolume{"volume", "m^3", Extent::Particle, kSnapshot, "reference_volume"};
inline constexpr Field kBody{"body", "1", Extent::Particle, kSnapshot, "body"};
inline constexpr Field kSpace{"space", "1", Extent::Particle, kSnapshot, "space"};
inline constexpr Field kTransient{"transient", "1", Extent::Particle, kSnapshot, "transient", 3};
inline constexpr Field kBondDamage{"bond_damage", "1",           Extent::Particle,
                                   kSnapshot,     "bond_damage", 4};

}  // namespace fields
}  // namespace gsph
