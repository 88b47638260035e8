// SPDX-License-Identifier: MIT
// One trilinear hex: centre, exact volume against closed forms, Jacobian checks, edges.
#include <gtest/gtest.h>

#include <Eigen/LU>
#include <cmath>

#include "hex_geometry.hpp"

namespace gsph::preproc {
namespace {

HexCorners unitCube() {
    HexCorners x;
    for (int c = 0; c < 8; ++c) x[c] = Vec3(c & 1, c >> 1 & 1, c >> 2 & 1);
    return x;
}

TEST(HexGeometry, UnitCube) {
    const HexCorners x = unitCube();
    EXPECT_NEAR((hexCentre(x) - Vec3(0.5, 0.5, 0.5)).norm(), 0.0, 1e-15);
    EXPECT_NEAR(hexVolume(x), 1.0, 1e-14);
    EXPECT_NEAR(minCornerJacobian(x), 0.125, 1e-15);  // J = I/2 on [−1,1]³
    const auto edges = edgeLengthRange(x);
    EXPECT_NEAR(edges[0], 1.0, 1e-15);
    EXPECT_NEAR(edges[1], 1.0, 1e-15);
}

TEST(HexGeometry, AffineHexHasDeterminantVolume) {
    Mat3 A;
    A << 2.0, 0.3, -0.1, 0.2, 1.5, 0.4, 0.1, -0.2, 0.7;
    const Vec3 b(1.0, -2.0, 3.0);
    HexCorners x = unitCube();
    for (Vec3& p : x) p = A * p + b;
    EXPECT_NEAR(hexVolume(x), A.determinant(), 1e-13);
    EXPECT_NEAR((hexCentre(x) - (A * Vec3(0.5, 0.5, 0.5) + b)).norm(), 0.0, 1e-14);
    EXPECT_NEAR(minCornerJacobian(x), A.determinant() / 8.0, 1e-14);
}

TEST(HexGeometry, FrustumVolume) {
    // Unit square at z = 0, centred square of side s at z = 1: a pyramid frustum (planar faces),
    // V = (A1 + A2 + √(A1 A2)) h / 3.
    const double s = 0.4;
    HexCorners x = unitCube();
    for (int c = 4; c < 8; ++c)
        x[c] = Vec3(0.5 + s * (x[c][0] - 0.5), 0.5 + s * (x[c][1] - 0.5), 1.0);
    EXPECT_NEAR(hexVolume(x), (1.0 + s * s + s) / 3.0, 1e-14);
}

TEST(HexGeometry, TwistedHexVolume) {
    // Top face turned by α about the z axis: non-planar side faces. Each horizontal section of
    // the trilinear solid is a square of area (1−z)² + z² + 2z(1−z)cos α, so V = (2 + cos α)/3.
    const double alpha = 0.7;
    HexCorners x;
    for (int c = 0; c < 8; ++c) {
        const Vec3 p((c & 1) - 0.5, (c >> 1 & 1) - 0.5, c >> 2 & 1);
        const double a = (c >> 2 & 1) ? alpha : 0.0;
        x[c] = Vec3(std::cos(a) * p[0] - std::sin(a) * p[1],
                    std::sin(a) * p[0] + std::cos(a) * p[1], p[2]);
    }
    EXPECT_NEAR(hexVolume(x), (2.0 + std::cos(alpha)) / 3.0, 1e-14);
    EXPECT_GT(minCornerJacobian(x), 0.0);
}

TEST(HexGeometry, MirroredHexIsInverted) {
    HexCorners x = unitCube();
    for (int c = 0; c < 4; ++c) std::swap(x[c], x[c + 4]);  // top and bottom exchanged
    EXPECT_LT(minCornerJacobian(x), 0.0);
    EXPECT_NEAR(hexVolume(x), -1.0, 1e-14);
}

TEST(HexGeometry, DegenerateHexHasZeroJacobian) {
    HexCorners x = unitCube();
    x[7] = x[6];  // a collapsed edge
    EXPECT_LE(minCornerJacobian(x), 0.0);
}

TEST(HexGeometry, JacobianOfAffineHexIsConstant) {
    Mat3 A;
    A << 1.0, 0.5, 0.0, 0.0, 2.0, 0.0, 0.0, 0.0, 3.0;
    HexCorners x = unitCube();
    for (Vec3& p : x) p = A * p;
    for (const Vec3& xi : {Vec3(0, 0, 0), Vec3(-1, 1, 0.3), Vec3(0.9, -0.2, -1)}) {
        EXPECT_NEAR((hexJacobian(x, xi) - A / 2.0).norm(), 0.0, 1e-15);
    }
}

}  // namespace
}  // namespace gsph::preproc
