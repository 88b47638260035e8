// SPDX-License-Identifier: MIT
#include "boundary/loads.hpp"

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace gsph {

std::vector<Vec3> loadPerParticle(const Reference& ref, const Loads& loads) {
    std::vector<Vec3> f(static_cast<std::size_t>(ref.size()));
    for (std::size_t a = 0; a < f.size(); ++a) f[a] = ref.mass[a] * loads.gravity;
    for (const SetForce& s : loads.setForces) {
        if (s.particles.empty()) throw InputError("force set '" + s.name + "' has no particles");
        double mass = 0.0;
        for (Index a : s.particles) {
            if (a < 0 || a >= ref.size())
                throw InputError("force set '" + s.name + "' names particle " + std::to_string(a) +
                                 " outside [0, " + std::to_string(ref.size()) + ")");
            mass += ref.mass[static_cast<std::size_t>(a)];
        }
        for (Index a : s.particles)
            f[static_cast<std::size_t>(a)] +=
                (ref.mass[static_cast<std::size_t>(a)] / mass) * s.total;
    }
    return f;
}

StageReport ConstantLoadStage::addForces(const State& /*state*/, ForceChannels& out) {
    parallelFor(static_cast<std::ptrdiff_t>(load_.size()), [&](std::ptrdiff_t a) {
        const auto ia = static_cast<std::size_t>(a);
        out.force[ia] += load_[ia];
        out.external[ia] += load_[ia];
    });
    return {};
}

}  // namespace gsph
