// SPDX-License-Identifier: MIT
#include "reference/reference_builder.hpp"

#include <cmath>
#include <string>

#include "core/error.hpp"
#include "spaces/metric.hpp"

namespace gsph {

Reference buildReference(const ParticleFile& f, std::span<const double> densityPerBody,
                         double kappa) {
    if (!(kappa > 0.0) || !std::isfinite(kappa)) {
        throw InputError("kappa must be positive (got " + std::to_string(kappa) + ")");
    }
    if (densityPerBody.size() < f.bodies.size()) {
        throw InputError("a density is needed for each of the " + std::to_string(f.bodies.size()) +
                         " bodies (got " + std::to_string(densityPerBody.size()) + ")");
    }
    for (std::size_t b = 0; b < f.bodies.size(); ++b) {
        if (!(densityPerBody[b] > 0.0) || !std::isfinite(densityPerBody[b])) {
            throw InputError("density of body " + std::to_string(b) + " must be positive");
        }
    }
    Reference ref;
    ref.dim = Dimension{f.dimension};
    ref.kappa = kappa;
    ref.spaces = f.spaces;
    ref.X = f.X;
    ref.theta = f.theta;
    ref.volume = f.volume;
    ref.body = f.body;
    ref.space = f.space;
    ref.overset.resize(f.overset.size());
    for (std::size_t e = 0; e < f.overset.size(); ++e)
        ref.overset[e] = {f.overset.particle[e], f.overset.space[e], f.overset.theta[e],
                          f.overset.omega[e]};
    ref.oversetKappa = f.overset.kappa;
    if (!ref.overset.empty() && kappa > ref.oversetKappa)
        throw InputError("kernel factor κ = " + std::to_string(kappa) +
                         " exceeds the κ = " + std::to_string(ref.oversetKappa) +
                         " the particle file's overset entries were made for (re-run gsph-preproc "
                         "with --overset-kappa ≥ κ)");
    ref.density.resize(f.volume.size());
    for (std::size_t a = 0; a < f.volume.size(); ++a) {
        ref.density[a] = densityPerBody[static_cast<std::size_t>(f.body[a])];
    }
    return ref;
}

void completeReference(Reference& ref, SearchMethod search,
                       const InterfaceSolveProgress& progress) {
    if (ref.pairs.particles() != ref.size()) buildPairs(ref, search);
    if (ref.G.size() != ref.X.size()) computeGeometry(ref, progress);
}

}  // namespace gsph
