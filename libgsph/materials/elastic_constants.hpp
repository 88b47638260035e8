// SPDX-License-Identifier: MIT
// Isotropic linear-elastic constants from (ρ0, E, ν), with the derived moduli every model and
// the time step need. Validated on construction: bad input throws InputError.
#pragma once

#include <cmath>
#include <string>

#include "core/error.hpp"

namespace gsph {

struct ElasticConstants {
    double density = 0.0;        ///< ρ0 [kg/m³]
    double youngsModulus = 0.0;  ///< E [Pa]
    double poissonRatio = 0.0;   ///< ν [-]

    ElasticConstants() = default;
    ElasticConstants(double rho0, double E, double nu)
        : density(rho0), youngsModulus(E), poissonRatio(nu) {
        if (!(rho0 > 0.0)) throw InputError("density must be > 0, got " + std::to_string(rho0));
        if (!(E > 0.0)) throw InputError("Young's modulus must be > 0, got " + std::to_string(E));
        if (!(nu > -1.0 && nu < 0.5))
            throw InputError("Poisson's ratio must lie in (-1, 0.5), got " + std::to_string(nu));
    }

    double shearModulus() const { return youngsModulus / (2.0 * (1.0 + poissonRatio)); }
    double bulkModulus() const { return youngsModulus / (3.0 * (1.0 - 2.0 * poissonRatio)); }
    double lame() const { return bulkModulus() - 2.0 / 3.0 * shearModulus(); }
    /// K + 4G/3: the modulus of uniaxial strain (P-wave modulus).
    double pWaveModulus() const { return bulkModulus() + 4.0 / 3.0 * shearModulus(); }
    /// Dilatational wave speed √((K + 4G/3)/ρ0), the fastest signal: used for the time step.
    double pWaveSpeed() const { return std::sqrt(pWaveModulus() / density); }
    /// Bar wave speed √(E/ρ0).
    double barWaveSpeed() const { return std::sqrt(youngsModulus / density); }
};

}  // namespace gsph
