// SPDX-License-Identifier: MIT
#include "integrator/velocity_verlet.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "forces/cohesive_bonds.hpp"
#include "forces/hoop_stress_stage.hpp"
#include "forces/internal_force_stage.hpp"
#include "integrator/power_ledger.hpp"
#include "integrator/time_step.hpp"

namespace gsph {
namespace {

// A per-body setting spread over the particles; bodies without an entry get `fallback` (εmax 0:
// never break; FailedBondRule::Keep).
template <class T>
std::vector<T> byParticle(const Reference& ref, const std::vector<T>& byBody, T fallback) {
    std::vector<T> out(static_cast<std::size_t>(ref.size()), fallback);
    for (std::size_t a = 0; a < out.size(); ++a) {
        const auto body = static_cast<std::size_t>(ref.body[a]);
        if (body < byBody.size()) out[a] = byBody[body];
    }
    return out;
}

void checkOptions(const SolverOptions& o) {
    if (!(o.cfl > 0.0 && o.cfl <= 1.0))
        throw InputError("CFL number must lie in (0, 1], got " + std::to_string(o.cfl));
    if (o.hourglass < 0.0) throw InputError("hourglass coefficient must be ≥ 0");
    if (o.viscosity.linear < 0.0 || o.viscosity.quadratic < 0.0)
        throw InputError("artificial viscosity coefficients must be ≥ 0");
    for (double g : o.fractureEnergy)
        if (!(g >= 0.0) || !std::isfinite(g))
            throw InputError("fracture energy G0 must be finite and ≥ 0, got " + std::to_string(g));
    if (!(o.viscosity.switchMach >= 0.0))
        throw InputError("the viscosity switch's Mach number M0 must be ≥ 0 (0 = off)");
}

// 1 per particle of a body with a fracture energy; empty when no body has one.
std::vector<std::uint8_t> softeningFlags(const Reference& ref, const SolverOptions& o) {
    if (!softensBonds(o)) return {};
    std::vector<std::uint8_t> flags;
    for (double g : byParticle(ref, o.fractureEnergy, 0.0)) flags.push_back(g > 0.0 ? 1 : 0);
    return flags;
}

TimeStepRule timeStepRule(const SolverOptions& o) {
    return {o.cfl, o.fixedTimeStep, o.minTimeStepRatio};
}

}  // namespace

VelocityVerlet::VelocityVerlet(const Reference& ref, std::vector<BodyRange> bodies,
                               std::vector<VelocityConstraint> constraints, SolverOptions options,
                               const Loads& loads, std::vector<Wall> walls,
                               std::vector<std::shared_ptr<ForceStage>> extraStages)
    : ref_(ref),
      bodies_(std::move(bodies)),
      constraints_(std::move(constraints)),
      options_(options),
      bonds_(ref, byParticle(ref, options_.bondStretch, 0.0),
             byParticle(ref, options_.failedBonds, FailedBondRule::Keep),
             !options_.precracks.empty(), softeningFlags(ref, options_)),
      stress_(ref, bodies_, bonds_, options_.viscosity, options_.hourglassModulus) {
    checkOptions(options_);
    checkConstraints(constraints_, ref);
    const auto n = static_cast<std::size_t>(ref.size());
    // The stages, in the order they add their forces.
    std::vector<double> youngsModulus, pWaveSpeed2(n, 0.0);
    for (const BodyRange& body : bodies_) {
        const ElasticConstants& e = elasticConstants(*body.material);
        youngsModulus.push_back(e.youngsModulus);
        for (Index a = body.begin; a < body.end; ++a)
            pWaveSpeed2[static_cast<std::size_t>(a)] = e.pWaveModulus() / e.density;
    }
    stages_.push_back(std::make_shared<InternalForceStage>(
        ref, std::move(youngsModulus), stress_.fields(), stress_.factors(), stress_.blocks(),
        stress_.staged(), stress_.rows(), options_.viscosity, options_.hourglass,
        options_.hourglassModulus, bonds_));
    if (softensBonds(options_))
        stages_.push_back(std::make_shared<CohesiveBondStage>(
            ref, bonds_, byParticle(ref, options_.bondStretch, 0.0),
            byParticle(ref, options_.fractureEnergy, 0.0)));
    if (ref.dim.axisymmetric) stages_.push_back(std::make_shared<HoopStressStage>(ref));
    for (auto& stage :
         makeContactStages(ref, pWaveSpeed2, bodies_.size(), options_.contact, std::move(walls)))
        stages_.push_back(std::move(stage));
    if (!loads.empty()) stages_.push_back(std::make_shared<ConstantLoadStage>(ref, loads));
    for (auto& stage : extraStages) stages_.push_back(std::move(stage));
    // The channels the stages write.
    channels_.force.assign(n, Vec3::Zero());
    StageNeeds needs;
    for (const auto& stage : stages_) {
        const StageNeeds s = stage->needs();
        needs.viscous |= s.viscous;
        needs.hourglass |= s.hourglass;
        needs.cohesive |= s.cohesive;
        needs.external |= s.external;
        needs.frequency2 |= s.frequency2;
    }
    if (needs.viscous) channels_.parts.viscous.assign(n, Vec3::Zero());
    if (needs.hourglass) channels_.parts.hourglass.assign(n, Vec3::Zero());
    if (needs.cohesive) channels_.parts.cohesive.assign(n, Vec3::Zero());
    if (needs.external) channels_.external.assign(n, Vec3::Zero());
    if (needs.frequency2) channels_.frequency2.assign(n, 0.0);
    owned_ = {0, ref.size()};
    channels_.owned = owned_;
}

void VelocityVerlet::setDomain(std::shared_ptr<Domain> domain) {
    domain_ = std::move(domain);
    owned_ = domain_->split(ref_, stress_.blocks(), !bonds_.enabled());
    channels_.owned = owned_;
    channels_.domain = domain_.get();
    stress_.restrictTo(owned_);
    if (stress_.averagesDriver())
        domain_->addHalo(GhostColumns::DamageDriver, stress_.driverReads(),
                         "the nonlocal damage's average");
}

void VelocityVerlet::shareGhosts(State& state, GhostColumns which) {
    if (domain_->processes() == 1) return;
    ghostArrays_.clear();
    const auto add = [&](auto& field) {
        for (int c = 0; c < std::decay_t<decltype(field)>::kComponents; ++c)
            ghostArrays_.push_back(ghostArray(field.component(c)));
    };
    const double t0 = omp_get_wtime();
    if (which == GhostColumns::DamageDriver) {
        ghostArrays_ = {ghostArray(state.damageDriver.data())};
        domain_->shareGhosts(which, ghostArrays_);
    } else if (which == GhostColumns::Motion) {
        // The state's x, v (the bonds' stretch and released energy read them), then the SoA
        // copies the stress update reads.
        ghostArrays_ = {ghostArray(state.x.data()), ghostArray(state.v.data())};
        domain_->shareGhosts(which, ghostArrays_);
        const std::span<const Index> ghosts = domain_->ghosts();
        parallelFor(static_cast<Index>(ghosts.size()),
                    [&](Index g) { stress_.pack(state, ghosts[static_cast<std::size_t>(g)]); });
    } else {
        StressFactors& f = stress_.factors();
        add(f.K);
        add(f.N);
        add(stress_.fields().F);
        for (std::vector<double>* column :
             {&f.soundSpeed, &f.density, &f.viscositySwitch, &f.hourglassScale})
            ghostArrays_.push_back(ghostArray(column->data()));
        // Bonds that break: a failed neighbour breaks them, a softening one starts from the
        // mean stress of its two ends.
        if (bonds_.breaksByDamage() && !state.damage.empty())
            ghostArrays_.push_back(ghostArray(state.damage.data()));
        if (softensBonds(options_)) ghostArrays_.push_back(ghostArray(state.cauchy.data()));
        domain_->shareGhosts(which, ghostArrays_);
    }
    times_.exchange += omp_get_wtime() - t0;
}

LedgerPowers VelocityVerlet::powersNow(const State& state) {
    return measurePowers(ref_, state, channels_, stagePower_, constraints_);
}

// Step 5: every stage adds its forces at x_{n+1}, t_{n+1} (v_{n+½}) in order; then a = f/m.
void VelocityVerlet::computeAccelerations(State& state) {
    std::fill(channels_.external.begin(), channels_.external.end(), Vec3::Zero());
    std::fill(channels_.frequency2.begin(), channels_.frequency2.end(), 0.0);
    double potential = 0.0;
    stagePower_ = 0.0;
    for (std::size_t k = 0; k < stages_.size(); ++k) {
        const double t0 = omp_get_wtime();
        const StageReport report = stages_[k]->addForces(state, channels_);
        potential += report.potential;
        stagePower_ += report.externalPower;
        (k == 0 ? times_.forces : times_.contact) += omp_get_wtime() - t0;
    }
    // The stages' reports and totals are over every process already (exactly rounded sums).
    for (const auto& stage : stages_) stage->record(state);
    state.ledger.contactEnergy = potential;
    parallelFor(owned_, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        state.acceleration[ia] = channels_.force[ia] / ref_.mass[ia];
    });
}

void VelocityVerlet::initialize(State& state) {
    if (softensBonds(options_) && state.cohesiveTraction.empty()) {
        state.cohesiveTraction.assign(state.bondIntact.size(), 0.0);
        state.cohesiveStretch.assign(state.bondIntact.size(), 0.0);
    }
    // Initial cracks break their bonds before anything reads them; a resumed state carries them.
    if (!options_.precracks.empty()) breakBondsAcross(ref_, options_.precracks, state.bondIntact);
    bonds_.attach(state);
    applyConstraints(constraints_, ref_, state, state.time);
    parallelFor(ref_.size(), [&](Index a) { stress_.pack(state, a); });
    stress_.advance(state, 0.0, true);
    shareGhosts(state, GhostColumns::ForceFactors);
    computeAccelerations(state);
    state.dt = stableTimeStep(ref_, state, timeStepRule(options_), stress_.lengthScale(),
                              stress_.factors().soundSpeed, channels_.frequency2, owned_, *domain_);
    state.initialDt = state.dt;
    startLedger(state.ledger, powersNow(state));
    times_ = PhaseTimes{};  // phase times count the steps only
}

void VelocityVerlet::resume(const State& state) {
    if (!(state.dt > 0.0) || !std::isfinite(state.dt))
        throw InputError("cannot resume a state whose next time step is " +
                         std::to_string(state.dt) + " s");
    bonds_.attach(state);
}

// Algorithm 1 of the paper (DESIGN §4), steps 1–7.
void VelocityVerlet::step(State& state) {
    const double t0 = omp_get_wtime();
    const double dt = state.dt;
    // 1–2: half kick, constraints at t_n + ½Δt, drift; bonds stretched too far break.
    parallelFor(owned_, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        state.v[ia] += 0.5 * dt * state.acceleration[ia];
    });
    applyConstraints(constraints_, ref_, state, state.time + 0.5 * dt);
    parallelFor(owned_, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        state.x[ia] += dt * state.v[ia];
        stress_.pack(state, a);
    });
    shareGhosts(state, GhostColumns::Motion);
    state.ledger.fractureEnergy +=
        bonds_.breakStretchedBonds(state, owned_, *domain_).releasedEnergy;
    // 3–4: F, Ḟ, σ at t_{n+1} and their dissipation.
    state.time += dt;
    const double t1 = omp_get_wtime();
    if (stress_.averagesDriver()) shareGhosts(state, GhostColumns::DamageDriver);
    stress_.advance(state, dt, false);
    shareGhosts(state, GhostColumns::ForceFactors);
    stress_.bookDissipation(state, owned_, *domain_);
    const double t2 = omp_get_wtime();
    // 5: the stages' forces (viscosity sees v_{n+½}).
    const double stagesBefore = times_.forces + times_.contact;
    computeAccelerations(state);
    const double t3 = omp_get_wtime();
    // 6: second half kick, constraints at t_{n+1}; the ledger's trapezoid over the step.
    parallelFor(owned_, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        state.v[ia] += 0.5 * dt * state.acceleration[ia];
    });
    applyConstraints(constraints_, ref_, state, state.time);
    ++state.step;
    bookStep(state.ledger, powersNow(state), dt);
    // 7: next step size.
    state.dt = stableTimeStep(ref_, state, timeStepRule(options_), stress_.lengthScale(),
                              stress_.factors().soundSpeed, channels_.frequency2, owned_, *domain_);
    const double t4 = omp_get_wtime();
    times_.kinematicsAndStress += t2 - t1;
    const double inStages = times_.forces + times_.contact - stagesBefore;
    times_.other += (t1 - t0) + (t4 - t3) + ((t3 - t2) - inStages);
}

}  // namespace gsph
