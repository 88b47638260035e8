// SPDX-License-Identifier: MIT
#include "materials/material_point_driver.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <cmath>
#include <string>

#include "core/error.hpp"

namespace gsph {
namespace {

using Kind = LoadingPath::Kind;

// Lateral stress accepted as zero in uniaxial stress: 1e-10 E + 1e-9 |σ_xx| [Pa].
constexpr double kLateralToleranceModulus = 1e-10;
constexpr double kLateralToleranceAxial = 1e-9;
constexpr int kLateralIterations = 60;

void validate(const LoadingPath& path) {
    if (path.outputEvery < 1) throw InputError("output_every must be ≥ 1");
    if (path.kind == Kind::DeformationGradient) {
        if (path.times.size() < 2 || path.times.size() != path.F.size())
            throw InputError("a deformation-gradient path needs at least two (time, F) rows");
        if (!(path.F[0] - Mat3::Identity()).isZero(1e-12))
            throw InputError("the first F of a path must be the identity (the stress-free start)");
        for (std::size_t i = 1; i < path.times.size(); ++i) {
            if (!(path.times[i] > path.times[i - 1]))
                throw InputError("path times must increase (row " + std::to_string(i + 1) + ")");
            if (!(path.F[i].determinant() > 0.0))
                throw InputError("det F must be > 0 (row " + std::to_string(i + 1) + ")");
        }
        if (path.substeps < 1) throw InputError("substeps must be ≥ 1");
        return;
    }
    if (!(path.strainRate != 0.0) || !std::isfinite(path.strainRate))
        throw InputError("strain_rate must be a non-zero number");
    if (!(path.finalStrain * path.strainRate > 0.0))
        throw InputError("final_strain must be non-zero and have the sign of strain_rate");
    if (path.steps < 1) throw InputError("steps must be ≥ 1");
}

// One increment F0 → F1 over dt, as the integrator does it (velocity_verlet.cpp, steps 3–4).
template <class Model>
MaterialPoint advance(const Model& model, MaterialPoint p, const Mat3& F0, const Mat3& F1,
                      double dt) {
    const Mat3 L = ((F1 - F0) / dt) * (0.5 * (F0 + F1)).inverse();
    p.density = model.elastic().density / F1.determinant();
    model.update(p, 0.5 * (L + L.transpose()), 0.5 * (L - L.transpose()), dt);
    return p;
}

// Uniaxial stress: the lateral stretch μ with σ_yy = σ_zz = 0 after the increment (secant).
template <class Model>
MaterialPoint advanceUniaxialStress(const Model& model, const MaterialPoint& p, Mat3& F,
                                    double stretch, double dt) {
    const double mu0 = F(1, 1);
    const double axial = std::log(stretch / F(0, 0));
    const auto trial = [&](double mu) {
        return advance(model, p, F, Vec3(stretch, mu, mu).asDiagonal(), dt);
    };
    const ElasticConstants& e = model.elastic();
    // Elastic and fully plastic (incompressible) guesses of the lateral strain.
    double muA = mu0 * std::exp(-e.poissonRatio * axial), muB = mu0 * std::exp(-0.5 * axial);
    MaterialPoint a = trial(muA), b = trial(muB);
    for (int it = 0; it < kLateralIterations; ++it) {
        const double tolerance = kLateralToleranceModulus * e.youngsModulus +
                                 kLateralToleranceAxial * std::abs(b.cauchy(0, 0));
        if (std::abs(a.cauchy(1, 1)) <= tolerance) std::swap(a, b), std::swap(muA, muB);
        if (std::abs(b.cauchy(1, 1)) <= tolerance) {
            F = Vec3(stretch, muB, muB).asDiagonal();
            return b;
        }
        const double slope = (b.cauchy(1, 1) - a.cauchy(1, 1)) / (muB - muA);
        if (!(slope != 0.0) || !std::isfinite(slope)) break;
        const double muC = muB - b.cauchy(1, 1) / slope;
        muA = muB;
        a = b;
        muB = muC;
        b = trial(muB);
    }
    throw NumericalError("uniaxial stress: the lateral stress did not vanish (stretch " +
                         std::to_string(stretch) + ")");
}

// F of a compact path at time t.
Mat3 compactF(const LoadingPath& path, double t) {
    Mat3 F = Mat3::Identity();
    if (path.kind == Kind::SimpleShear)
        F(0, 1) = path.strainRate * t;
    else
        F(0, 0) = std::exp(path.strainRate * t);
    return F;
}

// F of a tabulated path at increment k (substeps per segment, linear in time).
void tableState(const LoadingPath& path, int k, double& t, Mat3& F) {
    const std::size_t segment = static_cast<std::size_t>(k - 1) / path.substeps;
    const double s =
        static_cast<double>(k - static_cast<int>(segment) * path.substeps) / path.substeps;
    t = (1.0 - s) * path.times[segment] + s * path.times[segment + 1];
    F = (1.0 - s) * path.F[segment] + s * path.F[segment + 1];
}

template <class Model>
std::vector<MaterialPointRecord> drive(const Model& model, const LoadingPath& path) {
    MaterialPoint p;
    p.density = model.elastic().density;
    if constexpr (requires { model.roomTemperature(); })
        p.temperature = path.temperature.value_or(model.roomTemperature());
    else
        p.temperature = path.temperature.value_or(State::kRoomTemperature);
    if constexpr (requires { model.stressFreeInternalEnergy(0.0); })
        p.internalEnergy = model.stressFreeInternalEnergy(p.temperature);

    const bool table = path.kind == Kind::DeformationGradient;
    const int increments =
        table ? path.substeps * static_cast<int>(path.times.size() - 1) : path.steps;
    const double duration = path.finalStrain / path.strainRate;
    double t = table ? path.times[0] : 0.0;
    Mat3 F = Mat3::Identity();
    double plasticWork = 0.0;
    std::vector<MaterialPointRecord> out;
    auto record = [&]() {
        MaterialPointRecord r;
        r.time = t;
        r.strain = path.kind == Kind::SimpleShear ? F(0, 1)
                   : table                        ? equivalentLogStrain(F)
                                                  : std::log(F(0, 0));
        r.F = F;
        r.cauchy = p.cauchy;
        r.plasticStrain = p.plasticStrain;
        r.temperature = p.temperature;
        r.damage = p.damage;
        r.plasticWork = plasticWork;
        out.push_back(r);
    };
    record();
    for (int k = 1; k <= increments; ++k) {
        double t1 = 0.0;
        Mat3 F1;
        if (table)
            tableState(path, k, t1, F1);
        else
            t1 = duration * k / increments, F1 = compactF(path, t1);
        const double dt = t1 - t;
        if (path.kind == Kind::UniaxialStress) {
            p = advanceUniaxialStress(model, p, F, F1(0, 0), dt);
        } else {
            p = advance(model, p, F, F1, dt);
            F = F1;
        }
        t = t1;
        plasticWork += p.plasticWork / p.density;
        if (k % path.outputEvery == 0 || k == increments) record();
    }
    return out;
}

}  // namespace

double equivalentLogStrain(const Mat3& F) {
    const Eigen::SelfAdjointEigenSolver<Mat3> eig(F * F.transpose());
    const Vec3 logStretch = 0.5 * eig.eigenvalues().array().log().matrix();
    const Vec3 dev = logStretch - Vec3::Constant(logStretch.sum() / 3.0);
    return std::sqrt(2.0 / 3.0 * dev.squaredNorm());
}

std::vector<MaterialPointRecord> driveMaterialPoint(const Material& material,
                                                    const LoadingPath& path) {
    validate(path);
    return std::visit([&](const auto& model) { return drive(model, path); }, material);
}

}  // namespace gsph
