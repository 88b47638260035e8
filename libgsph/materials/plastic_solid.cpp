// SPDX-License-Identifier: MIT
#include "materials/plastic_solid.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "materials/hypoelastic.hpp"
#include "materials/johnson_cook.hpp"
#include "materials/linear_hardening.hpp"

namespace gsph {
namespace {

Mat3 deviator(const Mat3& t) {
    return t - (t.trace() / 3.0) * Mat3::Identity();
}

}  // namespace

void checkHeating(double taylorQuinney, double specificHeat) {
    requireConstant(taylorQuinney >= 0.0 && taylorQuinney <= 1.0,
                    "Taylor–Quinney coefficient χ must lie in [0, 1]", taylorQuinney);
    requireConstant(specificHeat > 0.0 || taylorQuinney == 0.0,
                    "specific heat must be > 0 (or χ = 0: no heating)", specificHeat);
}

template <class Strength>
double PlasticSolid<Strength>::stressFreeInternalEnergy(double T0) const {
    if (eos_.kind() == EquationOfState::Kind::Linear) return 0.0;
    return -strength_.specificHeat() * (T0 - strength_.roomTemperature());
}

template <class Strength>
void PlasticSolid<Strength>::update(MaterialPoint& p, const Mat3& D, const Mat3& W,
                                    double dt) const {
    const double G = elastic_.shearModulus();
    const double pressureOld = -p.cauchy.trace() / 3.0;
    const Mat3 R = jaumannRotation(W, dt);
    const Mat3 sOld = R * deviator(p.cauchy) * R.transpose();
    const Mat3 Ddev = deviator(D);
    const double strainRate = std::sqrt(2.0 / 3.0 * Ddev.squaredNorm());
    const double Tstar = strength_.homologousTemperature(p.temperature);
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
            (1.0 - p.damage) * strength_.flowStress(p.plasticStrain, strainRate, p.temperature);
        if (sigmaTrial > sigmaY) {
            const double cf = sigmaY / sigmaTrial;
            const Mat3 sNew = cf * s;
            dEps = (sigmaTrial - sigmaY) / (3.0 * G);
            p.plasticWork = (1.0 - cf) / (4.0 * G) * s.cwiseProduct(sOld + sNew).sum();
            s = sNew;
            p.plasticStrain += dEps;
            if (strength_.taylorQuinney() > 0.0)
                p.temperature += strength_.taylorQuinney() * p.plasticWork /
                                 (p.density * strength_.specificHeat());
        }
    }

    // Pressure from the equation of state; dv = tr(D) Δt/ρ is the change of specific volume.
    const double heat = strength_.specificHeat() * (p.temperature - strength_.roomTemperature());
    double pressure = eos_.advance(p.density, pressureOld, D.trace() * dt / p.density, heat,
                                   failedBefore, p.internalEnergy);

    // Damage and failure: at D = 1 the point drops its deviatoric stress and any tension. A
    // nonlocal damage accumulates the local driver and takes D from its neighbourhood's average
    // (failure/nonlocal_damage.hpp), so a point may fail without flowing itself.
    const bool nonlocal = damage_ && damage_->nonlocal() && !failedBefore;
    if (damage_ && (dEps > 0.0 || nonlocal)) {
        double failureStrain = 0.0;
        if (dEps > 0.0) {
            const double sigmaEq = std::sqrt(1.5 * s.squaredNorm());
            const double triaxiality = sigmaEq > 0.0 ? -pressure / sigmaEq : 0.0;
            failureStrain = damage_->scaledToSize(
                damage_->failureStrain(triaxiality, strainRate / strength_.referenceStrainRate(),
                                       Tstar),
                p.size);
        }
        if (nonlocal) {
            if (dEps > 0.0) p.damageDriver += damage_->driverIncrement(dEps, failureStrain);
            p.damage = std::min(1.0, std::max(p.damage, p.averagedDriver));
        } else {
            p.damage = damage_->accumulate(p.damage, dEps, failureStrain);
        }
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

template <class Strength>
double PlasticSolid<Strength>::waveSpeed(const MaterialPoint& p) const {
    const double pressure = -p.cauchy.trace() / 3.0;
    const double K = eos_.tangentBulkModulus(p.density, pressure);
    return std::sqrt((K + 4.0 / 3.0 * elastic_.shearModulus()) / p.density);
}

template <class Strength>
double PlasticSolid<Strength>::storedEnergyDensity(const MaterialPoint& p) const {
    return deviator(p.cauchy).squaredNorm() / (4.0 * elastic_.shearModulus()) +
           eos_.storedEnergyDensity(p.density, p.internalEnergy, p.damage >= 1.0);
}

template class PlasticSolid<JohnsonCookStrength>;
template class PlasticSolid<LinearHardeningStrength>;

}  // namespace gsph
