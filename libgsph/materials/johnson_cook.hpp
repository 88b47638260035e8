// SPDX-License-Identifier: MIT
// Johnson–Cook thermo-visco-plasticity with von Mises yield and the Wilkins radial return
// (DESIGN §5, paper §"Thermo-visco-plastic behavior"), pressure from an equation of state
// (materials/eos.hpp) and optional Johnson–Cook damage (materials/johnson_cook_damage.hpp).
//
//   σ = s − p I;  s_trial = R s_n R^T + 2G Δt dev D   (Jaumann, as materials/hypoelastic.hpp)
//   σy = (1 − D)(A + B ε̄p^n) · rate · (1 − T*^m),  T* = (T − Tr)/(Tm − Tr) clamped to [0, 1]
//   rate = 1 + C ln max(ε̇*, 1) (Johnson & Cook 1983)  or  (1 + ε̇*)^C (Børvik et al. 2001)
//   ε̇* = ε̇/ε̇0 with ε̇ = √(⅔ dev D : dev D), the equivalent strain rate of the step
//   cf = min(σy/σ_eq,trial, 1), σ_eq = √(3 J2);  s = cf s_trial;  Δε̄p = (σ_eq,trial − σy)/(3G)
//   Δw_p = Δεp : ½(s_n + s_{n+1}),  Δεp = (1 − cf) s_trial/(2G)   (per current volume)
//   ΔT = χ Δw_p/(ρ Cp)
// The flow stress is explicit in ε̄p, ε̇ and T (Wilkins): it uses their values at t_n.
// Δw_p takes the paper's Δεp : S at the step's mid-point: with the trapezoidal stress power of
// velocity Verlet, elastic energy + plastic work then balance exactly (the paper's end-point
// form loses ½(σ_trial − σy)Δε̄p per step, several % at impact strain increments).
// A point with D ≥ 1 has failed: s = 0 and p ≥ 0 from then on; the elastic energy it loses at
// that moment is reported as damageDissipation.
#pragma once

#include <optional>

#include "core/types.hpp"
#include "materials/elastic_constants.hpp"
#include "materials/eos.hpp"
#include "materials/johnson_cook_damage.hpp"
#include "materials/material_point.hpp"

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

class JohnsonCook {
  public:
    static constexpr bool kTracksHistory = true;

    /// Throws InputError naming the first bad constant.
    JohnsonCook(const ElasticConstants& elastic, const JohnsonCookParams& params,
                const EquationOfState& eos, std::optional<JohnsonCookDamage> damage = {});

    const ElasticConstants& elastic() const { return elastic_; }
    const JohnsonCookParams& params() const { return params_; }
    const EquationOfState& eos() const { return eos_; }
    const std::optional<JohnsonCookDamage>& damage() const { return damage_; }
    double roomTemperature() const { return params_.roomTemperature; }

    /// T* = (T − Tr)/(Tm − Tr), clamped to [0, 1] (no hardening below Tr, no strength above Tm).
    double homologousTemperature(double T) const;
    /// Undamaged flow stress (A + B ε̄p^n) · rate(ε̇) · (1 − T*^m) [Pa].
    double flowStress(double plasticStrain, double strainRate, double temperature) const;
    /// Specific internal energy e that makes a point at temperature T0 pressure-free in the
    /// Mie–Grüneisen form (whose thermal term counts from Tr); 0 for the linear form.
    double stressFreeInternalEnergy(double T0) const;

    void update(MaterialPoint& p, const Mat3& D, const Mat3& W, double dt) const;
    /// Dilatational speed √((K_s + 4G/3)/ρ) with the equation of state's bulk tangent K_s.
    double waveSpeed(const MaterialPoint& p) const;
    /// s:s/(4G) + the equation of state's stored energy of compression [J/m³].
    double storedEnergyDensity(const MaterialPoint& p) const;

  private:
    double rateFactor(double strainRate) const;

    ElasticConstants elastic_;
    JohnsonCookParams params_;
    EquationOfState eos_;
    std::optional<JohnsonCookDamage> damage_;
};

}  // namespace gsph
