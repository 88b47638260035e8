// SPDX-License-Identifier: MIT
// The nonlocal average of a body's damage driver (docs/theory.md "Nonlocal damage"): local
// Johnson–Cook damage localises into one row of particles, so a shear band's energy scales with
// its cells' width and perforation results do not converge. The nonlocal form (Pijaudier-Cabot
// & Bažant 1987; Bažant & Jirásek 2002) lets each particle accumulate its local driver
// ω_a = Σ Δε̄p/εf (materials/johnson_cook_damage.hpp) and takes the damage from the average
//   ω̄_a = Σ_b w_ab ω_b,   w_ab = V_b φ(r_ab) / Σ_c V_c φ(r_ac),   φ(r) = (1 − r²/ℓ²)² for r < ℓ,
// r_ab = |X_b − X_a| in the reference configuration, over the particles of the same body: in
// the total Lagrangian form the neighbourhoods and weights are fixed, built once here. ℓ is a
// material length; the band then spans about 2ℓ at any resolution finer than ℓ.
#pragma once

#include <span>
#include <vector>

#include "core/types.hpp"

namespace gsph {

class NonlocalAverage {
  public:
    NonlocalAverage() = default;
    /// The weights over particles [begin, end) (one body) of reference positions X and
    /// volumes V, radius ℓ = `length` > 0. Every particle has itself as a neighbour.
    NonlocalAverage(const std::vector<Vec3>& X, const std::vector<double>& V, Index begin,
                    Index end, double length);

    /// ω̄_a = Σ_b w_ab ω_b for a in [begin, end), in a fixed order (thread-independent).
    double average(const std::vector<double>& omega, Index a) const {
        const auto i = static_cast<std::size_t>(a - begin_);
        double sum = 0.0;
        for (std::size_t k = offset_[i]; k < offset_[i + 1]; ++k)
            sum += weight_[k] * omega[static_cast<std::size_t>(neighbor_[k])];
        return sum;
    }

    Index begin() const { return begin_; }
    Index end() const { return end_; }
    /// Neighbours (itself included) of particle a, ascending, and their weights (summing to 1).
    std::span<const Index> neighbors(Index a) const {
        const auto i = static_cast<std::size_t>(a - begin_);
        return {neighbor_.data() + offset_[i], offset_[i + 1] - offset_[i]};
    }
    double weight(Index a, Index b) const;

  private:
    Index begin_ = 0, end_ = 0;
    std::vector<std::size_t> offset_;
    std::vector<Index> neighbor_;
    std::vector<double> weight_;
};

}  // namespace gsph
