// SPDX-License-Identifier: MIT
// The nonlocal average of the damage driver (failure/nonlocal_damage.hpp) and its use by the
// plastic solid: the neighbourhoods are exactly the particles of the body within ℓ, the weights
// sum to one and reproduce constant and (inside) linear fields; a plastic point with nonlocal
// damage accumulates its driver uncapped, takes D from the average and fails when the average
// reaches 1, even without flowing itself, booking its elastic energy as damage dissipation.
#include <gtest/gtest.h>

#include <cmath>

#include "failure/nonlocal_damage.hpp"
#include "materials/johnson_cook.hpp"
#include "spaces/analytic_maps.hpp"
#include "support/johnson_cook_materials.hpp"

namespace gsph {
namespace {

// A graded 3-D block of two bodies' worth of particles: [0, n) and [n, 2n).
struct TwoBodies {
    Reference ref;
    Index n = 0;
};
TwoBodies twoBodies() {
    using Kind = AxisGrading::Kind;
    TwoBodies t;
    t.ref = latticeReference(
        gradedBoxMap(Vec3(1.0, 0.5, 0.5), {AxisGrading{Kind::OneSided, 3.0}, {}, {}}), 3,
        {16, 8, 8}, 7800.0, 1.2);
    t.n = t.ref.size();
    const Reference second = latticeReference(
        gradedBoxMap(Vec3(1.0, 0.5, 0.5), {}, Vec3(0.0, 0.0, 0.5)), 3, {16, 8, 8}, 7800.0, 1.2);
    t.ref.X.insert(t.ref.X.end(), second.X.begin(), second.X.end());
    t.ref.volume.insert(t.ref.volume.end(), second.volume.begin(), second.volume.end());
    return t;
}

TEST(NonlocalAverage, NeighbourhoodsAreTheBodysParticlesWithinTheLength) {
    const TwoBodies t = twoBodies();
    const double length = 0.15;
    const NonlocalAverage average(t.ref.X, t.ref.volume, 0, t.n, length);
    double worstSum = 0.0;
    for (Index a = 0; a < t.n; ++a) {
        std::size_t within = 0;
        double sum = 0.0;
        for (Index b = 0; b < 2 * t.n; ++b) {
            const double r =
                (t.ref.X[static_cast<std::size_t>(b)] - t.ref.X[static_cast<std::size_t>(a)])
                    .norm();
            const double w = b < t.n ? average.weight(a, b) : 0.0;
            if (b < t.n && r < length) {
                ++within;
                EXPECT_GT(w, 0.0) << a << " " << b;
            } else {
                EXPECT_EQ(w, 0.0) << "outside ℓ or another body: " << a << " " << b;
            }
            sum += w;
        }
        EXPECT_EQ(average.neighbors(a).size(), within);
        worstSum = std::max(worstSum, std::abs(sum - 1.0));
    }
    EXPECT_LT(worstSum, 4e-15);  // sums of about 60 weights
}

TEST(NonlocalAverage, ReproducesConstantFieldsAndInsideLinearOnes) {
    // Uniform lattice: the neighbourhoods of particles farther than ℓ from every face are
    // symmetric, so a linear field averages to its value there.
    const Reference ref =
        latticeReference(gradedBoxMap(Vec3(1.0, 1.0, 1.0), {}), 3, {12, 12, 12}, 7800.0, 1.2);
    const double length = 0.2;
    const NonlocalAverage average(ref.X, ref.volume, 0, ref.size(), length);
    std::vector<double> constant(ref.X.size(), 0.37), linear(ref.X.size());
    for (std::size_t a = 0; a < ref.X.size(); ++a)
        linear[a] = 0.2 + ref.X[a].dot(Vec3(0.3, -0.7, 1.1));
    double worstConstant = 0.0, worstLinear = 0.0;
    int inside = 0;
    for (Index a = 0; a < ref.size(); ++a) {
        const Vec3& X = ref.X[static_cast<std::size_t>(a)];
        worstConstant = std::max(worstConstant, std::abs(average.average(constant, a) - 0.37));
        if ((X.array() > length).all() && (X.array() < 1.0 - length).all()) {
            ++inside;
            worstLinear = std::max(worstLinear, std::abs(average.average(linear, a) -
                                                         linear[static_cast<std::size_t>(a)]));
        }
    }
    EXPECT_GT(inside, 100);
    EXPECT_LT(worstConstant, 1e-15);
    EXPECT_LT(worstLinear, 1e-14);
}

TEST(NonlocalAverage, RefusesANonPositiveLength) {
    const Reference ref =
        latticeReference(gradedBoxMap(Vec3(1.0, 1.0, 1.0), {}), 3, {2, 2, 2}, 7800.0, 1.2);
    EXPECT_THROW(NonlocalAverage(ref.X, ref.volume, 0, ref.size(), 0.0), InputError);
}

// A copper point with Johnson–Cook damage of constant εf = 0.2, local or nonlocal (ℓ > 0).
JohnsonCook copperWithDamage(double length) {
    JohnsonCookDamage damage{{0.2, 0.0, 0.0, 0.0, 0.0}};
    damage.length = length;
    const ElasticConstants& e = testing::kCopperElastic;
    return JohnsonCook(e, testing::copperParams(0.0),
                       EquationOfState::linear(e.density, e.bulkModulus()), damage);
}

// One update in uniaxial-strain extension at rate `rate` over dt from point p.
void pull(const JohnsonCook& model, MaterialPoint& p, double rate, double dt) {
    Mat3 D = Mat3::Zero();
    D(0, 0) = rate;
    p.density = testing::kCopperElastic.density;
    model.update(p, D, Mat3::Zero(), dt);
}

TEST(NonlocalDamage, AccumulatesItsDriverAndTakesTheDamageFromTheAverage) {
    const JohnsonCook local = copperWithDamage(0.0), nonlocal = copperWithDamage(1e-3);
    MaterialPoint a, b;
    // Flow plastically for a while: the local point's D and the nonlocal point's driver grow
    // alike; the nonlocal D follows the average it is given (here: half its own driver).
    for (int k = 0; k < 150; ++k) {
        b.averagedDriver = 0.5 * b.damageDriver;
        pull(local, a, 1e4, 1e-7);
        pull(nonlocal, b, 1e4, 1e-7);
    }
    ASSERT_GT(a.plasticStrain, 0.05);
    EXPECT_NEAR(a.damage, a.plasticStrain / 0.2, 1e-12);
    EXPECT_EQ(a.damageDriver, 0.0) << "local damage keeps no driver";
    EXPECT_GT(b.damageDriver, 0.2);
    EXPECT_NEAR(b.damage, 0.5 * b.damageDriver, 0.02 * b.damage) << "one step behind";
    EXPECT_LT(b.damage, 1.0);
    // The driver is not capped at 1 (the average is what fails the point).
    for (int k = 0; k < 1000; ++k) {
        b.averagedDriver = 0.0;
        pull(nonlocal, b, 1e4, 1e-7);
    }
    EXPECT_GT(b.damageDriver, 1.0);
    EXPECT_LT(b.damage, 1.0) << "D never decreases, and rises only with the average";
}

TEST(NonlocalDamage, APointFailsWhenItsAverageReachesOneWithoutFlowingItself) {
    const JohnsonCook nonlocal = copperWithDamage(1e-3);
    MaterialPoint p;
    // Elastic tension, below yield: no plastic flow, a stored elastic energy.
    pull(nonlocal, p, 1.0, 1e-4);
    ASSERT_EQ(p.plasticStrain, 0.0);
    ASSERT_GT(p.cauchy(0, 0), 0.0);
    const double stored = nonlocal.storedEnergyDensity(p);
    p.averagedDriver = 1.0;  // its neighbours failed
    pull(nonlocal, p, 0.0, 1e-7);
    EXPECT_EQ(p.damage, 1.0);
    EXPECT_EQ((p.cauchy + (p.cauchy.trace() / -3.0) * Mat3::Identity()).norm(), 0.0)
        << "no deviatoric stress";
    EXPECT_GE(-p.cauchy.trace() / 3.0, 0.0) << "no tension";
    EXPECT_NEAR(p.damageDissipation, stored, 1e-9 * stored);
    // Failed: later updates book nothing more.
    pull(nonlocal, p, 1.0, 1e-7);
    EXPECT_EQ(p.damageDissipation, 0.0);
}

}  // namespace
}  // namespace gsph
