// SPDX-License-Identifier: MIT
#include <gtest/gtest.h>

#include <cmath>

#include "kernel/cubic_bspline.hpp"

namespace gsph {
namespace {

// ∫W dV = 1: midpoint rule on a fine grid over the support (error ~1e-6 at this spacing).
double integrate(const CubicBSpline& W, int dim, double step) {
    const double R = W.supportRadius();
    const int n = static_cast<int>(std::ceil(R / step));
    double sum = 0.0;
    for (int i = -n; i < n; ++i)
        for (int j = -n; j < n; ++j)
            for (int k = (dim == 3 ? -n : 0); k < (dim == 3 ? n : 1); ++k) {
                const Vec3 r((i + 0.5) * step, (j + 0.5) * step, dim == 3 ? (k + 0.5) * step : 0.0);
                sum += W.value(r.norm());
            }
    return sum * std::pow(step, dim);
}

TEST(CubicBSpline, NormalisedIn2DAnd3D) {
    EXPECT_NEAR(integrate(CubicBSpline(2, 0.7), 2, 0.005), 1.0, 1e-4);
    EXPECT_NEAR(integrate(CubicBSpline(3, 1.3), 3, 0.02), 1.0, 1e-3);
}

TEST(CubicBSpline, CompactSupportAndContinuity) {
    const CubicBSpline W(3, 1.0);
    EXPECT_EQ(W.value(2.0), 0.0);
    EXPECT_EQ(W.derivative(2.5), 0.0);
    // C¹ at q = 1: value and slope agree from both sides.
    EXPECT_NEAR(W.value(1.0 - 1e-9), W.value(1.0 + 1e-9), 1e-8);
    EXPECT_NEAR(W.derivative(1.0 - 1e-9), W.derivative(1.0 + 1e-9), 1e-8);
}

TEST(CubicBSpline, DerivativeMatchesFiniteDifference) {
    const CubicBSpline W(2, 0.9);
    for (double r : {0.1, 0.5, 0.95, 1.2, 1.7}) {
        const double fd = (W.value(r + 1e-6) - W.value(r - 1e-6)) / 2e-6;
        EXPECT_NEAR(W.derivative(r), fd, 1e-7) << "r = " << r;
    }
    const Vec3 r(0.3, -0.4, 0.5);
    const Vec3 g = W.gradient(r);
    EXPECT_NEAR(g.normalized().dot(r.normalized()), -1.0, 1e-12);  // points towards the centre
}

}  // namespace
}  // namespace gsph
