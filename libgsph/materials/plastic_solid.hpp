// SPDX-License-Identifier: MIT
// A plastic solid composed of parts (DESIGN §5, paper §"Thermo-visco-plastic behavior"): the
// elastic constants, a strength model (the flow stress σy, e.g. Johnson–Cook or linear
// hardening), an equation of state for the pressure (materials/eos.hpp) and an optional damage
// model (materials/johnson_cook_damage.hpp). The update is von Mises plasticity with the Wilkins
// radial return, the same for every strength model:
//
//   σ = s − p I;  s_trial = R s_n R^T + 2G Δt dev D   (Jaumann, as materials/hypoelastic.hpp)
//   σy = (1 − D) · strength.flowStress(ε̄p, ε̇, T),  ε̇ = √(⅔ dev D : dev D) of the step
//   cf = min(σy/σ_eq,trial, 1), σ_eq = √(3 J2);  s = cf s_trial;  Δε̄p = (σ_eq,trial − σy)/(3G)
//   Δw_p = Δεp : ½(s_n + s_{n+1}),  Δεp = (1 − cf) s_trial/(2G)   (per current volume)
//   ΔT = χ Δw_p/(ρ Cp)
// The flow stress is explicit in ε̄p, ε̇ and T (Wilkins): it uses their values at t_n.
// Δw_p takes the paper's Δεp : S at the step's mid-point: with the trapezoidal stress power of
// velocity Verlet, elastic energy + plastic work then balance exactly (the paper's end-point
// form loses ½(σ_trial − σy)Δε̄p per step, several % at impact strain increments).
// A point with D ≥ 1 has failed: s = 0 and p ≥ 0 from then on; the elastic energy it loses at
// that moment is reported as damageDissipation.
//
// A strength model is a value with (materials/johnson_cook.hpp, materials/linear_hardening.hpp):
//   double flowStress(double plasticStrain, double strainRate, double temperature) const; // [Pa]
//   double homologousTemperature(double T) const;  // T* ∈ [0, 1] for damage (0: no such term)
//   double roomTemperature() const;                 // Tr [K]: the initial temperature
//   double specificHeat() const;                    // Cp [J/(kg K)]
//   double taylorQuinney() const;                   // χ: the share of plastic work that heats
//   double referenceStrainRate() const;             // ε̇0 [1/s] of damage's rate term
// Adding one is a header with that class and an alias PlasticSolid<It>, an explicit
// instantiation in plastic_solid.cpp, an entry in materials/material.hpp and its case-file
// reader (docs/extending.md).
#pragma once

#include <array>
#include <optional>

#include "core/types.hpp"
#include "materials/elastic_constants.hpp"
#include "materials/eos.hpp"
#include "materials/johnson_cook_damage.hpp"
#include "materials/material_point.hpp"

namespace gsph {

/// The heating constants every strength model checks: χ ∈ [0, 1], and Cp > 0 unless χ = 0.
/// Throws InputError naming the constant.
void checkHeating(double taylorQuinney, double specificHeat);

template <class Strength>
class PlasticSolid {
  public:
    /// Its history variables (materials/material_point.hpp): every strength model's, the
    /// equation of state's energy and the damage.
    static constexpr std::array kHistory{history::kPlasticStrain, history::kTemperature,
                                         history::kDamage, history::kInternalEnergy,
                                         history::kDamageDriver};

    PlasticSolid(const ElasticConstants& elastic, const Strength& strength,
                 const EquationOfState& eos, std::optional<JohnsonCookDamage> damage = {})
        : elastic_(elastic), strength_(strength), eos_(eos), damage_(damage) {}

    const ElasticConstants& elastic() const { return elastic_; }
    const Strength& strength() const { return strength_; }
    const EquationOfState& eos() const { return eos_; }
    const std::optional<JohnsonCookDamage>& damage() const { return damage_; }
    double roomTemperature() const { return strength_.roomTemperature(); }

    /// Undamaged flow stress [Pa] (the strength model's).
    double flowStress(double plasticStrain, double strainRate, double temperature) const {
        return strength_.flowStress(plasticStrain, strainRate, temperature);
    }
    /// Specific internal energy e that makes a point at temperature T0 pressure-free in the
    /// Mie–Grüneisen form (whose thermal term counts from Tr); 0 for the linear form.
    double stressFreeInternalEnergy(double T0) const;

    void update(MaterialPoint& p, const Mat3& D, const Mat3& W, double dt) const;
    /// Dilatational speed √((K_s + 4G/3)/ρ) with the equation of state's bulk tangent K_s.
    double waveSpeed(const MaterialPoint& p) const;
    /// s:s/(4G) + the equation of state's stored energy of compression [J/m³].
    double storedEnergyDensity(const MaterialPoint& p) const;

  private:
    ElasticConstants elastic_;
    Strength strength_;
    EquationOfState eos_;
    std::optional<JohnsonCookDamage> damage_;
};

}  // namespace gsph
