// SPDX-License-Identifier: MIT
#include "forces/internal_force.hpp"

#include "core/parallel.hpp"
#include "forces/hourglass.hpp"

namespace gsph {
namespace {

// The pair sums are split so that per pair only the neighbour's factor is applied:
//   Σ_b (K_c + K_b) w_cb = K_c Σ_b w_cb + Σ_b K_b w_cb,   w_cb = ω ∇W_cb (table),
// and the same for the viscous N terms weighted by q_cb.
template <bool Viscous, bool Hourglass>
void forceLoop(const Reference& ref, const State& state, const StressFactors& sf,
               const ForceOptions& opt, Index begin, Index end, std::vector<Vec3>& force,
               ForceParts& parts) {
    const PairList& P = ref.pairs;
    const Index* nb = P.neighbor.data();
    const Index* id = P.kernelId.data();
    const KernelEntry* table = P.table.data();
    const Vec3* x = state.x.data();
    const Vec3* v = state.v.data();
    const Vec3* X = ref.X.data();
    const Mat3* K = sf.K.data();
    const Mat3* N = sf.N.data();
    const Mat3* F = state.F.data();
    const double alphaE = opt.hourglass * opt.youngsModulus;
    parallelFor(end - begin, [&](Index i) {
        const Index c = begin + i;
        const auto ic = static_cast<std::size_t>(c);
        Vec3 sumW = Vec3::Zero();   // Σ w_cb
        Vec3 fK = Vec3::Zero();     // Σ K_b w_cb
        Vec3 sumQW = Vec3::Zero();  // Σ q_cb w_cb
        Vec3 fN = Vec3::Zero();     // Σ q_cb N_b w_cb
        Vec3 fh = Vec3::Zero();
        const Vec3 xc = x[ic];
        const Vec3 vc = v[ic];
        const Vec3 Xc = X[ic];
        const double cc = sf.soundSpeed[ic];
        const double rhoc = sf.density[ic];
        const double Vc = ref.quadVolume[ic];
        const double hc = ref.smoothingLength[ic];
        const Mat3 Fc = F[ic];
        for (Index k = P.begin(c); k < P.end(c); ++k) {
            const auto b = static_cast<std::size_t>(nb[k]);
            const KernelEntry& e = table[id[k]];
            // DESIGN §4: f_c = Σ_b (ω_b K_c + ω_c K_b) ∇W_cb
            sumW += e.gradW;
            fK.noalias() += K[b] * e.gradW;
            if constexpr (Viscous) {
                const Vec3 xcb = xc - x[b];
                const Vec3 vcb = vc - v[b];
                if (vcb.dot(xcb) < 0.0) {
                    const double hcb = 0.5 * (hc + ref.smoothingLength[b]);
                    const double q = viscousPairPressure(opt.viscosity, xcb, vcb, hcb,
                                                         0.5 * (cc + sf.soundSpeed[b]),
                                                         0.5 * (rhoc + sf.density[b]));
                    sumQW += q * e.gradW;
                    fN.noalias() += q * (N[b] * e.gradW);
                }
            }
            if constexpr (Hourglass) {
                const double weight = 0.5 * (Vc + ref.quadVolume[b]) * e.W;
                fh += hourglassPairForce(alphaE, Fc, F[b], X[b] - Xc, x[b] - xc, weight);
            }
        }
        Vec3 f = K[ic] * sumW + fK;
        if constexpr (Viscous) {
            const Vec3 fv = -(N[ic] * sumQW + fN);
            parts.viscous[ic] = fv;
            f += fv;
        }
        if constexpr (Hourglass) {
            parts.hourglass[ic] = fh;
            f += fh;
        }
        force[ic] = f;
    });
}

}  // namespace

void internalForce(const Reference& ref, const State& state, const StressFactors& factors,
                   const ForceOptions& options, Index begin, Index end, std::vector<Vec3>& force,
                   ForceParts& parts) {
    const bool viscous = options.viscosity.enabled();
    const bool hourglass = options.hourglass != 0.0;
    const auto n = static_cast<std::size_t>(ref.size());
    if (viscous) parts.viscous.resize(n, Vec3::Zero());
    if (hourglass) parts.hourglass.resize(n, Vec3::Zero());
    if (viscous && hourglass)
        forceLoop<true, true>(ref, state, factors, options, begin, end, force, parts);
    else if (viscous)
        forceLoop<true, false>(ref, state, factors, options, begin, end, force, parts);
    else if (hourglass)
        forceLoop<false, true>(ref, state, factors, options, begin, end, force, parts);
    else
        forceLoop<false, false>(ref, state, factors, options, begin, end, force, parts);
}

}  // namespace gsph
