// SPDX-License-Identifier: MIT
// Equations of state: the pressure of a strength model that splits σ = s − p I (DESIGN §5;
// p > 0 in compression). Two forms, chosen per material (a switch on a per-body constant,
// never a virtual call):
//   linear:          p = K ln(ρ/ρ0) = −K ln J, exact integral of ṗ = −K tr D, so the stored
//                    energy is a function of J alone: ρ0 ψ = K (J ln J − J + 1) per reference
//                    volume;
//   Mie–Grüneisen:   μ = ρ/ρ0 − 1,
//                    p = ρ0 c0² μ [1 + (1 − Γ0/2) μ] / [1 − (s − 1) μ]² + Γ0 ρ0 ê   (μ ≥ 0),
//                    p = ρ0 c0² μ + Γ0 ρ0 ê                                         (μ < 0),
//                    (the common hydrocode form, e.g. LS-DYNA *EOS_GRUNEISEN with a = S2 = S3 = 0),
//                    ê = e + heat: e = ∫ −p dv, the specific work of compression (State::
//                    internalEnergy), heat = Cp (T − Tr), the share of plastic work that became
//                    heat.
// A failed particle (damage D = 1) carries no tension: p ≥ 0 (noTension).
#pragma once

#include <algorithm>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace gsph {

struct MieGruneisenParams {
    double soundSpeed = 0.0;      ///< c0, bulk sound speed [m/s]
    double hugoniotSlope = 0.0;   ///< s of the shock Hugoniot U_s = c0 + s u_p
    double gruneisenGamma = 0.0;  ///< Γ0
};

class EquationOfState {
  public:
    enum class Kind { Linear, MieGruneisen };

    /// p = −K ln J; K > 0 [Pa].
    static EquationOfState linear(double referenceDensity, double bulkModulus) {
        if (!(bulkModulus > 0.0))
            throw InputError("bulk modulus must be > 0, got " + std::to_string(bulkModulus));
        EquationOfState e(Kind::Linear, referenceDensity);
        e.bulkModulus_ = bulkModulus;
        return e;
    }
    static EquationOfState mieGruneisen(double referenceDensity, const MieGruneisenParams& mg) {
        if (!(mg.soundSpeed > 0.0))
            throw InputError("sound speed c0 must be > 0, got " + std::to_string(mg.soundSpeed));
        if (!(mg.hugoniotSlope >= 0.0))
            throw InputError("Hugoniot slope s must be ≥ 0, got " +
                             std::to_string(mg.hugoniotSlope));
        if (!(mg.gruneisenGamma >= 0.0))
            throw InputError("Grüneisen Γ0 must be ≥ 0, got " + std::to_string(mg.gruneisenGamma));
        EquationOfState e(Kind::MieGruneisen, referenceDensity);
        e.mg_ = mg;
        e.bulkModulus_ = referenceDensity * mg.soundSpeed * mg.soundSpeed;
        return e;
    }

    Kind kind() const { return kind_; }
    const MieGruneisenParams& mieGruneisenParams() const { return mg_; }
    /// K of the linear form; ρ0 c0² (the bulk modulus at μ = 0) of Mie–Grüneisen [Pa].
    double bulkModulus() const { return bulkModulus_; }

    /// Advances the pressure to t_{n+1} at density rho, with the old pressure pOld, the change of
    /// specific volume dv over the step [m³/kg] and the plastic heat [J/kg]; updates the specific
    /// work of compression e = e_n − ½(p_n + p_{n+1}) dv (trapezoidal; Mie–Grüneisen is linear in
    /// e, so this is solved exactly). The linear form needs no e and leaves it alone.
    double advance(double rho, double pOld, double dv, double heat, bool noTension,
                   double& e) const {
        if (kind_ == Kind::Linear) {
            const double p = bulkModulus_ * std::log(rho / rho0_);
            return noTension ? std::max(p, 0.0) : p;
        }
        const double energyCoefficient = mg_.gruneisenGamma * rho0_;  // ∂p/∂e
        const double cold = hugoniotPressure(rho / rho0_ - 1.0) + energyCoefficient * heat;
        double eNew = (e - 0.5 * (pOld + cold) * dv) / (1.0 + 0.5 * energyCoefficient * dv);
        double p = cold + energyCoefficient * eNew;
        if (noTension && p < 0.0) {
            p = 0.0;
            eNew = e - 0.5 * pOld * dv;
        }
        e = eNew;
        return p;
    }

    /// Isentropic bulk tangent K_s = ρ dp/dρ|_s [Pa] at density rho and pressure p: K of the
    /// linear form; (1 + μ) p_H'(μ) + Γ0 ρ0 p/ρ for Mie–Grüneisen (never below 0).
    double tangentBulkModulus(double rho, double p) const {
        if (kind_ == Kind::Linear) return bulkModulus_;
        const double mu = rho / rho0_ - 1.0;
        const double k = (1.0 + mu) * hugoniotSlopeOf(mu) + mg_.gruneisenGamma * rho0_ * p / rho;
        return std::max(k, 0.0);
    }

    /// Stored energy of compression per current volume [J/m³] at density rho with specific work
    /// e: linear K (J ln J − J + 1)/J (0 for a failed particle in tension, which carries no
    /// pressure there); Mie–Grüneisen ρ e.
    double storedEnergyDensity(double rho, double e, bool failed) const {
        if (kind_ == Kind::MieGruneisen) return rho * e;
        const double J = rho0_ / rho;
        if (failed && J > 1.0) return 0.0;
        return bulkModulus_ * (J * std::log(J) - J + 1.0) / J;
    }

  private:
    EquationOfState(Kind kind, double rho0) : kind_(kind), rho0_(rho0) {}

    // The Hugoniot-referenced part p_H(μ)(1 − Γ0 μ/2) of Mie–Grüneisen, and its slope dp/dμ.
    double hugoniotPressure(double mu) const {
        if (mu < 0.0) return bulkModulus_ * mu;
        const double denominator = 1.0 - (mg_.hugoniotSlope - 1.0) * mu;
        return bulkModulus_ * mu * (1.0 + (1.0 - 0.5 * mg_.gruneisenGamma) * mu) /
               (denominator * denominator);
    }
    double hugoniotSlopeOf(double mu) const {
        if (mu < 0.0) return bulkModulus_;
        const double a = 1.0 - 0.5 * mg_.gruneisenGamma, b = mg_.hugoniotSlope - 1.0;
        const double d = 1.0 - b * mu;
        return bulkModulus_ * ((1.0 + 2.0 * a * mu) * d + 2.0 * b * mu * (1.0 + a * mu)) /
               (d * d * d);
    }

    Kind kind_;
    double rho0_;
    double bulkModulus_ = 0.0;
    MieGruneisenParams mg_;
};

}  // namespace gsph
