// SPDX-License-Identifier: MIT
// Velocity-Verlet step exactly as Algorithm 1 of the paper (DESIGN §4):
//   1. v_{n+½} = v_n + ½Δt a_n                         (then constraints at t_n + ½Δt)
//   2. x_{n+1} = x_n + Δt v_{n+½}; bonds stretched to εmax, and bonds of failed particles
//      (D ≥ 1) by the body's FailedBondRule, break (failure/brittle_bonds.hpp)
//   3. F_{n+1} from x_{n+1}, Ḟ from v_{n+½}; L = Ḟ F_{n+½}^{-1}, F_{n+½} = ½(F_n + F_{n+1})
//   4. σ_{n+1} by the body's material (Jaumann rate), P = J σ F^{-T}; models with a history
//      (Johnson–Cook) also advance ε̄p, T, D, e and book their plastic work and the energy
//      lost by failing particles in the ledger; a particle detached by broken bonds books the
//      elastic energy its stress held as fracture energy
//   5. a_{n+1} = f(x_{n+1}, σ_{n+1}, v_{n+½}) / m, f the sum of the force stages in their order
//      (forces/force_stage.hpp): the internal force with viscosity and hourglass control,
//      the softening bonds' cohesive forces, penalty contact between bodies, rigid walls (friction
//      from v_{n+½}), gravity and set forces, then the stages the caller added (addStage)
//   6. v_{n+1} = v_{n+½} + ½Δt a_{n+1}                   (then constraints at t_{n+1})
//   7. Δt_{n+1} by integrator/time_step.hpp
// Steps 3–4 are integrator/stress_update.hpp; the energy ledger is integrator/power_ledger.hpp.
// On entry `state` holds t_n, x_n, v_n, a_n, F_n, σ_n, Δt_n; on exit the same at n+1.
// Throws NumericalError (particle, time) on a NaN or an inverted particle (J ≤ 0), and on a
// collapsed time step (Δt_{n+1} not finite, ≤ 0, or below minTimeStepRatio · Δt_0); the
// message names the particle (index and reference position X), the time and the fault. The
// state is then the partially advanced one, for a final diagnostic snapshot.
// Across steps the integrator keeps nothing the next step reads that the State does not hold
// (the stress factors, SoA copies and force channels are rebuilt inside every step; the bonds'
// G and detached flags derive from State::bondIntact): resume() continues a checkpointed
// state bit for bit, provided the stages keep nothing across steps either.
// Split over processes (setDomain, distributed/domain.hpp), each process runs these steps on its
// own particles, with the neighbours' x, v shared after step 2 (every particle's x with contact
// between bodies) and their force factors after step 4; Δt is the minimum over the processes
// and the ledger's powers their sum.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "boundary/constraints.hpp"
#include "boundary/loads.hpp"
#include "contact/contact_stages.hpp"
#include "distributed/domain.hpp"
#include "failure/brittle_bonds.hpp"
#include "forces/force_stage.hpp"
#include "forces/internal_force.hpp"
#include "integrator/body_range.hpp"
#include "integrator/power_ledger.hpp"
#include "integrator/stress_update.hpp"
#include "materials/material.hpp"
#include "particles/reference.hpp"
#include "particles/state.hpp"

namespace gsph {

struct SolverOptions {
    double cfl = 0.3;                 ///< Courant number of the time step
    ViscosityCoefficients viscosity;  ///< β1, β2 (paper: Monaghan)
    double hourglass = 0.0;           ///< α of forces/hourglass.hpp (0 = off)
    /// The hourglass penalty's modulus in plastic flow (forces/hourglass.hpp)
    HourglassModulus hourglassModulus = HourglassModulus::Elastic;
    double fixedTimeStep = 0.0;  ///< > 0: use this Δt instead of the CFL estimate
    /// εmax of brittle bonds per body id (failure/brittle_bonds.hpp); a body without an entry,
    /// or with 0, never breaks.
    std::vector<double> bondStretch;
    /// Fracture energy G0 [J/m²] per body id: > 0 makes the body's bonds that break by stretch
    /// soften (forces/cohesive_bonds.hpp; εmax is then their onset). A body without an entry,
    /// or with 0, breaks them sharply.
    std::vector<double> fractureEnergy;
    /// Initial cracks: the bonds crossing any of these patches start broken (at initialize(),
    /// failure/brittle_bonds.hpp), in any body, breakable or not.
    std::vector<CrackPatch> precracks;
    /// Per body id: when Johnson–Cook damage breaks bonds (failure/brittle_bonds.hpp: Either
    /// or Both ends failed; ductile fracture). A body without an entry keeps them.
    std::vector<FailedBondRule> failedBonds;
    /// > 0: a stable Δt below this fraction of the run's first Δt (State::initialDt) stops the
    /// run with NumericalError naming the particle that limits it (0 = only Δt ≤ 0 or NaN).
    double minTimeStepRatio = 0.0;
    ContactOptions contact;  ///< penalty contact between bodies and with walls
};

/// True when some body's bonds soften (SolverOptions::fractureEnergy > 0): the run composes the
/// cohesive stage, and its state holds the cohesive arrays and its history the cohesive work.
inline bool softensBonds(const SolverOptions& o) {
    for (double g : o.fractureEnergy)
        if (g > 0.0) return true;
    return false;
}

/// Wall time spent in each phase of the steps taken so far [s] (for benchmarks and logs).
struct PhaseTimes {
    double kinematicsAndStress = 0.0;  ///< steps 3–4
    double forces = 0.0;               ///< step 5: the internal force stage
    double contact = 0.0;              ///< step 5: the other stages (contact, walls, loads, …)
    double other = 0.0;                ///< kicks, drift, constraints, energy ledger, Δt
    /// Of the above, waiting for the ghosts' columns of a split run (distributed/domain.hpp)
    double exchange = 0.0;
};

class VelocityVerlet {
  public:
    /// Composes the stages of a run: the internal force, then contact between bodies and walls
    /// (as options.contact and `walls` ask), then the constant loads, then `extraStages` in
    /// their order. Throws InputError on bad options, constraints, walls or loads.
    VelocityVerlet(const Reference& ref, std::vector<BodyRange> bodies,
                   std::vector<VelocityConstraint> constraints, SolverOptions options,
                   const Loads& loads, std::vector<Wall> walls,
                   std::vector<std::shared_ptr<ForceStage>> extraStages = {});
    // The stages read the stress update's arrays by reference: the integrator stays in place.
    VelocityVerlet(const VelocityVerlet&) = delete;
    VelocityVerlet& operator=(const VelocityVerlet&) = delete;

    /// Computes a_n, the stress factors and Δt_n for a state (once, before the first step).
    void initialize(State& state);
    /// Continues from a state an earlier run left after a step (a checkpoint): derives the
    /// bonds' data from state.bondIntact and takes a_n, Δt_n and the ledger's powers as they
    /// are (recomputing a_n would not give the same bits: the step's viscosity saw v_{n−½}).
    void resume(const State& state);
    void step(State& state);
    /// Splits the run over the domain's processes (before initialize() or resume()): this
    /// process then advances only its own particles. Throws InputError when the blocks leave
    /// some process no particles.
    void setDomain(std::shared_ptr<Domain> domain);
    const Domain& domain() const { return *domain_; }
    Domain& domain() { return *domain_; }
    /// The particles this process advances (all of them unless split).
    ParticleRange owned() const { return owned_; }

    const SolverOptions& options() const { return options_; }
    const PhaseTimes& phaseTimes() const { return times_; }
    const BrittleBonds& bonds() const { return bonds_; }
    const StressUpdate& stressUpdate() const { return stress_; }
    const ForceChannels& channels() const { return channels_; }
    /// The stages in the order they add their forces.
    const std::vector<std::shared_ptr<ForceStage>>& stages() const { return stages_; }
    /// The stage of type T (the first), or null.
    template <class T>
    const T* stage() const {
        for (const auto& s : stages_)
            if (const auto* t = dynamic_cast<const T*>(s.get())) return t;
        return nullptr;
    }

  private:
    void computeAccelerations(State& state);
    /// The ghosts' columns of one exchange point (distributed/domain.hpp).
    void shareGhosts(State& state, GhostColumns which);
    /// The ledger's powers now, summed over the processes.
    LedgerPowers powersNow(const State& state);

    const Reference& ref_;
    std::vector<BodyRange> bodies_;
    std::vector<VelocityConstraint> constraints_;
    SolverOptions options_;
    BrittleBonds bonds_;
    StressUpdate stress_;
    std::vector<std::shared_ptr<ForceStage>> stages_;
    ForceChannels channels_;
    double stagePower_ = 0.0;  ///< Σ of the stages' external power at the last evaluation [W]
    PhaseTimes times_;
    std::shared_ptr<Domain> domain_ = std::make_shared<Domain>();
    ParticleRange owned_;
    std::vector<GhostArray> ghostArrays_;  ///< scratch of shareGhosts
};

}  // namespace gsph
