// SPDX-License-Identifier: MIT
#include "contact/contact_stages.hpp"

namespace gsph {

StageReport PairContactStage::addForces(const State& state, ForceChannels& out) {
    StageReport report;
    contact_.restrictTo(out.owned, out.domain);
    report.potential = contact_.addForces(state.x, out.force, out.frequency2, state.bondIntact,
                                          state.contactSeparation);
    return report;
}

StageReport WallStage::addForces(const State& state, ForceChannels& out) {
    const WallResult w =
        walls_.addForces(state.time, state.dt, state.x, state.v, out.force, out.external,
                         out.frequency2, particleForce_, out.owned, out.domain);
    StageReport report;
    report.potential = w.energy;
    report.externalPower = w.pushPower;
    return report;
}

std::vector<std::unique_ptr<ForceStage>> makeContactStages(const Reference& ref,
                                                           const std::vector<double>& pWaveSpeed2,
                                                           std::size_t bodies,
                                                           const ContactOptions& options,
                                                           std::vector<Wall> walls) {
    std::vector<std::unique_ptr<ForceStage>> stages;
    const bool pairs = contactBetweenBodies(options, bodies) || options.selfContact;
    if (!pairs && walls.empty()) return stages;
    const std::vector<double> k = contactStiffness(ref, pWaveSpeed2, options.penalty);
    ContactShapes shapes = contactShapes(ref, options.distance);
    // Walls are checked (and their normals normalised) even when the pair contact alone runs.
    RigidWalls rigidWalls(ref, std::move(walls), k, shapes);
    if (pairs) {
        PenaltyContact contact(ref, k, std::move(shapes), options);
        if (contact.active())
            stages.push_back(std::make_unique<PairContactStage>(std::move(contact)));
    }
    if (rigidWalls.active())
        stages.push_back(std::make_unique<WallStage>(std::move(rigidWalls),
                                                     static_cast<std::size_t>(ref.size())));
    return stages;
}

}  // namespace gsph
