// SPDX-License-Identifier: MIT
#include "integrator/stress_update.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>
#include <string>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "forces/hourglass.hpp"
#include "kinematics/deformation_gradient.hpp"
#include "materials/stress_measures.hpp"
#include "particles/axisymmetry.hpp"

namespace gsph {
namespace {

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
    StressFactors& factors;
    ParticleFields& fields;
    std::vector<double>& lengthScale;
    std::vector<std::uint8_t>& failure;
    std::vector<double>& damageDissipation;
    std::vector<double>& fractureEnergy;
    const std::vector<double>& averagedDriver;  // ω̄ of nonlocal damage (empty: none)
    double dt;
    bool atRest;  // only derive the factors from the current F and σ (initialisation)
    Mat3 outOfPlane;
    bool axisymmetric;  // F_zz is the hoop stretch (particles/axisymmetry.hpp)
    const BrittleBonds& bonds;
    const Mat3* G;  // per particle: the reference's, or recomputed over surviving bonds
    const ViscosityCoefficients& viscosity;
    bool plasticHourglass;  // s_a of forces/hourglass.hpp from the plastic strain (else 1)
};

// The viscosity's compression switch from the step's tr D (0: at rest, detached).
void storeSwitch(KinematicsStep& s, std::size_t ia, double trD) {
    s.factors.viscositySwitch[ia] =
        viscositySwitch(s.viscosity, s.ref.smoothingLength[ia], trD, s.factors.soundSpeed[ia]);
}

// s_a of the hourglass penalty (forces/hourglass.hpp) from σ and ε̄p at t_{n+1}.
template <class Model>
void storeHourglassScale(const Model& model, KinematicsStep& s, std::size_t ia, const Mat3& cauchy,
                         double plasticStrain) {
    s.factors.hourglassScale[ia] =
        s.plasticHourglass && plasticStrain > 0.0
            ? hourglassPlasticScale(vonMises(cauchy), model.elastic().shearModulus(), plasticStrain)
            : 1.0;
}

// The factors the force loop reads, from F and σ at t_{n+1}:
// P = J σ F^{-T} (DESIGN §4); N = V J F^{-T} G = V (cof F) G, K = σ N = V P G.
template <class Model>
void storeFactors(const Model& model, KinematicsStep& s, std::size_t ia, const Mat3& F,
                  MaterialPoint& point) {
    const Mat3 C = cofactor(F);
    const double J = F.col(0).dot(C.col(0));
    if (!(J > 0.0)) {
        s.failure[ia] =
            static_cast<std::uint8_t>(std::isfinite(J) ? Failure::Inverted : Failure::NotFinite);
        return;
    }
    point.density = model.elastic().density / J;
    const Mat3 N = s.ref.quadVolume[ia] * C * s.G[ia];
    s.factors.N.set(ia, N);
    s.factors.K.set(ia, point.cauchy * N);
    s.factors.density[ia] = point.density;
    s.factors.soundSpeed[ia] = model.waveSpeed(point);
    s.fields.F.set(ia, F);
    // A particle whose surviving bonds raise its G stiffens its pair forces as ‖G‖²
    // (failure/brittle_bonds.hpp, stepFactor).
    s.lengthScale[ia] =
        s.ref.spacing[ia] * smallestStretchBound(C, J) * s.bonds.stepFactor(static_cast<Index>(ia));
    s.failure[ia] =
        static_cast<std::uint8_t>(point.cauchy.allFinite() ? Failure::None : Failure::NotFinite);
}

// Steps 3–4 for particle a from its θ-gradients of x and v (kinematics/deformation_gradient.hpp):
// F, Ḟ, L = Ḟ F_{n+½}^{-1}, the material update, then the force factors.
template <class Model>
void advanceParticle(const Model& model, KinematicsStep& s, Index a, const Mat3& gradX,
                     const Mat3& gradV) {
    const auto ia = static_cast<std::size_t>(a);
    const Mat3& G = s.G[ia];
    Mat3 Fdot = gradV * G.transpose();
    if (s.axisymmetric) Fdot(2, 2) = hoopStretchRate(s.ref.X[ia], s.state.v[ia]);
    // A particle that lost bonds in a body whose bonds break by damage integrates F in time
    // (failure/brittle_bonds.hpp, integratesF): F over the surviving bonds would jump.
    const bool integrated = s.bonds.integratesF(a);
    Mat3 F =
        integrated ? Mat3(s.state.F[ia] + s.dt * Fdot) : Mat3(gradX * G.transpose() + s.outOfPlane);
    if (s.axisymmetric && !integrated) F(2, 2) = hoopStretch(s.ref.X[ia], s.state.x[ia]);
    const Mat3 L = Fdot * (0.5 * (s.state.F[ia] + F)).inverse();
    MaterialPoint point;
    point.cauchy = s.state.cauchy[ia];
    const double J = F.determinant();
    point.density = model.elastic().density / J;
    if constexpr (kHasHistory<Model>) {
        loadHistory<Model>(s.state, ia, point);
        if (!s.averagedDriver.empty()) point.averagedDriver = s.averagedDriver[ia];
        point.size = s.ref.spacing[ia];
    }
    model.update(point, 0.5 * (L + L.transpose()), 0.5 * (L - L.transpose()), s.dt);
    s.state.F[ia] = F;
    s.state.cauchy[ia] = point.cauchy;
    if constexpr (kHasHistory<Model>) {
        storeHistory<Model>(point, ia, s.state);
        // Per current volume → per particle: V J (the particle's current volume).
        const double volume = s.ref.quadVolume[ia] * J;
        s.state.plasticWork[ia] += volume * point.plasticWork;
        s.damageDissipation[ia] = volume * point.damageDissipation;
    }
    storeFactors(model, s, ia, F, point);
    storeSwitch(s, ia, L.trace());
    storeHourglassScale(model, s, ia, point.cauchy, point.plasticStrain);
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
    const double J = s.state.F[ia].determinant();
    MaterialPoint point;
    point.cauchy = s.state.cauchy[ia];
    point.density = model.elastic().density / J;
    if constexpr (kHasHistory<Model>) loadHistory<Model>(s.state, ia, point);
    const double stored = model.storedEnergyDensity(point);
    point.cauchy.setZero();
    s.fractureEnergy[ia] = s.ref.quadVolume[ia] * J * (stored - model.storedEnergyDensity(point));
    s.state.cauchy[ia].setZero();
    s.factors.N.set(ia, Mat3::Zero());
    s.factors.K.set(ia, Mat3::Zero());
    s.factors.density[ia] = point.density;
    s.factors.soundSpeed[ia] = model.waveSpeed(point);
    s.fields.F.set(ia, s.state.F[ia]);
    storeSwitch(s, ia, 0.0);
    storeHourglassScale(model, s, ia, point.cauchy, point.plasticStrain);
    s.lengthScale[ia] = s.ref.spacing[ia];
    s.failure[ia] = 0;
    if (!s.damageDissipation.empty()) s.damageDissipation[ia] = 0.0;
}

template <class Model>
void updateBlock(const Model& model, KinematicsStep& s, const StencilBlocks& blocks,
                 const CsrPairWeights& staged, const ParticleBlock& block) {
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
            storeSwitch(s, ia, 0.0);
            // A restart resumes with the scale its plastic strain gives.
            if (!s.state.plasticStrain.empty())
                storeHourglassScale(model, s, ia, point.cauchy, s.state.plasticStrain[ia]);
        }
    } else if (block.stencil != kNoStencil && bonds.allIntact(block.begin, block.end)) {
        BlockThetaGradients g;
        stencilThetaGradients(blocks.stencils[static_cast<std::size_t>(block.stencil)], block,
                              s.fields.x, s.fields.v, g);
        for (Index i = 0; i < block.size(); ++i)
            advanceParticle(model, s, block.particle(i), g.gradX(i), g.gradV(i));
    } else {
        BlockThetaGradients g;
        csrThetaGradients(s.ref, &staged, bonds, block, s.fields.x, s.fields.v, g);
        for (Index i = 0; i < block.size(); ++i) {
            const Index a = block.particle(i);
            if (s.bonds.detached(a)) {
                detachParticle(model, s, static_cast<std::size_t>(a));
                continue;
            }
            advanceParticle(model, s, a, g.gradX(i), g.gradV(i));
        }
    }
}

}  // namespace

StressUpdate::StressUpdate(const Reference& ref, const std::vector<BodyRange>& bodies,
                           const BrittleBonds& bonds, const ViscosityCoefficients& viscosity,
                           HourglassModulus hourglass)
    : ref_(ref), bodies_(bodies), bonds_(bonds), viscosity_(viscosity), hourglass_(hourglass) {
    const auto n = static_cast<std::size_t>(ref.size());
    factors_.resize(n);
    fields_.resize(n);
    lengthScale_.assign(n, 0.0);
    failure_.assign(n, 0);
    for (std::size_t a = 0; a < n; ++a) fields_.X.set(a, ref.X[a]);
    for (const BodyRange& body : bodies_)
        blocks_.push_back(buildStencilBlocks(ref.pairs, body.begin, body.end, ref.oversetCoupled));
    for (const StencilBlocks& blocks : blocks_) staged_.push_back(stageCsrPairs(ref, blocks));
    for (const BodyRange& body : bodies_)
        if (tracksHistory(*body.material)) damageDissipation_.assign(n, 0.0);
    if (bonds_.enabled()) fractureEnergy_.assign(n, 0.0);
    for (const BodyRange& body : bodies_) {
        const JohnsonCookDamage* damage = damageModel(*body.material);
        nonlocal_.push_back(
            damage && damage->nonlocal()
                ? NonlocalAverage(ref.X, ref.quadVolume, body.begin, body.end, damage->length)
                : NonlocalAverage());
        if (damage && damage->nonlocal()) averagedDriver_.assign(n, 0.0);
    }
}

void StressUpdate::advance(State& state, double dt, bool atRest) {
    KinematicsStep s{ref_,
                     state,
                     factors_,
                     fields_,
                     lengthScale_,
                     failure_,
                     damageDissipation_,
                     fractureEnergy_,
                     averagedDriver_,
                     dt,
                     atRest,
                     ref_.dim.outOfPlane(),
                     ref_.dim.axisymmetric,
                     bonds_,
                     bonds_.G().data(),
                     viscosity_,
                     hourglass_ == HourglassModulus::Secant};
    // The nonlocal damage's averages of the drivers at t_n, before any particle updates its own.
    for (const NonlocalAverage& average : nonlocal_)
        if (!atRest && average.end() > average.begin())
            parallelFor(average.end() - average.begin(), [&](std::ptrdiff_t i) {
                const Index a = average.begin() + static_cast<Index>(i);
                averagedDriver_[static_cast<std::size_t>(a)] =
                    average.average(state.damageDriver, a);
            });
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        const StencilBlocks& blocks = blocks_[b];
        std::visit(
            [&](const auto& model) {
                parallelForBlocks(blocks.cost, [&](std::ptrdiff_t k) {
                    updateBlock(model, s, blocks, staged_[b],
                                blocks.blocks[static_cast<std::size_t>(k)]);
                });
            },
            *bodies_[b].material);
    }
    throwOnFailure(state);
}

void StressUpdate::throwOnFailure(const State& state) const {
    for (std::size_t a = 0; a < failure_.size(); ++a) {
        const auto f = static_cast<Failure>(failure_[a]);
        if (f == Failure::None) continue;
        const std::string what = f == Failure::Inverted
                                     ? "inverted particle (J ≤ 0)"
                                     : "non-finite deformation or stress (NaN/Inf)";
        throw NumericalError(
            what + ": " + describeParticle(ref_, static_cast<Index>(a), state.time),
            static_cast<long>(a), state.time);
    }
}

void StressUpdate::bookDissipation(State& state, ParticleRange owned, Domain& domain) {
    // Per body (and the fracture energy last), this process's share, summed over the processes
    // and then booked in body order: one process books exactly as the serial run did.
    dissipated_.assign(bodies_.size() + 1, 0.0);
    if (bonds_.enabled())
        dissipated_.back() = deterministicSum(
            owned, 0.0, [&](Index a) { return fractureEnergy_[static_cast<std::size_t>(a)]; },
            partialSums_);
    for (std::size_t b = 0; b < bodies_.size(); ++b) {
        if (!tracksHistory(*bodies_[b].material)) continue;
        dissipated_[b] = deterministicSum(
            owned.within(bodies_[b].begin, bodies_[b].end), 0.0,
            [&](Index a) { return damageDissipation_[static_cast<std::size_t>(a)]; }, partialSums_);
    }
    if (domain.processes() > 1) domain.sum(dissipated_);
    if (bonds_.enabled()) state.ledger.fractureEnergy += dissipated_.back();
    for (std::size_t b = 0; b < bodies_.size(); ++b)
        if (tracksHistory(*bodies_[b].material)) state.ledger.damageDissipation += dissipated_[b];
}

void StressUpdate::restrictTo(ParticleRange owned) {
    for (std::size_t b = 0; b < blocks_.size(); ++b) {
        StencilBlocks& body = blocks_[b];
        StencilBlocks kept;
        kept.stencils = body.stencils;
        kept.cost.push_back(0);
        for (const ParticleBlock& whole : body.blocks) {
            // A strided block may be cut at the range's ends (distributed/halo_plan.hpp).
            const ParticleBlock block = whole.within(owned.begin, owned.end);
            if (block.size() == 0) continue;
            kept.blocks.push_back(block);
            kept.particles += block.size();
            kept.cost.push_back(kept.cost.back() + block.cost());
        }
        body = std::move(kept);
        staged_[b] = stageCsrPairs(ref_, body);
    }
}

}  // namespace gsph
