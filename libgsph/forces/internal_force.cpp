// SPDX-License-Identifier: MIT
#include "forces/internal_force.hpp"

#include "core/parallel.hpp"
#include "forces/hourglass.hpp"

namespace gsph {
namespace {

template <bool Viscous, bool Hourglass>
void forceLoop(const Reference& ref, const State& state, const StressFactors& sf,
               const ForceOptions& opt, Index begin, Index end, std::vector<Vec3>& force,
               ForceParts& parts) {
    const PairList& P = ref.pairs;
    const double alphaE = opt.hourglass * opt.youngsModulus;
    parallelFor(end - begin, [&](Index i) {
        const Index c = begin + i;
        const auto ic = static_cast<std::size_t>(c);
        const Mat3& Kc = sf.K[ic];
        const double wc = ref.omega[ic];
        Vec3 f = Vec3::Zero();
        Vec3 fv = Vec3::Zero();
        Vec3 fh = Vec3::Zero();
        for (Index k = P.begin(c); k < P.end(c); ++k) {
            const auto b = static_cast<std::size_t>(P.neighbor[static_cast<std::size_t>(k)]);
            const KernelEntry& e =
                P.table[static_cast<std::size_t>(P.kernelId[static_cast<std::size_t>(k)])];
            const double wb = ref.omega[b];
            // DESIGN §4: f_c = Σ_b (ω_b K_c + ω_c K_b) ∇W_cb
            f.noalias() += (wb * Kc + wc * sf.K[b]) * e.gradW;
            if constexpr (Viscous) {
                const Vec3 xcb = state.x[ic] - state.x[b];
                const Vec3 vcb = state.v[ic] - state.v[b];
                if (vcb.dot(xcb) < 0.0) {
                    const double hcb = e.hOverR * (ref.X[ic] - ref.X[b]).norm();
                    const double q = viscousPairPressure(
                        opt.viscosity, xcb, vcb, hcb, 0.5 * (sf.soundSpeed[ic] + sf.soundSpeed[b]),
                        0.5 * (sf.density[ic] + sf.density[b]));
                    fv.noalias() -= q * ((wb * sf.N[ic] + wc * sf.N[b]) * e.gradW);
                }
            }
            if constexpr (Hourglass) {
                Vec3 dir;
                const double weight =
                    0.5 * (ref.quadVolume[ic] * wb + ref.quadVolume[b] * wc) * e.W;
                const double s =
                    hourglassPairForce(alphaE, state.F[ic], state.F[b], ref.X[b] - ref.X[ic],
                                       state.x[b] - state.x[ic], weight, dir);
                fh.noalias() -= s * dir;
            }
        }
        if constexpr (Viscous) parts.viscous[ic] = fv;
        if constexpr (Hourglass) parts.hourglass[ic] = fh;
        force[ic] = f + fv + fh;
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
