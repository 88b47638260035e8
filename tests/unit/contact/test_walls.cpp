// SPDX-License-Identifier: MIT
// Rigid cylindrical walls of contact/walls.hpp: a particle pressed into a cylinder feels the
// analytic radial force k g n; with anisotropic cells the force is the exact gradient of the
// spring energy; the push power is the rate of that energy at fixed particles (the identity the
// energy ledger rests on); a moving cylinder pressed into an elastic block keeps the ledger's
// total; each wall's total force is the sum of its forces on the particles.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "contact/walls.hpp"
#include "neighbors/theta_search.hpp"
#include "simulation.hpp"
#include "spaces/metric.hpp"
#include "support/contact_fixtures.hpp"

namespace gsph {
namespace {

using testing::Box;

ParticleRange all(const Reference& ref) {
    return {0, ref.size()};
}

struct Block {
    Reference ref;
    ContactShapes shapes;
    std::vector<double> k;
};

Block block(const Vec3& size, const std::array<int, 3>& cells) {
    Block b;
    b.ref = testing::boxBodies({Box{Vec3::Zero(), size, cells}});
    buildPairs(b.ref);
    computeGeometry(b.ref);
    b.shapes = contactShapes(b.ref, 1.0);
    b.k = contactStiffness(b.ref, std::vector<double>(b.ref.X.size(), 3.4e7), 4.0);
    return b;
}

Wall cylinder(const Vec3& point, const Vec3& axis, double radius,
              const Vec3& velocity = Vec3::Zero(), double friction = 0.0) {
    Wall w{"roller", point, Vec3::UnitZ(), velocity, friction};
    w.shape = WallShape::Cylinder;
    w.axis = axis;
    w.radius = radius;
    return w;
}

struct Forces {
    std::vector<Vec3> force, friction, wallForce;
    std::vector<double> frequency2;
    explicit Forces(std::size_t n)
        : force(n, Vec3::Zero()),
          friction(n, Vec3::Zero()),
          wallForce(n, Vec3::Zero()),
          frequency2(n, 0.0) {}
};

// Cubic cells: every contact ellipsoid is a sphere of radius ℓ/2, so the force is k_a g_a n_a
// with g_a = ℓ/2 + R − r_a, r_a the distance to the axis: nothing but geometry.
TEST(CylinderWall, ParticlePressedIntoACylinderFeelsTheAnalyticRadialForce) {
    const double l = 1e-3, radius = 4e-3;
    Block b = block(Vec3(4 * l, 3 * l, 3 * l), {4, 3, 3});
    const std::size_t n = b.ref.X.size();
    // Axis along y (given unnormalised), under the block's bottom face, slightly off-centre.
    const Vec3 point(1.7 * l, -5.0 * l, -radius + 0.35 * l);
    RigidWalls walls(b.ref, {cylinder(point, Vec3(0, 2.0, 0), radius)}, b.k, b.shapes);
    std::vector<Vec3> x = b.ref.X;
    // Particle 0 placed by hand: a gap g = 0.1ℓ along n0 = (1, 0, 1)/√2, 0.7ℓ along the axis.
    const Vec3 n0 = Vec3(1, 0, 1).normalized();
    const double g0 = 0.1 * l;
    x[0] = point + (radius + 0.5 * l - g0) * n0 + 0.7 * l * Vec3::UnitY();
    Forces f(n);
    const WallResult r = walls.addForces(0.0, 0.0, x, std::vector<Vec3>(n, Vec3::Zero()), f.force,
                                         f.friction, f.frequency2, f.wallForce, all(b.ref));
    EXPECT_LT((f.force[0] - b.k[0] * g0 * n0).norm(), 1e-12 * b.k[0] * g0);
    int touching = 0;
    double energy = 0.0;
    Vec3 total = Vec3::Zero();
    for (std::size_t a = 0; a < n; ++a) {
        Vec3 radial = x[a] - point;
        radial[1] = 0.0;
        const double gap = 0.5 * l + radius - radial.norm();
        const Vec3 expected = gap > 0.0 ? Vec3(b.k[a] * gap * radial.normalized()) : Vec3::Zero();
        touching += gap > 0.0;
        energy += gap > 0.0 ? 0.5 * b.k[a] * gap * gap : 0.0;
        EXPECT_LT((f.force[a] - expected).norm(), 1e-12 * b.k[a] * l) << "particle " << a;
        EXPECT_EQ(f.wallForce[a], f.force[a]);
        EXPECT_EQ(f.frequency2[a], gap > 0.0 ? b.k[a] / b.ref.mass[a] : 0.0);
        total += f.force[a];
    }
    EXPECT_GE(touching, 4) << "the fixture presses several particles";
    EXPECT_NEAR(r.energy, energy, 1e-12 * energy);
    EXPECT_EQ(r.pushPower, 0.0) << "a wall at rest does no work";
    std::vector<Vec3> totals;
    walls.totalForces(totals);
    ASSERT_EQ(totals.size(), 1u);
    EXPECT_LT((totals[0] - total).norm(), 1e-12 * total.norm());
}

// Cells 1 × 2 × 1.5 mm: ρ_a(n) turns with n around the axis, and the force keeps the term
// that makes it −∂U/∂x (central differences, step 1e-9 m, gaps ~1e-4 m).
TEST(CylinderWall, ForceIsTheGradientOfTheSpringEnergyForAnisotropicCells) {
    Block b = block(Vec3(0.004, 0.008, 0.006), {4, 4, 4});
    const std::size_t n = b.ref.X.size();
    RigidWalls walls(b.ref, {cylinder(Vec3(0.0021, 0.004, -0.0026), Vec3(0.3, 1.0, 0.2), 0.003)},
                     b.k, b.shapes);
    const std::vector<Vec3> v(n, Vec3::Zero());
    Forces f(n);
    walls.addForces(0.0, 0.0, b.ref.X, v, f.force, f.friction, f.frequency2, f.wallForce,
                    all(b.ref));
    const auto energy = [&](const std::vector<Vec3>& x) {
        Forces scratch(n);
        return walls
            .addForces(0.0, 0.0, x, v, scratch.force, scratch.friction, scratch.frequency2,
                       scratch.wallForce, all(b.ref))
            .energy;
    };
    double worst = 0.0, largest = 0.0, turning = 0.0;
    int touching = 0;
    for (std::size_t a = 0; a < n; ++a) {
        if (f.force[a].isZero(0.0)) continue;
        ++touching;
        Vec3 radial = b.ref.X[a] - Vec3(0.0021, 0.004, -0.0026);
        const Vec3 e = Vec3(0.3, 1.0, 0.2).normalized();
        radial -= radial.dot(e) * e;
        turning = std::max(
            turning,
            (f.force[a] - f.force[a].dot(radial.normalized()) * radial.normalized()).norm() /
                f.force[a].norm());
        for (int d = 0; d < 3; ++d) {
            std::vector<Vec3> xp = b.ref.X, xm = b.ref.X;
            const double step = 1e-9;
            xp[a][d] += step;
            xm[a][d] -= step;
            const double numeric = -(energy(xp) - energy(xm)) / (2 * step);
            worst = std::max(worst, std::abs(numeric - f.force[a][d]));
            largest = std::max(largest, std::abs(f.force[a][d]));
        }
    }
    std::printf(
        "[cylinder gradient] %d particles touching, worst |f + ∂U/∂x| = %.2e of the "
        "largest component, largest non-radial part %.2e of |f|\n",
        touching, worst / largest, turning);
    EXPECT_GE(touching, 4);
    EXPECT_GT(turning, 1e-3) << "the fixture exercises the turning term";
    EXPECT_LT(worst, 1e-6 * largest);
}

// The ledger books f_n·v_wall as external work and U as contact energy; that balances because
// U depends on x − p(t) only, so ∂U/∂t at fixed x = Σ f_n·v_wall (checked by differences).
// The wall w against the particles of b at rest at their reference positions, at t = 10 µs:
// the push power is positive and equals dU/dt (central differences) to 1e-6.
void expectPushPowerIsTheRateOfTheSpringEnergy(const Block& b, const Wall& w) {
    const std::size_t n = b.ref.X.size();
    RigidWalls walls(b.ref, {w}, b.k, b.shapes);
    const std::vector<Vec3> v(n, Vec3::Zero());
    const auto at = [&](double t) {
        Forces f(n);
        return walls.addForces(t, 0.0, b.ref.X, v, f.force, f.friction, f.frequency2, f.wallForce,
                               all(b.ref));
    };
    const double t = 1e-5, step = 1e-10;
    const WallResult now = at(t);
    const double rate = (at(t + step).energy - at(t - step).energy) / (2 * step);
    std::printf("[cylinder power] push %.6e W, dU/dt %.6e W\n", now.pushPower, rate);
    EXPECT_GT(now.pushPower, 0.0);
    EXPECT_NEAR(rate, now.pushPower, 1e-6 * std::abs(now.pushPower));
}

TEST(CylinderWall, PushPowerIsTheRateOfTheSpringEnergyAtFixedParticles) {
    const Block b = block(Vec3(0.004, 0.008, 0.006), {4, 4, 4});
    const Vec3 velocity(0.7, -0.2, 3.0);
    expectPushPowerIsTheRateOfTheSpringEnergy(
        b, cylinder(Vec3(0.0021, 0.004, -0.0026), Vec3(0.3, 1.0, 0.2), 0.003, velocity));
}

// A steel block, 12 × 4 × 6 cells of 1 mm, indented by a cylinder (R = 3 mm, axis along y,
// μ = 0.2) moving down at 5 m/s for 10 µs: kinetic + elastic + … + contact − external stays at
// its initial value, to 0.5 % of the work the cylinder did.
TEST(CylinderWall, MovingCylinderKeepsTheEnergyLedgerBalanced) {
    const ElasticConstants steel(7800.0, 200e9, 0.3);
    SolverOptions options;
    Simulation sim(testing::boxBodies({Box{Vec3::Zero(), Vec3(0.012, 0.004, 0.006), {12, 4, 6}}}),
                   {HypoElastic(steel)}, options);
    sim.addWall(cylinder(Vec3(0.0065, 0.0, 0.006 + 0.003 + 0.00002), Vec3::UnitY(), 0.003,
                         Vec3(0.0, 0.0, -5.0), 0.2));
    sim.addWall({"floor", Vec3::Zero(), Vec3::UnitZ()});
    sim.start();
    const double e0 = sim.energy().total();
    double worst = 0.0;
    sim.advanceTo(
        1e-5, [&](const State&) { worst = std::max(worst, std::abs(sim.energy().total() - e0)); });
    const EnergyReport e = sim.energy();
    std::printf(
        "[moving cylinder] external work %.4e J, contact %.3e J, worst |ΔE| %.3e J "
        "(%.2e of the work); indenter force z %.3f N\n",
        e.externalWork, e.contactEnergy, worst, worst / e.externalWork, sim.wallForces()[0][2]);
    EXPECT_GT(e.externalWork, 0.0);
    EXPECT_GT(e.contactEnergy, 0.0);
    EXPECT_LT(worst, 5e-3 * e.externalWork);
    // The force columns: per wall, Σ over particles of that wall's force; the two walls'
    // together are the per-particle totals.
    Vec3 sum = Vec3::Zero();
    for (const Vec3& fa : sim.integrator().stage<WallStage>()->particleForces()) sum += fa;
    const Vec3 both = sim.wallForces()[0] + sim.wallForces()[1];
    EXPECT_LT((both - sum).norm(), 1e-9 * sum.norm());
    EXPECT_LT(sim.wallForces()[0][2], 0.0) << "the indenter pushes down";
    EXPECT_GT(sim.wallForces()[1][2], 0.0) << "the floor pushes up";
}

// A speed ramp (ramp_time T): the displacement is the integral of the velocity (t²/2T, then
// t − T/2), and during the ramp the push power is still the rate of the spring energy.
TEST(CylinderWall, SpeedRampIsTheIntegralOfItsVelocityAndKeepsThePowerIdentity) {
    Wall w = cylinder(Vec3::Zero(), Vec3::UnitY(), 0.003, Vec3(0.0, 0.0, -2.0));
    w.rampTime = 4e-5;
    EXPECT_EQ(w.velocityAt(0.0), Vec3::Zero());
    EXPECT_EQ(w.velocityAt(2e-5), Vec3(0.0, 0.0, -1.0));
    EXPECT_EQ(w.velocityAt(5e-5), Vec3(0.0, 0.0, -2.0));
    EXPECT_NEAR(w.displacement(2e-5)[2], -2.0 * 0.5 * 4e-10 / 4e-5, 1e-18);
    EXPECT_NEAR(w.displacement(6e-5)[2], -2.0 * (6e-5 - 2e-5), 1e-18);
    for (double t : {1e-5, 3.9e-5, 4.1e-5}) {  // d/dt displacement = velocity, across the knee
        const double h = 1e-9;
        EXPECT_NEAR((w.displacement(t + h)[2] - w.displacement(t - h)[2]) / (2 * h),
                    w.velocityAt(t)[2], 1e-6);
    }
    const Block b = block(Vec3(0.004, 0.008, 0.006), {4, 4, 4});
    w.point = Vec3(0.0021, 0.004, 0.006 + 0.003 - 0.0004);  // pressed 0.4 mm + ℓ/2 into the top
    expectPushPowerIsTheRateOfTheSpringEnergy(b, w);
    Wall bad = w;
    bad.rampTime = -1.0;
    EXPECT_THROW(RigidWalls(b.ref, {bad}, b.k, b.shapes), InputError);
}

TEST(CylinderWall, BadShapeParametersAreInputErrors) {
    Block b = block(Vec3(0.003, 0.003, 0.003), {3, 3, 3});
    EXPECT_THROW(RigidWalls(b.ref, {cylinder(Vec3::Zero(), Vec3::Zero(), 0.01)}, b.k, b.shapes),
                 InputError);
    EXPECT_THROW(RigidWalls(b.ref, {cylinder(Vec3::Zero(), Vec3::UnitY(), 0.0)}, b.k, b.shapes),
                 InputError);
}

}  // namespace
}  // namespace gsph
