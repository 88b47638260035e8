// SPDX-License-Identifier: MIT
#include "hex_geometry.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <algorithm>
#include <cmath>

namespace gsph::preproc {

Vec3 hexCentre(const HexCorners& x) {
    Vec3 sum = Vec3::Zero();
    for (const Vec3& c : x) sum += c;
    return sum / 8.0;
}

Vec3 outwardQuadArea(const Vec3& p0, const Vec3& p1, const Vec3& p2, const Vec3& p3,
                     const Vec3& inside) {
    const Vec3 area = 0.5 * (p2 - p0).cross(p3 - p1);
    const Vec3 centre = 0.25 * (p0 + p1 + p2 + p3);
    return area.dot(centre - inside) < 0.0 ? Vec3(-area) : area;
}

Vec3 hexPoint(const HexCorners& x, const Vec3& xi) {
    Vec3 sum = Vec3::Zero();
    for (int c = 0; c < 8; ++c) {
        double N = 1.0;
        for (int a = 0; a < 3; ++a) N *= 0.5 * (1.0 + ((c >> a & 1) ? xi[a] : -xi[a]));
        sum += N * x[static_cast<std::size_t>(c)];
    }
    return sum;
}

double jacobianCondition(const Mat3& J, int skipAxis) {
    // σ² are the eigenvalues of the Gram matrix JᵀJ (3×3, or 2×2 without one column).
    double lo = 0.0, hi = 0.0;
    if (skipAxis < 0) {
        Eigen::SelfAdjointEigenSolver<Mat3> eigen;
        eigen.computeDirect(J.transpose() * J, Eigen::EigenvaluesOnly);
        lo = eigen.eigenvalues()[0];
        hi = eigen.eigenvalues()[2];
    } else {
        const Vec3 a = J.col((skipAxis + 1) % 3), b = J.col((skipAxis + 2) % 3);
        const double p = a.squaredNorm(), q = b.squaredNorm(), r = a.dot(b);
        const double mean = 0.5 * (p + q), radius = std::hypot(0.5 * (p - q), r);
        lo = mean - radius;
        hi = mean + radius;
    }
    return lo > 0.0 ? std::sqrt(hi / lo) : INFINITY;
}

Mat3 hexJacobian(const HexCorners& x, const Vec3& xi) {
    // N_c = Π_a (1 + s_a ξ_a)/2 with s_a = ±1 from bit a of c; ∂N_c/∂ξ_a = s_a/2 Π_{b≠a}(...).
    Mat3 J = Mat3::Zero();
    for (int c = 0; c < 8; ++c) {
        std::array<double, 3> s, f;
        for (int a = 0; a < 3; ++a) {
            s[a] = (c >> a & 1) ? 1.0 : -1.0;
            f[a] = 0.5 * (1.0 + s[a] * xi[a]);
        }
        const Vec3 dN(0.5 * s[0] * f[1] * f[2], 0.5 * s[1] * f[0] * f[2], 0.5 * s[2] * f[0] * f[1]);
        J += x[static_cast<std::size_t>(c)] * dN.transpose();
    }
    return J;
}

double minCornerJacobian(const HexCorners& x) {
    // At corner c, J's columns are the edge vectors to c^1, c^2, c^4 (halved), each negated when
    // c lies on the + side of that axis: det J = (−1)^popcount(c) det(edges) / 8.
    double smallest = INFINITY;
    for (int c = 0; c < 8; ++c) {
        Mat3 edges;
        int flips = 0;
        for (int a = 0; a < 3; ++a) {
            edges.col(a) =
                x[static_cast<std::size_t>(c ^ (1 << a))] - x[static_cast<std::size_t>(c)];
            flips += c >> a & 1;
        }
        const double det = (flips % 2 == 0 ? 1.0 : -1.0) * edges.determinant() / 8.0;
        smallest = std::min(smallest, det);
    }
    return smallest;
}

std::array<double, 2> edgeLengthRange(const HexCorners& x, int skipAxis) {
    double lo = INFINITY, hi = 0.0;
    for (int c = 0; c < 8; ++c) {
        for (int a = 0; a < 3; ++a) {
            if (c >> a & 1 || a == skipAxis) continue;  // each edge once, from its lower corner
            const double length =
                (x[static_cast<std::size_t>(c | (1 << a))] - x[static_cast<std::size_t>(c)]).norm();
            lo = std::min(lo, length);
            hi = std::max(hi, length);
        }
    }
    return {lo, hi};
}

int depthAxis(const HexCorners& x) {
    for (int a = 0; a < 3; ++a) {
        const Vec3 edge = x[static_cast<std::size_t>(1 << a)] - x[0];
        if (edge[0] == 0.0 && edge[1] == 0.0 && edge[2] != 0.0) return a;
    }
    return -1;
}

}  // namespace gsph::preproc
