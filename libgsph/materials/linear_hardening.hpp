// SPDX-License-Identifier: MIT
// Linear isotropic hardening, a strength model of PlasticSolid (materials/plastic_solid.hpp):
//   σy = σ0 + H ε̄p
// independent of the strain rate and the temperature (a bilinear metal model, as LS-DYNA's
// *MAT_PLASTIC_KINEMATIC with β = 1 and no rate terms). Under uniaxial stress the slope past
// yield is E H/(E + H). Heating is optional (χ, Cp); without a melting temperature, damage's
// temperature term has T* = 0.
#pragma once

#include "materials/plastic_solid.hpp"

namespace gsph {

struct LinearHardeningParams {
    double yieldStress = 0.0;          ///< σ0 [Pa]
    double hardeningModulus = 0.0;     ///< H = dσy/dε̄p [Pa]
    double roomTemperature = 293.15;   ///< Tr [K]
    double specificHeat = 0.0;         ///< Cp [J/(kg K)] (needed only with χ > 0)
    double taylorQuinney = 0.0;        ///< χ (default 0: isothermal)
    double referenceStrainRate = 1.0;  ///< ε̇0 [1/s] of the damage's rate term
};

class LinearHardeningStrength {
  public:
    /// Throws InputError naming the first bad constant.
    LinearHardeningStrength(const LinearHardeningParams& params);  // NOLINT: implicit

    const LinearHardeningParams& params() const { return params_; }
    double flowStress(double plasticStrain, double /*strainRate*/, double /*temperature*/) const {
        return params_.yieldStress + params_.hardeningModulus * plasticStrain;
    }
    double homologousTemperature(double /*T*/) const { return 0.0; }
    double roomTemperature() const { return params_.roomTemperature; }
    double specificHeat() const { return params_.specificHeat; }
    double taylorQuinney() const { return params_.taylorQuinney; }
    double referenceStrainRate() const { return params_.referenceStrainRate; }

  private:
    LinearHardeningParams params_;
};

using LinearHardening = PlasticSolid<LinearHardeningStrength>;

}  // namespace gsph
