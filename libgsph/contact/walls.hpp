// SPDX-License-Identifier: MIT
// Rigid planar walls (issue #6; docs/theory.md "Walls"). A wall is the infinite plane through
// p(t) = point + velocity·t with unit normal n pointing into the bodies' side. A particle
// penetrates by g_a = ρ_a(n) − (x_a − p(t))·n (ρ_a(n) its contact ellipsoid's radius along n,
// penalty_contact.hpp: half its cell's width across the wall) and, when g_a > 0, feels
//   normal:  f_n = k_a g_a n                      (k_a of contactStiffness, U = ½ k_a g_a²)
//   Coulomb: f_t = −min(μ |f_n|, m_a |w_t|/Δt) w_t/|w_t|,  w_t the tangential part of v_a − v_wall,
// the min being the stick limit: friction never reverses the sliding within a step. The power
// the wall puts into the bodies, f_n·v_wall + f_t·v_a (its push, and the friction, negative
// for a wall at rest), is booked as external work; the normal spring's energy as contact energy.
// Each particle writes only its own entries (parallel, thread-count-independent).
#pragma once

#include <string>
#include <vector>

#include "contact/penalty_contact.hpp"
#include "core/types.hpp"
#include "particles/reference.hpp"

namespace gsph {

struct Wall {
    std::string name;  ///< for messages
    Vec3 point = Vec3::Zero();
    Vec3 normal = Vec3::UnitZ();   ///< normalised by RigidWalls; points to the bodies' side
    Vec3 velocity = Vec3::Zero();  ///< rigid translation of the wall [m/s]
    double friction = 0.0;         ///< Coulomb coefficient μ ≥ 0
};

/// What the walls did at the last evaluation, per particle and in total.
struct WallResult {
    double energy = 0.0;     ///< Σ ½ k g² [J]
    double pushPower = 0.0;  ///< Σ f_n·v_wall [W] (friction's power needs v, the caller's)
};

class RigidWalls {
  public:
    RigidWalls() = default;
    /// Throws InputError on a zero normal or μ < 0. `stiffness`: k_a; `shapes`: the contact
    /// ellipsoids (contactShapes).
    RigidWalls(const Reference& ref, std::vector<Wall> walls, std::vector<double> stiffness,
               const ContactShapes& shapes);

    bool active() const { return !walls_.empty(); }
    const std::vector<Wall>& walls() const { return walls_; }

    /// Adds the walls' forces at time t (positions x, velocities v, step dt for the stick
    /// limit; dt ≤ 0: no limit) to force[a], the friction part also to friction[a], k_a for
    /// each wall touched to frequency2[a]; wallForce[a] = the walls' total force on a.
    WallResult addForces(double t, double dt, const std::vector<Vec3>& x,
                         const std::vector<Vec3>& v, std::vector<Vec3>& force,
                         std::vector<Vec3>& friction, std::vector<double>& frequency2,
                         std::vector<Vec3>& wallForce);

  private:
    const Reference* ref_ = nullptr;
    std::vector<Wall> walls_;
    std::vector<double> stiffness_;
    std::vector<double> radius_;  ///< ρ_a(n_w), particle-major: radius_[a · walls + w]
    std::vector<double> energy_, pushPower_, partial_;  ///< per particle scratch
};

}  // namespace gsph
