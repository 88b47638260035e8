// SPDX-License-Identifier: MIT
// Penalty contact between bodies and rigid walls as force stages (forces/force_stage.hpp).
// Both springs' stiffness and the particles' contact ellipsoids come from one set-up
// (contactStiffness, contactShapes: penalty_contact.hpp), so the two share it. Their springs'
// potential is the stage's potential (the ledger's contact energy), their ω² bounds go to the
// time step's frequency channel; a wall's friction goes to the external channel and its push
// f_n·v_wall is the stage's external power (walls.hpp).
#pragma once

#include <memory>
#include <vector>

#include "contact/penalty_contact.hpp"
#include "contact/walls.hpp"
#include "forces/force_stage.hpp"
#include "particles/reference.hpp"

namespace gsph {

class PairContactStage final : public ForceStage {
  public:
    explicit PairContactStage(PenaltyContact contact) : contact_(std::move(contact)) {}
    std::string name() const override { return "contact between particles"; }
    StageNeeds needs() const override { return {.frequency2 = true}; }
    StageReport addForces(const State& state, ForceChannels& out) override;
    /// Per ordered pair of bodies, the force between them: State::contactForce (history); with
    /// self-contact the broken pairs' separations (State::contactSeparation).
    void record(State& state) const override {
        contact_.bodyPairForces(state.contactForce);
        contact_.recordSeparations(state.x, state.bondIntact, state.contactSeparation);
    }
    const PenaltyContact& contact() const { return contact_; }

  private:
    PenaltyContact contact_;
};

class WallStage final : public ForceStage {
  public:
    explicit WallStage(RigidWalls walls, std::size_t particles)
        : walls_(std::move(walls)), particleForce_(particles, Vec3::Zero()) {}
    std::string name() const override { return "rigid walls"; }
    StageNeeds needs() const override { return {.external = true, .frequency2 = true}; }
    StageReport addForces(const State& state, ForceChannels& out) override;
    /// Per wall, its total force on the bodies: State::wallForce (history, restart).
    void record(State& state) const override { walls_.totalForces(state.wallForce); }
    const RigidWalls& walls() const { return walls_; }
    /// Per particle, the walls' total force on it at the last evaluation [N].
    const std::vector<Vec3>& particleForces() const { return particleForce_; }

  private:
    RigidWalls walls_;
    std::vector<Vec3> particleForce_;
};

/// Whether a run of `bodies` bodies has contact between them (PairContactStage).
inline bool contactBetweenBodies(const ContactOptions& options, std::size_t bodies) {
    return options.betweenBodies && bodies > 1;
}

/// The contact stages a run needs, in their order (pair contact, then walls): none without
/// walls and with a single body (or contact between bodies off) unless self-contact is on.
/// `pWaveSpeed2`: c_a² per particle [m²/s²], the penalty stiffness's scale (contactStiffness).
std::vector<std::unique_ptr<ForceStage>> makeContactStages(const Reference& ref,
                                                           const std::vector<double>& pWaveSpeed2,
                                                           std::size_t bodies,
                                                           const ContactOptions& options,
                                                           std::vector<Wall> walls);

}  // namespace gsph
