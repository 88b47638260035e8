// SPDX-License-Identifier: MIT
// Rigid walls (docs/theory.md "Walls"): planes and cylinders in rigid translation,
// p(t) = point + displacement(t) (velocity·t, or after a linear speed ramp). A particle a at x_a
// penetrates a wall by
//   plane    (unit normal n towards the bodies):  g_a = ρ_a(n) − (x_a − p)·n,
//   cylinder (unit axis e through p, radius R):   g_a = ρ_a(n) − (r_a − R),
//            q = x_a − p, r_a = |q − (q·e)e|, n = (q − (q·e)e)/r_a the outward radial direction
// (ρ_a(n) its contact ellipsoid's radius along n, penalty_contact.hpp) and, when g_a > 0, feels
//   normal:  f_n = −∂U/∂x_a,  U = ½ k_a g_a²      (k_a of contactStiffness)
//            plane: k_a g_a n;  cylinder: k_a g_a (n + P h/r_a), h = S^T S n/|S n|³,
//            P = I − nnᵀ − eeᵀ (ρ_a(n) turns with n around the cylinder; as in the pair contact)
//   Coulomb: f_t = −min(μ k_a g_a, m_a |w_t|/Δt) w_t/|w_t|,  w_t the part of v_a − v_wall
//            tangential to the wall at the particle (normal n),
// the min being the stick limit: friction never reverses the sliding within a step. The power
// the wall puts into the bodies, f_n·v_wall + f_t·v_a (its push, and the friction, negative
// for a wall at rest), is booked as external work; the normal spring's energy as contact energy
// (U is a potential in the wall's frame, so dU/dt = −f_n·(v_a − v_wall)).
// Each particle writes only its own entries (parallel, thread-count-independent); the force
// of each wall on the bodies is summed in a fixed order.
#pragma once

#include <string>
#include <vector>

#include "contact/penalty_contact.hpp"
#include "core/exact_sum.hpp"
#include "core/parallel.hpp"
#include "core/types.hpp"
#include "distributed/domain.hpp"
#include "particles/reference.hpp"

namespace gsph {

enum class WallShape { Plane, Cylinder };

struct Wall {
    std::string name;              ///< for messages and output columns
    Vec3 point = Vec3::Zero();     ///< a point of the plane, or of the cylinder's axis [m]
    Vec3 normal = Vec3::UnitZ();   ///< plane: normalised by RigidWalls; points to the bodies' side
    Vec3 velocity = Vec3::Zero();  ///< rigid translation of the wall [m/s]
    double friction = 0.0;         ///< Coulomb coefficient μ ≥ 0
    WallShape shape = WallShape::Plane;
    Vec3 axis = Vec3::UnitY();  ///< cylinder: direction of its axis (normalised by RigidWalls)
    double radius = 0.0;        ///< cylinder: R > 0 [m]; the bodies are outside it
    /// T ≥ 0: the wall's speed rises linearly from 0 to `velocity` over [0, T] (a smooth start
    /// for quasi-static loading), then stays; 0: `velocity` from t = 0.
    double rampTime = 0.0;

    /// Speed factor s'(t) = min(t/T, 1) (1 without a ramp).
    double speedFactor(double t) const {
        return rampTime > 0.0 && t < rampTime ? t / rampTime : 1.0;
    }
    /// The wall's velocity at time t.
    Vec3 velocityAt(double t) const { return speedFactor(t) * velocity; }
    /// Its displacement from `point` at time t: velocity · s(t), s(t) = t²/2T before T, t − T/2
    /// after.
    Vec3 displacement(double t) const {
        const double s =
            rampTime > 0.0 && t < rampTime ? 0.5 * t * t / rampTime : t - 0.5 * rampTime;
        return s * velocity;
    }
};

/// What the walls did at the last evaluation, in total (over every process of a split run).
struct WallResult {
    double energy = 0.0;     ///< Σ ½ k g² [J]
    double pushPower = 0.0;  ///< Σ f_n·v_wall [W] (friction's power needs v, the caller's)
};

class RigidWalls {
  public:
    RigidWalls() = default;
    /// Throws InputError on a zero normal or axis, a radius ≤ 0 or μ < 0. `stiffness`: k_a;
    /// `shapes`: the contact ellipsoids (contactShapes).
    RigidWalls(const Reference& ref, std::vector<Wall> walls, std::vector<double> stiffness,
               const ContactShapes& shapes);

    bool active() const { return !walls_.empty(); }
    const std::vector<Wall>& walls() const { return walls_; }

    /// Adds the walls' forces at time t (positions x, velocities v, step dt for the stick
    /// limit; dt ≤ 0: no limit) to force[a], the friction part also to friction[a], k_a for
    /// each wall touched to frequency2[a]; wallForce[a] = the walls' total force on a; for the
    /// `owned` particles (all of them in a serial run). The sums are exact over the owned
    /// particles and, with a `domain` (a split run; collective), over every process's.
    WallResult addForces(double t, double dt, const std::vector<Vec3>& x,
                         const std::vector<Vec3>& v, std::vector<Vec3>& force,
                         std::vector<Vec3>& friction, std::vector<double>& frequency2,
                         std::vector<Vec3>& wallForce, ParticleRange owned,
                         Domain* domain = nullptr);

    /// Per wall, the total force (normal and friction) it exerted on the bodies at the last
    /// addForces [N] (zero before the first); the reaction on the wall is its opposite. Exactly
    /// rounded sums over the particles of that addForces and its domain's processes
    /// (collective): the same bits for any thread or process count. `totals` is resized to the
    /// walls.
    void totalForces(std::vector<Vec3>& totals) const;

  private:
    const Reference* ref_ = nullptr;
    std::vector<Wall> walls_;
    std::vector<double> stiffness_;
    std::vector<double> radius_;  ///< planes: ρ_a(n_w), particle-major: radius_[a · walls + w]
    std::vector<Mat3> S_;         ///< the ellipsoids' S_a (kept only when a cylinder needs them)
    std::vector<Vec3> perWall_;   ///< force of wall w on a: perWall_[a · walls + w]
    std::vector<double> energy_, pushPower_;       ///< per particle scratch
    mutable std::vector<ExactSum> totalsScratch_;  ///< of totalForces: 3 per wall
    ParticleRange owned_;                          ///< of the last addForces
    Domain* domain_ = nullptr;                     ///< of the last addForces
};

}  // namespace gsph
