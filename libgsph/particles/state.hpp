// SPDX-License-Identifier: MIT
// The evolving state of a run: exactly what a checkpoint stores (style habit 2). Everything
// else (stress measures used by the force, sound speeds) is derived from it and the Reference.
#pragma once

#include <cstdint>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "core/types.hpp"
#include "particles/fields.hpp"

namespace gsph {

/// Work done by the non-conservative parts of the model, accumulated over the run [J].
struct EnergyLedger {
    double viscousWork = 0.0;    ///< dissipated by artificial viscosity (≥ 0)
    double hourglassWork = 0.0;  ///< stored/dissipated by the hourglass control
    double boundaryWork = 0.0;   ///< done on the body by prescribed-velocity particles
    /// Elastic energy the failed particles lost when their damage reached 1 (DESIGN §5).
    double damageDissipation = 0.0;
    /// Elastic energy released by brittle bond failure [J]: the stored energy of the particles
    /// whose surviving bonds no longer span the space when they were detached (their stress is
    /// set to zero, failure/brittle_bonds.hpp; docs/theory.md "Fracture energy").
    double fractureEnergy = 0.0;
    /// Done on the bodies by gravity, set forces and walls (their push and friction) [J].
    double externalWork = 0.0;
    /// Potential of the penalty springs (contact between bodies, walls) at the current x [J]:
    /// a function of x, stored so that the history and a restart need no contact search.
    double contactEnergy = 0.0;
    /// Taken out of the motion by the cohesive forces of softening bonds [J] (their work on the
    /// opening, forces/cohesive_bonds.hpp); at a bond's full separation its whole share is
    /// dissipated.
    double cohesiveWork = 0.0;
    // Powers at the current time, for the trapezoidal rule of the next step [W].
    double viscousPower = 0.0;
    double hourglassPower = 0.0;
    double boundaryPower = 0.0;
    double externalPower = 0.0;
    double cohesivePower = 0.0;
};

struct State {
    double time = 0.0;
    double dt = 0.0;  ///< the step the integrator takes next
    /// Δt_0 of the run (set when the integrator starts): the reference of the time-step
    /// collapse guard (SolverOptions::minTimeStepRatio).
    double initialDt = 0.0;
    long step = 0;
    std::vector<Vec3> x;                ///< current position [m]
    std::vector<Vec3> v;                ///< velocity [m/s]
    std::vector<Vec3> acceleration;     ///< [m/s²], consistent with x and cauchy
    std::vector<Mat3> F;                ///< deformation gradient
    std::vector<Mat3> cauchy;           ///< Cauchy stress σ [Pa]
    std::vector<double> plasticStrain;  ///< effective plastic strain ε̄p (DESIGN §5)
    std::vector<double> temperature;    ///< [K]
    std::vector<double> damage;         ///< Johnson–Cook damage D ∈ [0, 1]
    /// Specific internal energy of compression e [J/kg], ∫ −p tr(D)/ρ dt: the energy term of the
    /// Mie–Grüneisen equation of state (materials/eos.hpp); 0 for models that do not need it.
    std::vector<double> internalEnergy;
    /// The local driver ω = Σ Δε̄p/εf of a nonlocal damage (failure/nonlocal_damage.hpp), whose
    /// average over the material length is D; 0 for local damage and models without damage.
    std::vector<double> damageDriver;
    /// Work dissipated by plastic flow in the particle over the run, Σ V J Δw_p [J] (≥ 0): kept
    /// per particle rather than in the ledger so that the bodies' shares add up to the run's
    /// plastic work exactly (integrator/energy.hpp).
    std::vector<double> plasticWork;
    /// Per pair of Reference::pairs (CSR order): 1 while the bond holds, 0 once broken for good
    /// (DESIGN §5). Both directions (a,b) and (b,a) carry the same value.
    std::vector<std::uint8_t> bondIntact;
    /// Per rigid wall (in the order added), its total force on the bodies at the last force
    /// evaluation [N] (history rows; empty without walls).
    std::vector<Vec3> wallForce;
    /// Per ordered pair of bodies (i, j), i·B + j over the B bodies in particle order, the force
    /// of j's particles on i's through the contact between bodies at the last force evaluation
    /// [N] (history rows; empty without contact between bodies).
    std::vector<Vec3> contactForce;
    /// Per pair of Reference::pairs (CSR order), with self-contact: the largest distance a pair
    /// whose bond broke has had since, capped at its reference distance [m] (0 while the bond
    /// holds or before it was first measured; contact/penalty_contact.hpp); empty without
    /// self-contact.
    std::vector<double> contactSeparation;
    /// Per pair of Reference::pairs (CSR order), in bodies with a fracture energy: the normal
    /// stress n·σ̄·n across the bond when it broke by stretch [Pa] (> 0: it softens, carrying a
    /// cohesive force; 0: it holds, or broke without cohesion; forces/cohesive_bonds.hpp); empty
    /// without such bodies.
    std::vector<double> cohesiveTraction;
    /// Per pair, beside cohesiveTraction: the largest stretch |x_ab|/|X_ab| − 1 the softening bond
    /// has had since it broke.
    std::vector<double> cohesiveStretch;
    EnergyLedger ledger;

    /// Calls visit(field, array) for every array of the state, in a fixed order, with its entry
    /// of the field registry (particles/fields.hpp: name, unit, extent, where it is saved). The
    /// one list of what the state holds: checkpoints, restarts and snapshots go through it, so a
    /// field added here is saved and restored without more code.
    /// Array types: std::vector<Vec3>, std::vector<Mat3>, std::vector<double>,
    /// std::vector<std::uint8_t>.
    template <class Visitor>
    void forEachArray(Visitor&& visit) {
        std::apply([&](const auto&... e) { (visit(*e.first, this->*e.second), ...); }, arrays());
    }
    template <class Visitor>
    void forEachArray(Visitor&& visit) const {
        std::apply([&](const auto&... e) { (visit(*e.first, this->*e.second), ...); }, arrays());
    }
    /// Calls visit(field, a's array, b's array) for every array of two states (State or const
    /// State), in forEachArray's order: to copy or compare arrays of two states.
    template <class A, class B, class Visitor>
    static void forEachArrayOf(A& a, B& b, Visitor&& visit) {
        std::apply([&](const auto&... e) { (visit(*e.first, a.*e.second, b.*e.second), ...); },
                   arrays());
    }
    /// Calls visit(name, value) for every scalar of the state (time, step, ledger), in order;
    /// value is a double or a long. Like forEachArray, the one list checkpoints go through.
    template <class Visitor>
    void forEachScalar(Visitor&& visit) {
        visitScalars(*this, visit);
    }
    template <class Visitor>
    void forEachScalar(Visitor&& visit) const {
        visitScalars(*this, visit);
    }

  private:
    template <class Self, class Visitor>
    static void visitScalars(Self& s, Visitor& visit) {
        visit("time", s.time);
        visit("dt", s.dt);
        visit("initial_dt", s.initialDt);
        visit("step", s.step);
        visit("ledger/viscous_work", s.ledger.viscousWork);
        visit("ledger/hourglass_work", s.ledger.hourglassWork);
        visit("ledger/boundary_work", s.ledger.boundaryWork);
        visit("ledger/damage_dissipation", s.ledger.damageDissipation);
        visit("ledger/fracture_energy", s.ledger.fractureEnergy);
        visit("ledger/viscous_power", s.ledger.viscousPower);
        visit("ledger/hourglass_power", s.ledger.hourglassPower);
        visit("ledger/boundary_power", s.ledger.boundaryPower);
        visit("ledger/external_work", s.ledger.externalWork);
        visit("ledger/contact_energy", s.ledger.contactEnergy);
        visit("ledger/external_power", s.ledger.externalPower);
        visit("ledger/cohesive_work", s.ledger.cohesiveWork);
        visit("ledger/cohesive_power", s.ledger.cohesivePower);
    }

  public:
    /// The checkpoint format 3.N that added the scalar `name` (0: every 3.x file has it); an
    /// older file reads it as 0.
    static int scalarSinceMinor(std::string_view name) {
        return name.starts_with("ledger/cohesive_") ? 3 : 0;
    }

  private:
    // The arrays in order, each with its field (particles/fields.hpp).
    static constexpr auto arrays() {
        return std::tuple{std::pair{&fields::kPosition, &State::x},
                          std::pair{&fields::kVelocity, &State::v},
                          std::pair{&fields::kAcceleration, &State::acceleration},
                          std::pair{&fields::kDeformationGradient, &State::F},
                          std::pair{&fields::kStress, &State::cauchy},
                          std::pair{&fields::kPlasticStrain, &State::plasticStrain},
                          std::pair{&fields::kTemperature, &State::temperature},
                          std::pair{&fields::kDamage, &State::damage},
                          std::pair{&fields::kInternalEnergy, &State::internalEnergy},
                          std::pair{&fields::kDamageDriver, &State::damageDriver},
                          std::pair{&fields::kPlasticWork, &State::plasticWork},
                          std::pair{&fields::kBondIntact, &State::bondIntact},
                          std::pair{&fields::kWallForce, &State::wallForce},
                          std::pair{&fields::kContactForce, &State::contactForce},
                          std::pair{&fields::kContactSeparation, &State::contactSeparation},
                          std::pair{&fields::kCohesiveTraction, &State::cohesiveTraction},
                          std::pair{&fields::kCohesiveStretch, &State::cohesiveStretch}};
    }

  public:
    /// Room temperature of a state at rest unless the material sets another [K].
    static constexpr double kRoomTemperature = 293.15;

    /// State at rest in the reference configuration, every bond of `pairCount` intact.
    static State atRest(const std::vector<Vec3>& X, std::size_t pairCount = 0) {
        State s;
        const std::size_t n = X.size();
        s.x = X;
        s.v.assign(n, Vec3::Zero());
        s.acceleration.assign(n, Vec3::Zero());
        s.F.assign(n, Mat3::Identity());
        s.cauchy.assign(n, Mat3::Zero());
        s.plasticStrain.assign(n, 0.0);
        s.temperature.assign(n, kRoomTemperature);
        s.damage.assign(n, 0.0);
        s.internalEnergy.assign(n, 0.0);
        s.damageDriver.assign(n, 0.0);
        s.plasticWork.assign(n, 0.0);
        s.bondIntact.assign(pairCount, 1);
        return s;
    }
};

}  // namespace gsph
