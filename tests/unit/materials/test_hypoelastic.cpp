// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>

#include "core/error.hpp"
#include "materials/hypoelastic.hpp"

namespace gsph {
namespace {

const ElasticConstants kSteel(7800.0, 200e9, 0.3);

TEST(ElasticConstants, DerivedModuliAndValidation) {
    EXPECT_NEAR(kSteel.shearModulus(), 200e9 / 2.6, 1.0);
    EXPECT_NEAR(kSteel.bulkModulus(), 200e9 / 1.2, 1.0);
    EXPECT_NEAR(kSteel.barWaveSpeed(), std::sqrt(200e9 / 7800.0), 1e-9);
    EXPECT_THROW(ElasticConstants(-1.0, 1e9, 0.3), InputError);
    EXPECT_THROW(ElasticConstants(1000.0, 1e9, 0.5), InputError);
    EXPECT_THROW(ElasticConstants(1000.0, 0.0, 0.3), InputError);
}

TEST(HypoElastic, UniaxialStrainSlope) {
    // Small strain increments along x: σ_xx = (K + 4G/3) ε, σ_yy = σ_zz = λ ε.
    const HypoElastic model(kSteel);
    MaterialPoint p;
    Mat3 D = Mat3::Zero();
    D(0, 0) = 1e-3;                                                        // strain rate [1/s]
    for (int i = 0; i < 100; ++i) model.update(p, D, Mat3::Zero(), 1e-2);  // ε = 1e-3
    EXPECT_NEAR(p.cauchy(0, 0) / (kSteel.pWaveModulus() * 1e-3), 1.0, 1e-12);
    EXPECT_NEAR(p.cauchy(1, 1) / (kSteel.lame() * 1e-3), 1.0, 1e-12);
    EXPECT_NEAR(p.cauchy(0, 1), 0.0, 1e-6);
}

TEST(HypoElastic, JaumannRateRotatesAStressedPointWithoutChangingItsInvariants) {
    // A rigid spin (D = 0) of a stressed point: the Jaumann update rotates σ. The
    // Hughes–Winget rotation is exactly orthogonal, so the invariants hold to round-off
    // (1e-10) and the result is the rotated tensor (up to the O(Δt²) angle error).
    const HypoElastic model(kSteel);
    MaterialPoint p;
    p.cauchy << 100e6, 20e6, 0, 20e6, -50e6, 10e6, 0, 10e6, 30e6;
    const Mat3 start = p.cauchy;
    const double omega = 1.0, dt = 1e-4;
    Mat3 W = Mat3::Zero();
    W(0, 1) = -omega;
    W(1, 0) = omega;  // spin about z
    const int steps = static_cast<int>(std::round(std::acos(-1.0) / 2 / (omega * dt)));
    for (int i = 0; i < steps; ++i) model.update(p, Mat3::Zero(), W, dt);
    const double angle = steps * omega * dt;
    Mat3 R = Mat3::Identity();
    R(0, 0) = R(1, 1) = std::cos(angle);
    R(1, 0) = std::sin(angle);
    R(0, 1) = -std::sin(angle);
    const Mat3 expected = R * start * R.transpose();
    EXPECT_NEAR(p.cauchy.trace(), start.trace(), 1e-10 * start.norm());
    EXPECT_NEAR(p.cauchy.norm() / start.norm(), 1.0, 1e-10);
    EXPECT_NEAR(p.cauchy.determinant() / start.determinant(), 1.0, 1e-10);
    EXPECT_LT((p.cauchy - expected).norm() / start.norm(), 1e-6);
}

TEST(HypoElastic, StoredEnergyOfUniaxialStress) {
    // σ_xx = s alone stores s²/(2E).
    const HypoElastic model(kSteel);
    Mat3 s = Mat3::Zero();
    s(0, 0) = 100e6;
    EXPECT_NEAR(model.storedEnergyDensity(s) / (100e6 * 100e6 / (2 * 200e9)), 1.0, 1e-12);
}

}  // namespace
}  // namespace gsph
