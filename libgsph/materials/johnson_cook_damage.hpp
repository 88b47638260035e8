// SPDX-License-Identifier: MIT
// Johnson–Cook ductile damage (DESIGN §5, the paper's damage model; Johnson & Cook 1985):
//   D = Σ Δε̄p / εf,   εf = [D1 + D2 exp(D3 σ*)] [1 + ε̇*]^D4 [1 + D5 T*],
// σ* = σ_m/σ_eq the stress triaxiality (σ_m = −p the mean stress), ε̇* = ε̇/ε̇0 and T* the
// homologous temperature of the strength model. The rate term is the paper's power form
// (Børvik et al.); Johnson & Cook's original 1 + D4 ln ε̇* agrees with it to first order in
// D4 ln ε̇*. The strength model accumulates D and couples it to the yield stress, (1 − D)σy;
// a point with D ≥ 1 has failed: no deviatoric stress and no tension (materials/plastic_solid.hpp).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>

namespace gsph {

struct JohnsonCookDamage {
    std::array<double, 5> D = {0.0, 0.0, 0.0, 0.0, 0.0};  ///< D1 … D5
    /// ℓ [m] of the nonlocal average of the damage driver (failure/nonlocal_damage.hpp); 0:
    /// local damage, D = Σ Δε̄p/εf at the particle itself.
    double length = 0.0;
    /// L0 [m] of the size regularization of the failure strain: a particle of size h fails at
    /// εf L0/h, so that a band one particle wide dissipates per unit area what a band of width L0
    /// with the constants' εf does (the band-width scaling of FE codes' erosion, the simpler
    /// alternative to the nonlocal average); 0: off.
    double referenceSize = 0.0;

    bool nonlocal() const { return length > 0.0; }

    /// εf scaled to a particle of size h [m] (unchanged without a reference size, or h ≤ 0:
    /// a material point without a particle).
    double scaledToSize(double failureStrainValue, double size) const {
        return referenceSize > 0.0 && size > 0.0 ? failureStrainValue * (referenceSize / size)
                                                 : failureStrainValue;
    }

    /// εf at triaxiality σ*, strain-rate ratio ε̇* = ε̇/ε̇0 and homologous temperature T*.
    /// May be ≤ 0 for constants with D1 < 0 at high triaxiality: the point then fails at once.
    double failureStrain(double triaxiality, double rateRatio, double homologousTemperature) const {
        return (D[0] + D[1] * std::exp(D[2] * triaxiality)) * std::pow(1.0 + rateRatio, D[3]) *
               (1.0 + D[4] * homologousTemperature);
    }

    /// The driver increment Δε̄p/εf of a plastic increment dEps > 0, not capped (nonlocal
    /// damage averages it); 1 where εf ≤ 0 (the point fails at once).
    double driverIncrement(double dEps, double failureStrainValue) const {
        return failureStrainValue > 0.0 ? dEps / failureStrainValue : 1.0;
    }

    /// Damage after a plastic increment dEps (≥ 0); 1 once the point has failed.
    double accumulate(double damage, double dEps, double failureStrainValue) const {
        if (dEps <= 0.0) return damage;
        if (!(failureStrainValue > 0.0)) return 1.0;
        return std::min(1.0, damage + dEps / failureStrainValue);
    }
};

}  // namespace gsph
