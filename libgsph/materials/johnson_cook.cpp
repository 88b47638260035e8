// SPDX-License-Identifier: MIT
#include "materials/johnson_cook.hpp"

#include <string>

#include "core/error.hpp"

namespace gsph {

JohnsonCookStrength::JohnsonCookStrength(const JohnsonCookParams& params) : params_(params) {
    const JohnsonCookParams& p = params_;
    requireConstant(p.yieldStress >= 0.0, "yield stress A must be ≥ 0", p.yieldStress);
    requireConstant(p.hardeningModulus >= 0.0, "hardening modulus B must be ≥ 0",
                    p.hardeningModulus);
    requireConstant(p.hardeningExponent > 0.0, "hardening exponent n must be > 0",
                    p.hardeningExponent);
    requireConstant(p.strainRateCoefficient >= 0.0, "strain-rate coefficient C must be ≥ 0",
                    p.strainRateCoefficient);
    requireConstant(p.referenceStrainRate > 0.0, "reference strain rate must be > 0",
                    p.referenceStrainRate);
    requireConstant(p.thermalSofteningExponent > 0.0, "thermal softening exponent m must be > 0",
                    p.thermalSofteningExponent);
    requireConstant(p.roomTemperature > 0.0, "room temperature must be > 0 K", p.roomTemperature);
    requireConstant(p.meltingTemperature > p.roomTemperature,
                    "melting temperature must exceed the room temperature " +
                        std::to_string(p.roomTemperature) + " K",
                    p.meltingTemperature);
    checkHeating(p.taylorQuinney, p.specificHeat);
}

}  // namespace gsph
