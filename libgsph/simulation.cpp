// SPDX-License-Identifier: MIT
#include "simulation.hpp"

#include <algorithm>
#include <string>

#include "contact/contact_stages.hpp"
#include "core/error.hpp"
#include "io/checkpoint.hpp"
#include "reference/reference_builder.hpp"

namespace gsph {

Simulation::Simulation(Reference ref, std::vector<Material> materialsByBody, SolverOptions options,
                       SearchMethod search)
    : ref_(std::move(ref)), materials_(std::move(materialsByBody)), options_(options) {
    completeReference(ref_, search);
    // Bodies are contiguous ranges (Reference invariant, checked by buildPairs).
    for (Index a = 0; a < ref_.size();) {
        const Index id = ref_.body[static_cast<std::size_t>(a)];
        Index end = a;
        while (end < ref_.size() && ref_.body[static_cast<std::size_t>(end)] == id) ++end;
        if (id < 0 || static_cast<std::size_t>(id) >= materials_.size())
            throw InputError("body " + std::to_string(id) + " has no material");
        bodies_.push_back({a, end, &materials_[static_cast<std::size_t>(id)]});
        a = end;
    }
    state_ = State::atRest(ref_.X, static_cast<std::size_t>(ref_.pairs.pairs()));
    // Each body starts at its material's room temperature (Johnson–Cook Tr).
    for (const BodyRange& body : bodies_) {
        const double T0 = roomTemperature(*body.material, State::kRoomTemperature);
        for (Index a = body.begin; a < body.end; ++a)
            state_.temperature[static_cast<std::size_t>(a)] = T0;
    }
}

void Simulation::constrain(VelocityConstraint constraint) {
    if (integrator_) throw Error("constraints must be set before the first step");
    constraints_.push_back(std::move(constraint));
}

void Simulation::setVelocity(const std::function<Vec3(const Vec3& X)>& velocity) {
    if (integrator_) throw Error("initial velocities must be set before the first step");
    for (std::size_t a = 0; a < state_.v.size(); ++a) state_.v[a] = velocity(ref_.X[a]);
}

void Simulation::setVelocities(const std::vector<Vec3>& velocities) {
    if (integrator_) throw Error("initial velocities must be set before the first step");
    if (velocities.size() != state_.v.size())
        throw InputError("setVelocities: " + std::to_string(velocities.size()) +
                         " velocities for " + std::to_string(state_.v.size()) + " particles");
    state_.v = velocities;
}

void Simulation::setGravity(const Vec3& g) {
    if (integrator_) throw Error("gravity must be set before the first step");
    loads_.gravity = g;
}

void Simulation::applyForce(SetForce force) {
    if (integrator_) throw Error("forces must be set before the first step");
    loads_.setForces.push_back(std::move(force));
}

void Simulation::addWall(Wall wall) {
    if (integrator_) throw Error("walls must be set before the first step");
    walls_.push_back(std::move(wall));
}

void Simulation::addStage(std::shared_ptr<ForceStage> stage) {
    if (integrator_) throw Error("force stages must be added before the first step");
    if (!stage) throw Error("addStage: no stage");
    stages_.push_back(std::move(stage));
}

std::vector<Vec3> Simulation::wallForces() const {
    return integrator_ ? state_.wallForce : std::vector<Vec3>{};
}

std::vector<Vec3> Simulation::contactForces() const {
    return integrator_ ? state_.contactForce : std::vector<Vec3>{};
}

// The one place the integrator is built: a fresh start and a resumed run see the same
// constraints, loads and walls.
void Simulation::makeIntegrator() {
    integrator_ = std::make_unique<VelocityVerlet>(ref_, bodies_, constraints_, options_, loads_,
                                                   walls_, stages_);
    if (domain_) integrator_->setDomain(domain_);
}

void Simulation::setDomain(std::shared_ptr<Domain> domain) {
    if (integrator_) throw Error("the domain must be set before the first step");
    domain_ = std::move(domain);
}

EnergyReport Simulation::energy() const {
    if (!integrator_ || !domain_ || domain_->processes() == 1)
        return measureEnergy(ref_, state_, bodies_);
    return measureEnergy(ref_, state_, bodies_, integrator_->owned(), domain_.get());
}

void Simulation::gatherState() {
    if (domain_ && domain_->processes() > 1) domain_->gather(state_);
}

void Simulation::start() {
    if (integrator_) return;
    makeIntegrator();
    integrator_->initialize(state_);
}

void Simulation::resume(State state, const std::string& source) {
    if (integrator_) throw Error("resume() must come before the first step");
    State expected = State::atRest(ref_.X, static_cast<std::size_t>(ref_.pairs.pairs()));
    expected.wallForce.assign(walls_.size(), Vec3::Zero());
    if (contactBetweenBodies(options_.contact, bodies_.size()))
        expected.contactForce.assign(bodies_.size() * bodies_.size(), Vec3::Zero());
    if (options_.contact.selfContact) {
        expected.contactSeparation.assign(expected.bondIntact.size(), 0.0);
        // A state saved without self-contact has measured no separation: zeros (the pairs'
        // current distances are taken at their next evaluation).
        if (state.contactSeparation.empty())
            state.contactSeparation.assign(expected.bondIntact.size(), 0.0);
    }
    if (softensBonds(options_)) {
        expected.cohesiveTraction.assign(expected.bondIntact.size(), 0.0);
        expected.cohesiveStretch.assign(expected.bondIntact.size(), 0.0);
        // A state saved without softening bonds has none softening.
        if (state.cohesiveTraction.empty()) {
            state.cohesiveTraction.assign(expected.bondIntact.size(), 0.0);
            state.cohesiveStretch.assign(expected.bondIntact.size(), 0.0);
        }
    }
    checkStateShape(state, expected, source);
    state_ = std::move(state);
    makeIntegrator();
    integrator_->resume(state_);
}

void Simulation::step() {
    start();
    integrator_->step(state_);
}

bool Simulation::advanceTo(double endTime, const std::function<void(const State&)>& afterStep,
                           const std::function<bool(const State&)>& stop) {
    start();
    while (state_.time < endTime) {
        // Land on endTime rather than overshoot it (1e-12 keeps round-off from adding a step).
        const double remaining = endTime - state_.time;
        if (remaining < 1e-12 * std::max(1.0, endTime)) break;
        if (state_.dt > remaining) state_.dt = remaining;
        integrator_->step(state_);
        if (afterStep) afterStep(state_);
        if (stop && stop(state_)) return false;
    }
    return true;
}

}  // namespace gsph
