// SPDX-License-Identifier: MIT
#include "materials/linear_hardening.hpp"

#include "core/error.hpp"

namespace gsph {

LinearHardeningStrength::LinearHardeningStrength(const LinearHardeningParams& params)
    : params_(params) {
    const LinearHardeningParams& p = params_;
    requireConstant(p.yieldStress >= 0.0, "yield stress must be ≥ 0", p.yieldStress);
    requireConstant(p.hardeningModulus >= 0.0, "hardening modulus must be ≥ 0", p.hardeningModulus);
    requireConstant(p.roomTemperature > 0.0, "room temperature must be > 0 K", p.roomTemperature);
    requireConstant(p.referenceStrainRate > 0.0, "reference strain rate must be > 0",
                    p.referenceStrainRate);
    checkHeating(p.taylorQuinney, p.specificHeat);
}

}  // namespace gsph
