// SPDX-License-Identifier: MIT
#include "integrator/velocity_verlet.hpp"

#include <omp.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "kinematics/deformation_gradient.hpp"

namespace gsph {
namespace {

// Cofactor matrix cof F = J F^{-T}, columns F₁×F₂, F₂×F₀, F₀×F₁ (F_i: columns of F). The
// force factors need J F^{-T} only, so taking it directly saves the inverse and its division.
Mat3 cofactor(const Mat3& F) {
    Mat3 C;
    C.col(0) = F.col(1).cross(F.col(2));
    C.col(1) = F.col(2).cross(F.col(0));
    C.col(2) = F.col(0).cross(F.col(1));
    return C;
}

// Lower bound of the smallest stretch σ_min(F) = 1/‖F^{-1}‖₂ ≥ 1/√(‖F^{-1}‖₁‖F^{-1}‖∞):
// exact for diagonal F, cheap, and conservative for the time step. With F^{-1} = (cof F)^T/J:
// ‖F^{-1}‖₁‖F^{-1}‖∞ = ‖cof F‖∞‖cof F‖₁/J².
double smallestStretchBound(const Mat3& cof, double J) {
    const double norm1 = cof.cwiseAbs().colwise().sum().maxCoeff();
    const double normInf = cof.cwiseAbs().rowwise().sum().maxCoeff();
    return J / std::sqrt(norm1 * normInf);
}

enum class Failure : std::uint8_t { None, Inverted, NotFinite };

// What steps 3–4 read and write, shared by the per-block functions below.
struct KinematicsStep {
    const Reference& ref;
    State& state;
    StepWorkspace& work;
    double dt;
    bool atRest;  // only derive the factors from the current F and σ (initialisation)
    Mat3 outOfPlane;
    const BrittleBonds& bonds;
    const Mat3* G;  // per particle: the reference's, or recomputed over surviving bonds
};

// The factors the force loop reads, from F and σ at t_{n+1}:
// P = J σ F^{-T} (DESIGN §4); N = V J F^{-T} G = V (cof F) G, K = σ N = V P G.
template <class Model>
void storeFactors(const Model& model, KinematicsStep& s, std::size_t ia, const Mat3& F,
                  MaterialPoint& point) {
    StepWorkspace& w = s.work;
    const Mat3 C = cofactor(F);
    const double J = F.col(0).dot(C.col(0));
    if (!(J > 0.0)) {
        w.failure[ia] =
            static_cast<std::uint8_t>(std::isfinite(J) ? Failure::Inverted : Failure::NotFinite);
        return;
    }
    point.density = model.elastic().density / J;
    const Mat3 N = s.ref.quadVolume[ia] * C * s.G[ia];
    w.factors.N.set(ia, N);
    w.factors.K.set(ia, point.cauchy * N);
    w.factors.density[ia] = point.density;
    w.factors.soundSpeed[ia] = model.waveSpeed(point);
    w.fields.F.set(ia, F);
    // A particle whose surviving bonds raise its G stiffens its pair forces as ‖G‖²
    // (failure/brittle_bonds.hpp, stepFactor).
    w.lengthScale[ia] =
        s.ref.spacing[ia] * smallestStretchBound(C, J) * s.bonds.stepFactor(static_cast<Index>(ia));
    w.failure[ia] =
        static_cast<std::uint8_t>(point.cauchy.allFinite() ? Failure::None : Failure::NotFinite);
}

// Steps 3–4 for particle a from its θ-gradients of x and v (kinematics/deformation_gradient.hpp):
// F, Ḟ, L = Ḟ F_{n+½}^{-1}, the material update, then the force factors.
template <class Model>
void advanceParticle(const Model& model, KinematicsStep& s, Index a, const Mat3& gradX,
                     const Mat3& gradV) {
    const auto ia = static_cast<std::size_t>(a);
    const Mat3& G = s.G[ia];
    const Mat3 Fdot = gradV * G.transpose();
    // A particle that lost bonds in a body whose bonds break by damage integrates F in time
    // (failure/brittle_bonds.hpp, integratesF): F over the surviving bonds would jump.
    const Mat3 F = s.bonds.integratesF(a) ? Mat3(s.state.F[ia] + s.dt * Fdot)
                                          : Mat3(gradX * G.transpose() + s.outOfPlane);
    const Mat3 L = Fdot * (0.5 * (s.state.F[ia] + F)).inverse();
    MaterialPoint point;
    point.cauchy = s.state.cauchy[ia];
    const double J = F.determinant();
    point.density = model.elastic().density / J;
    if constexpr (Model::kTracksHistory) loadHistory(s.state, ia, point);
    model.update(point, 0.5 * (L + L.transpose()), 0.5 * (L - L.transpose()), s.dt);
    s.state.F[ia] = F;
    s.state.cauchy[ia] = point.cauchy;
    if constexpr (Model::kTracksHistory) {
        storeHistory(point, ia, s.state);
        // Per current volume → per particle: V J (the particle's current volume).
        const double volume = s.ref.quadVolume[ia] * J;
        s.work.plasticWork[ia] = volume * point.plasticWork;
        s.work.damageDissipation[ia] = volume * point.damageDissipation;
    }
    storeFactors(model, s, ia, F, point);
}

// A detached particle (failure/brittle_bonds.hpp) keeps its last F and carries no stress; it
// still needs a sound speed and a length for the time step. The elastic energy its stress
// stored is released when σ is set to zero: V J (ψ(σ) − ψ(0)) at its kept F, booked as this
// step's fracture energy (zero on later steps, σ being zero then). The part ψ(0) of the kept F
// (the equation of state's compression energy of a Johnson–Cook particle, a function of J
// alone) stays in the elastic energy, constant from then on; booking all of ψ(σ) would book
// that part again on every step of a compressed detached particle.
template <class Model>
void detachParticle(const Model& model, KinematicsStep& s, std::size_t ia) {
    StepWorkspace& w = s.work;
    const double J = s.state.F[ia].determinant();
    MaterialPoint point;
    point.cauchy = s.state.cauchy[ia];
    point.density = model.elastic().density / J;
    if constexpr (Model::kTracksHistory) loadHistory(s.state, ia, point);
    const double stored = model.storedEnergyDensity(point);
    point.cauchy.setZero();
    w.fractureEnergy[ia] = s.ref.quadVolume[ia] * J * (stored - model.storedEnergyDensity(point));
    s.state.cauchy[ia].setZero();
    w.factors.N.set(ia, Mat3::Zero());
    w.factors.K.set(ia, Mat3::Zero());
    w.factors.density[ia] = point.density;
    w.factors.soundSpeed[ia] = model.waveSpeed(point);
    w.fields.F.set(ia, s.state.F[ia]);
    w.lengthScale[ia] = s.ref.spacing[ia];
    w.failure[ia] = 0;
    if (!w.plasticWork.empty()) w.plasticWork[ia] = w.damageDissipation[ia] = 0.0;
}

template <class Model>
void updateBlock(const Model& model, KinematicsStep& s, const StencilBlocks& blocks,
                 const ParticleBlock& block) {
    const BondView bonds = s.bonds.view(s.state);
    if (s.atRest) {
        for (Index i = 0; i < block.size(); ++i) {
            const Index a = block.particle(i);
            const auto ia = static_cast<std::size_t>(a);
            if (s.bonds.detached(a)) {
                detachParticle(model, s, ia);
                continue;
            }
            MaterialPoint point;
            point.cauchy = s.state.cauchy[ia];
            storeFactors(model, s, ia, s.state.F[ia], point);
        }
    } else if (block.stencil != kNoStencil && bonds.allIntact(block.begin, block.end)) {
        BlockThetaGradients g;
        stencilThetaGradients(blocks.stencils[static_cast<std::size_t>(block.stencil)], block,
                              s.work.fields.x, s.work.fields.v, g);
        for (Index i = 0; i < block.size(); ++i)
            advanceParticle(model, s, block.particle(i), g.gradX(i), g.gradV(i));
    } else {
        for (Index i = 0; i < block.size(); ++i) {
            const Index a = block.particle(i);
            if (s.bonds.detached(a)) {
                detachParticle(model, s, static_cast<std::size_t>(a));
                continue;
            }
            Mat3 gradX, gradV;
            thetaGradients(s.ref, a, s.state.x.data(), s.state.v.data(), gradX, gradV, bonds.intact,
                           bonds.keepsAll(a) ? s.ref.pairCorrections(a) : nullptr);
            advanceParticle(model, s, a, gradX, gradV);
        }
    }
}

// "particle 12 at X = (…) m, t = … s": what a NumericalError names.
std::string particleAndTime(const Reference& ref, Index a, double time) {
    const Vec3& X = ref.X[static_cast<std::size_t>(a)];
    char text[160];
    std::snprintf(text, sizeof text, "particle %d at X = (%.6g, %.6g, %.6g) m, t = %.6e s", a, X[0],
                  X[1], X[2], time);
    return text;
}

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

}  // namespace

void StepWorkspace::resize(std::size_t n) {
    factors.resize(n);
    fields.resize(n);
    force.assign(n, Vec3::Zero());
    lengthScale.assign(n, 0.0);
    failure.assign(n, 0);
}

VelocityVerlet::VelocityVerlet(const Reference& ref, std::vector<BodyRange> bodies,
                               std::vector<VelocityConstraint> constraints, SolverOptions options,
                               const Loads& loads, std::vector<Wall> walls)
    : ref_(ref),
      bodies_(std::move(bodies)),
      constraints_(std::move(constraints)),
      options_(options),
      bonds_(ref, byParticle(ref, options_.bondStretch, 0.0),
             byParticle(ref, options_.failedBonds, FailedBondRule::Keep),
             !options_.precracks.empty()) {
    if (!(options_.cfl > 0.0 && options_.cfl <= 1.0))
        throw InputError("CFL number must lie in (0, 1], got " + std::to_string(options_.cfl));
    if (options_.hourglass < 0.0) throw InputError("hourglass coefficient must be ≥ 0");
    if (options_.viscosity.linear < 0.0 || options_.viscosity.quadratic < 0.0)
        throw InputError("artificial viscosity coefficients must be ≥ 0");
    for (const VelocityConstraint& c : constraints_)
        for (Index a : c.particles)
            if (a < 0 || a >= ref.size())
                throw InputError("constraint '" + c.name + "' names particle " + std::to_string(a) +
                                 " outside [0, " + std::to_string(ref.size()) + ")");
    const auto n = static_cast<std::size_t>(ref.size());
    work_.resize(n);
    for (std::size_t a = 0; a < n; ++a) work_.fields.X.set(a, ref.X[a]);
    for (const BodyRange& body : bodies_)
        work_.blocks.push_back(
            buildStencilBlocks(ref.pairs, body.begin, body.end, ref.oversetCoupled));
    for (const BodyRange& body : bodies_)
        if (tracksHistory(*body.material)) {
            work_.plasticWork.assign(n, 0.0);
            work_.damageDissipation.assign(n, 0.0);
        }
    if (bonds_.enabled()) work_.fractureEnergy.assign(n, 0.0);
    if (options_.viscosity.enabled()) work_.parts.viscous.assign(n, Vec3::Zero());
    if (options_.hourglass != 0.0) work_.parts.hourglass.assign(n, Vec3::Zero());
    setUpContactAndLoads(loads, std::move(walls));
}

// Penalty stiffness from each body's P-wave modulus (contact/penalty_contact.hpp), the pair
// contact between bodies, the walls and the constant loads; scratch only for what is on.
void VelocityVerlet::setUpContactAndLoads(const Loads& loads, std::vector<Wall> walls) {
    const auto n = static_cast<std::size_t>(ref_.size());
    std::vector<double> c2(n, 0.0);
    for (const BodyRange& body : bodies_) {
        const ElasticConstants& e = elasticConstants(*body.material);
        for (Index a = body.begin; a < body.end; ++a)
            c2[static_cast<std::size_t>(a)] = e.pWaveModulus() / e.density;
    }
    const bool pairs = options_.contact.betweenBodies && bodies_.size() > 1;
    if (pairs || !walls.empty()) {
        const std::vector<double> k = contactStiffness(ref_, c2, options_.contact.penalty);
        ContactShapes shapes = contactShapes(ref_, options_.contact.distance);
        walls_ = RigidWalls(ref_, std::move(walls), k, shapes);
        if (pairs) pairContact_ = PenaltyContact(ref_, k, std::move(shapes), options_.contact);
    }
    if (!loads.empty()) load_ = loadPerParticle(ref_, loads);
    if (pairContact_.active() || walls_.active()) work_.contactFrequency2.assign(n, 0.0);
    if (walls_.active() || !load_.empty()) work_.externalForce.assign(n, Vec3::Zero());
    if (walls_.active()) work_.wallForce.assign(n, Vec3::Zero());
}

// SoA copies of x_a and v_a for the stencil loops (ParticleFields).
void VelocityVerlet::packKinematics(const State& state, Index a) {
    const auto ia = static_cast<std::size_t>(a);
    work_.fields.x.set(ia, state.x[ia]);
    work_.fields.v.set(ia, state.v[ia]);
}

// Steps 3–4 of Algorithm 1, fused per particle and run block by block (stencil blocks
// vectorise the θ-gradient sums): F and Ḟ, the material update, and the factors K, N the
// force loop reads. Reads the SoA x, v packed by the drift.
void VelocityVerlet::updateKinematicsAndStress(State& state, double dt, bool atRest) {
    KinematicsStep s{
        ref_, state, work_, dt, atRest, ref_.dim.outOfPlane(), bonds_, bonds_.G().data()};
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const StencilBlocks& blocks = work_.blocks[b];
        std::visit(
            [&](const auto& model) {
                parallelForBlocks(static_cast<std::ptrdiff_t>(blocks.blocks.size()),
                                  bodies_[b].end - bodies_[b].begin, [&](std::ptrdiff_t k) {
                                      updateBlock(model, s, blocks,
                                                  blocks.blocks[static_cast<std::size_t>(k)]);
                                  });
            },
            *bodies_[b].material);
    }
    throwOnFailure(state);
}

void VelocityVerlet::throwOnFailure(const State& state) const {
    for (std::size_t a = 0; a < work_.failure.size(); ++a) {
        const auto f = static_cast<Failure>(work_.failure[a]);
        if (f == Failure::None) continue;
        const std::string what = f == Failure::Inverted
                                     ? "inverted particle (J ≤ 0)"
                                     : "non-finite deformation or stress (NaN/Inf)";
        throw NumericalError(what + ": " + particleAndTime(ref_, static_cast<Index>(a), state.time),
                             static_cast<long>(a), state.time);
    }
}

void VelocityVerlet::computeAccelerations(State& state) {
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const BodyRange& body = bodies_[b];
        ForceOptions fo;
        fo.viscosity = options_.viscosity;
        fo.hourglass = options_.hourglass;
        fo.youngsModulus = elasticConstants(*body.material).youngsModulus;
        internalForce(ref_, work_.fields, work_.factors, work_.blocks[b], fo, work_.force,
                      work_.parts, bonds_.view(state), bonds_.G().data());
    }
    addContactAndLoads(state);
    if (walls_.active()) walls_.totalForces(state.wallForce);
    parallelFor(ref_.size(), [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        state.acceleration[ia] = work_.force[ia] / ref_.mass[ia];
    });
}

// Step 5's forces beyond the internal one, at x_{n+1} and t_{n+1} (friction from v_{n+½}),
// added to each particle's force in a fixed order: contact between bodies, walls, loads.
void VelocityVerlet::addContactAndLoads(State& state) {
    const double t0 = omp_get_wtime();
    double energy = 0.0;
    if (!work_.contactFrequency2.empty())
        std::fill(work_.contactFrequency2.begin(), work_.contactFrequency2.end(), 0.0);
    if (!work_.externalForce.empty())
        std::fill(work_.externalForce.begin(), work_.externalForce.end(), Vec3::Zero());
    if (pairContact_.active())
        energy += pairContact_.addForces(state.x, work_.force, work_.contactFrequency2);
    wallPushPower_ = 0.0;
    if (walls_.active()) {
        const WallResult w =
            walls_.addForces(state.time, state.dt, state.x, state.v, work_.force,
                             work_.externalForce, work_.contactFrequency2, work_.wallForce);
        energy += w.energy;
        wallPushPower_ = w.pushPower;
    }
    if (!load_.empty())
        parallelFor(ref_.size(), [&](Index a) {
            const auto ia = static_cast<std::size_t>(a);
            work_.force[ia] += load_[ia];
            work_.externalForce[ia] += load_[ia];
        });
    state.ledger.contactEnergy = energy;
    times_.contact += omp_get_wtime() - t0;
}

// Power of gravity, set forces and walls on the bodies: Σ (load + friction)·v + Σ f_n·v_wall.
double VelocityVerlet::externalPower(const State& state) {
    if (work_.externalForce.empty()) return wallPushPower_;
    return wallPushPower_ + nonConservativePower(state, work_.externalForce);
}

void VelocityVerlet::applyConstraints(State& state, double t) {
    for (const VelocityConstraint& c : constraints_)
        for (Index a : c.particles) {
            const auto ia = static_cast<std::size_t>(a);
            state.v[ia] = c.at(t, ref_.X[ia]);
        }
}

// This step's plastic work and failure losses of the bodies with a history, and the fracture
// energy of the particles detached by this step's broken bonds, in a fixed order.
void VelocityVerlet::bookDissipation(State& state) {
    if (bonds_.enabled())
        state.ledger.fractureEnergy += deterministicSum(
            ref_.size(), 0.0,
            [&](Index a) { return work_.fractureEnergy[static_cast<std::size_t>(a)]; },
            work_.partialSums);
    for (const BodyRange& body : bodies_) {
        if (!tracksHistory(*body.material)) continue;
        const auto sumOver = [&](const std::vector<double>& perParticle) {
            return deterministicSum(
                body.end - body.begin, 0.0,
                [&](Index i) { return perParticle[static_cast<std::size_t>(body.begin + i)]; },
                work_.partialSums);
        };
        state.ledger.plasticWork += sumOver(work_.plasticWork);
        state.ledger.damageDissipation += sumOver(work_.damageDissipation);
    }
}

double VelocityVerlet::nonConservativePower(const State& state, const std::vector<Vec3>& part) {
    if (part.empty()) return 0.0;
    return deterministicSum(
        ref_.size(), 0.0,
        [&](Index a) {
            return part[static_cast<std::size_t>(a)].dot(state.v[static_cast<std::size_t>(a)]);
        },
        work_.partialSums);
}

// Power of the reactions that keep constrained particles on their prescribed velocity:
// R = m a_prescribed − f, with a_prescribed by a central difference of the prescription.
double VelocityVerlet::boundaryPower(const State& state) const {
    double power = 0.0;
    const double eps = std::max(state.dt, 1e-12) * 1e-3;
    for (const VelocityConstraint& c : constraints_) {
        if (!c.velocity) continue;  // fixed: no power
        for (Index a : c.particles) {
            const auto ia = static_cast<std::size_t>(a);
            const Vec3 accel =
                (c.at(state.time + eps, ref_.X[ia]) - c.at(state.time - eps, ref_.X[ia])) /
                (2 * eps);
            power += (ref_.mass[ia] * accel - work_.force[ia]).dot(state.v[ia]);
        }
    }
    return power;
}

double VelocityVerlet::stableTimeStep(const State& state) const {
    if (options_.fixedTimeStep > 0.0) return options_.fixedTimeStep;
    const auto ratioOf = [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        const double wave =
            work_.lengthScale[ia] / (work_.factors.soundSpeed[ia] + state.v[ia].norm());
        if (work_.contactFrequency2.empty() || work_.contactFrequency2[ia] == 0.0) return wave;
        // Springs in parallel: ω² = (2/wave)² + ω_contact², Δt = CFL · 2/ω.
        return 1.0 / std::sqrt(1.0 / (wave * wave) + 0.25 * work_.contactFrequency2[ia]);
    };
    const double ratio = parallelMin(ref_.size(), std::numeric_limits<double>::infinity(), ratioOf);
    const double dt = options_.cfl * ratio;
    const double floor = options_.minTimeStepRatio * state.initialDt;
    if (ratio > 0.0 && std::isfinite(ratio) && !(dt < floor)) return dt;
    // Failure only: name the particle that limits Δt (the first NaN, or the smallest ratio).
    Index worst = 0;
    double worstRatio = ref_.size() > 0 ? ratioOf(0) : 0.0;
    for (Index a = 0; a < ref_.size() && !std::isnan(worstRatio); ++a) {
        const double r = ratioOf(a);
        if (std::isnan(r) || r < worstRatio) {
            worst = a;
            worstRatio = r;
        }
    }
    const auto iw = static_cast<std::size_t>(worst);
    char detail[200];
    std::snprintf(detail, sizeof detail,
                  "time step collapsed: Δt = %.3e s, below %.3g × Δt0 (Δt0 = %.3e s; spacing "
                  "%.3e m, wave speed %.3e m/s, |v| = %.3e m/s): ",
                  dt, options_.minTimeStepRatio, state.initialDt, work_.lengthScale[iw],
                  work_.factors.soundSpeed[iw], state.v[iw].norm());
    throw NumericalError(detail + particleAndTime(ref_, worst, state.time), worst, state.time);
}

void VelocityVerlet::initialize(State& state) {
    // Initial cracks break their bonds before anything reads them; a resumed state carries them.
    if (!options_.precracks.empty()) breakBondsAcross(ref_, options_.precracks, state.bondIntact);
    bonds_.attach(state);
    applyConstraints(state, state.time);
    parallelFor(ref_.size(), [&](Index a) { packKinematics(state, a); });
    updateKinematicsAndStress(state, 0.0, true);
    computeAccelerations(state);
    state.dt = stableTimeStep(state);
    state.initialDt = state.dt;
    EnergyLedger& L = state.ledger;
    L.viscousPower = nonConservativePower(state, work_.parts.viscous);
    L.hourglassPower = nonConservativePower(state, work_.parts.hourglass);
    L.boundaryPower = boundaryPower(state);
    L.externalPower = externalPower(state);
    times_.contact = 0.0;  // phase times count the steps only
}

void VelocityVerlet::resume(const State& state) {
    if (!(state.dt > 0.0) || !std::isfinite(state.dt))
        throw InputError("cannot resume a state whose next time step is " +
                         std::to_string(state.dt) + " s");
    bonds_.attach(state);
}

void VelocityVerlet::step(State& state) {
    const double t0 = omp_get_wtime();
    const double dt = state.dt;
    const Index n = ref_.size();
    // 1–2: half kick and drift.
    parallelFor(n, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        state.v[ia] += 0.5 * dt * state.acceleration[ia];
    });
    applyConstraints(state, state.time + 0.5 * dt);
    parallelFor(n, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        state.x[ia] += dt * state.v[ia];
        packKinematics(state, a);
    });
    state.ledger.fractureEnergy += bonds_.breakStretchedBonds(state).releasedEnergy;
    // 3–5: kinematics, stress, forces at t_{n+1} (viscosity sees v_{n+½}).
    state.time += dt;
    const double t1 = omp_get_wtime();
    updateKinematicsAndStress(state, dt, false);
    bookDissipation(state);
    const double t2 = omp_get_wtime();
    const double contactBefore = times_.contact;
    computeAccelerations(state);
    const double t3 = omp_get_wtime();
    // 6: second half kick.
    parallelFor(n, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        state.v[ia] += 0.5 * dt * state.acceleration[ia];
    });
    applyConstraints(state, state.time);
    ++state.step;
    // Energy ledger: trapezoidal rule over the step; the forces are the reactions' and
    // the internal parts' at t_{n+1}, the velocities v_{n+1}.
    EnergyLedger& L = state.ledger;
    const double pv = nonConservativePower(state, work_.parts.viscous);
    const double ph = nonConservativePower(state, work_.parts.hourglass);
    const double pb = boundaryPower(state);
    const double pe = externalPower(state);
    L.externalWork += 0.5 * dt * (L.externalPower + pe);
    L.externalPower = pe;
    L.viscousWork -= 0.5 * dt * (L.viscousPower + pv);
    L.hourglassWork -= 0.5 * dt * (L.hourglassPower + ph);
    L.boundaryWork += 0.5 * dt * (L.boundaryPower + pb);
    L.viscousPower = pv;
    L.hourglassPower = ph;
    L.boundaryPower = pb;
    // 7: next step size.
    state.dt = stableTimeStep(state);
    const double t4 = omp_get_wtime();
    times_.kinematicsAndStress += t2 - t1;
    times_.forces += (t3 - t2) - (times_.contact - contactBefore);
    times_.other += (t1 - t0) + (t4 - t3);
}

}  // namespace gsph
