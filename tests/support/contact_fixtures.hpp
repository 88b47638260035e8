// SPDX-License-Identifier: MIT
// References of several bodies for the contact tests: boxes laid on their own
// lattices, one body and one space each, concatenated in body order (Reference invariant);
// the Simulation builds pairs and geometry.
#pragma once

#include <array>
#include <cmath>
#include <limits>
#include <vector>

#include "contact/penalty_contact.hpp"
#include "spaces/analytic_maps.hpp"
#include "support/lattice_fixtures.hpp"

namespace gsph::testing {

struct Box {
    Vec3 origin = Vec3::Zero();
    Vec3 size = Vec3::Ones();
    std::array<int, 3> cells = {1, 1, 1};
    double density = 7800.0;
};

/// One body per box (body id = position in `boxes`), each its own lattice space.
inline Reference boxBodies(const std::vector<Box>& boxes, double kappa = 1.2, int dim = 3) {
    Reference out;
    for (std::size_t b = 0; b < boxes.size(); ++b) {
        const Box& box = boxes[b];
        const Reference r = latticeReference(gradedBoxMap(box.size, {}, box.origin), dim, box.cells,
                                             box.density, kappa, static_cast<Index>(b));
        if (b == 0)
            out = r;
        else
            appendSpace(out, r, static_cast<Index>(b));
    }
    return out;
}

/// Smallest |x_a − x_b| / d_ab(n) over pairs of different bodies (d_ab(n) = ρ_a(n) + ρ_b(n),
/// the contact distance of contact/penalty_contact.hpp along the pair), by brute force:
/// independent of the contact search.
inline double smallestContactRatio(const Reference& ref, const std::vector<Vec3>& x,
                                   double distance = 1.0) {
    const ContactShapes shapes = contactShapes(ref, distance);
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t a = 0; a < x.size(); ++a)
        for (std::size_t b = a + 1; b < x.size(); ++b) {
            if (ref.body[a] == ref.body[b]) continue;
            const Vec3 n = (x[a] - x[b]).normalized();
            const double d = shapes.radius(a, n) + shapes.radius(b, n);
            smallest = std::min(smallest, (x[a] - x[b]).norm() / d);
        }
    return smallest;
}

}  // namespace gsph::testing
