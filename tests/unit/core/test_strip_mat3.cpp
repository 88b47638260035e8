// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cstring>
#include <random>

#include "core/strip_mat3.hpp"
#include "materials/hypoelastic.hpp"

namespace gsph {
namespace {

Mat3 randomMatrix(std::mt19937_64& rng) {
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    Mat3 m;
    for (int i = 0; i < 9; ++i) m.data()[i] = u(rng) * std::exp(3.0 * u(rng));
    return m;
}

double relativeError(const Mat3& a, const Mat3& b) {
    return (a - b).norm() / b.norm();
}

// The operations against Eigen's: the same values to round-off (their sums are ordered
// differently), the cofactor matrix exactly (the same products and differences).
TEST(StripMat3, OperationsAreEigensToRoundOff) {
    std::mt19937_64 rng(7);
    double worstProduct = 0.0, worstInverse = 0.0, worstDeterminant = 0.0;
    for (int t = 0; t < 1000; ++t) {
        const Mat3 A = randomMatrix(rng), B = randomMatrix(rng);
        const StripMat3<double> a = stripOf(A), b = stripOf(B);
        worstProduct = std::max(worstProduct, relativeError(eigenOf(a * b), A * B));
        worstInverse =
            std::max(worstInverse, relativeError(eigenOf(inverse(a) * a), Mat3::Identity()));
        worstDeterminant = std::max(
            worstDeterminant,
            std::abs(determinant(a) - A.determinant()) /
                (A.cwiseAbs().maxCoeff() * A.cwiseAbs().maxCoeff() * A.cwiseAbs().maxCoeff()));
        Mat3 C;
        C.col(0) = A.col(1).cross(A.col(2));
        C.col(1) = A.col(2).cross(A.col(0));
        C.col(2) = A.col(0).cross(A.col(1));
        EXPECT_EQ(std::memcmp(eigenOf(cofactor(a)).data(), C.data(), sizeof(Mat3)), 0);
    }
    EXPECT_LT(worstProduct, 5e-16);
    EXPECT_LT(worstDeterminant, 1e-16);
    // inverse(a) a = I to the matrix's conditioning (random matrices, some near singular).
    EXPECT_LT(worstInverse, 1e-11);
}

// Each lane of a strip gets exactly the bits the same operations give one particle as double:
// the Jaumann update of the hypo-elastic model and the inverse, lane by lane against double.
TEST(StripMat3, EveryLaneHasTheBitsOfDouble) {
    std::mt19937_64 rng(11);
    const ElasticConstants steel(7850.0, 2.0e11, 0.3);
    Mat3 sigma[8], D[8], W[8];
    for (int j = 0; j < 8; ++j) {
        sigma[j] = 1e8 * randomMatrix(rng);
        sigma[j] = 0.5 * (sigma[j] + sigma[j].transpose()).eval();
        const Mat3 L = 1e3 * randomMatrix(rng);
        D[j] = 0.5 * (L + L.transpose());
        W[j] = 0.5 * (L - L.transpose());
    }
    const Mat3* ps[8] = {&sigma[0], &sigma[1], &sigma[2], &sigma[3],
                         &sigma[4], &sigma[5], &sigma[6], &sigma[7]};
    const Mat3* pd[8] = {&D[0], &D[1], &D[2], &D[3], &D[4], &D[5], &D[6], &D[7]};
    const Mat3* pw[8] = {&W[0], &W[1], &W[2], &W[3], &W[4], &W[5], &W[6], &W[7]};
    const double dt = 1e-7;
    const StripMat3<Lanes8> next8 = jaumannElasticUpdate(
        steel, lanesOf<Lanes8>(ps), lanesOf<Lanes8>(pd), lanesOf<Lanes8>(pw), dt);
    const StripMat3<Lanes2> next2 = jaumannElasticUpdate(
        steel, lanesOf<Lanes2>(ps), lanesOf<Lanes2>(pd), lanesOf<Lanes2>(pw), dt);
    const StripMat3<Lanes8> inv8 = inverse(lanesOf<Lanes8>(pd));
    for (int j = 0; j < 8; ++j) {
        const Mat3 one = jaumannElasticUpdate(steel, sigma[j], D[j], W[j], dt);
        EXPECT_EQ(std::memcmp(laneOf(next8, j).data(), one.data(), sizeof(Mat3)), 0) << j;
        if (j < 2) {
            EXPECT_EQ(std::memcmp(laneOf(next2, j).data(), one.data(), sizeof(Mat3)), 0);
        }
        const Mat3 inv = eigenOf(inverse(stripOf(D[j])));
        EXPECT_EQ(std::memcmp(laneOf(inv8, j).data(), inv.data(), sizeof(Mat3)), 0) << j;
    }
    // The rotation is orthogonal to round-off.
    const Mat3 R = jaumannRotation(W[0], dt * 1e3);
    EXPECT_LT((R * R.transpose() - Mat3::Identity()).norm(), 1e-15);
}

}  // namespace
}  // namespace gsph
