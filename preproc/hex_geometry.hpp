// SPDX-License-Identifier: MIT
// Geometry of one trilinear (8-node) hexahedron (DESIGN §2): the isoparametric map
// X(ξ) = Σ_c N_c(ξ) X_c on ξ ∈ [−1,1]³, its centre, its exact volume and its Jacobian checks.
//
// Corners are given in corner-bit order (hex_topology.hpp): X_c with c = di + 2dj + 4dk, so
// corner c sits at ξ = (2di−1, 2dj−1, 2dk−1). Invariants: hexCentre is X(0,0,0) = the mean of
// the corners; hexVolume integrates det ∂X/∂ξ with 2×2×2 Gauss points, exact for trilinear maps
// (det J is at most quadratic in each ξ; spaces/hexahedron.hpp); a hex is valid when det J > 0
// at all 8 corners.
#pragma once

#include <array>

#include "core/types.hpp"
#include "spaces/hexahedron.hpp"  // hexVolume

namespace gsph::preproc {

using HexCorners = std::array<Vec3, 8>;

/// X(ξ = 0): the particle position of DESIGN §2 (the parametric centre of the hex).
Vec3 hexCentre(const HexCorners& x);

/// The vector area of the bilinear quadrilateral p0 p1 p2 p3 (corners in a cycle), ½ (p2 − p0) ×
/// (p3 − p1) (exact for a bilinear face), turned to point away from `inside` [m²].
Vec3 outwardQuadArea(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3,
                     const Vec3& inside);

/// X(ξ) = Σ_c N_c(ξ) X_c; ξ may lie outside [−1,1]³ (the hex's polynomial, extended).
Vec3 hexPoint(const HexCorners& x, const Vec3& xi);

/// Condition number σmax/σmin of J = ∂X/∂ξ (∞ if J is singular); with `skipAxis` in 0..2, of
/// the 3×2 matrix of the other two columns (the in-plane metric of a one-layer slab).
double jacobianCondition(const Mat3& J, int skipAxis = -1);

/// ∂X/∂ξ at ξ ∈ [−1,1]³ (columns: derivatives along ξ1, ξ2, ξ3).
Mat3 hexJacobian(const HexCorners& x, const Vec3& xi);

/// Smallest det J over the 8 corners (≤ 0: the hex is inverted or degenerate).
double minCornerJacobian(const HexCorners& x);

/// Shortest and longest of the 12 edges; with `skipAxis` in 0..2, of the 8 edges along the other
/// two corner-bit axes (a 2-D mesh's quad, without the depth of its extrusion).
std::array<double, 2> edgeLengthRange(const HexCorners& x, int skipAxis = -1);

/// The corner-bit axis along which the hex's first edge runs parallel to z (the depth of a 2-D
/// mesh's quad extruded along z), or −1.
int depthAxis(const HexCorners& x);

}  // namespace gsph::preproc
