// SPDX-License-Identifier: MIT
#include "materials/johnson_cook.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "materials/hypoelastic.hpp"

namespace gsph {
namespace {

void require(bool ok, const std::string& what, double value) {
    if (!ok) throw InputError(what + ", got " + std::to_string(value));
}

Mat3 deviator(const Mat3& t) {
    return t - (t.trace() / 3.0) * Mat3::Identity();
}

}  // namespace

JohnsonCook::JohnsonCook(const ElasticConstants& elastic, const JohnsonCookParams& params,
                         const EquationOfState& eos, std::optional<JohnsonCookDamage> damage)
    : elastic_(elastic), params_(params), eos_(eos), damage_(damage) {
    const JohnsonCookParams& p = params_;
    require(p.yieldStress >= 0.0, "yield stress A must be ≥ 0", p.yieldStress);
    require(p.hardeningModulus >= 0.0, "hardening modulus B must be ≥ 0", p.hardeningModulus);
    require(p.hardeningExponent > 0.0, "hardening exponent n must be > 0", p.hardeningExponent);
    require(p.strainRateCoefficient >= 0.0, "strain-rate coefficient C must be ≥ 0",
            p.strainRateCoefficient);
    require(p.referenceStrainRate > 0.0, "reference strain rate must be > 0",
            p.referenceStrainRate);
    require(p.thermalSofteningExponent > 0.0, "thermal softening exponent m must be > 0",
            p.thermalSofteningExponent);
    require(p.roomTemperature > 0.0, "room temperature must be > 0 K", p.roomTemperature);
    require(p.meltingTemperature > p.roomTemperature,
            "melting temperature must exceed the room temperature " +
                std::to_string(p.roomTemperature) + " K",
            p.meltingTemperature);
    require(p.taylorQuinney >= 0.0 && p.taylorQuinney <= 1.0,
            "Taylor–Quinney coefficient χ must lie in [0, 1]", p.taylorQuinney);
    require(p.specificHeat > 0.0 || p.taylorQuinney == 0.0,
            "specific heat must be > 0 (or χ = 0: no heating)", p.specificHeat);
}

double JohnsonCook::homologousTemperature(double T) const {
    const double t =
        (T - params_.roomTemperature) / (params_.meltingTemperature - params_.roomTemperature);
    return std::clamp(t, 0.0, 1.0);
}

double JohnsonCook::rateFactor(double strainRate) const {
    const double ratio = strainRate / params_.referenceStrainRate;
    if (params_.rateForm == StrainRateForm::Power)
        return std::pow(1.0 + ratio, params_.strainRateCoefficient);
    // Below the reference rate the logarithm would soften (and diverge at rest): no rate effect.
    return 1.0 + params_.strainRateCoefficient * std::log(std::max(ratio, 1.0));
}

double JohnsonCook::flowStress(double plasticStrain, double strainRate, double temperature) const {
    const JohnsonCookParams& p = params_;
    const double hardening =
        p.yieldStress + p.hardeningModulus * std::pow(plasticStrain, p.hardeningExponent);
    const double softening =
        1.0 - std::pow(homologousTemperature(temperature), p.thermalSofteningExponent);
    return hardening * rateFactor(strainRate) * softening;
}

double JohnsonCook::stressFreeInternalEnergy(double T0) const {
    if (eos_.kind() == EquationOfState::Kind::Linear) return 0.0;
    return -params_.specificHeat * (T0 - params_.roomTemperature);
}

void JohnsonCook::update(MaterialPoint& p, const Mat3& D, const Mat3& W, double dt) const {
    const double G = elastic_.shearModulus();
    const double pressureOld = -p.cauchy.trace() / 3.0;
    const Mat3 R = jaumannRotation(W, dt);
    const Mat3 sOld = R * deviator(p.cauchy) * R.transpose();
    const Mat3 Ddev = deviator(D);
    const double strainRate = std::sqrt(2.0 / 3.0 * Ddev.squaredNorm());
    const double Tstar = homologousTemperature(p.temperature);
    const bool failedBefore = p.damage >= 1.0;
    p.plasticWork = 0.0;
    p.damageDissipation = 0.0;

    // Deviatoric part: elastic trial and Wilkins radial return (DESIGN §5).
    Mat3 s = Mat3::Zero();
    double dEps = 0.0;
    if (!failedBefore) {
        s = sOld + (2.0 * G * dt) * Ddev;
        const double sigmaTrial = std::sqrt(1.5 * s.squaredNorm());
        const double sigmaY =
            (1.0 - p.damage) * flowStress(p.plasticStrain, strainRate, p.temperature);
        if (sigmaTrial > sigmaY) {
            const double cf = sigmaY / sigmaTrial;
            const Mat3 sNew = cf * s;
            dEps = (sigmaTrial - sigmaY) / (3.0 * G);
            p.plasticWork = (1.0 - cf) / (4.0 * G) * s.cwiseProduct(sOld + sNew).sum();
            s = sNew;
            p.plasticStrain += dEps;
            if (params_.taylorQuinney > 0.0)
                p.temperature +=
                    params_.taylorQuinney * p.plasticWork / (p.density * params_.specificHeat);
        }
    }

    // Pressure from the equation of state; dv = tr(D) Δt/ρ is the change of specific volume.
    const double heat = params_.specificHeat * (p.temperature - params_.roomTemperature);
    double pressure = eos_.advance(p.density, pressureOld, D.trace() * dt / p.density, heat,
                                   failedBefore, p.internalEnergy);

    // Damage and failure: at D = 1 the point drops its deviatoric stress and any tension.
    if (damage_ && dEps > 0.0) {
        const double sigmaEq = std::sqrt(1.5 * s.squaredNorm());
        const double triaxiality = sigmaEq > 0.0 ? -pressure / sigmaEq : 0.0;
        const double failureStrain =
            damage_->failureStrain(triaxiality, strainRate / params_.referenceStrainRate, Tstar);
        p.damage = damage_->accumulate(p.damage, dEps, failureStrain);
        if (p.damage >= 1.0) {
            const double before = s.squaredNorm() / (4.0 * G) +
                                  eos_.storedEnergyDensity(p.density, p.internalEnergy, false);
            s.setZero();
            if (pressure < 0.0) {
                pressure = 0.0;
                if (eos_.kind() == EquationOfState::Kind::MieGruneisen) p.internalEnergy = 0.0;
            }
            p.damageDissipation =
                before - eos_.storedEnergyDensity(p.density, p.internalEnergy, true);
        }
    }
    p.cauchy = s - pressure * Mat3::Identity();
}

double JohnsonCook::waveSpeed(const MaterialPoint& p) const {
    const double pressure = -p.cauchy.trace() / 3.0;
    const double K = eos_.tangentBulkModulus(p.density, pressure);
    return std::sqrt((K + 4.0 / 3.0 * elastic_.shearModulus()) / p.density);
}

double JohnsonCook::storedEnergyDensity(const MaterialPoint& p) const {
    return deviator(p.cauchy).squaredNorm() / (4.0 * elastic_.shearModulus()) +
           eos_.storedEnergyDensity(p.density, p.internalEnergy, p.damage >= 1.0);
}

}  // namespace gsph
