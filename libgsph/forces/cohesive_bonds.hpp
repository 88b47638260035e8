// SPDX-License-Identifier: MIT
// Softening bonds: a cohesive law for brittle fracture, calibrated from the fracture energy G0
// (docs/theory.md "Softening bonds").
//
// In a body with a fracture energy, a bond that breaks by its stretch (the sharp criterion of
// failure/brittle_bonds.hpp, whose εmax = s0 becomes the onset) leaves the pair sums as every
// broken bond does, and its pair then carries a central force that softens linearly with the
// pair's opening until it has taken the bond's share of G0:
//   f_a = T n_ab,  n_ab = (x_b − x_a)/|x_b − x_a|,  f_b = −f_a,
//   T = f_env(m) · s/m for 0 < s ≤ m, 0 for s ≤ 0 (a closing crack is left to contact),
//   f_env(m) = f0 · max(0, 1 − (m − s0)/Δs),
// with s = |x_ab|/|X_ab| − 1 the stretch, m the largest stretch since the break (unloading and
// reloading run along the secant to the origin, so damage is irreversible), f0 = t β_ab V_a V_b
// and Δs = 2 ψ_ab/(t β_ab): t is the normal stress n·σ̄·n across the bond when it broke
// (State::cohesiveTraction), so the bonds across a crack take over the traction the material
// carried, and ½ f0 Δs |X_ab| = w_ab = ψ_ab V_a V_b |X_ab| is the energy the bond takes to
// separate, whatever t. The per-particle constants, from the reference pairs of a (ξ = X_b − X_a,
// V the quadrature volumes; pair constants the means of the two ends'):
//   β_a = 1 / (½ ⟨(n·ξ̂)²⟩ Σ_b V_b |ξ|)     bonds carrying f = t β V_a V_b transmit the traction t
//                                          across a plane, averaged over its orientations n;
//   ψ_a = G0 / (½ ⟨|n·ξ̂|⟩ Σ_b V_b |ξ|²)    the bonds a plane crack cuts hold G0 per unit area,
//                                          averaged over the plane's orientations and positions;
// ⟨(n·ξ̂)²⟩ = 1/3, ⟨|n·ξ̂|⟩ = 1/2 in 3-D (1/2 and 2/π in plane strain). The average over
// orientations is what a crack of unknown direction sees; on a cubic lattice an axis-aligned
// plane gets G0 within 1 % (tests/verification/cohesive_bonds.cpp).
//
// Energy: the force's power −Σ f·v is booked as the ledger's cohesive work (ForceParts::cohesive,
// integrator/power_ledger.hpp); once a bond has separated (m ≥ s0 + Δs) it has taken w_ab (less
// the sliver (m_break − s0)/Δs of an overshooting break) and carries nothing more. Its stiffness
// f_env(m)/(m |X_ab|) adds to the particle's ω² for the time step. Each side of a pair evaluates
// the same bits (the stretch from the same squared lengths, the pair constants as sums of the
// two ends'), so the forces are equal and opposite and independent of the thread count; the
// largest stretch is written to State::cohesiveStretch by record(), so a restart continues it.
#pragma once

#include <vector>

#include "failure/brittle_bonds.hpp"
#include "forces/force_stage.hpp"
#include "particles/reference.hpp"

namespace gsph {

class CohesiveBondStage final : public ForceStage {
  public:
    /// Per particle: the onset stretch s0 (its body's εmax) and the fracture energy G0 [J/m²]
    /// (0: its bonds do not soften). Throws InputError on an axisymmetric reference, on G0 < 0
    /// or not finite, on G0 > 0 with s0 ≤ 0, or on a size mismatch.
    /// `bonds`: the run's bonds (only a particle that lost a bond can have a softening one).
    CohesiveBondStage(const Reference& ref, const BrittleBonds& bonds,
                      std::vector<double> onsetStretch, std::vector<double> fractureEnergy);

    std::string name() const override { return "cohesive bonds"; }
    StageNeeds needs() const override {
        StageNeeds n;
        n.cohesive = true;
        n.frequency2 = true;
        return n;
    }
    StageReport addForces(const State& state, ForceChannels& out) override;
    void record(State& state) const override;

    /// The law of the bond at CSR entry k of particle a, broken under the normal stress t.
    struct BondLaw {
        double peak;   ///< f0 = t β_ab V_a V_b [N]
        double width;  ///< Δs = 2 ψ_ab / (t β_ab): the stretch over which it softens to 0
    };
    BondLaw law(Index a, Index k, double traction) const;
    /// w_ab: the energy the bond at CSR entry k of particle a takes to separate [J].
    double separationEnergy(Index a, Index k) const;

  private:
    const Reference& ref_;
    const BrittleBonds& bonds_;
    std::vector<double> onset_, fractureEnergy_;
    std::vector<double> traction_, energy_;  ///< β_a and ψ_a per particle (see above)
    std::vector<double> largestStretch_;     ///< per pair: m after the last evaluation
    ParticleRange owned_;                    ///< the particles the last evaluation covered
};

}  // namespace gsph
