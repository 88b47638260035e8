// SPDX-License-Identifier: MIT
#include "forces/hoop_stress_stage.hpp"

#include <Eigen/LU>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace gsph {

HoopStressStage::HoopStressStage(const Reference& ref) : ref_(ref) {
    if (!ref.dim.axisymmetric) throw InputError("the hoop stress acts in axisymmetric runs only");
}

StageReport HoopStressStage::addForces(const State& state, ForceChannels& out) {
    parallelFor(ref_.size(), [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        const Mat3& F = state.F[ia];
        // P_zz = J σ_zz / F_zz: the hoop direction decouples from the (r, z) plane.
        const double Pzz = F.determinant() * state.cauchy[ia](2, 2) / F(2, 2);
        out.force[ia][0] -= ref_.quadVolume[ia] * Pzz / ref_.X[ia][0];
    });
    return {};
}

}  // namespace gsph
