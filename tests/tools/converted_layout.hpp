// SPDX-License-Identifier: MIT
// A sample geometry (geometries/*.geo) converted in-process as gsph-preproc converts it, and the
// run's reference built from the particles as gsph-solve builds it (buildReference, pairs and
// geometry included): the overset layouts end to end, without files. Also the checks the
// curved samples share: Σ V converging to the exact volume under refinement, and F exact at
// rest and under an affine motion, with the body at rest for a number of steps.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "conversion.hpp"
#include "gmsh_input.hpp"
#include "io/particle_file.hpp"
#include "kinematics/deformation_gradient.hpp"
#include "neighbors/theta_search.hpp"
#include "reference/reference_builder.hpp"
#include "simulation.hpp"
#include "spaces/metric.hpp"

namespace gsph::test {

/// DefineConstant overrides of a .geo (gsph-preproc --set NAME=VALUE).
using Parameters = std::vector<std::pair<std::string, double>>;

/// Converts `geometries/<name>` with the overrides `parameters` and the transient rule `rule`
/// as gsph-preproc converts it (a warning is a test failure) and validates the particle file;
/// the mesh goes to `meshOut` if given.
inline preproc::Conversion convertSample(
    const std::string& name, const Parameters& parameters,
    preproc::TransientRule rule = preproc::TransientRule::Automatic,
    preproc::HexMesh* meshOut = nullptr) {
    const std::string path = std::string(GSPH_SOURCE_DIR) + "/geometries/" + name;
    std::vector<std::string> warnings;
    preproc::HexMesh mesh =
        preproc::readHexMesh(path, preproc::MeshReadOptions{parameters}, warnings);
    preproc::ConversionOptions options;
    options.transients = rule;
    preproc::Conversion c = preproc::convertHexMesh(mesh, options);
    warnings.insert(warnings.end(), c.warnings.begin(), c.warnings.end());
    for (const std::string& w : warnings) ADD_FAILURE() << path << ": warning: " << w;
    validateParticleFile(c.particles);
    if (meshOut != nullptr) *meshOut = std::move(mesh);
    return c;
}

/// Σ V of the particles [m³].
inline double totalVolume(const ParticleFile& f) {
    double v = 0.0;
    for (double V : f.volume) v += V;
    return v;
}

/// Relative error of Σ V against `exact` at refine = 1, 2, 3 (with `parameters`) and the
/// observed orders between successive refinements; printed, tagged `tag`.
struct VolumeConvergence {
    double error[3] = {0.0, 0.0, 0.0};
    double order12 = 0.0, order23 = 0.0;
};

inline VolumeConvergence volumeConvergence(const char* tag, const std::string& name,
                                           Parameters parameters, double exact) {
    VolumeConvergence out;
    parameters.emplace_back("refine", 1.0);
    for (int r = 1; r <= 3; ++r) {
        parameters.back().second = r;
        const preproc::Conversion c = convertSample(name, parameters);
        out.error[r - 1] = std::abs(totalVolume(c.particles) - exact) / exact;
        std::printf("[%s] refine %d: %d particles in %zu spaces, volume error %.3e\n", tag, r,
                    c.particles.size(), c.particles.spaces.size(), out.error[r - 1]);
    }
    out.order12 = std::log(out.error[0] / out.error[1]) / std::log(2.0);
    out.order23 = std::log(out.error[1] / out.error[2]) / std::log(1.5);
    std::printf("[%s] observed order %.3f (refine 1→2), %.3f (2→3)\n", tag, out.order12,
                out.order23);
    return out;
}

/// On a reference: the largest entry of |F − A| under an affine motion x = A X + b (A general,
/// b = `shift`), the largest |F − I| at rest, and the largest |v| over `steps` steps from rest
/// with viscosity {1, 1} and hourglass control 0.1 (the cases' defaults otherwise).
struct RestAndAffine {
    Index particles = 0;
    std::size_t entries = 0;  ///< transient entries
    double affine = 0.0, rest = 0.0, speed = 0.0;
};

inline RestAndAffine restAndAffine(Reference ref, const ElasticConstants& material, int steps,
                                   const Vec3& shift) {
    RestAndAffine out;
    out.particles = ref.size();
    out.entries = ref.overset.size();
    const Mat3 A = (Mat3() << 1.10, 0.07, -0.03, -0.05, 0.92, 0.04, 0.02, -0.06, 1.05).finished();
    std::vector<Vec3> x(ref.X.size());
    for (std::size_t a = 0; a < x.size(); ++a) x[a] = A * ref.X[a] + shift;
    std::vector<Mat3> F;
    deformationGradient(ref, x, F);
    for (const Mat3& Fa : F) out.affine = std::max(out.affine, (Fa - A).cwiseAbs().maxCoeff());
    deformationGradient(ref, ref.X, F);
    for (const Mat3& Fa : F) out.rest = std::max(out.rest, (Fa - Mat3::Identity()).norm());
    SolverOptions options;
    options.viscosity = {1.0, 1.0};
    options.hourglass = 0.1;
    Simulation sim(std::move(ref), {HypoElastic(material)}, options);
    for (int s = 0; s < steps; ++s) {
        sim.step();
        for (const Vec3& v : sim.state().v) out.speed = std::max(out.speed, v.norm());
    }
    return out;
}

struct ConvertedLayout {
    Reference ref;
    preproc::ConversionStats stats;
};

/// Converts `geometries/<name>` with the DefineConstant overrides `parameters` (a warning is a
/// test failure) into a reference of density `density` and kernel factor `kappa`.
inline ConvertedLayout convertAndBuild(const std::string& name, const Parameters& parameters,
                                       double density, double kappa = 1.2) {
    preproc::Conversion c = convertSample(name, parameters);
    ConvertedLayout out{buildReference(c.particles, std::vector<double>{density}, kappa),
                        std::move(c.stats)};
    buildPairs(out.ref);
    computeGeometry(out.ref);
    return out;
}

/// The O-grid cylinder of taylor_bar.geo with radius R, length L along z, no grading: a core of
/// n × n cells (half-side core·R), an annulus of nr radial × 4n angular cells, nz layers.
inline ConvertedLayout ogridCylinder(double R, double L, int n, int nr, int nz, double density,
                                     double core = 0.4) {
    return convertAndBuild(
        "taylor_bar.geo",
        {{"R", R}, {"L", L}, {"core", core}, {"n", n}, {"nr", nr}, {"nz", nz}, {"grading", 1.0}},
        density);
}

}  // namespace gsph::test
