// SPDX-License-Identifier: MIT
#include "forces/cohesive_bonds.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace gsph {

CohesiveBondStage::CohesiveBondStage(const Reference& ref, const BrittleBonds& bonds,
                                     std::vector<double> onsetStretch,
                                     std::vector<double> fractureEnergy)
    : ref_(ref),
      bonds_(bonds),
      onset_(std::move(onsetStretch)),
      fractureEnergy_(std::move(fractureEnergy)) {
    const auto n = static_cast<std::size_t>(ref.size());
    if (onset_.size() != n || fractureEnergy_.size() != n)
        throw InputError("softening bonds: " + std::to_string(fractureEnergy_.size()) +
                         " fracture energies and " + std::to_string(onset_.size()) +
                         " onset stretches for " + std::to_string(n) + " particles");
    if (ref.dim.axisymmetric)
        throw InputError("fracture_energy (softening bonds) is not available in axisymmetric runs");
    for (std::size_t a = 0; a < n; ++a) {
        const double g = fractureEnergy_[a];
        if (!(g >= 0.0) || !std::isfinite(g))
            throw InputError("fracture energy G0 must be finite and ≥ 0, got " + std::to_string(g));
        if (g > 0.0 && !(onset_[a] > 0.0))
            throw InputError("a fracture energy needs a bond stretch εmax > 0 (its bonds' onset)");
    }
    // ⟨(n·ξ̂)²⟩ and ⟨|n·ξ̂|⟩ over the orientations of a plane: 1/3, 1/2 in 3-D; 1/2, 2/π in 2-D.
    const bool planar = ref.dim.value == 2;
    const double meanSquare = planar ? 0.5 : 1.0 / 3.0;
    const double meanAbs = planar ? 2.0 / std::numbers::pi : 0.5;
    traction_.assign(n, 0.0);
    energy_.assign(n, 0.0);
    for (Index a = 0; a < ref.size(); ++a) {  // once, at set-up
        const auto ia = static_cast<std::size_t>(a);
        if (fractureEnergy_[ia] == 0.0) continue;
        double first = 0.0, second = 0.0;  // Σ V_b |ξ|, Σ V_b |ξ|²
        for (Index k = ref.pairs.begin(a); k < ref.pairs.end(a); ++k) {
            const auto ib =
                static_cast<std::size_t>(ref.pairs.neighbor[static_cast<std::size_t>(k)]);
            const double length = (ref.X[ib] - ref.X[ia]).norm();
            first += ref.quadVolume[ib] * length;
            second += ref.quadVolume[ib] * length * length;
        }
        if (!(first > 0.0))
            throw InputError("softening bonds: particle " + std::to_string(a) +
                             " has no neighbours to carry a cohesive force");
        traction_[ia] = 1.0 / (0.5 * meanSquare * first);
        energy_[ia] = fractureEnergy_[ia] / (0.5 * meanAbs * second);
    }
    largestStretch_.assign(static_cast<std::size_t>(ref.pairs.pairs()), 0.0);
}

// The pair's constants are the means of the two ends' (the same bits from either side).
CohesiveBondStage::BondLaw CohesiveBondStage::law(Index a, Index k, double traction) const {
    const auto ia = static_cast<std::size_t>(a);
    const auto ib = static_cast<std::size_t>(ref_.pairs.neighbor[static_cast<std::size_t>(k)]);
    const double beta = 0.5 * (traction_[ia] + traction_[ib]);
    const double psi = 0.5 * (energy_[ia] + energy_[ib]);
    return {traction * beta * ref_.quadVolume[ia] * ref_.quadVolume[ib],
            2.0 * psi / (traction * beta)};
}

double CohesiveBondStage::separationEnergy(Index a, Index k) const {
    const auto ia = static_cast<std::size_t>(a);
    const auto ib = static_cast<std::size_t>(ref_.pairs.neighbor[static_cast<std::size_t>(k)]);
    return 0.5 * (energy_[ia] + energy_[ib]) * ref_.quadVolume[ia] * ref_.quadVolume[ib] *
           (ref_.X[ib] - ref_.X[ia]).norm();
}

StageReport CohesiveBondStage::addForces(const State& state, ForceChannels& out) {
    const auto pairs = static_cast<std::size_t>(ref_.pairs.pairs());
    if (state.cohesiveTraction.size() != pairs || state.cohesiveStretch.size() != pairs)
        throw Error("softening bonds: the state holds no cohesive arrays of the pairs' size");
    const BondView view = bonds_.view(state);
    owned_ = out.owned;
    parallelFor(owned_, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        Vec3 force = Vec3::Zero();
        double frequency2 = 0.0;
        if (fractureEnergy_[ia] > 0.0 && !view.keepsAll(a))
            for (Index k = ref_.pairs.begin(a); k < ref_.pairs.end(a); ++k) {
                const auto ik = static_cast<std::size_t>(k);
                const double t = state.cohesiveTraction[ik];
                if (t <= 0.0) continue;
                const auto ib = static_cast<std::size_t>(ref_.pairs.neighbor[ik]);
                const auto [peak, width] = law(a, k, t);
                const double s0 = onset_[ia];
                double largest = state.cohesiveStretch[ik];
                largestStretch_[ik] = largest;
                if (largest >= s0 + width) continue;  // separated: nothing more, ever
                const Vec3 d = state.x[ib] - state.x[ia];
                const double length2 = d.squaredNorm();
                const double reference2 = (ref_.X[ib] - ref_.X[ia]).squaredNorm();
                const double s = std::sqrt(length2 / reference2) - 1.0;
                largest = std::max(largest, s);
                largestStretch_[ik] = largest;
                const double envelope = peak * std::max(0.0, 1.0 - (largest - s0) / width);
                if (envelope == 0.0) continue;
                if (s > 0.0) force += (envelope * s / largest / std::sqrt(length2)) * d;
                frequency2 += envelope / (largest * std::sqrt(reference2));
            }
        out.force[ia] += force;
        out.parts.cohesive[ia] = force;
        out.frequency2[ia] += frequency2 / ref_.mass[ia];
    });
    return {};
}

void CohesiveBondStage::record(State& state) const {
    const BondView view = bonds_.view(state);
    parallelFor(owned_, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        if (fractureEnergy_[ia] == 0.0 || view.keepsAll(a)) return;
        for (Index k = ref_.pairs.begin(a); k < ref_.pairs.end(a); ++k) {
            const auto ik = static_cast<std::size_t>(k);
            if (state.cohesiveTraction[ik] > 0.0) state.cohesiveStretch[ik] = largestStretch_[ik];
        }
    });
}

}  // namespace gsph
