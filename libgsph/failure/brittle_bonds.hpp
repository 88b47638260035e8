// SPDX-License-Identifier: MIT
// Brittle bond failure (DESIGN §5, the paper's Rankine criterion): the bond of a pair (a, b)
// breaks for good when its stretch (|x_b − x_a| − |X_b − X_a|) / |X_b − X_a| ≥ εmax, εmax an
// input per body (0: the body's bonds never break). A broken bond leaves every pair sum of
// the step (F, Ḟ, the force, viscosity, hourglass control), and the particle's metric
// (B, M, G of spaces/metric.hpp) is recomputed over the surviving bonds, so F = I stays
// exact at rest and an affine motion still gives its F (DESIGN §3).
//
// The integrity lives in State::bondIntact (per CSR pair, checkpointed); this class keeps
// what derives from it: G per particle, which particles lost a bond (they leave the stencil
// fast path for the masked CSR path), and which are detached (their surviving bonds no
// longer span the space: |det B| fell below kDetachedCorrection of its intact value, or M
// inverts). A detached particle carries no stress and keeps its last F; its surviving bonds
// still move it with its neighbours.
//
// Both directions of a pair evaluate the same stretch from the same positions, so a and b
// always agree without writing each other's entries: the check runs in parallel and gives the
// same result for any thread count.
#pragma once

#include <cstdint>
#include <vector>

#include "particles/reference.hpp"
#include "particles/state.hpp"

namespace gsph {

/// What the pair loops need of the bonds: null pointers when no body can break.
struct BondView {
    const std::uint8_t* intact = nullptr;   ///< per CSR pair: 1 holds, 0 broken
    const std::uint8_t* damaged = nullptr;  ///< per particle: 1 if any of its bonds broke
    /// True when every particle of [begin, end) keeps all its bonds (stencil path allowed).
    bool allIntact(Index begin, Index end) const {
        if (damaged == nullptr) return true;
        for (Index a = begin; a < end; ++a)
            if (damaged[a] != 0) return false;
        return true;
    }
    bool holds(Index pair) const { return intact == nullptr || intact[pair] != 0; }
};

class BrittleBonds {
  public:
    /// |det B| of a particle's surviving bonds below this fraction of its intact value: detached.
    static constexpr double kDetachedCorrection = 1e-3;

    /// `stretchByParticle`: εmax of each particle's body (0 = unbreakable), from the body ranges.
    /// Throws InputError on a negative or non-finite εmax.
    BrittleBonds(const Reference& ref, std::vector<double> stretchByParticle);

    bool enabled() const { return enabled_; }

    /// Derives G, damaged and detached from state.bondIntact (at the start and after a restart).
    void attach(const State& state);

    /// Breaks every bond stretched to εmax at the current positions state.x, updates what
    /// derives from it; returns the number of pairs (a < b) broken by this call.
    Index breakStretchedBonds(State& state);

    /// G per particle: the reference's until a bond of the particle breaks.
    const std::vector<Mat3>& G() const { return enabled_ ? G_ : ref_.G; }
    bool detached(Index a) const { return enabled_ && detached_[static_cast<std::size_t>(a)] != 0; }
    BondView view(const State& state) const;
    /// Pairs (a < b) broken so far.
    Index brokenPairs() const { return brokenPairs_; }

  private:
    void refreshParticle(const State& state, Index a);

    const Reference& ref_;
    std::vector<double> stretch_;  ///< εmax per particle
    bool enabled_ = false;
    std::vector<Mat3> G_;
    std::vector<std::uint8_t> damaged_, detached_;
    std::vector<Index> changed_;      ///< per particle: bonds broken by the current call
    std::vector<double> intactDetB_;  ///< |det B| with every bond, per particle
    Index brokenPairs_ = 0;
};

}  // namespace gsph
