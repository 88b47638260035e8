// SPDX-License-Identifier: MIT
// Penalty contact between particles of different bodies (docs/theory.md "Contact").
// Pairs are found in the current configuration every step: a hashed cell list over x, cells no
// smaller than the largest contact distance, rebuilt from scratch each call (exact, no skin),
// over the particles that lie within another body's bounding box grown by that distance.
// Each particle is an ellipsoid, δ times the one inscribed in its cell (semi-axes ½δΔθ M_a,
// M = ∂X/∂θ, δ = ContactOptions::distance): its contact radius along a unit direction n is
// ρ_a(n) = 1/|S_a n|, S_a = (½δΔθ M_a)^{-1} (half the cell's width along an axis of the cell).
// A pair (a, b) of different bodies, n = (x_a − x_b)/r, closer than d_ab(n) = ρ_a(n) + ρ_b(n)
// stores U_ab = ½ k_ab (d_ab − r)² and feels its gradient,
//   f_a = k_ab (d_ab − r) [n + (h − (n·h) n)/r] = −f_b,  h = −∂d_ab/∂n = Σ_{a,b} S^T S n/|S n|³,
// k_ab = k_a k_b/(k_a + k_b), k_a = s m_a c_a²/ℓ_a² the particle's penalty stiffness
// (contactStiffness). Frictionless between bodies (walls have friction).
// Self-contact (ContactOptions::selfContact): the parts of one body that its broken bonds
// have separated (fragments, a plug and the plate it leaves) meet by the same law. A pair of
// one body is in it when at least one of the two has lost a bond and no intact bond joins them
// (a bond's own pair force holds bonded particles). For a pair whose bond broke, the contact
// distance is min(d_ab(n), |X_a − X_b|, s_ab), s_ab the largest distance the pair has had since
// the bond broke (this evaluation's included; State::contactSeparation): a bond that breaks in
// compressed material stores no energy at the break (the first perforation runs, capped at the
// reference distance alone, blew up), the faces of a crack at rest touch without force (the
// ellipsoids of a graded lattice overlap a little), and the contact distance grows back only
// while the pair is apart, so U is a potential of x. Pairs that never shared a bond meet at
// d_ab. The search then also covers the particles within reach of the bounding box of their
// body's damaged particles.
#pragma once

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

#include "core/parallel.hpp"
#include "core/types.hpp"
#include "distributed/domain.hpp"
#include "particles/reference.hpp"

namespace gsph {

struct ContactOptions {
    bool betweenBodies = true;  ///< penalty contact between particles of different bodies
    /// s: k_a = s m_a c_a²/ℓ_a², so that a particle on a contact spring alone oscillates at
    /// ω = √s c/ℓ (the lattice's own highest frequency is 2c/ℓ). 2: an elastic rebound keeps
    /// 0.8 points more momentum than at 4, for a contact 0.2–1 % longer (docs/theory.md).
    double penalty = 2.0;
    double distance = 1.0;  ///< δ: the contact ellipsoid is δ × the cell's inscribed one
    /// Contact between the parts of one body once broken bonds separate them (see above).
    bool selfContact = false;
};

/// The particles' contact ellipsoids: S_a = (½δΔθ M_a)^{-1} and the largest semi-axis
/// ½δΔθ σ_max(M_a) [m] (bounds ρ_a(n) for every n). M_a from spaces/metric.hpp.
struct ContactShapes {
    std::vector<Mat3> S;
    std::vector<double> largestRadius;
    /// ρ_a(n) = 1/|S_a n| for a unit n [m].
    double radius(std::size_t a, const Vec3& n) const { return 1.0 / (S[a] * n).norm(); }
};
ContactShapes contactShapes(const Reference& ref, double distance);

/// Penalty stiffness k_a = s m_a c_a²/ℓ_a² [N/m] (docs/theory.md): with m = ρ ℓ³ and c² = M/ρ
/// this is s M ℓ, a column of one particle's section and length ℓ/s (M: P-wave modulus).
/// `pWaveSpeed2` is c_a² per particle [m²/s²].
std::vector<double> contactStiffness(const Reference& ref, const std::vector<double>& pWaveSpeed2,
                                     double penalty);

class PenaltyContact {
  public:
    PenaltyContact() = default;
    /// `stiffness`: k_a per particle (contactStiffness); `shapes`: contactShapes. Active with
    /// more than one body and options.betweenBodies, or with options.selfContact.
    PenaltyContact(const Reference& ref, std::vector<double> stiffness, ContactShapes shapes,
                   const ContactOptions& options);

    bool active() const { return active_; }
    /// The particles whose forces, energy and body totals addForces computes (all of them
    /// unless set: a process of a split run, distributed/domain.hpp). x need hold only their
    /// positions: each process bounds and lists its own particles near the contact zone and
    /// the positions and lost-bond flags of the others' come over `domain` (null: serial).
    void restrictTo(ParticleRange owned, Domain* domain = nullptr) {
        owned_ = owned;
        domain_ = domain;
        if (split() && positions_.size() != candidate_.size()) positions_.resize(candidate_.size());
    }

    /// Adds the contact force of every pair to force[a], adds Σ_b k_ab |∂gap/∂x_a|² (1/m_a +
    /// 1/√(m_a m_b)) (Gershgorin bound of the squared frequency) to frequency2[a]; returns U [J],
    /// exactly rounded over every process of a split run (collective).
    /// `bondIntact` (State::bondIntact, per CSR pair; empty: no bond broken) decides the pairs
    /// of self-contact, `separation` (State::contactSeparation; empty: none measured) caps
    /// their contact distance.
    double addForces(const std::vector<Vec3>& x, std::vector<Vec3>& force,
                     std::vector<double>& frequency2,
                     const std::vector<std::uint8_t>& bondIntact = {},
                     const std::vector<double>& separation = {});
    /// With self-contact, after addForces at the same x: raises each broken pair's separation
    /// to its current distance, capped at its reference distance (sized to the pairs on first
    /// use; particles write only their own pairs).
    void recordSeparations(const std::vector<Vec3>& x, const std::vector<std::uint8_t>& bondIntact,
                           std::vector<double>& separation) const;

    /// Pairs in contact at the last addForces (a diagnostic; each pair counted once; in a split
    /// run, the pairs of this process's particles).
    long pairsInContact() const { return pairs_; }

    /// Bodies in contact with each other: the runs of equal Reference::body in particle order.
    std::size_t bodies() const { return ranges_.size(); }
    /// Per ordered pair of bodies (i, j) (bodies in particle order), the force that j's
    /// particles exert on i's at the last addForces [N], into out[i·B + j] (B = bodies();
    /// out[i·B + i] = 0). Exactly rounded sums over the particles of restrictTo and its domain's
    /// processes (collective): independent of the thread and process count, and out[i·B + j] =
    /// −out[j·B + i] to round-off (LS-DYNA's rcforc). Self-contact forces are internal to a body
    /// and not in it; empty unless contact between bodies is on.
    void bodyPairForces(std::vector<Vec3>& out) const;

  private:
    using Cell = std::array<std::int64_t, 3>;
    bool split() const { return domain_ != nullptr && domain_->processes() > 1; }
    void markDamaged(const std::vector<std::uint8_t>& bondIntact);
    const std::vector<Vec3>& markCandidates(const std::vector<Vec3>& x);
    const std::vector<Vec3>& build(const std::vector<Vec3>& x);
    Index pairOf(Index a, Index b) const;
    std::size_t bucketOf(const Cell& c) const;

    const Reference* ref_ = nullptr;
    ContactShapes shapes_;
    bool active_ = false;
    bool betweenBodies_ = false;  ///< pairs of different bodies
    bool selfContact_ = false;    ///< pairs of one body separated by broken bonds
    bool anyDamaged_ = false;     ///< some particle has lost a bond (at the last addForces)
    std::vector<double> stiffness_;
    double cellSize_ = 0.0;
    std::vector<std::pair<Index, Index>> ranges_;  ///< per body: its particle range
    std::vector<std::size_t> rangeOfBody_;         ///< per body id: its entry of ranges_
    std::vector<Vec3> boxLow_, boxHigh_;           ///< per body: bounding box grown by the reach
    std::vector<std::uint8_t> candidate_;          ///< per particle: within another body's box, or
                                           ///< (self-contact) its body's damaged particles' box
    std::vector<std::uint8_t> damaged_;           ///< per particle: lost a bond (self-contact only)
    std::vector<Vec3> damagedLow_, damagedHigh_;  ///< per body: damaged particles' box + reach
    std::vector<Cell> cell_;                      ///< per particle
    std::vector<std::uint32_t> bucket_;           ///< per particle: its hash bucket
    std::vector<Index> bucketStart_;              ///< CSR over buckets (size buckets + 1)
    std::vector<Index> sorted_;                   ///< particles, bucket by bucket, by index within
    std::vector<double> energy_;                  ///< per particle: half of each of its pairs' U
    std::vector<std::int32_t> pairCount_;         ///< per particle: its pairs in contact
    /// Per candidate particle a and body j: the force of j's particles on a (a·B + j) [N].
    std::vector<Vec3> forceByBody_;
    mutable std::vector<ExactSum> bodyPairScratch_;  ///< of bodyPairForces
    long pairs_ = 0;
    ParticleRange owned_;
    Domain* domain_ = nullptr;
    // Split runs: the candidates' positions (this process's and the others'), which of them
    // this process listed and which it received at the last search, the boxes' bounds.
    std::vector<Vec3> positions_;
    std::vector<Index> listed_, received_;
    std::vector<double> bounds_;
};

}  // namespace gsph
