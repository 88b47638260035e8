// SPDX-License-Identifier: MIT
#include "boundary/pressure.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "kinematics/deformation_gradient.hpp"

namespace gsph {

double PressureLoad::at(double t) const {
    if (t <= curve.front().first) return curve.front().second;
    for (std::size_t k = 1; k < curve.size(); ++k)
        if (t < curve[k].first) {
            const auto& [t0, p0] = curve[k - 1];
            const auto& [t1, p1] = curve[k];
            return p0 + (p1 - p0) * ((t - t0) / (t1 - t0));
        }
    return curve.back().second;
}

PressureStage::PressureStage(const Reference& ref, PressureLoad load) : load_(std::move(load)) {
    const std::string set = "pressure set '" + load_.name + "'";
    if (load_.particles.empty()) throw InputError(set + " has no particles");
    if (load_.area.size() != load_.particles.size())
        throw InputError(set + ": " + std::to_string(load_.area.size()) + " face areas for " +
                         std::to_string(load_.particles.size()) + " particles");
    for (std::size_t k = 0; k < load_.particles.size(); ++k) {
        const Index a = load_.particles[k];
        if (a < 0 || a >= ref.size() || (k > 0 && a <= load_.particles[k - 1]))
            throw InputError(set + ": particle indices out of range or not sorted");
        if (!load_.area[k].allFinite()) throw InputError(set + ": a face area is not finite");
    }
    if (load_.curve.empty()) throw InputError(set + " has no pressure");
    for (std::size_t k = 0; k < load_.curve.size(); ++k) {
        const auto& [t, p] = load_.curve[k];
        if (!std::isfinite(t) || !std::isfinite(p))
            throw InputError(set + ": a time or pressure is not finite");
        if (k > 0 && !(t > load_.curve[k - 1].first))
            throw InputError(set + ": the times of the pressure curve must increase");
    }
}

StageReport PressureStage::addForces(const State& state, ForceChannels& out) {
    const double p = load_.at(state.time);
    parallelFor(static_cast<std::ptrdiff_t>(load_.particles.size()), [&](std::ptrdiff_t k) {
        const auto ik = static_cast<std::size_t>(k);
        const auto ia = static_cast<std::size_t>(load_.particles[ik]);
        const Vec3 f = -p * (cofactor(state.F[ia]) * load_.area[ik]);
        out.force[ia] += f;
        out.external[ia] += f;
    });
    return {};
}

}  // namespace gsph
