// SPDX-License-Identifier: MIT
#include "spaces/analytic_maps.hpp"

#include <Eigen/Dense>
#include <cmath>
#include <numbers>

#include "core/error.hpp"

namespace gsph {
namespace {

constexpr double kPi = std::numbers::pi;

// 3-point Gauss–Legendre rule on [0,1] (exact for degree 5).
constexpr std::array<double, 3> kGaussPoints = {0.5 - 0.3872983346207417, 0.5,
                                                0.5 + 0.3872983346207417};
constexpr std::array<double, 3> kGaussWeights = {5.0 / 18.0, 8.0 / 18.0, 5.0 / 18.0};

}  // namespace

// OneSided: spacing ∝ exp(β s), β = ln(ratio). Symmetric: spacing ∝ 1 − a cos(2πs) with
// (1 + a)/(1 − a) = ratio (finest at both ends, coarsest in the middle).
double AxisGrading::x(double s) const {
    switch (kind) {
        case Kind::Uniform:
            return s;
        case Kind::OneSided: {
            const double beta = std::log(ratio);
            return beta == 0.0 ? s : std::expm1(beta * s) / std::expm1(beta);
        }
        case Kind::Symmetric: {
            const double a = (ratio - 1.0) / (ratio + 1.0);
            return s - a * std::sin(2.0 * kPi * s) / (2.0 * kPi);
        }
    }
    return s;
}

double AxisGrading::dx(double s) const {
    switch (kind) {
        case Kind::Uniform:
            return 1.0;
        case Kind::OneSided: {
            const double beta = std::log(ratio);
            return beta == 0.0 ? 1.0 : beta * std::exp(beta * s) / std::expm1(beta);
        }
        case Kind::Symmetric: {
            const double a = (ratio - 1.0) / (ratio + 1.0);
            return 1.0 - a * std::cos(2.0 * kPi * s);
        }
    }
    return 1.0;
}

AnalyticMap gradedBoxMap(const Vec3& lengths, const std::array<AxisGrading, 3>& grading,
                         const Vec3& origin) {
    AnalyticMap m;
    m.position = [=](const Vec3& s) {
        Vec3 X;
        for (int d = 0; d < 3; ++d)
            X[d] = origin[d] + lengths[d] * grading[static_cast<std::size_t>(d)].x(s[d]);
        return X;
    };
    m.jacobian = [=](const Vec3& s) {
        Mat3 J = Mat3::Zero();
        for (int d = 0; d < 3; ++d)
            J(d, d) = lengths[d] * grading[static_cast<std::size_t>(d)].dx(s[d]);
        return J;
    };
    return m;
}

AnalyticMap annulusMap(double ri, double ro, double phi0, double phi1, double height,
                       const AxisGrading& radial) {
    if (!(ro > ri && ri > 0.0)) throw InputError("annulus needs 0 < inner radius < outer radius");
    AnalyticMap m;
    m.position = [=](const Vec3& s) {
        const double r = ri + (ro - ri) * radial.x(s[0]);
        const double phi = phi0 + (phi1 - phi0) * s[1];
        return Vec3(r * std::cos(phi), r * std::sin(phi), height * s[2]);
    };
    m.jacobian = [=](const Vec3& s) {
        const double r = ri + (ro - ri) * radial.x(s[0]);
        const double dr = (ro - ri) * radial.dx(s[0]);
        const double phi = phi0 + (phi1 - phi0) * s[1];
        const double dphi = phi1 - phi0;
        Mat3 J;
        J << dr * std::cos(phi), -r * std::sin(phi) * dphi, 0.0,  //
            dr * std::sin(phi), r * std::cos(phi) * dphi, 0.0,    //
            0.0, 0.0, height;
        return J;
    };
    m.periodic[1] = std::abs(std::abs(phi1 - phi0) - 2.0 * kPi) < 1e-12;
    return m;
}

AnalyticMap wavyBoxMap(const Vec3& L, double eps) {
    AnalyticMap m;
    m.position = [=](const Vec3& s) {
        const Vec3 w(std::sin(kPi * s[1]) * std::sin(kPi * s[2]),
                     std::sin(kPi * s[2]) * std::sin(kPi * s[0]),
                     std::sin(kPi * s[0]) * std::sin(kPi * s[1]));
        return Vec3((L.array() * (s + eps * w).array()).matrix());
    };
    m.jacobian = [=](const Vec3& s) {
        const Vec3 sn(std::sin(kPi * s[0]), std::sin(kPi * s[1]), std::sin(kPi * s[2]));
        const Vec3 cs(std::cos(kPi * s[0]), std::cos(kPi * s[1]), std::cos(kPi * s[2]));
        Mat3 J = Mat3::Identity();
        J(0, 1) += eps * kPi * cs[1] * sn[2];
        J(0, 2) += eps * kPi * sn[1] * cs[2];
        J(1, 2) += eps * kPi * cs[2] * sn[0];
        J(1, 0) += eps * kPi * sn[2] * cs[0];
        J(2, 0) += eps * kPi * cs[0] * sn[1];
        J(2, 1) += eps * kPi * sn[0] * cs[1];
        return Mat3(L.asDiagonal() * J);
    };
    return m;
}

Reference latticeReference(const AnalyticMap& map, int dimension, const std::array<int, 3>& cells,
                           double density, double kappa, Index body) {
    if (dimension != 2 && dimension != 3) throw InputError("dimension must be 2 or 3");
    if (dimension == 2 && cells[2] != 1) throw InputError("a 2-D lattice has one cell in z");
    for (int c : cells)
        if (c < 1) throw InputError("lattice needs at least one cell per index");
    Reference ref;
    ref.dim.value = dimension;
    ref.kappa = kappa;
    LatticeSpace space;
    space.dtheta = 1.0;
    space.cells = cells;
    space.periodic = map.periodic;
    ref.spaces.push_back(space);

    const std::size_t n = static_cast<std::size_t>(cells[0]) * cells[1] * cells[2];
    ref.X.resize(n);
    ref.theta.resize(n);
    ref.volume.resize(n);
    ref.density.assign(n, density);
    ref.body.assign(n, body);
    ref.space.assign(n, 0);
    const Vec3 ds(1.0 / cells[0], 1.0 / cells[1], 1.0 / cells[2]);
    const int gz = dimension == 3 ? 3 : 1;  // 2-D: the cell has unit depth, s_z = ½
    for (int k = 0; k < cells[2]; ++k)
        for (int j = 0; j < cells[1]; ++j)
            for (int i = 0; i < cells[0]; ++i) {
                const auto a = static_cast<std::size_t>(latticeIndex(cells, i, j, k));
                const Vec3 theta(i + 0.5, j + 0.5, dimension == 3 ? k + 0.5 : 0.0);
                const Vec3 s(theta[0] * ds[0], theta[1] * ds[1],
                             dimension == 3 ? theta[2] * ds[2] : 0.5);
                ref.theta[a] = theta;
                ref.X[a] = map.position(s);
                if (dimension == 2) ref.X[a][2] = 0.0;
                double V = 0.0;
                for (int p = 0; p < 3; ++p)
                    for (int q = 0; q < 3; ++q)
                        for (int r = 0; r < gz; ++r) {
                            const Vec3 sg(
                                (i + kGaussPoints[static_cast<std::size_t>(p)]) * ds[0],
                                (j + kGaussPoints[static_cast<std::size_t>(q)]) * ds[1],
                                dimension == 3
                                    ? (k + kGaussPoints[static_cast<std::size_t>(r)]) * ds[2]
                                    : 0.5);
                            const Mat3 J = map.jacobian(sg);
                            const double w =
                                kGaussWeights[static_cast<std::size_t>(p)] *
                                kGaussWeights[static_cast<std::size_t>(q)] *
                                (dimension == 3 ? kGaussWeights[static_cast<std::size_t>(r)] : 1.0);
                            const double det = dimension == 3
                                                   ? J.determinant()
                                                   : J.topLeftCorner<2, 2>().determinant();
                            V += w * det;
                        }
                V *= ds[0] * ds[1] * (dimension == 3 ? ds[2] : 1.0);
                ref.volume[a] = V;
            }
    return ref;
}

}  // namespace gsph
