// SPDX-License-Identifier: MIT
// The difference the hourglass control makes (DESIGN §4). A checkerboard velocity
// v = v0 (−1)^{i+j+k} e_z on a free elastic block is invisible to the SPH deformation gradient
// inside the block (the symmetric stencil sums it to zero), so without control it meets no
// stiffness there and the particles drift apart: the hourglass error η grows steadily. With
// α = 0.1 the penalty turns the mode into a bounded oscillation. In plastic flow the penalty
// takes each particle's secant modulus (forces/hourglass.hpp).
#include <gtest/gtest.h>

#include <cmath>

#include "forces/hourglass_diagnostic.hpp"
#include "simulation.hpp"
#include "spaces/analytic_maps.hpp"
#include "spaces/metric.hpp"
#include "support/johnson_cook_materials.hpp"

namespace gsph {
namespace {

struct HourglassRun {
    double finalError = 0.0;
    double peakError = 0.0;
    double energyError = 0.0;  ///< |E(t) − E(0)| / E(0) with the ledger's hourglass work
};

HourglassRun runCheckerboard(double alpha) {
    const ElasticConstants steel(7800.0, 200e9, 0.3);
    SolverOptions options;
    options.hourglass = alpha;
    Simulation sim(latticeReference(gradedBoxMap(Vec3(0.01, 0.01, 0.01), {}), 3, {10, 10, 10},
                                    steel.density, 1.2),
                   {HypoElastic(steel)}, options);
    std::vector<Vec3> v(sim.state().v.size());
    for (Index a = 0; a < sim.reference().size(); ++a) {
        const Vec3 t = sim.reference().theta[static_cast<std::size_t>(a)];
        const int parity = static_cast<int>(t[0] + t[1] + t[2] - 1.5) % 2;
        v[static_cast<std::size_t>(a)] = Vec3(0, 0, parity ? 1.0 : -1.0);
    }
    sim.setVelocities(v);
    sim.start();
    const double e0 = sim.energy().total();
    HourglassRun r;
    const double transit = 0.01 / steel.pWaveSpeed();
    sim.advanceTo(20 * transit, [&](const State& s) {
        r.peakError = std::max(r.peakError, hourglassError(sim.reference(), s));
    });
    r.finalError = hourglassError(sim.reference(), sim.state());
    r.energyError = std::abs(sim.energy().total() - e0) / e0;
    return r;
}

TEST(HourglassControl, SuppressesTheCheckerboardMode) {
    const HourglassRun off = runCheckerboard(0.0);
    const HourglassRun on = runCheckerboard(0.1);
    std::printf(
        "[hourglass] checkerboard mode after 20 wave transits: η = %.2e without control, %.2e with "
        "α = 0.1 "
        "(peak %.2e); energy balance error %.1e / %.1e\n",
        off.finalError, on.finalError, on.peakError, off.energyError, on.energyError);
    EXPECT_LT(on.finalError, 0.2 * off.finalError);
    EXPECT_LT(on.energyError, 0.01);  // the ledger books what the penalty stores and returns
}

TEST(HourglassControl, AffineMotionHasNoHourglassError) {
    const Reference ref = [] {
        Reference r =
            latticeReference(annulusMap(0.5, 1.0, 0.0, 1.0, 0.3), 3, {6, 8, 6}, 1000.0, 1.2);
        buildPairs(r);
        computeGeometry(r);
        return r;
    }();
    State s = State::atRest(ref.X, static_cast<std::size_t>(ref.pairs.pairs()));
    const Mat3 A = (Mat3() << 1.1, 0.2, 0.0, -0.1, 0.9, 0.05, 0.0, 0.1, 1.2).finished();
    for (std::size_t a = 0; a < s.x.size(); ++a) {
        s.x[a] = A * ref.X[a];
        s.F[a] = A;
    }
    EXPECT_LT(hourglassError(ref, s), 1e-12);
}

// The force at the start of a run on a curved block of yielded copper whose particles are
// displaced in a checkerboard along z, under a uniform shear stress τ with F = I: the hourglass
// penalty's share is the difference from the run without it. With the same plastic strain ε̄p
// everywhere every pair's scale is s = σ_eq/(σ_eq + 3G ε̄p), σ_eq = √3 τ, so that share is s
// times the unyielded one (measured 7e-15 of the largest force; "elastic" keeps it bit for bit);
// the state is set as a restart would find it, so this is also the scale a resumed run starts with.
std::vector<Vec3> startForces(double alpha, HourglassModulus modulus, double plasticStrain) {
    SolverOptions options;
    options.hourglass = alpha;
    options.hourglassModulus = modulus;
    Simulation sim(latticeReference(wavyBoxMap(Vec3(0.01, 0.008, 0.006), 0.05), 3, {10, 8, 6},
                                    testing::kCopperElastic.density, 1.2),
                   {testing::withLinearEos(testing::kCopperElastic, testing::copperParams())},
                   options);
    State& s = sim.state();
    const Mat3 shear = (Mat3() << 0, 1, 0, 1, 0, 0, 0, 0, 0).finished();
    for (Index a = 0; a < sim.reference().size(); ++a) {
        const auto ia = static_cast<std::size_t>(a);
        const Vec3 t = sim.reference().theta[ia];
        const int parity = static_cast<int>(t[0] + t[1] + t[2] - 1.5) % 2;
        s.x[ia] += Vec3(0, 0, parity ? 2e-6 : -2e-6);
        s.cauchy[ia] = 150e6 * shear;
        s.plasticStrain[ia] = plasticStrain;
    }
    sim.start();
    std::vector<Vec3> f(s.x.size());
    for (std::size_t a = 0; a < f.size(); ++a)
        f[a] = sim.reference().mass[a] * sim.state().acceleration[a];
    return f;
}

TEST(HourglassControl, PlasticFlowScalesThePenaltyByTheSecantModulus) {
    const double strain = 0.5, tau = 150e6;
    const double vonMises = std::sqrt(3.0) * tau, G = testing::kCopperElastic.shearModulus();
    const double scale = vonMises / (vonMises + 3.0 * G * strain);
    const auto none = startForces(0.0, HourglassModulus::Secant, strain);
    const auto unyielded = startForces(0.1, HourglassModulus::Secant, 0.0);
    const auto yielded = startForces(0.1, HourglassModulus::Secant, strain);
    const auto elastic = startForces(0.1, HourglassModulus::Elastic, strain);
    double largest = 0.0, worstSecant = 0.0, worstElastic = 0.0;
    for (std::size_t a = 0; a < none.size(); ++a) {
        const Vec3 full = unyielded[a] - none[a];
        largest = std::max(largest, full.norm());
        worstSecant = std::max(worstSecant, (yielded[a] - none[a] - scale * full).norm());
        worstElastic = std::max(worstElastic, (elastic[a] - none[a] - full).norm());
    }
    std::printf(
        "[hourglass] yielded copper (ε̄p = %.1f, s = %.4f): secant share off s × unyielded by "
        "%.1e, elastic share off the unyielded one by %.1e (largest %.3e N)\n",
        strain, scale, worstSecant / largest, worstElastic / largest, largest);
    ASSERT_GT(largest, 0.0);
    EXPECT_LT(scale, 0.01);  // a plastic strain of 0.5 leaves well under 1 % of E
    EXPECT_LT(worstSecant, 1e-13 * largest);
    EXPECT_EQ(worstElastic, 0.0);  // s = 1: the same operations
}

}  // namespace
}  // namespace gsph
