// SPDX-License-Identifier: MIT
#include "contact/walls.hpp"

#include <algorithm>
#include <cmath>

#include "core/error.hpp"
#include "core/parallel.hpp"

namespace gsph {

RigidWalls::RigidWalls(const Reference& ref, std::vector<Wall> walls, std::vector<double> stiffness,
                       const ContactShapes& shapes)
    : ref_(&ref), walls_(std::move(walls)), stiffness_(std::move(stiffness)) {
    for (Wall& w : walls_) {
        const double length = w.normal.norm();
        if (!(length > 0.0) || !std::isfinite(length))
            throw InputError("wall '" + w.name + "': the normal must be a non-zero vector");
        if (!(w.friction >= 0.0))
            throw InputError("wall '" + w.name + "': the friction coefficient must be ≥ 0");
        w.normal /= length;
    }
    if (walls_.empty()) return;
    const auto n = static_cast<std::size_t>(ref.size());
    radius_.resize(n * walls_.size());
    for (std::size_t a = 0; a < n; ++a)
        for (std::size_t w = 0; w < walls_.size(); ++w)
            radius_[a * walls_.size() + w] = shapes.radius(a, walls_[w].normal);
    energy_.resize(n);
    pushPower_.resize(n);
}

WallResult RigidWalls::addForces(double t, double dt, const std::vector<Vec3>& x,
                                 const std::vector<Vec3>& v, std::vector<Vec3>& force,
                                 std::vector<Vec3>& friction, std::vector<double>& frequency2,
                                 std::vector<Vec3>& wallForce) {
    WallResult result;
    if (walls_.empty()) return result;
    const Reference& ref = *ref_;
    parallelFor(ref.size(), [&](Index a) {
        const auto ia = static_cast<std::size_t>(a);
        Vec3 total = Vec3::Zero(), tangential = Vec3::Zero();
        double u = 0.0, push = 0.0, w2 = 0.0;
        for (std::size_t iw = 0; iw < walls_.size(); ++iw) {
            const Wall& w = walls_[iw];
            const double gap = radius_[ia * walls_.size() + iw] -
                               (x[ia] - (w.point + t * w.velocity)).dot(w.normal);
            if (!(gap > 0.0)) continue;
            const double k = stiffness_[ia], fn = k * gap;
            const Vec3 normalForce = fn * w.normal;
            u += 0.5 * k * gap * gap;
            push += normalForce.dot(w.velocity);
            w2 += k / ref.mass[ia];
            total += normalForce;
            if (w.friction > 0.0) {
                const Vec3 slip = v[ia] - w.velocity;
                const Vec3 wt = slip - slip.dot(w.normal) * w.normal;
                const double speed = wt.norm();
                if (speed > 0.0) {
                    double ft = w.friction * fn;
                    if (dt > 0.0) ft = std::min(ft, ref.mass[ia] * speed / dt);  // stick limit
                    const Vec3 f = (-ft / speed) * wt;
                    tangential += f;
                    total += f;
                }
            }
        }
        force[ia] += total;
        friction[ia] += tangential;
        frequency2[ia] += w2;
        wallForce[ia] = total;
        energy_[ia] = u;
        pushPower_[ia] = push;
    });
    const auto sum = [&](const std::vector<double>& part) {
        return deterministicSum(
            ref.size(), 0.0, [&](Index a) { return part[static_cast<std::size_t>(a)]; }, partial_);
    };
    result.energy = sum(energy_);
    result.pushPower = sum(pushPower_);
    return result;
}

}  // namespace gsph
