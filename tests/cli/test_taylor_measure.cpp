// SPDX-License-Identifier: MIT
// scripts/validation/taylor.py, the Taylor bar's measure, on the undeformed rod (the snapshot
// at t = 0 of a run): its cells' reach spans the rod's length L0 exactly and the impact face's
// area is the meshed face's, on layouts graded along the axis, across the core and towards the
// lip (the cells' half-edges come from their corners, not from their neighbours' centres,
// which misjudged a graded lattice's end cells by 0.03 mm and a graded core's face by 1 %).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "support/taylor_run.hpp"
#include "tools/temp_dir.hpp"

namespace gsph {
namespace {

constexpr int kExitInterrupted = 3;

// taylor.py's measure of the snapshot at t = 0 of `caseFile` run on `geometry` with `sets`.
test::TaylorShape measureAtRest(const std::filesystem::path& dir, const std::string& geometry,
                                const std::string& sets, const std::string& caseFile) {
    return test::runAndMeasureTaylor(dir, geometry, sets, caseFile, "--stop-after-steps 1",
                                     kExitInterrupted, "snapshot_000000.h5");
}

// The O-grid of the impact zone (core graded towards the axis, radial cells towards the lip,
// 34 layers graded 1.08): L0 = 25.4 mm; the face is the meshed 48-gon (4 × 12 arcs),
// D = 2 √(½ · 48 R² sin(2π/48) / π) = 7.58914 mm. taylor.py prints three decimals.
TEST(TaylorMeasure, GradedOgridAtRestSpansTheRodAndItsMeshedFace) {
    test::TempDir dir;
    const test::TaylorShape shape = measureAtRest(
        dir.path(), "geometries/taylor_bar.geo",
        "--set n=12 --set nr=3 --set nz=34 --set grading=1.08 --set centre=10 --set lip=0.7",
        "cases/taylor_bar/case.toml");
    const double R = 3.8, sides = 48;
    const double polygon = 0.5 * sides * R * R * std::sin(2 * M_PI / sides);
    EXPECT_NEAR(shape.length, 25.4, 5e-4);
    EXPECT_NEAR(shape.footprint, 2 * std::sqrt(polygon / M_PI), 5e-4);
}

// The axisymmetric section graded towards the face (8 × 50 cells, 1.06): L0 = 25.4 mm and the
// rings of the face sweep the disc of D0 = 7.6 mm exactly.
TEST(TaylorMeasure, GradedSectionAtRestSpansTheRodAndItsFace) {
    test::TempDir dir;
    const test::TaylorShape shape = measureAtRest(
        dir.path(), "geometries/taylor_bar_axisymmetric.geo",
        "--set nr=8 --set nz=50 --set grading=1.06", "cases/taylor_bar_axisymmetric/case.toml");
    EXPECT_NEAR(shape.length, 25.4, 5e-4);
    EXPECT_NEAR(shape.footprint, 7.6, 5e-4);
}

}  // namespace
}  // namespace gsph
