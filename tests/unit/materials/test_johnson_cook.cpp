// SPDX-License-Identifier: MIT
// Johnson–Cook plasticity, damage and the equations of state at one material point, against
// closed forms: elastic slopes, the flow curve at three strain rates and two
// temperatures, adiabatic heating, damage at failure for a constant triaxiality, objectivity.
// The points are driven by the material-point driver (materials/material_point_driver.hpp),
// which takes the solver's own update path.
#include <gtest/gtest.h>

#include <Eigen/LU>

#include <cmath>

#include "core/error.hpp"
#include "materials/material_point_driver.hpp"
#include "support/johnson_cook_materials.hpp"

namespace gsph {
namespace {

using testing::copperParams;
using testing::weldoxDamage;
const ElasticConstants& kCopper = testing::kCopperElastic;

JohnsonCook copper(double chi, std::optional<JohnsonCookDamage> damage = {}) {
    return testing::withLinearEos(kCopper, copperParams(chi), damage);
}

LoadingPath compact(LoadingPath::Kind kind, double rate, double strain, int steps,
                    std::optional<double> T = {}) {
    LoadingPath path;
    path.kind = kind;
    path.strainRate = rate;
    path.finalStrain = strain;
    path.steps = steps;
    path.temperature = T;
    return path;
}

double vonMises(const Mat3& s) {
    const Mat3 dev = s - (s.trace() / 3.0) * Mat3::Identity();
    return std::sqrt(1.5 * dev.squaredNorm());
}

// Closed form of the flow stress in uniaxial stress (JC 1983, log rate form).
double closedForm(double eps, double rate, double T) {
    const double Tstar = (T - 293.15) / (1356.0 - 293.15);
    return (90e6 + 292e6 * std::pow(eps, 0.31)) * (1.0 + 0.025 * std::log(std::max(rate, 1.0))) *
           (1.0 - std::pow(Tstar, 1.09));
}

TEST(JohnsonCook, ElasticSlopesBelowYield) {
    // A yield stress far above the load keeps the point elastic: uniaxial stress gives E,
    // uniaxial strain K + 4G/3, simple shear G (small strain 1e-5, tolerance 1e-3). The linear
    // equation of state takes K from E and ν here, so the slopes are those of (E, ν).
    JohnsonCookParams p = copperParams(0.0);
    p.yieldStress = 1e12;
    const Material m =
        JohnsonCook(kCopper, p, EquationOfState::linear(8960.0, kCopper.bulkModulus()));
    const double eps = 1e-5, G = kCopper.shearModulus();
    using Kind = LoadingPath::Kind;
    const auto stress = driveMaterialPoint(m, compact(Kind::UniaxialStress, 1.0, eps, 20));
    EXPECT_NEAR(stress.back().cauchy(0, 0) / (kCopper.youngsModulus * eps), 1.0, 1e-3);
    EXPECT_NEAR(stress.back().cauchy(1, 1) / stress.back().cauchy(0, 0), 0.0, 1e-8);
    EXPECT_NEAR(stress.back().F(1, 1) - 1.0, -kCopper.poissonRatio * eps, 1e-3 * eps);
    const auto strain = driveMaterialPoint(m, compact(Kind::UniaxialStrain, 1.0, eps, 20));
    EXPECT_NEAR(strain.back().cauchy(0, 0) / (kCopper.pWaveModulus() * eps), 1.0, 1e-3);
    const auto shear = driveMaterialPoint(m, compact(Kind::SimpleShear, 1.0, eps, 20));
    EXPECT_NEAR(shear.back().cauchy(0, 1) / (G * eps), 1.0, 1e-3);
    EXPECT_EQ(shear.back().plasticStrain, 0.0);
}

TEST(JohnsonCook, FlowCurveMatchesTheClosedFormAtThreeRatesAndTwoTemperatures) {
    // Isothermal (χ = 0) uniaxial tension to ε = 0.5: σ_xx against the closed form at the
    // point's own ε̄p, from ε̄p = 0.02 on (the elastic-plastic transition is not a closed form).
    const Material m = copper(0.0);
    double worst = 0.0;
    for (const double rate : {1.0, 1e2, 1e4})
        for (const double T : {293.15, 600.0}) {
            const auto rows = driveMaterialPoint(
                m, compact(LoadingPath::Kind::UniaxialStress, rate, 0.5, 5000, T));
            int checked = 0;
            for (const MaterialPointRecord& r : rows) {
                if (r.plasticStrain < 0.02) continue;
                const double expected = closedForm(r.plasticStrain, rate, T);
                worst = std::max(worst, std::abs(r.cauchy(0, 0) / expected - 1.0));
                EXPECT_NEAR(r.cauchy(0, 0) / expected, 1.0, 0.005)
                    << "rate " << rate << ", T " << T << ", ε̄p " << r.plasticStrain;
                EXPECT_NEAR(r.temperature, T, 1e-12);
                ++checked;
            }
            EXPECT_GT(checked, 4000);
        }
    std::printf("[johnson-cook] flow curve: worst relative error %.2e (3 rates × 2 temperatures)\n",
                worst);
}

TEST(JohnsonCook, PowerRateFormAndRateBelowTheReference) {
    JohnsonCookParams p = copperParams(0.0);
    const JohnsonCook logForm(kCopper, p, EquationOfState::linear(8960.0, 129e9));
    EXPECT_NEAR(logForm.flowStress(0.0, 0.01, 293.15), 90e6, 1e-6) << "ε̇* < 1: no rate effect";
    EXPECT_NEAR(logForm.flowStress(0.0, 100.0, 293.15), 90e6 * (1 + 0.025 * std::log(100.0)), 1e-6);
    p.rateForm = StrainRateForm::Power;
    const JohnsonCook powerForm(kCopper, p, EquationOfState::linear(8960.0, 129e9));
    EXPECT_NEAR(powerForm.flowStress(0.0, 100.0, 293.15), 90e6 * std::pow(101.0, 0.025), 1e-6);
    EXPECT_NEAR(powerForm.flowStress(0.1, 0.0, 1356.0), 0.0, 1e-9) << "no strength at Tm";
    EXPECT_NEAR(powerForm.flowStress(0.0, 0.0, 200.0), 90e6, 1e-6) << "T* clamped at 0";
}

TEST(JohnsonCook, AdiabaticHeatingFollowsThePlasticWork) {
    // χ = 0.9, uniaxial tension at 1e3/s to ε = 0.6. (1) T − T0 = χ ∫ σ_eq dε̄p/(ρ Cp), the
    // integral taken by the trapezoidal rule over the output; (2) an independent solution of
    // the coupled ODE dT/dε̄p = χ σy(ε̄p, T)/(ρ0 Cp) (RK4) gives the same T and σ.
    const double rate = 1e3, chi = 0.9;
    const Material m = copper(chi);
    const auto rows =
        driveMaterialPoint(m, compact(LoadingPath::Kind::UniaxialStress, rate, 0.6, 6000));
    double work = 0.0;  // ∫ σ_eq dε̄p/ρ [J/kg]
    for (std::size_t i = 1; i < rows.size(); ++i) {
        const double rho0 = 8960.0 / rows[i - 1].F.determinant();
        const double rho1 = 8960.0 / rows[i].F.determinant();
        work += 0.5 * (vonMises(rows[i - 1].cauchy) / rho0 + vonMises(rows[i].cauchy) / rho1) *
                (rows[i].plasticStrain - rows[i - 1].plasticStrain);
    }
    const MaterialPointRecord& last = rows.back();
    const double rise = last.temperature - 293.15;
    EXPECT_GT(rise, 50.0);
    EXPECT_NEAR(rise / (chi * work / 383.0), 1.0, 0.005);
    EXPECT_NEAR(last.plasticWork / work, 1.0, 0.005);

    // RK4 in ε̄p of dT/dε = χ σy(ε, T)/(ρ0 Cp), σy at this rate.
    const auto dTde = [&](double e, double T) {
        return chi * closedForm(e, rate, T) / (8960 * 383);
    };
    double T = 293.15, e = 0.0;
    const int n = 20000;
    const double h = last.plasticStrain / n;
    for (int i = 0; i < n; ++i, e += h) {
        const double k1 = dTde(e, T), k2 = dTde(e + h / 2, T + h / 2 * k1);
        const double k3 = dTde(e + h / 2, T + h / 2 * k2), k4 = dTde(e + h, T + h * k3);
        T += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
    }
    EXPECT_NEAR((last.temperature - 293.15) / (T - 293.15), 1.0, 0.005);
    EXPECT_NEAR(last.cauchy(0, 0) / closedForm(last.plasticStrain, rate, T), 1.0, 0.005);
    std::printf("[johnson-cook] adiabatic: ΔT %.2f K, χ∫σdε̄p/(ρCp) %.2f K, ODE %.2f K\n", rise,
                chi * work / 383.0, T - 293.15);
}

TEST(JohnsonCook, DamageReachesOneWhereTheFailureStrainSays) {
    // Uniaxial tension: σ* = 1/3 throughout, isothermal, constant rate ⇒ εf is a constant and
    // the point fails at ε̄p = εf. After failure it carries no stress in tension.
    const double rate = 10.0;
    const Material m = copper(0.0, weldoxDamage(0.0));
    const auto rows =
        driveMaterialPoint(m, compact(LoadingPath::Kind::UniaxialStress, rate, 1.6, 16000));
    const double ef = (0.0705 + 1.732 * std::exp(-0.54 / 3.0)) * std::pow(1.0 + rate, -0.015);
    double failedAt = -1.0;
    for (const MaterialPointRecord& r : rows) {
        if (r.damage >= 1.0 && failedAt < 0.0) failedAt = r.plasticStrain;
        if (r.damage > 0.0 && r.damage < 1.0) {
            EXPECT_NEAR(r.damage, r.plasticStrain / ef, 1e-3) << "D = ε̄p/εf";
            const Mat3& s = r.cauchy;
            EXPECT_NEAR(s.trace() / 3.0 / vonMises(s), 1.0 / 3.0, 1e-6) << "σ* = 1/3";
        }
    }
    ASSERT_GT(failedAt, 0.0);
    EXPECT_NEAR(failedAt / ef, 1.0, 0.005);
    EXPECT_NEAR(rows.back().cauchy.norm(), 0.0, 1e-6) << "failed: no stress in tension";
    std::printf("[johnson-cook] damage: failed at ε̄p = %.4f, εf = %.4f\n", failedAt, ef);
}

// The size regularization (damage_size = L0): a particle of size h fails at εf L0/h. Points
// driven alike by an isochoric stretch: one of size L0 fails where one without a size does (to
// the bit), one of size L0/2 at twice that plastic strain (to the step's increment).
TEST(JohnsonCook, SizeRegularizedDamageFailsAtTheScaledStrain) {
    JohnsonCookDamage damage = weldoxDamage(0.0);
    damage.referenceSize = 1e-3;
    const JohnsonCook model = copper(0.0, damage);
    const double rate = 100.0, dt = 1e-6;  // Δε̄p ≈ 1e-4 per step
    const Mat3 D = rate * Vec3(1.0, -0.5, -0.5).asDiagonal().toDenseMatrix();
    const auto failedAt = [&](double size) {
        MaterialPoint p;
        p.density = kCopper.density;
        p.size = size;
        for (int i = 0; i < 100000; ++i) {
            model.update(p, D, Mat3::Zero(), dt);
            if (p.damage >= 1.0) return p.plasticStrain;
        }
        return -1.0;
    };
    const double plain = failedAt(0.0), atL0 = failedAt(1e-3), half = failedAt(0.5e-3);
    std::printf(
        "[johnson-cook] size-regularized damage: fails at ε̄p = %.5f (no size), %.5f "
        "(h = L0), %.5f (h = L0/2: ratio %.5f)\n",
        plain, atL0, half, half / atL0);
    ASSERT_GT(plain, 0.0);
    EXPECT_EQ(atL0, plain);
    EXPECT_NEAR(half / atL0, 2.0, 2e-4);
}

TEST(JohnsonCook, DamageWithHeatingMatchesTheIntegralOfTheFailureStrain) {
    // With adiabatic heating and D5 ≠ 0, εf changes along the path: D = ∫ dε̄p/εf(T), the
    // integral taken by the trapezoidal rule over the output rows.
    const double rate = 1e3;
    const double d5 = 1.12;
    const JohnsonCook model = copper(0.9, weldoxDamage(d5));
    const auto rows =
        driveMaterialPoint(model, compact(LoadingPath::Kind::UniaxialStress, rate, 1.6, 16000));
    const auto ef = [&](double T) {
        return (0.0705 + 1.732 * std::exp(-0.54 / 3.0)) * std::pow(1.0 + rate, -0.015) *
               (1.0 + d5 * model.strength().homologousTemperature(T));
    };
    double integral = 0.0;
    bool failed = false;
    for (std::size_t i = 1; i < rows.size() && !failed; ++i) {
        integral += 0.5 * (1 / ef(rows[i - 1].temperature) + 1 / ef(rows[i].temperature)) *
                    (rows[i].plasticStrain - rows[i - 1].plasticStrain);
        if (rows[i].damage < 1.0) {
            EXPECT_NEAR(rows[i].damage, integral, 0.005 * integral + 1e-9);
        } else {
            failed = true;
            EXPECT_NEAR(integral, 1.0, 0.005) << "fails when ∫dε̄p/εf reaches 1";
            std::printf(
                "[johnson-cook] heated damage: failed at ε̄p = %.4f, T = %.0f K, "
                "∫dε̄p/εf = %.4f\n",
                rows[i].plasticStrain, rows[i].temperature, integral);
        }
    }
    EXPECT_TRUE(failed);
}

TEST(JohnsonCook, RigidRotationOfAStressedPlasticPointKeepsItsInvariants) {
    // Stretch into the plastic range (uniaxial strain 2 %), unload by 1e-4 (inside the yield
    // surface of the rate-free flow stress, which applies once the point stops straining), then
    // spin the deformed point a quarter turn about z: every F on the way is R(θ)U with an exact
    // rotation, one increment between rows. The invariants of σ and ε̄p must not change (1e-10).
    const Material m = copper(0.9, weldoxDamage(0.0));
    LoadingPath path;
    path.kind = LoadingPath::Kind::DeformationGradient;
    path.substeps = 1;
    const int stretchRows = 200, spinRows = 2000;
    for (int i = 0; i <= stretchRows; ++i) {
        path.times.push_back(1e-5 * i);
        Mat3 F = Mat3::Identity();
        F(0, 0) = 1.0 + 0.02 * i / stretchRows;
        path.F.push_back(F);
    }
    for (int i = 1; i <= 20; ++i) {
        Mat3 F = Mat3::Identity();
        F(0, 0) = 1.02 - 1e-4 * i / 20;
        path.times.push_back(path.times.back() + 1e-5);
        path.F.push_back(F);
    }
    const Mat3 U = path.F.back();
    for (int i = 1; i <= spinRows; ++i) {
        const double angle = 0.5 * std::acos(-1.0) * i / spinRows;
        Mat3 R = Mat3::Identity();
        R(0, 0) = R(1, 1) = std::cos(angle);
        R(1, 0) = std::sin(angle);
        R(0, 1) = -std::sin(angle);
        path.times.push_back(path.times.back() + 1e-5);
        path.F.push_back(R * U);
    }
    const auto rows = driveMaterialPoint(m, path);
    const MaterialPointRecord& before = rows[stretchRows + 20];
    const MaterialPointRecord& after = rows.back();
    ASSERT_GT(before.plasticStrain, 0.01);
    const Mat3& s0 = before.cauchy;
    const Mat3& s1 = after.cauchy;
    EXPECT_NEAR(s1.trace() / s0.trace(), 1.0, 1e-10);
    EXPECT_NEAR(s1.norm() / s0.norm(), 1.0, 1e-10);
    EXPECT_NEAR(s1.determinant() / s0.determinant(), 1.0, 1e-10);
    EXPECT_NEAR(after.plasticStrain, before.plasticStrain, 1e-10 * before.plasticStrain);
    std::printf("[johnson-cook] quarter turn: |Δ tr σ|/|tr σ| %.1e, |Δ|σ||/|σ| %.1e, Δε̄p %.1e\n",
                std::abs(s1.trace() / s0.trace() - 1), std::abs(s1.norm() / s0.norm() - 1),
                after.plasticStrain - before.plasticStrain);
    // The stress turned with the body: σ_yy now holds what σ_xx held.
    EXPECT_NEAR(s1(1, 1) / s0(0, 0), 1.0, 1e-6);
}

TEST(EquationOfState, LinearAndMieGruneisenClosedForms) {
    const double rho0 = 8960.0;
    const EquationOfState lin = EquationOfState::linear(rho0, 130e9);
    double e = 0.0;
    EXPECT_NEAR(lin.advance(rho0 * 1.01, 0.0, 0.0, 0.0, false, e), 130e9 * std::log(1.01), 1e-3);
    EXPECT_EQ(lin.advance(rho0 / 1.01, 0.0, 0.0, 0.0, true, e), 0.0) << "no tension when failed";
    const MieGruneisenParams mg{3940.0, 1.49, 1.96};
    const EquationOfState eos = EquationOfState::mieGruneisen(rho0, mg);
    const double mu = 0.1, K0 = rho0 * 3940.0 * 3940.0;
    const double hugoniot = K0 * mu * (1 + (1 - 0.98) * mu) / std::pow(1 - 0.49 * mu, 2);
    // No volume change in the step (dv = 0): p = p_H + Γ0 ρ0 (e + heat), e unchanged.
    e = 1000.0;
    EXPECT_NEAR(
        eos.advance(rho0 * (1 + mu), 0.0, 0.0, 500.0, false, e) / (hugoniot + 1.96 * rho0 * 1500.0),
        1.0, 1e-12);
    EXPECT_NEAR(e, 1000.0, 1e-12);
    e = 0.0;
    EXPECT_NEAR(eos.advance(rho0 * 0.99, 0.0, 0.0, 0.0, false, e) / (K0 * -0.01), 1.0, 1e-12);
    // Sound speed at rest: c0 (bulk), √((K + 4G/3)/ρ0) for the point.
    EXPECT_NEAR(std::sqrt(eos.tangentBulkModulus(rho0, 0.0) / rho0), 3940.0, 1e-9);
    EXPECT_THROW(EquationOfState::mieGruneisen(rho0, {0.0, 1.49, 1.96}), InputError);
    EXPECT_THROW(EquationOfState::linear(rho0, -1.0), InputError);
}

TEST(EquationOfState, StoredEnergyIsTheWorkOfCompression) {
    // Compress to μ = 0.2 and back to μ = 0.05 in small steps: the work −∫p dv per unit mass
    // equals the stored energy ψ/ρ of either form (linear: K (J ln J − J + 1)/ρ0, exact).
    const double rho0 = 8960.0;
    for (const EquationOfState& eos :
         {EquationOfState::linear(rho0, 130e9),
          EquationOfState::mieGruneisen(rho0, MieGruneisenParams{3940.0, 1.49, 1.96})}) {
        double e = 0.0, p = 0.0, work = 0.0, rho = rho0;
        const auto step = [&](double rhoNew) {
            const double dv = 1 / rhoNew - 1 / rho;
            const double pNew = eos.advance(rhoNew, p, dv, 0.0, false, e);
            work -= 0.5 * (p + pNew) * dv;
            p = pNew;
            rho = rhoNew;
        };
        for (int i = 1; i <= 4000; ++i) step(rho0 * (1 + 0.2 * i / 4000));
        for (int i = 1; i <= 3000; ++i) step(rho0 * (1.2 - 0.15 * i / 3000));
        EXPECT_NEAR(eos.storedEnergyDensity(rho, e, false) / rho / work, 1.0, 1e-5);
    }
}

TEST(JohnsonCook, RejectsBadConstants) {
    const EquationOfState eos = EquationOfState::linear(8960.0, 129e9);
    JohnsonCookParams p = copperParams(0.9);
    p.meltingTemperature = 200.0;
    EXPECT_THROW(JohnsonCook(kCopper, p, eos), InputError);
    p = copperParams(0.9);
    p.specificHeat = 0.0;
    EXPECT_THROW(JohnsonCook(kCopper, p, eos), InputError);
    p.taylorQuinney = 0.0;
    EXPECT_NO_THROW(JohnsonCook(kCopper, p, eos)) << "no heating: Cp is not needed";
    p = copperParams(0.9);
    p.hardeningExponent = 0.0;
    EXPECT_THROW(JohnsonCook(kCopper, p, eos), InputError);
}

TEST(MaterialPointDriver, RejectsBadPaths) {
    const Material m = copper(0.9);
    EXPECT_THROW(driveMaterialPoint(m, compact(LoadingPath::Kind::UniaxialStress, 1.0, -0.1, 10)),
                 InputError);
    LoadingPath table;
    table.kind = LoadingPath::Kind::DeformationGradient;
    table.times = {0.0, 1.0};
    table.F = {Mat3::Identity() * 1.1, Mat3::Identity()};
    EXPECT_THROW(driveMaterialPoint(m, table), InputError);
}

}  // namespace
}  // namespace gsph
