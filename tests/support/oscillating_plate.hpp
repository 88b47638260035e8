// SPDX-License-Identifier: MIT
// The oscillating cantilever plate of Gray, Monaghan & Swift (2001), 2-D plane strain, as set
// up in shared/references.md: free length L = 0.2 m, thickness H = 0.02 m, clamped over an
// extra length at x < 0, ρ = 1000 kg/m³, E = 2 MPa, ν = 0.3975, initial vertical velocity
//   v(x) = Vf c0 [M (cos kx − cosh kx) − N (sin kx − sinh kx)] / Q,  kL = 1.875,
// c0 = √(K/ρ). Analytic period from ω² = E H² k⁴ / (12 ρ (1 − ν²)).
#pragma once

#include <cmath>
#include <cstdio>
#include <vector>

#include "simulation.hpp"
#include "spaces/analytic_maps.hpp"

namespace gsph::testing {

struct PlateRun {
    int cellsAlong = 100;         ///< particles along the free length L
    int cellsThrough = 10;        ///< particles through the thickness H
    double thicknessGrading = 1;  ///< symmetric grading ratio through H (1 = uniform)
    double vf = 0.01;             ///< tip velocity / c0
    double kappa = 1.2;
    double hourglass = 0.0;
    double cfl = 0.3;
    double periods = 1.6;  ///< simulated time in analytic periods
};

struct PlateResult {
    int particles = 0;
    double period = 0.0;                ///< measured from the tip's zero crossings [s]
    double analyticPeriod = 0.0;        ///< [s]
    double amplitude = 0.0;             ///< largest tip deflection [m]
    double energyDriftPerPeriod = 0.0;  ///< max |E(t) − E(0)| / E(0), per analytic period
    long steps = 0;
};

inline PlateResult runOscillatingPlate(const PlateRun& run) {
    const double L = 0.2, H = 0.02, rho = 1000.0, E = 2.0e6, nu = 0.3975;
    const ElasticConstants elastic(rho, E, nu);
    const double kL = 1.875;
    const double k = kL / L;
    const double omega = std::sqrt(E * H * H * std::pow(k, 4) / (12.0 * rho * (1.0 - nu * nu)));
    const double dx = L / run.cellsAlong;
    const int clampCells = static_cast<int>(std::ceil(2.0 * run.kappa)) + 1;
    const double clamp = clampCells * dx;
    const AnalyticMap map =
        gradedBoxMap(Vec3(L + clamp, H, 0.0),
                     {AxisGrading{},
                      AxisGrading{run.thicknessGrading > 1 ? AxisGrading::Kind::Symmetric
                                                           : AxisGrading::Kind::Uniform,
                                  run.thicknessGrading},
                      AxisGrading{}},
                     Vec3(-clamp, -H / 2, 0.0));
    Reference ref = latticeReference(map, 2, {run.cellsAlong + clampCells, run.cellsThrough, 1},
                                     rho, run.kappa);
    SolverOptions options;
    options.cfl = run.cfl;
    options.hourglass = run.hourglass;
    VelocityConstraint clampSet{"clamp", {}, {}};
    std::vector<Index> tip;  // the last column of particles
    for (Index a = 0; a < ref.size(); ++a) {
        if (ref.X[static_cast<std::size_t>(a)][0] < 0.0) clampSet.particles.push_back(a);
        if (ref.theta[static_cast<std::size_t>(a)][0] > run.cellsAlong + clampCells - 1)
            tip.push_back(a);
    }
    Simulation sim(std::move(ref), {HypoElastic(elastic)}, options);
    sim.constrain(clampSet);
    const double c0 = std::sqrt(elastic.bulkModulus() / rho);
    const double M = std::sin(kL) + std::sinh(kL), N = std::cos(kL) + std::cosh(kL);
    const double Q = 2.0 * (std::cos(kL) * std::sinh(kL) - std::sin(kL) * std::cosh(kL));
    sim.setVelocity([&](const Vec3& X) -> Vec3 {
        if (X[0] < 0.0) return Vec3::Zero();
        const double kx = k * X[0];
        const double shape =
            (M * (std::cos(kx) - std::cosh(kx)) - N * (std::sin(kx) - std::sinh(kx))) / Q;
        return Vec3(0.0, run.vf * c0 * shape, 0.0);
    });

    PlateResult r;
    r.particles = sim.reference().size();
    r.analyticPeriod = 2.0 * std::acos(-1.0) / omega;
    sim.start();
    const double e0 = sim.energy().total();
    auto tipDeflection = [&] {
        double y = 0.0;
        for (Index a : tip)
            y += sim.state().x[static_cast<std::size_t>(a)][1] -
                 sim.reference().X[static_cast<std::size_t>(a)][1];
        return y / tip.size();
    };
    std::vector<double> downCrossings;
    double previous = 0.0, drift = 0.0;
    int sample = 0;
    sim.advanceTo(run.periods * r.analyticPeriod, [&](const State& s) {
        const double y = tipDeflection();
        r.amplitude = std::max(r.amplitude, std::abs(y));
        if (previous > 0.0 && y <= 0.0)  // linear interpolation of the crossing time
            downCrossings.push_back(s.time - s.dt * y / (y - previous));
        previous = y;
        if (++sample % 50 == 0) drift = std::max(drift, std::abs(sim.energy().total() - e0) / e0);
    });
    drift = std::max(drift, std::abs(sim.energy().total() - e0) / e0);
    r.steps = sim.state().step;
    if (downCrossings.size() >= 2) r.period = downCrossings[1] - downCrossings[0];
    r.energyDriftPerPeriod = drift / run.periods;
    return r;
}

}  // namespace gsph::testing
