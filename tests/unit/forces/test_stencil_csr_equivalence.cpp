// SPDX-License-Identifier: MIT
// The stencil kernels and the CSR pair list evaluate the same formulas: a wavy (curved) block of
// Johnson–Cook steel with viscosity and hourglass control (either modulus), every particle forced
// onto the CSR path, gives the state of the stencil run to round-off after 30 steps of a shear and
// compression (x, v, F, σ, ε̄p, the ledger and the plastic work). The sums run in another order, so
// the states are not bitwise equal; measured, relative to each field's largest value: x 5.4e-16,
// v 1.9e-13, F 7.2e-15, ε̄p 6.9e-14, σ 9.6e-12 (the radial return of a 3 % plastic flow amplifies
// the round-off of the trial stress).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "reference/reference_builder.hpp"
#include "simulation.hpp"
#include "spaces/analytic_maps.hpp"
#include "support/johnson_cook_materials.hpp"

namespace gsph {
namespace {

State run(bool forceCsr, HourglassModulus modulus) {
    Reference ref =
        latticeReference(wavyBoxMap(Vec3(0.02, 0.015, 0.01), 0.05), 3, {12, 9, 6}, 7850.0, 1.2);
    completeReference(ref);
    if (forceCsr) ref.oversetCoupled.assign(ref.X.size(), 1);  // every particle takes CSR
    SolverOptions options;
    options.viscosity = {0.05, 1.0};
    options.hourglass = 0.1;
    options.hourglassModulus = modulus;
    JohnsonCookParams soft = testing::weldoxParams();  // yields within the 30 steps
    soft.yieldStress = 1e6;
    soft.hardeningModulus = 50e6;
    Simulation sim(std::move(ref), {testing::withLinearEos(testing::kWeldoxElastic, soft)},
                   options);
    sim.setVelocity([](const Vec3& X) {
        return Vec3(400.0 * X[1] - 300.0 * X[0], 150.0 * std::sin(200.0 * X[2]), -500.0 * X[2]);
    });
    for (int s = 0; s < 30; ++s) sim.step();
    return sim.state();
}

template <class T>
double worstRelative(const std::vector<T>& a, const std::vector<T>& b) {
    double worst = 0.0, scale = 0.0;
    for (std::size_t i = 0; i < a.size(); ++i) {
        if constexpr (std::is_same_v<T, double>) {
            worst = std::max(worst, std::abs(a[i] - b[i]));
            scale = std::max(scale, std::abs(a[i]));
        } else {
            worst = std::max(worst, (a[i] - b[i]).norm());
            scale = std::max(scale, a[i].norm());
        }
    }
    return scale > 0.0 ? worst / scale : worst;
}

class StencilCsrEquivalence : public ::testing::TestWithParam<HourglassModulus> {};

TEST_P(StencilCsrEquivalence, TheWholeStepAgreesToRoundOff) {
    const State stencil = run(false, GetParam()), csr = run(true, GetParam());
    ASSERT_EQ(stencil.step, csr.step);
    const double dx = worstRelative(stencil.x, csr.x), dv = worstRelative(stencil.v, csr.v),
                 dF = worstRelative(stencil.F, csr.F),
                 ds = worstRelative(stencil.cauchy, csr.cauchy),
                 dp = worstRelative(stencil.plasticStrain, csr.plasticStrain);
    std::printf("[stencil/csr] x %.1e v %.1e F %.1e σ %.1e ε̄p %.1e; ε̄p max %.3e\n", dx, dv, dF, ds,
                dp, *std::max_element(stencil.plasticStrain.begin(), stencil.plasticStrain.end()));
    EXPECT_GT(*std::max_element(stencil.plasticStrain.begin(), stencil.plasticStrain.end()), 0.0)
        << "the block must yield, so the plastic update is compared too";
    EXPECT_LT(dx, 1e-15);
    EXPECT_LT(dv, 4e-13);
    EXPECT_LT(dF, 1e-14);
    EXPECT_LT(dp, 2e-13);
    EXPECT_LT(ds, 2e-11);
    EXPECT_NEAR(stencil.ledger.viscousWork, csr.ledger.viscousWork,
                1e-12 * std::abs(stencil.ledger.viscousWork));
    const auto plasticWork = [](const State& s) {
        return std::accumulate(s.plasticWork.begin(), s.plasticWork.end(), 0.0);
    };
    EXPECT_NEAR(plasticWork(stencil), plasticWork(csr), 1e-12 * std::abs(plasticWork(stencil)));
}

// Both moduli of the hourglass penalty: with the secant one the yielded particles' pairs carry
// ½(s_a + s_b) on both paths.
INSTANTIATE_TEST_SUITE_P(HourglassModulus, StencilCsrEquivalence,
                         ::testing::Values(HourglassModulus::Elastic, HourglassModulus::Secant),
                         [](const auto& param) {
                             return param.param == HourglassModulus::Secant ? "Secant" : "Elastic";
                         });

}  // namespace
}  // namespace gsph
