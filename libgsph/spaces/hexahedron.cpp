// SPDX-License-Identifier: MIT
#include "spaces/hexahedron.hpp"

#include <Eigen/LU>
#include <cmath>

namespace gsph {

namespace {

/// ∂N_c/∂ξ at the 2×2×2 Gauss points ξ = (±g, ±g, ±g), g = 1/√3 (weights 1), computed once.
struct GaussTable {
    std::array<std::array<Vec3, 8>, 8> dN;  // [point][corner]
    GaussTable() {
        const double g = 1.0 / std::sqrt(3.0);
        for (int q = 0; q < 8; ++q) {
            const Vec3 xi((q & 1) ? g : -g, (q & 2) ? g : -g, (q & 4) ? g : -g);
            for (int c = 0; c < 8; ++c) {
                std::array<double, 3> s, f;
                for (int a = 0; a < 3; ++a) {
                    s[a] = (c >> a & 1) ? 1.0 : -1.0;
                    f[a] = 0.5 * (1.0 + s[a] * xi[a]);
                }
                dN[q][c] = Vec3(0.5 * s[0] * f[1] * f[2], 0.5 * s[1] * f[0] * f[2],
                                0.5 * s[2] * f[0] * f[1]);
            }
        }
    }
};

}  // namespace

double hexVolume(const std::array<Vec3, 8>& x) {
    static const GaussTable table;
    double volume = 0.0;
    for (int q = 0; q < 8; ++q) {
        Mat3 J = Mat3::Zero();
        for (int c = 0; c < 8; ++c) J.noalias() += x[c] * table.dN[q][c].transpose();
        volume += J.determinant();
    }
    return volume;
}

}  // namespace gsph
