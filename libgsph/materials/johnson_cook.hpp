// SPDX-License-Identifier: MIT
// Johnson–Cook thermo-visco-plastic strength (Johnson & Cook 1983), a strength model of
// PlasticSolid (materials/plastic_solid.hpp):
//   σy = (A + B ε̄p^n) · rate · (1 − T*^m),  T* = (T − Tr)/(Tm − Tr) clamped to [0, 1]
//   rate = 1 + C ln max(ε̇*, 1) (Johnson & Cook 1983)  or  (1 + ε̇*)^C (Børvik et al. 2001)
//   ε̇* = ε̇/ε̇0
// JohnsonCook is the plastic solid with this strength: σy as above, heating by χ Δw_p/(ρ Cp),
// pressure from its equation of state, optional Johnson–Cook damage.
#pragma once

#include <algorithm>
#include <cmath>

#include "materials/plastic_solid.hpp"

namespace gsph {

enum class StrainRateForm {
    Logarithmic,  ///< 1 + C ln max(ε̇*, 1)  (Johnson & Cook 1983)
    Power,        ///< (1 + ε̇*)^C          (Børvik et al. 2001)
};

struct JohnsonCookParams {
    double yieldStress = 0.0;               ///< A [Pa]
    double hardeningModulus = 0.0;          ///< B [Pa]
    double hardeningExponent = 1.0;         ///< n
    double strainRateCoefficient = 0.0;     ///< C
    double referenceStrainRate = 1.0;       ///< ε̇0 [1/s]
    double thermalSofteningExponent = 1.0;  ///< m
    double roomTemperature = 293.15;        ///< Tr [K]
    double meltingTemperature = 0.0;        ///< Tm [K]
    double specificHeat = 0.0;              ///< Cp [J/(kg K)]
    double taylorQuinney = 0.9;  ///< χ, the share of plastic work that heats (0: isothermal)
    StrainRateForm rateForm = StrainRateForm::Logarithmic;
};

class JohnsonCookStrength {
  public:
    /// Throws InputError naming the first bad constant.
    JohnsonCookStrength(const JohnsonCookParams& params);  // NOLINT: implicit from its params

    const JohnsonCookParams& params() const { return params_; }
    /// T* = (T − Tr)/(Tm − Tr), clamped to [0, 1] (no hardening below Tr, no strength above Tm).
    double homologousTemperature(double T) const;
    /// Undamaged flow stress (A + B ε̄p^n) · rate(ε̇) · (1 − T*^m) [Pa].
    double flowStress(double plasticStrain, double strainRate, double temperature) const;
    double roomTemperature() const { return params_.roomTemperature; }
    double specificHeat() const { return params_.specificHeat; }
    double taylorQuinney() const { return params_.taylorQuinney; }
    double referenceStrainRate() const { return params_.referenceStrainRate; }

  private:
    double rateFactor(double strainRate) const;

    JohnsonCookParams params_;
};

using JohnsonCook = PlasticSolid<JohnsonCookStrength>;

// Inline: the radial return calls them once per particle and step.
inline double JohnsonCookStrength::homologousTemperature(double T) const {
    const double t =
        (T - params_.roomTemperature) / (params_.meltingTemperature - params_.roomTemperature);
    return std::clamp(t, 0.0, 1.0);
}

inline double JohnsonCookStrength::rateFactor(double strainRate) const {
    const double ratio = strainRate / params_.referenceStrainRate;
    if (params_.rateForm == StrainRateForm::Power)
        return std::pow(1.0 + ratio, params_.strainRateCoefficient);
    // Below the reference rate the logarithm would soften (and diverge at rest): no rate effect
    // (ln 1 = 0 exactly, so the logarithm is skipped there: the same bits).
    if (ratio <= 1.0) return 1.0;
    return 1.0 + params_.strainRateCoefficient * std::log(ratio);
}

inline double JohnsonCookStrength::flowStress(double plasticStrain, double strainRate,
                                              double temperature) const {
    const JohnsonCookParams& p = params_;
    // 0^n = 0 exactly (n > 0): a point that has not flowed, or is at room temperature, skips
    // its power (the same bits).
    const double hardening =
        p.yieldStress +
        p.hardeningModulus *
            (plasticStrain == 0.0 ? 0.0 : std::pow(plasticStrain, p.hardeningExponent));
    const double Tstar = homologousTemperature(temperature);
    const double softening = Tstar == 0.0 ? 1.0 : 1.0 - std::pow(Tstar, p.thermalSofteningExponent);
    return hardening * rateFactor(strainRate) * softening;
}

}  // namespace gsph
