// SPDX-License-Identifier: MIT
// Linear hardening (materials/linear_hardening.hpp), a strength model composed into a plastic
// solid with an equation of state and an optional damage model, at one material point against
// closed forms: the flow curve σ = σ0 + H ε̄p in uniaxial stress and its slope EH/(E + H)
// against the total strain, heating by χ times the plastic work, failure where Johnson–Cook
// damage with a constant failure strain says, and the checks of its constants.
#include <gtest/gtest.h>

#include <cmath>

#include "core/error.hpp"
#include "materials/material_point_driver.hpp"

namespace gsph {
namespace {

const ElasticConstants kSteel(7850.0, 200e9, 0.3);

LinearHardeningParams steelParams() {
    LinearHardeningParams p;
    p.yieldStress = 300e6;
    p.hardeningModulus = 2e9;
    return p;
}

LinearHardening steel(const LinearHardeningParams& p,
                      std::optional<JohnsonCookDamage> damage = std::nullopt) {
    return LinearHardening(kSteel, p, EquationOfState::linear(kSteel.density, kSteel.bulkModulus()),
                           damage);
}

LoadingPath tension(double strain, int steps) {
    LoadingPath path;
    path.kind = LoadingPath::Kind::UniaxialStress;
    path.strainRate = 1e3;
    path.finalStrain = strain;
    path.steps = steps;
    return path;
}

// Isothermal uniaxial tension to ε = 0.2 in 4000 increments: past yield, σ_xx = σ0 + H ε̄p at
// the start of each increment (the return uses ε̄p of t_n, so the end-of-increment ε̄p is
// ahead by one Δε̄p), and the total log strain splits into σ/E + ε̄p, so σ_xx follows the line
// of slope EH/(E + H) from the yield point.
TEST(LinearHardening, UniaxialFlowCurveIsTheBilinearLine) {
    const LinearHardeningParams p = steelParams();
    const Material m = steel(p);
    const auto rows = driveMaterialPoint(m, tension(0.2, 4000));
    const double E = kSteel.youngsModulus, H = p.hardeningModulus;
    double worstFlow = 0.0, worstLine = 0.0;
    int plastic = 0;
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const MaterialPointRecord& r = rows[i];
        if (rows[i - 1].plasticStrain <= 0.0) continue;
        const double flow = p.yieldStress + H * rows[i - 1].plasticStrain;
        worstFlow = std::max(worstFlow, std::abs(r.cauchy(0, 0) / flow - 1.0));
        const double line = (p.yieldStress + H * r.strain) * E / (E + H);
        worstLine = std::max(worstLine, std::abs(r.cauchy(0, 0) / line - 1.0));
        EXPECT_EQ(r.temperature, 293.15) << "isothermal by default";
        ++plastic;
    }
    std::printf(
        "[linear hardening] %d plastic increments: σ against σ0 + H ε̄p %.2e, against "
        "(σ0 + Hε) E/(E + H) %.2e; final σ %.4e Pa at ε̄p %.4f\n",
        plastic, worstFlow, worstLine, rows.back().cauchy(0, 0), rows.back().plasticStrain);
    EXPECT_GT(plastic, 3900);
    EXPECT_LT(worstFlow, 1e-9);  // measured 5.5e-10: the lateral iteration's tolerance
    EXPECT_LT(worstLine, 5e-4);  // measured 3.3e-4
}

// With χ > 0 the point heats by χ Δw_p/(ρ Cp): T − Tr = χ w_p/Cp for the accumulated plastic
// work per mass, and w_p ρ0 = ∫σ dε̄p = σ0 ε̄p + ½ H ε̄p² to the density's change.
TEST(LinearHardening, HeatingFollowsThePlasticWork) {
    LinearHardeningParams p = steelParams();
    p.taylorQuinney = 0.9;
    p.specificHeat = 470.0;
    const auto rows = driveMaterialPoint(steel(p), tension(0.2, 4000));
    const MaterialPointRecord& last = rows.back();
    const double eps = last.plasticStrain;
    const double work =
        (p.yieldStress * eps + 0.5 * p.hardeningModulus * eps * eps) / kSteel.density;
    std::printf("[linear hardening] heating %.3f K; plastic work %.6e J/kg, closed form %.6e\n",
                last.temperature - 293.15, last.plasticWork, work);
    EXPECT_NEAR(last.temperature - 293.15, 0.9 * last.plasticWork / 470.0,
                1e-12 * last.temperature);
    EXPECT_NEAR(last.plasticWork / work, 1.0, 2e-3);  // measured 8.5e-4
}

// Composed with Johnson–Cook damage of a constant failure strain (D1 = 0.1, the rest 0): the
// point fails (D = 1: no deviatoric stress, no tension) once ε̄p reaches 0.1.
TEST(LinearHardening, ComposedDamageFailsThePointAtItsFailureStrain) {
    const Material m = steel(steelParams(), JohnsonCookDamage{{0.1, 0.0, 0.0, 0.0, 0.0}});
    const auto rows = driveMaterialPoint(m, tension(0.2, 4000));
    std::size_t failed = 0;
    while (failed < rows.size() && rows[failed].damage < 1.0) ++failed;
    ASSERT_LT(failed, rows.size()) << "the point failed";
    const double step = rows[failed].plasticStrain - rows[failed - 1].plasticStrain;
    EXPECT_GE(rows[failed].plasticStrain, 0.1);
    EXPECT_LE(rows[failed].plasticStrain, 0.1 + step);
    EXPECT_NEAR(rows[failed - 1].damage, rows[failed - 1].plasticStrain / 0.1, 1e-12);
    EXPECT_EQ(rows.back().cauchy(0, 0), 0.0) << "a failed point carries no tension";
}

TEST(LinearHardening, RejectsBadConstants) {
    const EquationOfState eos = EquationOfState::linear(kSteel.density, kSteel.bulkModulus());
    LinearHardeningParams p = steelParams();
    p.hardeningModulus = -1.0;
    EXPECT_THROW(LinearHardening(kSteel, p, eos), InputError);
    p = steelParams();
    p.taylorQuinney = 0.9;  // heating without a specific heat
    EXPECT_THROW(LinearHardening(kSteel, p, eos), InputError);
    p.specificHeat = 470.0;
    EXPECT_NO_THROW(LinearHardening(kSteel, p, eos));
    p.taylorQuinney = 1.5;
    EXPECT_THROW(LinearHardening(kSteel, p, eos), InputError);
}

}  // namespace
}  // namespace gsph
