// SPDX-License-Identifier: MIT
// The one composition point of the library: owns the reference configuration, the state, the
// materials and the integrator of a run.
//
//   Simulation sim(std::move(ref), {HypoElastic(steel)}, options);  // builds pairs + geometry
//   sim.constrain({"clamp", clampIds, {}});                           // fixed set
//   sim.setVelocity([](const Vec3& X) { return Vec3(0, 0, -10); });
//   sim.addWall({"floor", Vec3::Zero(), Vec3::UnitZ()});             // rigid plane z = 0
//   sim.setGravity(Vec3(0, 0, -9.81));
//   sim.advanceTo(1e-3);
//
// Materials are indexed by body id. Constraints, loads, walls and initial velocities are set
// before the first step (start() or the first advanceTo()). Contact between bodies is on by
// default (SolverOptions::contact).
#pragma once

#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "boundary/constraints.hpp"
#include "integrator/energy.hpp"
#include "integrator/velocity_verlet.hpp"
#include "materials/material.hpp"
#include "neighbors/theta_search.hpp"
#include "particles/reference.hpp"
#include "particles/state.hpp"

namespace gsph {

class Simulation {
  public:
    /// Takes a reference with particles (X, θ, mass, body, space, spaces); builds its pairs and
    /// geometry unless `ref.pairs` is already filled. Throws InputError if a body has no material.
    Simulation(Reference ref, std::vector<Material> materialsByBody, SolverOptions options,
               SearchMethod search = SearchMethod::CellList);
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    void constrain(VelocityConstraint constraint);
    void setVelocity(const std::function<Vec3(const Vec3& X)>& velocity);
    /// One initial velocity per particle (size must equal the particle count).
    void setVelocities(const std::vector<Vec3>& velocities);
    void setGravity(const Vec3& g);
    /// A total force on a particle set, shared by mass (boundary/loads.hpp).
    void applyForce(SetForce force);
    void addWall(Wall wall);
    /// A force term beyond those the library composes itself (forces/force_stage.hpp); stages
    /// add their forces after the internal force, contact, walls and constant loads, in the
    /// order added.
    void addStage(std::shared_ptr<ForceStage> stage);
    /// Splits the run over processes (distributed/domain.hpp; before the first step): this
    /// process advances its own particles, and state() holds the others' only after
    /// gatherState(), on the process that writes the files. Throws InputError when the blocks
    /// leave some process no particles (VelocityVerlet::setDomain).
    void setDomain(std::shared_ptr<Domain> domain);
    /// Collective: the process that writes the files gets every particle's state (nothing to do
    /// in a serial run).
    void gatherState();

    /// Computes the initial accelerations and time step; called by the first step if needed.
    void start();
    /// Instead of start(): continues from `state`, a state of this same run after some step
    /// (read from a checkpoint, io/checkpoint.hpp), so that the steps that follow are bit-
    /// identical to those of the uninterrupted run. Constraints must be set as in that run.
    /// Throws InputError naming `source` if the state does not fit this reference.
    void resume(State state, const std::string& source);
    void step();
    /// Steps until state().time ≥ endTime (the last step is shortened to land on it). After
    /// each step calls afterStep, then stop: if that returns true, returns false at once
    /// (endTime not reached). Returns true once endTime is reached.
    bool advanceTo(double endTime, const std::function<void(const State&)>& afterStep = {},
                   const std::function<bool(const State&)>& stop = {});

    const Reference& reference() const { return ref_; }
    const State& state() const { return state_; }
    State& state() { return state_; }
    const std::vector<BodyRange>& bodies() const { return bodies_; }
    const VelocityVerlet& integrator() const { return *integrator_; }
    const SolverOptions& options() const { return options_; }
    /// The energies and momentum (integrator/energy.hpp); in a split run over every process's
    /// particles (collective: every process calls it at the same point).
    EnergyReport energy() const;
    /// Per wall (in the order added), its force on the bodies at the last force evaluation
    /// [N] (State::wallForce, so a resumed run reports what the straight run did); empty
    /// without walls or before start().
    std::vector<Vec3> wallForces() const;
    /// Per ordered pair of bodies (i, j) of bodies(), i·B + j, the force of j on i through the
    /// contact between bodies at the last force evaluation [N] (State::contactForce); empty
    /// without contact between bodies or before start().
    std::vector<Vec3> contactForces() const;

  private:
    void makeIntegrator();

    Reference ref_;
    std::vector<Material> materials_;
    SolverOptions options_;
    std::vector<BodyRange> bodies_;
    std::vector<VelocityConstraint> constraints_;
    Loads loads_;
    std::vector<Wall> walls_;
    std::vector<std::shared_ptr<ForceStage>> stages_;
    State state_;
    std::unique_ptr<VelocityVerlet> integrator_;
    std::shared_ptr<Domain> domain_;  ///< null: serial
};

}  // namespace gsph
