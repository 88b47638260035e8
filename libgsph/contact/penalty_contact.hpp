// SPDX-License-Identifier: MIT
// Penalty contact between particles of different bodies (issue #6; docs/theory.md "Contact").
// Pairs are found in the current configuration every step: a hashed cell list over x, cells no
// smaller than the largest contact distance, rebuilt from scratch each call (exact, no skin).
// A pair (a, b) of different bodies closer than d_ab = ρ_a + ρ_b (contact radius
// ρ_a = ½ δ ℓ_a, ℓ_a = Reference::spacing, δ = ContactOptions::distance) is pushed apart by
//   f_a = k_ab (d_ab − r) (x_a − x_b)/r = −f_b,   k_ab = k_a k_b/(k_a + k_b),
// the gradient of U = Σ_pairs ½ k_ab (d_ab − r)²; k_a = s m_a c_a²/ℓ_a² is the particle's
// penalty stiffness (contactStiffness). Frictionless between bodies (walls have friction).
// Each particle gathers its own pairs in a fixed order (cells in a fixed order, particles by
// index within a cell), so results do not depend on the thread count, and f_ab, f_ba are
// computed from the same operands: f_a = −f_b bit for bit, Σ f = 0 to round-off.
// Allocation-free once constructed. Outputs per particle: the force (added to the caller's),
// a bound of the squared contact frequency ω_a² (for the stable step), and U.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "core/types.hpp"
#include "particles/reference.hpp"

namespace gsph {

struct ContactOptions {
    bool betweenBodies = true;  ///< penalty contact between particles of different bodies
    /// s: k_a = s m_a c_a²/ℓ_a², so that a particle on a contact spring alone oscillates at
    /// ω = √s c/ℓ (the lattice's own highest frequency is 2c/ℓ).
    double penalty = 4.0;
    double distance = 1.0;  ///< δ: contact radius ρ_a = ½ δ ℓ_a
};

/// Penalty stiffness k_a = s m_a c_a²/ℓ_a² [N/m] (docs/theory.md): with m = ρ ℓ³ and c² = M/ρ
/// this is s M ℓ, a column of one particle's section and length ℓ/s (M: P-wave modulus).
/// `pWaveSpeed2` is c_a² per particle [m²/s²].
std::vector<double> contactStiffness(const Reference& ref, const std::vector<double>& pWaveSpeed2,
                                     double penalty);

class PenaltyContact {
  public:
    PenaltyContact() = default;
    /// `stiffness`: k_a per particle (contactStiffness). Active only with more than one body
    /// and options.betweenBodies.
    PenaltyContact(const Reference& ref, std::vector<double> stiffness,
                   const ContactOptions& options);

    bool active() const { return active_; }

    /// Adds the contact force of every pair to force[a], adds Σ_b k_ab (1/m_a + 1/√(m_a m_b))
    /// (Gershgorin bound of the squared frequency) to frequency2[a]; returns U [J].
    double addForces(const std::vector<Vec3>& x, std::vector<Vec3>& force,
                     std::vector<double>& frequency2);

    /// Pairs in contact at the last addForces (a diagnostic; each pair counted once).
    long pairsInContact() const { return pairs_; }

  private:
    using Cell = std::array<std::int64_t, 3>;
    void build(const std::vector<Vec3>& x);
    std::size_t bucketOf(const Cell& c) const;

    const Reference* ref_ = nullptr;
    bool active_ = false;
    std::vector<double> stiffness_, radius_;
    double cellSize_ = 0.0;
    std::vector<Cell> cell_;               ///< per particle
    std::vector<std::uint32_t> bucket_;    ///< per particle: its hash bucket
    std::vector<Index> bucketStart_;       ///< CSR over buckets (size buckets + 1)
    std::vector<Index> sorted_;            ///< particles, bucket by bucket, by index within
    std::vector<double> energy_;           ///< per particle: half of each of its pairs' U
    std::vector<std::int32_t> pairCount_;  ///< per particle: its pairs in contact
    std::vector<double> partial_;          ///< scratch of deterministicSum
    long pairs_ = 0;
};

}  // namespace gsph
