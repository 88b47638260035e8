// SPDX-License-Identifier: MIT
#include "integrator/velocity_verlet.hpp"

#include <omp.h>

#include <Eigen/LU>
#include <cmath>
#include <limits>
#include <string>

#include "core/error.hpp"
#include "core/parallel.hpp"
#include "kinematics/deformation_gradient.hpp"

namespace gsph {
namespace {

// Lower bound of the smallest stretch σ_min(F) = 1/‖F^{-1}‖₂ ≥ 1/√(‖F^{-1}‖₁‖F^{-1}‖∞):
// exact for diagonal F, cheap, and conservative for the time step.
double smallestStretchBound(const Mat3& Finv) {
    const double norm1 = Finv.cwiseAbs().colwise().sum().maxCoeff();
    const double normInf = Finv.cwiseAbs().rowwise().sum().maxCoeff();
    return 1.0 / std::sqrt(norm1 * normInf);
}

enum class Failure : std::uint8_t { None, Inverted, NotFinite };

}  // namespace

void StepWorkspace::resize(std::size_t n) {
    factors.resize(n);
    force.assign(n, Vec3::Zero());
    lengthScale.assign(n, 0.0);
}

VelocityVerlet::VelocityVerlet(const Reference& ref, std::vector<BodyRange> bodies,
                               std::vector<VelocityConstraint> constraints, SolverOptions options)
    : ref_(ref),
      bodies_(std::move(bodies)),
      constraints_(std::move(constraints)),
      options_(options) {
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
    work_.resize(static_cast<std::size_t>(ref.size()));
}

// Steps 3–4 of Algorithm 1, fused per particle: θ-gradients of x and v, F and Ḟ, the material
// update, and the factors K, N the force loop reads. atRest: only derive the factors from the
// current F and σ (initialisation), without advancing the stress.
void VelocityVerlet::updateKinematicsAndStress(State& state, double dt, bool atRest) {
    const Mat3 outOfPlane = ref_.dim.outOfPlane();
    StressFactors& sf = work_.factors;
    std::vector<Failure> failure(state.x.size(), Failure::None);
    for (const BodyRange& body : bodies_) {
        std::visit(
            [&](const auto& model) {
                const double rho0 = model.elastic().density;
                parallelFor(body.end - body.begin, [&](Index i) {
                    const Index a = body.begin + i;
                    const auto ia = static_cast<std::size_t>(a);
                    Mat3 F = state.F[ia];
                    MaterialPoint point;
                    point.cauchy = state.cauchy[ia];
                    if (!atRest) {
                        Mat3 gradX, gradV;
                        thetaGradients(ref_, a, state.x.data(), state.v.data(), gradX, gradV);
                        const Mat3& G = ref_.G[ia];
                        F = gradX * G.transpose() + outOfPlane;
                        const Mat3 Fdot = gradV * G.transpose();
                        const Mat3 L = Fdot * (0.5 * (state.F[ia] + F)).inverse();
                        const double J = F.determinant();
                        point.density = rho0 / J;
                        model.update(point, 0.5 * (L + L.transpose()), 0.5 * (L - L.transpose()),
                                     dt);
                        state.F[ia] = F;
                        state.cauchy[ia] = point.cauchy;
                    }
                    const double J = F.determinant();
                    if (!(J > 0.0)) {
                        failure[ia] = std::isfinite(J) ? Failure::Inverted : Failure::NotFinite;
                        return;
                    }
                    point.density = rho0 / J;
                    const Mat3 Finv = F.inverse();
                    // P = J σ F^{-T} (DESIGN §4); N = V J F^{-T} G, K = σ N = V P G.
                    sf.N[ia] = (ref_.quadVolume[ia] * J) * Finv.transpose() * ref_.G[ia];
                    sf.K[ia] = point.cauchy * sf.N[ia];
                    sf.density[ia] = point.density;
                    sf.soundSpeed[ia] = model.waveSpeed(point);
                    work_.lengthScale[ia] = ref_.spacing[ia] * smallestStretchBound(Finv);
                    if (!point.cauchy.allFinite()) failure[ia] = Failure::NotFinite;
                });
            },
            *body.material);
    }
    for (std::size_t a = 0; a < failure.size(); ++a) {
        if (failure[a] == Failure::None) continue;
        const std::string what = failure[a] == Failure::Inverted
                                     ? "inverted particle (J ≤ 0)"
                                     : "non-finite deformation or stress (NaN/Inf)";
        throw NumericalError(what + " at particle " + std::to_string(a) +
                                 ", t = " + std::to_string(state.time) + " s",
                             static_cast<long>(a), state.time);
    }
}

void VelocityVerlet::computeAccelerations(State& state) {
    for (const BodyRange& body : bodies_) {
        ForceOptions fo;
        fo.viscosity = options_.viscosity;
        fo.hourglass = options_.hourglass;
        fo.youngsModulus = elasticConstants(*body.material).youngsModulus;
        internalForce(ref_, state, work_.factors, fo, body.begin, body.end, work_.force,
                      work_.parts);
    }
    parallelFor(ref_.size(), [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        state.acceleration[ia] = work_.force[ia] / ref_.mass[ia];
    });
}

void VelocityVerlet::applyConstraints(State& state, double t) {
    for (const VelocityConstraint& c : constraints_)
        for (Index a : c.particles) {
            const auto ia = static_cast<std::size_t>(a);
            state.v[ia] = c.at(t, ref_.X[ia]);
        }
}

double VelocityVerlet::nonConservativePower(const State& state,
                                            const std::vector<Vec3>& part) const {
    if (part.empty()) return 0.0;
    return deterministicSum(ref_.size(), 0.0, [&](Index a) {
        return part[static_cast<std::size_t>(a)].dot(state.v[static_cast<std::size_t>(a)]);
    });
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
    const double ratio =
        parallelMin(ref_.size(), std::numeric_limits<double>::infinity(), [&](Index a) {
            const auto ia = static_cast<std::size_t>(a);
            return work_.lengthScale[ia] / (work_.factors.soundSpeed[ia] + state.v[ia].norm());
        });
    if (!(ratio > 0.0) || !std::isfinite(ratio))
        throw NumericalError("time step collapsed (Δt = " + std::to_string(options_.cfl * ratio) +
                                 " s) at t = " + std::to_string(state.time) + " s",
                             -1, state.time);
    return options_.cfl * ratio;
}

void VelocityVerlet::initialize(State& state) {
    applyConstraints(state, state.time);
    updateKinematicsAndStress(state, 0.0, true);
    computeAccelerations(state);
    state.dt = stableTimeStep(state);
    EnergyLedger& L = state.ledger;
    L.viscousPower = nonConservativePower(state, work_.parts.viscous);
    L.hourglassPower = nonConservativePower(state, work_.parts.hourglass);
    L.boundaryPower = boundaryPower(state);
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
    });
    // 3–5: kinematics, stress, forces at t_{n+1} (viscosity sees v_{n+½}).
    state.time += dt;
    const double t1 = omp_get_wtime();
    updateKinematicsAndStress(state, dt, false);
    const double t2 = omp_get_wtime();
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
    times_.forces += t3 - t2;
    times_.other += (t1 - t0) + (t4 - t3);
}

}  // namespace gsph
