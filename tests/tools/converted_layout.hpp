// SPDX-License-Identifier: MIT
// A sample geometry (geometries/*.geo) converted in-process as gsph-preproc converts it, and the
// run's reference built from the particles as gsph-solve builds it (buildReference, pairs and
// geometry included): the overset layouts end to end, without files.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "conversion.hpp"
#include "gmsh_input.hpp"
#include "io/particle_file.hpp"
#include "neighbors/theta_search.hpp"
#include "reference/reference_builder.hpp"
#include "spaces/metric.hpp"

namespace gsph::test {

struct ConvertedLayout {
    Reference ref;
    preproc::ConversionStats stats;
};

/// Converts `geometries/<name>` with the DefineConstant overrides `parameters` (a warning is a
/// test failure) into a reference of density `density` and kernel factor `kappa`.
inline ConvertedLayout convertAndBuild(
    const std::string& name, const std::vector<std::pair<std::string, double>>& parameters,
    double density, double kappa = 1.2) {
    const std::string path = std::string(GSPH_SOURCE_DIR) + "/geometries/" + name;
    std::vector<std::string> warnings;
    const preproc::HexMesh mesh =
        preproc::readHexMesh(path, preproc::MeshReadOptions{parameters}, warnings);
    preproc::Conversion c = preproc::convertHexMesh(mesh);
    warnings.insert(warnings.end(), c.warnings.begin(), c.warnings.end());
    for (const std::string& w : warnings) ADD_FAILURE() << path << ": warning: " << w;
    validateParticleFile(c.particles);
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
