// SPDX-License-Identifier: MIT
// The default mass basis (MassBasis::NormalizedQuadratureVolume, docs/theory.md "Volumes and
// mass"): each body's quadrature volumes ω det M scaled by one factor so that they add up to
// its meshed volume, in the energy and the mass alike.
//   * A body on its own moves as with the quadrature volumes: a graded copper block striking a
//     rigid wall (plastic flow, the default viscosity, hourglass control, the wall's penalty)
//     follows the quadrature run to round-off, while its mass and momentum are exact.
//   * Two bodies each get their own factor: each one's mass is ρ0 × its meshed volume.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>

#include "simulation.hpp"
#include "support/johnson_cook_materials.hpp"
#include "support/lattice_fixtures.hpp"

namespace gsph {
namespace {

// A block graded 4:1 along x (fine at the wall x = 0, which its face touches), 16 × 4 × 4
// cells, 10 × 4 × 4 mm: ω det M misses the meshed volume at the one-sided faces.
Reference gradedBlock(MassBasis basis, const Vec3& origin = Vec3::Zero(), Index body = 0,
                      double ratio = 4.0) {
    Reference ref = latticeReference(gradedBoxMap(Vec3(0.010, 0.004, 0.004),
                                                  {AxisGrading{AxisGrading::Kind::OneSided, ratio},
                                                   AxisGrading{}, AxisGrading{}},
                                                  origin),
                                     3, {16, 4, 4}, testing::kCopperElastic.density, 1.2, body);
    ref.massBasis = basis;
    return ref;
}

std::unique_ptr<Simulation> blockOnWall(MassBasis basis) {
    SolverOptions options;
    options.viscosity = kDefaultViscosity;
    options.hourglass = 0.1;
    auto sim = std::make_unique<Simulation>(gradedBlock(basis),
                                            std::vector<Material>{testing::withLinearEos(
                                                testing::kCopperElastic, testing::copperParams())},
                                            options);
    sim->addWall({"wall", Vec3::Zero(), Vec3::UnitX()});
    sim->setVelocity([](const Vec3&) { return Vec3(-100.0, 0.0, 0.0); });
    sim->start();
    return sim;
}

double sumOf(const std::vector<double>& values) {
    double s = 0.0;
    for (double v : values) s += v;
    return s;
}

TEST(MassBasis, NormalizedBodyMovesAsTheQuadratureOneWithItsExactMass) {
    const std::unique_ptr<Simulation> quadrature = blockOnWall(MassBasis::QuadratureVolume);
    const std::unique_ptr<Simulation> normalized =
        blockOnWall(MassBasis::NormalizedQuadratureVolume);
    const Reference& ref = normalized->reference();
    const double meshed = ref.density[0] * sumOf(ref.volume);
    const double factor = sumOf(ref.mass) / sumOf(quadrature->reference().mass);
    EXPECT_NEAR(sumOf(ref.mass) / meshed, 1.0, 1e-14);
    EXPECT_GT(factor - 1.0, 1e-3) << "the quadrature misses part of the graded block's volume";

    const int steps = 400;
    for (int n = 0; n < steps; ++n) {
        quadrature->step();
        normalized->step();
    }
    const State& q = quadrature->state();
    const State& s = normalized->state();
    double worst = 0.0, plastic = 0.0, squashed = 0.0;
    for (std::size_t a = 0; a < s.x.size(); ++a) {
        worst = std::max(worst, (s.x[a] - q.x[a]).norm());
        plastic = std::max(plastic, s.plasticStrain[a]);
        squashed = std::max(squashed, (s.x[a] - ref.X[a]).norm());
    }
    const EnergyReport eq = quadrature->energy(), es = normalized->energy();
    std::printf(
        "[mass basis] factor %.6f; after %d steps (%.2f µs, ε̄p up to %.3f, displacement up to "
        "%.3e m): positions differ by %.2e of it, time by %.1e; momentum and plastic work ratios "
        "differ from the factor by %.1e, %.1e\n",
        factor, steps, s.time * 1e6, plastic, squashed, worst / squashed, s.time / q.time - 1.0,
        es.momentum[0] / eq.momentum[0] - factor, es.plasticWork / eq.plasticWork - factor);
    EXPECT_GT(plastic, 0.05) << "the block must flow at the wall";
    EXPECT_LT(worst / squashed, 1e-13);
    EXPECT_NEAR(s.time / q.time, 1.0, 1e-15);
    EXPECT_NEAR(es.momentum[0] / eq.momentum[0], factor, 1e-14);
    EXPECT_NEAR(es.plasticWork / eq.plasticWork, factor, 1e-14);
}

TEST(MassBasis, EachBodyGetsItsOwnFactor) {
    // Two blocks graded 4:1 and 2:1, side by side: one factor each, each body's mass exact.
    Reference two = gradedBlock(MassBasis::NormalizedQuadratureVolume);
    const Reference second =
        gradedBlock(MassBasis::NormalizedQuadratureVolume, Vec3(0.0, 0.006, 0.0), 1, 2.0);
    testing::appendSpace(two, second, 1);
    Reference quadrature = two;
    quadrature.massBasis = MassBasis::QuadratureVolume;
    for (Reference* r : {&two, &quadrature}) {
        buildPairs(*r);
        computeGeometry(*r);
    }
    double mass[2] = {0, 0}, meshed[2] = {0, 0}, quad[2] = {0, 0};
    for (std::size_t a = 0; a < two.X.size(); ++a) {
        const auto b = static_cast<std::size_t>(two.body[a]);
        mass[b] += two.mass[a];
        meshed[b] += two.density[a] * two.volume[a];
        quad[b] += quadrature.mass[a];
    }
    std::printf("[mass basis] two bodies: factors %.6f and %.6f\n", mass[0] / quad[0],
                mass[1] / quad[1]);
    for (int b = 0; b < 2; ++b) EXPECT_NEAR(mass[b] / meshed[b], 1.0, 1e-14) << "body " << b;
    EXPECT_GT(std::abs(mass[0] / quad[0] - mass[1] / quad[1]), 1e-4);
}

}  // namespace
}  // namespace gsph
