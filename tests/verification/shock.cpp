// SPDX-License-Identifier: MIT
// The artificial viscosity on its own problem: a piston driven at constant speed into an
// elastic–perfectly-plastic bar in uniaxial strain (2-D plane strain, every particle held
// laterally) makes two waves, an elastic precursor at the Hugoniot elastic limit and a plastic
// shock behind it. Their states and speeds follow from the Rankine–Hugoniot conditions in the
// reference frame, [σ] = ρ0 U [u] and [u] = U [ε] (ε = 1 − J), with σ_x = K(−ln J) + ⅔Y on the
// plastic branch (the linear equation of state and von Mises yield of the Johnson–Cook model
// with B = C = 0, isothermal). The test checks the shocked stress and the shock's position
// against them, and that the state behind the shock is steady (no growing oscillation), with
// the case's default viscosity (its compression switch on) and with the constant coefficients.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "simulation.hpp"
#include "spaces/analytic_maps.hpp"

namespace gsph {
namespace {

struct HugoniotStates {
    double sigmaElastic, uElastic, speedElastic;  // precursor: σ_x [Pa], u [m/s], U [m/s]
    double sigma, strain, speed;                  // behind the plastic shock: σ_x, ε, U
};

// The two-wave solution for piston speed up (compression positive).
HugoniotStates twoWaveSolution(const ElasticConstants& e, double yield, double up) {
    const double K = e.bulkModulus(), G = e.shearModulus(), rho = e.density;
    // Hypo-elastic uniaxial strain: s_x = (4/3) G e, p = K e with e = −ln J; yield at s_x = ⅔Y.
    const double e1 = yield / (2.0 * G);
    const double eps1 = 1.0 - std::exp(-e1);
    const double sigma1 = K * e1 + 2.0 / 3.0 * yield;
    const double U1 = std::sqrt(sigma1 / (rho * eps1)), u1 = U1 * eps1;
    const auto sigmaOf = [&](double eps) { return -K * std::log(1.0 - eps) + 2.0 / 3.0 * yield; };
    // (u2 − u1)² = (σ2 − σ1)(ε2 − ε1)/ρ0: the left side is fixed, the right grows with ε2.
    double lo = eps1, hi = 0.5;
    for (int it = 0; it < 200; ++it) {
        const double mid = 0.5 * (lo + hi);
        ((sigmaOf(mid) - sigma1) * (mid - eps1) / rho < (up - u1) * (up - u1) ? lo : hi) = mid;
    }
    const double eps2 = 0.5 * (lo + hi);
    return {sigma1, u1, U1, sigmaOf(eps2), eps2, (up - u1) / (eps2 - eps1)};
}

struct ShockRun {
    double plateau;      // mean σ_x over the middle of the shocked region [Pa]
    double spread;       // its standard deviation there, relative to the mean
    double front;        // reference position of the plastic front (σ_x at mid-jump) [m]
    double precursor;    // reference position of the precursor (σ_x at half the HEL) [m]
    double viscousWork;  // share of the piston's work the viscosity took
};

ShockRun pistonIntoBar(const ViscosityCoefficients& viscosity, double up, double time,
                       const ElasticConstants& e, double yield, int n) {
    const double length = 0.1, h = length / n;
    const std::array<int, 3> cells = {n, 4, 1};
    SolverOptions options;
    options.viscosity = viscosity;
    options.hourglass = 0.1;
    JohnsonCookParams p;
    p.yieldStress = yield;
    p.hardeningModulus = 0.0;
    p.meltingTemperature = 1000.0;
    p.specificHeat = 900.0;
    p.taylorQuinney = 0.0;
    Simulation sim(latticeReference(gradedBoxMap(Vec3(length, cells[1] * h, 0.0), {}), 2, cells,
                                    e.density, 1.2),
                   {JohnsonCook(e, p, EquationOfState::linear(e.density, e.bulkModulus()))},
                   options);
    const Reference& ref = sim.reference();
    VelocityConstraint piston{"piston", {}, [&](double, const Vec3&) { return Vec3(up, 0, 0); }};
    VelocityConstraint lateral{"lateral", {}, {}, {false, true, false}};
    for (Index a = 0; a < ref.size(); ++a) {
        if (ref.theta[static_cast<std::size_t>(a)][0] < 1.0) piston.particles.push_back(a);
        lateral.particles.push_back(a);
    }
    sim.constrain(lateral);
    sim.constrain(piston);
    sim.start();
    sim.advanceTo(time);
    const State& s = sim.state();
    // σ_x along the bar, averaged over each lattice column.
    std::vector<double> sigma(static_cast<std::size_t>(n), 0.0);
    for (Index a = 0; a < ref.size(); ++a) {
        const auto i = static_cast<std::size_t>(ref.theta[static_cast<std::size_t>(a)][0]);
        sigma[i] += -s.cauchy[static_cast<std::size_t>(a)](0, 0) / cells[1];
    }
    const HugoniotStates rh = twoWaveSolution(e, yield, up);
    const auto crossing = [&](double level) {  // the last column above `level`, interpolated
        for (std::size_t i = sigma.size() - 1; i > 0; --i)
            if (sigma[i - 1] >= level && sigma[i] < level)
                return h * (static_cast<double>(i) - 0.5 +
                            (sigma[i - 1] - level) / (sigma[i - 1] - sigma[i]));
        return 0.0;
    };
    ShockRun r{};
    // Both waves leave the piston's column, at X = h/2.
    r.front = crossing(0.5 * (rh.sigma + rh.sigmaElastic)) - 0.5 * h;
    r.precursor = crossing(0.5 * rh.sigmaElastic) - 0.5 * h;
    // The shocked region between the piston's boundary layer and the front's width.
    const auto first = static_cast<std::size_t>(0.25 * r.front / h);
    const auto last = static_cast<std::size_t>(0.75 * r.front / h);
    double sum = 0.0, sum2 = 0.0;
    for (std::size_t i = first; i < last; ++i) sum += sigma[i], sum2 += sigma[i] * sigma[i];
    const double count = static_cast<double>(last - first);
    r.plateau = sum / count;
    r.spread = std::sqrt(std::max(0.0, sum2 / count - r.plateau * r.plateau)) / r.plateau;
    r.viscousWork = s.ledger.viscousWork / std::max(1e-300, s.ledger.boundaryWork);
    return r;
}

TEST(ArtificialViscosity, ElasticPlasticShockMatchesRankineHugoniot) {
    const ElasticConstants aluminium(2700.0, 70e9, 0.33);
    const double yield = 300e6, up = 200.0;
    const HugoniotStates rh = twoWaveSolution(aluminium, yield, up);
    const double time = 0.7 * 0.1 / rh.speedElastic;
    std::printf(
        "[shock] Rankine–Hugoniot: HEL %.1f MPa at %.0f m/s; shock %.1f MPa (ε %.4f) at "
        "%.0f m/s\n",
        rh.sigmaElastic * 1e-6, rh.speedElastic, rh.sigma * 1e-6, rh.strain, rh.speed);
    const auto report = [&](const char* what, const ViscosityCoefficients& viscosity) {
        const ShockRun run = pistonIntoBar(viscosity, up, time, aluminium, yield, 200);
        std::printf(
            "[shock] %s: plateau %.1f MPa (%+.2f %%, spread %.2f %%), shock at %.3f mm "
            "(%+.2f %%), precursor at %.3f mm (%+.2f %%), viscous work %.2f %% of the "
            "piston's\n",
            what, run.plateau * 1e-6, 100 * (run.plateau / rh.sigma - 1), 100 * run.spread,
            run.front * 1e3, 100 * (run.front / (rh.speed * time) - 1), run.precursor * 1e3,
            100 * (run.precursor / (rh.speedElastic * time) - 1), 100 * run.viscousWork);
        return run;
    };
    const ShockRun defaults = report("default (switch M0 = 0.01)", kDefaultViscosity);
    const ShockRun constant = report("constant [1, 1]", {1.0, 1.0, 0.0});
    const ShockRun none = report("no viscosity", {0.0, 0.0, 0.0});
    EXPECT_NEAR(defaults.plateau / rh.sigma, 1.0, 0.01);
    EXPECT_NEAR(defaults.front / (rh.speed * time), 1.0, 0.015);
    EXPECT_NEAR(defaults.precursor / (rh.speedElastic * time), 1.0, 0.015);
    EXPECT_LT(defaults.spread, 0.02) << "the shocked state rings";
    // What the switch changes: the constant coefficients smear the precursor; without any
    // viscosity the shocked state rings.
    EXPECT_GT(constant.precursor / (rh.speedElastic * time), 1.05);
    EXPECT_GT(none.spread, 0.04);
}

}  // namespace
}  // namespace gsph
