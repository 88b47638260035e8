// SPDX-License-Identifier: MIT
// The artificial viscosity's pair pressure and its compression switch
// (forces/artificial_viscosity.hpp), against their closed forms.
#include <gtest/gtest.h>

#include <cmath>

#include "forces/artificial_viscosity.hpp"

namespace gsph {
namespace {

TEST(ArtificialViscosity, SwitchIsHalfOnAtM0AndOffWithoutCompression) {
    const ViscosityCoefficients c{1.0, 1.0, 0.01};
    const double h = 1e-3, sound = 5000.0;
    // M = h (−tr D)/c = M0 at tr D = −M0 c/h.
    EXPECT_DOUBLE_EQ(viscositySwitch(c, h, -0.01 * sound / h, sound), 0.5);
    EXPECT_DOUBLE_EQ(viscositySwitch(c, h, -0.03 * sound / h, sound), 0.9);  // 9/(9 + 1)
    EXPECT_EQ(viscositySwitch(c, h, 0.0, sound), 0.0) << "isochoric flow, shear";
    EXPECT_EQ(viscositySwitch(c, h, 1e5, sound), 0.0) << "expansion";
    EXPECT_EQ(viscositySwitch({1.0, 1.0, 0.0}, h, 0.0, sound), 1.0) << "switch off: constant";
    EXPECT_EQ(viscositySwitch({1.0, 1.0, 0.0}, h, -1e5, sound), 1.0);
}

TEST(ArtificialViscosity, PairPressureIsMonaghansScaledByTheSwitch) {
    const ViscosityCoefficients c{0.7, 1.3, 0.01};
    const double h = 2e-3, sound = 4000.0, rho = 8000.0, x2 = h * h;
    const double vx = -50.0 * h;  // approaching at 50 m/s along the pair
    const double phi = h * vx / (x2 + 0.01 * h * h);
    const double monaghan = rho * (-c.linear * sound * phi + c.quadratic * phi * phi);
    EXPECT_DOUBLE_EQ(viscousPairPressure(c, vx, x2, h, sound, rho, 1.0), monaghan);
    EXPECT_DOUBLE_EQ(viscousPairPressure(c, vx, x2, h, sound, rho, 0.25), 0.25 * monaghan);
    EXPECT_GT(monaghan, 0.0) << "an approaching pair is pushed apart";
    EXPECT_EQ(viscousPairPressure(c, -vx, x2, h, sound, rho, 1.0), 0.0) << "separating pair";
}

}  // namespace
}  // namespace gsph
