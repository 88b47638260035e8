// SPDX-License-Identifier: MIT
// A ductile steel bar pulled apart, shared by the energy and the bond-failure tests: Weldox 460E
// strength with damage constants scaled down so that it fails within a short pull (εf ≈ 0.15 at
// σ* = 1/3); 10 × 2 × 2 mm, 25 × 5 × 5 particles (κ = 1.2), viscosity [1, 1], hourglass 0.1; its
// end layers held at ∓20 m/s and the bar given the matching linear velocity profile. The caller
// starts and advances `sim`.
#pragma once

#include <vector>

#include "simulation.hpp"
#include "spaces/analytic_maps.hpp"
#include "support/johnson_cook_materials.hpp"

namespace gsph::testing {

struct PulledWeldoxBar {
    static constexpr double kLength = 0.01, kWidth = 0.002, kSpeed = 20.0;
    static constexpr double kSpacing = kLength / 25;

    Simulation sim;
    std::vector<Index> left, right;  ///< the end layers, held at −kSpeed and +kSpeed along x

    /// `failedBonds`: SolverOptions::failedBonds (empty: failed particles keep their bonds);
    /// `damageLength`: ℓ of a nonlocal damage (0: local).
    explicit PulledWeldoxBar(std::vector<FailedBondRule> failedBonds = {},
                             double damageLength = 0.0)
        : sim(latticeReference(gradedBoxMap(Vec3(kLength, kWidth, kWidth), {}), 3, {25, 5, 5},
                               7850.0, 1.2),
              {withLinearEos(kWeldoxElastic, weldoxParams(), damage(damageLength))},
              options(std::move(failedBonds))) {
        const Reference& ref = sim.reference();
        for (Index a = 0; a < ref.size(); ++a) {
            const double X = ref.X[static_cast<std::size_t>(a)][0];
            if (X < kSpacing) left.push_back(a);
            if (X > kLength - kSpacing) right.push_back(a);
        }
        sim.constrain({"left", left, [](double, const Vec3&) { return Vec3(-kSpeed, 0, 0); }});
        sim.constrain({"right", right, [](double, const Vec3&) { return Vec3(kSpeed, 0, 0); }});
        sim.setVelocity(
            [](const Vec3& X) { return Vec3(kSpeed * (2 * X[0] / kLength - 1), 0, 0); });
    }

  private:
    static JohnsonCookDamage damage(double length) {
        JohnsonCookDamage d{{0.01, 0.17, -0.54, -0.015, 0.0}};
        d.length = length;
        return d;
    }
    static SolverOptions options(std::vector<FailedBondRule> failedBonds) {
        SolverOptions o;
        o.viscosity = {1.0, 1.0};
        o.hourglass = 0.1;
        o.failedBonds = std::move(failedBonds);
        return o;
    }
};

}  // namespace gsph::testing
