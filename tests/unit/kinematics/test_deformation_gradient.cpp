// SPDX-License-Identifier: MIT
// F from the corrected θ-gradients (kinematics/deformation_gradient.hpp) on a curved (wavy)
// lattice: an affine motion x = A X + c gives F = A at every particle, boundary ones included
// (DESIGN §3, the correction's first-order completeness); cof F = J F^{-T} exactly.
#include <gtest/gtest.h>

#include <Eigen/LU>

#include "kinematics/deformation_gradient.hpp"
#include "reference/reference_builder.hpp"
#include "spaces/analytic_maps.hpp"

namespace gsph {
namespace {

TEST(DeformationGradient, AffineMotionGivesFExactlyOnACurvedLattice) {
    Reference ref =
        latticeReference(wavyBoxMap(Vec3(0.03, 0.02, 0.01), 0.08), 3, {9, 7, 5}, 7850.0, 1.2);
    completeReference(ref);
    Mat3 A;
    A << 1.2, 0.3, -0.1, -0.2, 0.9, 0.25, 0.05, -0.15, 1.1;
    const Vec3 c(0.4, -0.1, 2.0);
    std::vector<Vec3> x(ref.X.size());
    for (std::size_t a = 0; a < x.size(); ++a) x[a] = A * ref.X[a] + c;
    std::vector<Mat3> F;
    deformationGradient(ref, x, F);
    double worst = 0.0;
    for (const Mat3& Fa : F) worst = std::max(worst, (Fa - A).cwiseAbs().maxCoeff());
    std::printf("[kinematics] affine F on a wavy lattice: worst entry error %.2e\n", worst);
    EXPECT_LT(worst, 1e-12);  // measured 5.1e-13 (round-off of the translated positions)
}

TEST(DeformationGradient, CofactorIsJTimesTheInverseTranspose) {
    Mat3 F;
    F << 1.2, 0.3, -0.1, -0.2, 0.9, 0.25, 0.05, -0.15, 1.1;
    const Mat3 expected = F.determinant() * F.inverse().transpose();
    EXPECT_LT((cofactor(F) - expected).cwiseAbs().maxCoeff(), 1e-15);
    EXPECT_NEAR(F.col(0).dot(cofactor(F).col(0)), F.determinant(), 1e-15);
}

}  // namespace
}  // namespace gsph
