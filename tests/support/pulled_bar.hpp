// SPDX-License-Identifier: MIT
// A free steel bar (ν = 0.3; 40 × 4 × 4 cells of 1 mm, κ = 1.2) whose end layers are driven
// outwards at ±v0: it is stretched until bonds break and it comes apart, while the prescribed
// velocities do work on it (the bonds' energy balance tests).
#pragma once

#include <memory>
#include <vector>

#include "simulation.hpp"
#include "spaces/analytic_maps.hpp"

namespace gsph::testing {

inline constexpr double kPulledBarLength = 0.04;  // [m]

inline std::unique_ptr<Simulation> pulledBar(const SolverOptions& options, double v0) {
    const ElasticConstants steel(7800.0, 200e9, 0.3);
    const int cells = 40;
    const double length = kPulledBarLength;
    auto sim =
        std::make_unique<Simulation>(latticeReference(gradedBoxMap(Vec3(length, 0.004, 0.004), {}),
                                                      3, {cells, 4, 4}, steel.density, 1.2),
                                     std::vector<Material>{HypoElastic(steel)}, options);
    const Reference& ref = sim->reference();
    std::vector<Index> left, right;
    for (Index a = 0; a < ref.size(); ++a) {
        const double X = ref.X[static_cast<std::size_t>(a)][0];
        if (X < length / cells) left.push_back(a);
        if (X > length - length / cells) right.push_back(a);
    }
    sim->constrain({"left", left, [v0](double, const Vec3&) { return Vec3(-v0, 0.0, 0.0); }});
    sim->constrain({"right", right, [v0](double, const Vec3&) { return Vec3(v0, 0.0, 0.0); }});
    return sim;
}

}  // namespace gsph::testing
