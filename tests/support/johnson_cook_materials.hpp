// SPDX-License-Identifier: MIT
// The Johnson–Cook constants of the material library (materials/ofhc_copper.toml,
// materials/weldox_460e.toml, sources there) as library structs, for tests and benchmarks that
// build a model without reading a file. The equation of state is the linear one (K from E, ν).
#pragma once

#include "materials/johnson_cook.hpp"

namespace gsph::testing {

inline const ElasticConstants kCopperElastic(8960.0, 124e9, 0.34);
inline const ElasticConstants kWeldoxElastic(7850.0, 200e9, 0.33);

/// OFHC copper (Johnson & Cook 1983); χ = taylorQuinney (0: isothermal).
inline JohnsonCookParams copperParams(double taylorQuinney = 0.9) {
    JohnsonCookParams p;
    p.yieldStress = 90e6;
    p.hardeningModulus = 292e6;
    p.hardeningExponent = 0.31;
    p.strainRateCoefficient = 0.025;
    p.referenceStrainRate = 1.0;
    p.thermalSofteningExponent = 1.09;
    p.roomTemperature = 293.15;
    p.meltingTemperature = 1356.0;
    p.specificHeat = 383.0;
    p.taylorQuinney = taylorQuinney;
    return p;
}

/// Weldox 460E strength (Børvik et al. 2001, power rate form).
inline JohnsonCookParams weldoxParams() {
    JohnsonCookParams p;
    p.yieldStress = 490e6;
    p.hardeningModulus = 807e6;
    p.hardeningExponent = 0.73;
    p.strainRateCoefficient = 0.0114;
    p.referenceStrainRate = 5e-4;
    p.rateForm = StrainRateForm::Power;
    p.thermalSofteningExponent = 0.94;
    p.roomTemperature = 293.0;
    p.meltingTemperature = 1800.0;
    p.specificHeat = 452.0;
    return p;
}

/// Weldox 460E damage of the paper: D1 … D5 = 0.0705, 1.732, −0.54, −0.015, D5.
inline JohnsonCookDamage weldoxDamage(double d5 = 0.0) {
    return JohnsonCookDamage{{0.0705, 1.732, -0.54, -0.015, d5}};
}

inline JohnsonCook withLinearEos(const ElasticConstants& e, const JohnsonCookParams& p,
                                 std::optional<JohnsonCookDamage> damage = {}) {
    return JohnsonCook(e, p, EquationOfState::linear(e.density, e.bulkModulus()), damage);
}

/// A soft steel (A = 2 MPa) with the Mie–Grüneisen pressure and damage that fails at
/// ε̄p ≈ 0.001: a 40 m/s impact flows, heats and fails at once (tests of plastic runs).
/// `damageLength`: ℓ of a nonlocal damage (0: local).
inline JohnsonCook softFailingSteel(double damageLength = 0.0) {
    JohnsonCookParams p;
    p.yieldStress = 2e6;
    p.hardeningModulus = 50e6;
    p.hardeningExponent = 0.3;
    p.strainRateCoefficient = 0.02;
    p.meltingTemperature = 1800.0;
    p.specificHeat = 450.0;
    const ElasticConstants e(7800.0, 200e9, 0.3);
    JohnsonCookDamage damage{{0.0, 0.001, 0.0, 0.0, 0.0}};
    damage.length = damageLength;
    return JohnsonCook(e, p, EquationOfState::mieGruneisen(7800.0, {4570.0, 1.49, 1.93}), damage);
}

}  // namespace gsph::testing
