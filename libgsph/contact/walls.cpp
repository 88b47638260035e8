// SPDX-License-Identifier: MIT
#include "contact/walls.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace gsph {
namespace {

// Normalises `direction` in place; throws InputError naming the wall and what it is.
void normalise(Vec3& direction, const Wall& w, const char* what) {
    const double length = direction.norm();
    if (!(length > 0.0) || !std::isfinite(length))
        throw InputError("wall '" + w.name + "': the " + what + " must be a non-zero vector");
    direction /= length;
}

}  // namespace

RigidWalls::RigidWalls(const Reference& ref, std::vector<Wall> walls, std::vector<double> stiffness,
                       const ContactShapes& shapes)
    : ref_(&ref), walls_(std::move(walls)), stiffness_(std::move(stiffness)) {
    bool cylinder = false;
    for (Wall& w : walls_) {
        if (!(w.friction >= 0.0))
            throw InputError("wall '" + w.name + "': the friction coefficient must be ≥ 0");
        if (!(w.rampTime >= 0.0 && std::isfinite(w.rampTime)))
            throw InputError("wall '" + w.name + "': the ramp time must be ≥ 0");
        if (w.shape == WallShape::Plane) {
            normalise(w.normal, w, "normal");
            continue;
        }
        normalise(w.axis, w, "axis");
        if (!(w.radius > 0.0) || !std::isfinite(w.radius))
            throw InputError("wall '" + w.name + "': the cylinder's radius must be > 0");
        cylinder = true;
    }
    if (walls_.empty()) return;
    const auto n = static_cast<std::size_t>(ref.size());
    radius_.resize(n * walls_.size());
    for (std::size_t a = 0; a < n; ++a)
        for (std::size_t w = 0; w < walls_.size(); ++w)
            radius_[a * walls_.size() + w] =
                walls_[w].shape == WallShape::Plane ? shapes.radius(a, walls_[w].normal) : 0.0;
    if (cylinder) S_ = shapes.S;
    perWall_.assign(n * walls_.size(), Vec3::Zero());
    energy_.resize(n);
    pushPower_.resize(n);
}

WallResult RigidWalls::addForces(double t, double dt, const std::vector<Vec3>& x,
                                 const std::vector<Vec3>& v, std::vector<Vec3>& force,
                                 std::vector<Vec3>& friction, std::vector<double>& frequency2,
                                 std::vector<Vec3>& wallForce, ParticleRange owned,
                                 Domain* domain) {
    WallResult result;
    if (walls_.empty()) return result;
    const Reference& ref = *ref_;
    const std::size_t walls = walls_.size();
    owned_ = owned;
    domain_ = domain;
    parallelFor(owned, [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        Vec3 total = Vec3::Zero(), tangential = Vec3::Zero();
        double u = 0.0, push = 0.0, w2 = 0.0;
        for (std::size_t iw = 0; iw < walls; ++iw) {
            const Wall& w = walls_[iw];
            Vec3& mine = perWall_[ia * walls + iw];
            mine = Vec3::Zero();
            const Vec3 q = x[ia] - (w.point + w.displacement(t));
            const Vec3 wallVelocity = w.velocityAt(t);
            double gap = 0.0, distance = 0.0;
            Vec3 n = w.normal;
            if (w.shape == WallShape::Plane) {
                gap = radius_[ia * walls + iw] - q.dot(w.normal);
            } else {
                const Vec3 radial = q - q.dot(w.axis) * w.axis;
                distance = radial.norm();
                if (!(distance > 0.0)) continue;  // on the axis: no outward direction
                n = radial / distance;
                gap = 1.0 / (S_[ia] * n).norm() - (distance - w.radius);
            }
            if (!(gap > 0.0)) continue;
            const double k = stiffness_[ia], fn = k * gap;
            Vec3 normalForce = fn * n;
            if (w.shape == WallShape::Cylinder) {
                // −∂U/∂x: ρ_a(n) changes as n turns about the axis (h = −∂ρ/∂n).
                const Vec3 sn = S_[ia] * n;
                const double sNorm = sn.norm();
                const Vec3 h = (S_[ia].transpose() * sn) / (sNorm * sNorm * sNorm);
                const Vec3 turning = h - h.dot(n) * n - h.dot(w.axis) * w.axis;
                normalForce += (fn / distance) * turning;
            }
            u += 0.5 * k * gap * gap;
            push += normalForce.dot(wallVelocity);
            w2 += k / ref.mass[ia];
            mine = normalForce;
            if (w.friction > 0.0) {
                const Vec3 slip = v[ia] - wallVelocity;
                const Vec3 wt = slip - slip.dot(n) * n;
                const double speed = wt.norm();
                if (speed > 0.0) {
                    double ft = w.friction * fn;
                    if (dt > 0.0) ft = std::min(ft, ref.mass[ia] * speed / dt);  // stick limit
                    const Vec3 f = (-ft / speed) * wt;
                    tangential += f;
                    mine += f;
                }
            }
            total += mine;
        }
        force[ia] += total;
        friction[ia] += tangential;
        frequency2[ia] += w2;
        wallForce[ia] = total;
        energy_[ia] = u;
        pushPower_[ia] = push;
    });
    const auto sum = [&](const std::vector<double>& part) {
        return exactSum(owned, [&](Index a) { return part[static_cast<std::size_t>(a)]; });
    };
    std::array<ExactSum, 2> sums = {sum(energy_), sum(pushPower_)};
    if (domain) domain->sum(sums);
    result.energy = sums[0].value();
    result.pushPower = sums[1].value();
    return result;
}

void RigidWalls::totalForces(std::vector<Vec3>& totals) const {
    const std::size_t walls = walls_.size();
    totals.assign(walls, Vec3::Zero());
    if (walls == 0 || perWall_.empty()) return;
    totalsScratch_.assign(3 * walls, ExactSum{});
    for (std::size_t iw = 0; iw < walls; ++iw)
        for (std::size_t r = 0; r < 3; ++r)
            totalsScratch_[3 * iw + r] = exactSum(owned_, [&](Index a) {
                return perWall_[static_cast<std::size_t>(a) * walls + iw][static_cast<Index>(r)];
            });
    if (domain_) domain_->sum(totalsScratch_);
    for (std::size_t iw = 0; iw < walls; ++iw)
        for (std::size_t r = 0; r < 3; ++r)
            totals[iw][static_cast<Index>(r)] = totalsScratch_[3 * iw + r].value();
}

}  // namespace gsph
