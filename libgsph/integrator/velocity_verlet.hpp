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
//   5. a_{n+1} = f(x_{n+1}, σ_{n+1}, v_{n+½}) / m, f = internal force + penalty contact between
//      bodies + rigid walls (friction from v_{n+½}) + gravity and set forces (contact/,
//      boundary/loads.hpp)
//   6. v_{n+1} = v_{n+½} + ½Δt a_{n+1}                   (then constraints at t_{n+1})
//   7. Δt_{n+1} = CFL · min_a ℓ_a/(c_a + |v_a|), ℓ_a = current particle spacing; a particle in
//      contact takes CFL / √(((c_a + |v_a|)/ℓ_a)² + ω_a²/4), ω_a its contact frequency bound
// On entry `state` holds t_n, x_n, v_n, a_n, F_n, σ_n, Δt_n; on exit the same at n+1.
// Throws NumericalError (particle, time) on a NaN or an inverted particle (J ≤ 0), and on a
// collapsed time step (Δt_{n+1} not finite, ≤ 0, or below minTimeStepRatio · Δt_0); the
// message names the particle (index and reference position X), the time and the fault. The
// state is then the partially advanced one, for a final diagnostic snapshot.
// Across steps the integrator keeps nothing the next step reads that the State does not hold
// (the stress factors, SoA copies and force parts are rebuilt inside every step; the bonds'
// G and detached flags derive from State::bondIntact): resume() continues a checkpointed
// state bit for bit.
#pragma once

#include <cstdint>
#include <vector>

#include "boundary/constraints.hpp"
#include "boundary/loads.hpp"
#include "contact/penalty_contact.hpp"
#include "contact/walls.hpp"
#include "failure/brittle_bonds.hpp"
#include "forces/internal_force.hpp"
#include "materials/material.hpp"
#include "particles/reference.hpp"
#include "particles/state.hpp"

namespace gsph {

struct SolverOptions {
    double cfl = 0.3;                 ///< Courant number of the time step
    ViscosityCoefficients viscosity;  ///< β1, β2 (paper: Monaghan)
    double hourglass = 0.0;           ///< α of forces/hourglass.hpp (0 = off)
    double fixedTimeStep = 0.0;       ///< > 0: use this Δt instead of the CFL estimate
    /// εmax of brittle bonds per body id (failure/brittle_bonds.hpp); a body without an entry,
    /// or with 0, never breaks.
    std::vector<double> bondStretch;
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

/// Contiguous range of one body and its material.
struct BodyRange {
    Index begin = 0, end = 0;
    const Material* material = nullptr;
};

/// Wall time spent in each phase of the steps taken so far [s] (for benchmarks and logs).
struct PhaseTimes {
    double kinematicsAndStress = 0.0;  ///< steps 3–4
    double forces = 0.0;               ///< step 5 without contact
    double contact = 0.0;              ///< step 5: contact search and forces, walls, loads
    double other = 0.0;                ///< kicks, drift, constraints, energy ledger, Δt
};

/// Scratch arrays of a step, sized once (no allocation inside the step).
struct StepWorkspace {
    StressFactors factors;
    ParticleFields fields;              ///< SoA x, v, F, X for the pair loops
    std::vector<StencilBlocks> blocks;  ///< per body: stencil and CSR blocks
    ForceParts parts;
    std::vector<Vec3> force;
    std::vector<double> lengthScale;    ///< current spacing ℓ_a
    std::vector<std::uint8_t> failure;  ///< per particle: why steps 3–4 failed (0: they did not)
    /// Per particle, this step's V J Δw_p and failure loss [J] (sized only when a body's model
    /// tracks a history; summed into the ledger in a fixed order).
    std::vector<double> plasticWork, damageDissipation;
    /// Per particle, the elastic energy released when it was detached [J] (sized only when
    /// bonds can break; written by the detaching step alone, zero before and after it).
    std::vector<double> fractureEnergy;
    std::vector<double> partialSums;  ///< scratch of deterministicSum
    // Contact and loads (sized only when the run has them).
    std::vector<double> contactFrequency2;  ///< ω_a² bound of the contact springs [1/s²]
    std::vector<Vec3> externalForce;        ///< loads + wall friction: their power is Σ f·v
    std::vector<Vec3> wallForce;            ///< the walls' force on each particle [N]
    void resize(std::size_t n);
};

class VelocityVerlet {
  public:
    VelocityVerlet(const Reference& ref, std::vector<BodyRange> bodies,
                   std::vector<VelocityConstraint> constraints, SolverOptions options,
                   const Loads& loads, std::vector<Wall> walls);

    /// Computes a_n, the stress factors and Δt_n for a state (once, before the first step).
    void initialize(State& state);
    /// Continues from a state an earlier run left after a step (a checkpoint): derives the
    /// bonds' data from state.bondIntact and takes a_n, Δt_n and the ledger's powers as they
    /// are (recomputing a_n would not give the same bits: the step's viscosity saw v_{n−½}).
    void resume(const State& state);
    void step(State& state);

    const StepWorkspace& workspace() const { return work_; }
    const SolverOptions& options() const { return options_; }
    const PhaseTimes& phaseTimes() const { return times_; }
    const BrittleBonds& bonds() const { return bonds_; }
    const PenaltyContact& contact() const { return pairContact_; }
    const RigidWalls& walls() const { return walls_; }

  private:
    void updateKinematicsAndStress(State& state, double dt, bool atRest);
    void throwOnFailure(const State& state) const;
    void packKinematics(const State& state, Index a);
    void computeAccelerations(State& state);
    void setUpContactAndLoads(const Loads& loads, std::vector<Wall> walls);
    void addContactAndLoads(State& state);
    double externalPower(const State& state);
    void applyConstraints(State& state, double t);
    double nonConservativePower(const State& state, const std::vector<Vec3>& part);
    void bookDissipation(State& state);
    double boundaryPower(const State& state) const;
    double stableTimeStep(const State& state) const;

    const Reference& ref_;
    std::vector<BodyRange> bodies_;
    std::vector<VelocityConstraint> constraints_;
    SolverOptions options_;
    BrittleBonds bonds_;
    PenaltyContact pairContact_;
    RigidWalls walls_;
    std::vector<Vec3> load_;      ///< constant load per particle (empty: none)
    double wallPushPower_ = 0.0;  ///< Σ f_n·v_wall at the last force evaluation [W]
    StepWorkspace work_;
    PhaseTimes times_;
};

}  // namespace gsph
