// SPDX-License-Identifier: MIT
// The copper Taylor bar (cases/taylor_bar, 190 m/s, 80 µs) in 3-D on the GSPH O-grid and as an
// axisymmetric section (cases/taylor_bar_axisymmetric), measured alike by
// scripts/validation/taylor.py, with the cases' settings (the hourglass penalty's secant modulus
// among them): at matched resolution the two agree; against the converged reference of the
// section's refinement series (docs/validation.md) the layouts graded towards the impact face
// meet their tolerances.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include "support/taylor_run.hpp"
#include "tools/temp_dir.hpp"

namespace gsph {
namespace {

namespace fs = std::filesystem;
const fs::path kSource = GSPH_SOURCE_DIR;

using Shape = test::TaylorShape;

// The O-grid of scripts/validate's gsph-medium (8 cells per quarter of arc, 4 from the core to
// the surface: about 8 across the radius; 40 layers, each 1.03 times the one below; 7680
// particles) and the section of 8 cells across with the same layers (320): final length and
// footprint agree within 1 % (measured −0.15 % and +0.09 %, O-grid against section).
TEST(TaylorValidation, AxisymmetricSectionAndOgridAgreeOnLengthAndFootprint) {
    test::TempDir ogrid, section;
    const Shape three =
        test::runAndMeasureTaylor(ogrid.path(), "geometries/taylor_bar.geo",
                                  "--set n=8 --set nr=4 --set nz=40", "cases/taylor_bar/case.toml");
    const Shape axi = test::runAndMeasureTaylor(
        section.path(), "geometries/taylor_bar_axisymmetric.geo",
        "--set nr=8 --set nz=40 --set grading=1.03", "cases/taylor_bar_axisymmetric/case.toml");
    std::printf(
        "[taylor] O-grid (7680 particles): length %.3f mm, footprint %.3f mm; "
        "axisymmetric (320): %.3f mm, %.3f mm (%+.2f %%, %+.2f %%)\n",
        three.length, three.footprint, axi.length, axi.footprint,
        100 * (three.length / axi.length - 1), 100 * (three.footprint / axi.footprint - 1));
    EXPECT_NEAR(three.length / axi.length, 1.0, 0.01);
    EXPECT_NEAR(three.footprint / axi.footprint, 1.0, 0.01);
}

// The converged reference of docs/validation.md ("Taylor bar, axisymmetric"): length and
// footprint from the graded sections' refinement series, the face centre's plastic strain (the
// mean over its centre region) from the square sections', copper at 190 m/s.
constexpr double kConvergedLength = 17.392, kConvergedFootprint = 14.777;  // [mm]
constexpr double kConvergedRegionStrain = 2.666;
// The same for Weldox 460E at 300 m/s (cases/taylor_bar/weldox_300.toml).
constexpr double kWeldoxLength = 18.481, kWeldoxFootprint = 13.214;  // [mm]
constexpr double kWeldoxRegionStrain = 2.019;

// cases/taylor_bar_axisymmetric/case.toml with its line `key = ...` replaced by `line`, in `dir`.
fs::path axisymmetricCaseWith(const fs::path& dir, const std::string& key,
                              const std::string& line) {
    std::ifstream in(kSource / "cases/taylor_bar_axisymmetric/case.toml");
    std::stringstream text;
    text << in.rdbuf();
    std::string c = text.str();
    const std::size_t at = c.find("\n" + key + " = ") + 1;
    c.replace(at, c.find('\n', at) - at, line);
    const std::string material = "file = \"../../materials/";
    c.replace(c.find(material), material.size(),
              "file = \"" + (kSource / "materials").string() + "/");
    const fs::path path = dir / "case.toml";
    std::ofstream(path) << c;
    return path;
}

// The section graded towards the impact face (8 cells across, 50 along, each 1.06 times the one
// below: 400 particles) against the converged reference: with the hourglass penalty's secant
// modulus (the case's) its footprint is within 2.5 % (measured −2.17 %), with E throughout
// it is 5.54 % short; the length within 1 % either way.
TEST(TaylorValidation, GradedSectionMeetsTheConvergedFootprintWithTheSecantHourglass) {
    test::TempDir secantDir, elasticDir;
    const std::string layout = "--set nr=8 --set nz=50 --set grading=1.06";
    const Shape secant =
        test::runAndMeasureTaylor(secantDir.path(), "geometries/taylor_bar_axisymmetric.geo",
                                  layout, "cases/taylor_bar_axisymmetric/case.toml");
    const Shape elastic = test::runAndMeasureTaylor(
        elasticDir.path(), "geometries/taylor_bar_axisymmetric.geo", layout,
        axisymmetricCaseWith(elasticDir.path(), "hourglass_modulus",
                             "hourglass_modulus = \"elastic\"")
            .string());
    std::printf(
        "[taylor] graded section (400 particles) against the converged %.3f / %.3f mm: secant "
        "hourglass %.3f / %.3f mm (%+.2f %%, %+.2f %%), elastic %.3f / %.3f mm (%+.2f %%, %+.2f "
        "%%)\n",
        kConvergedLength, kConvergedFootprint, secant.length, secant.footprint,
        100 * (secant.length / kConvergedLength - 1),
        100 * (secant.footprint / kConvergedFootprint - 1), elastic.length, elastic.footprint,
        100 * (elastic.length / kConvergedLength - 1),
        100 * (elastic.footprint / kConvergedFootprint - 1));
    EXPECT_NEAR(secant.footprint / kConvergedFootprint, 1.0, 0.025);
    EXPECT_NEAR(secant.length / kConvergedLength, 1.0, 0.01);
    EXPECT_LT(elastic.footprint / kConvergedFootprint, 0.96);
    EXPECT_NEAR(elastic.length / kConvergedLength, 1.0, 0.01);
}

// A 3-D O-grid layout (gsph-preproc's `sets` on geometries/taylor_bar.geo) run with
// `caseFile`'s settings against the converged reference: length within 1 %, footprint within
// 3 %, the face centre's plastic strain (the mean over its centre region) within
// `strainTolerance`.
void expectOgridNearReference(const std::string& what, const std::string& sets,
                              const std::string& caseFile, double length, double footprint,
                              double regionStrain, double strainTolerance) {
    test::TempDir dir;
    const Shape shape =
        test::runAndMeasureTaylor(dir.path(), "geometries/taylor_bar.geo", sets, caseFile);
    std::printf(
        "[taylor] %s: length %.3f mm (%+.2f %%), footprint %.3f mm (%+.2f %%) against the "
        "converged %.3f / %.3f mm; face centre's strain %.3f (%+.1f %%) against %.3f\n",
        what.c_str(), shape.length, 100 * (shape.length / length - 1), shape.footprint,
        100 * (shape.footprint / footprint - 1), length, footprint, shape.regionStrain,
        100 * (shape.regionStrain / regionStrain - 1), regionStrain);
    EXPECT_NEAR(shape.length / length, 1.0, 0.01);
    EXPECT_NEAR(shape.footprint / footprint, 1.0, 0.03);
    EXPECT_NEAR(shape.regionStrain / regionStrain, 1.0, strainTolerance);
}

// The 3-D O-grid with its resolution where the impact zone needs it (scripts/validate's
// gsph-centre): a core of 12 cells a side, finer towards the axis (gmsh Bump 10: R/35 there), 3
// radial cells finer towards the lip (0.7), 34 layers graded 1.08 towards the face; 9792
// particles. The face centre's strain within 10 %: the bars at ≤ 10k particles in 3-D.
void expectCentreGradedOgridNearReference(const std::string& metal, const std::string& caseFile,
                                          double length, double footprint, double regionStrain) {
    expectOgridNearReference(metal +
                                 " on the O-grid graded towards the axis, the lip and the face "
                                 "(9792 particles)",
                             "--set n=12 --set nr=3 --set nz=34 --set grading=1.08 "
                             "--set centre=10 --set lip=0.7",
                             caseFile, length, footprint, regionStrain, 0.10);
}

// Copper: measured −0.58 % (length), −2.45 % (footprint), −8.3 % (face centre's strain). The
// O-grid of the same size with a uniform core and 50 layers (n 8, nr 4, grading 1.06) gives the
// face centre −20 % (docs/theory.md "The face centre as a region").
TEST(TaylorValidation, CentreGradedOgridMeetsTheImpactZoneBars) {
    expectCentreGradedOgridNearReference("copper", "cases/taylor_bar/case.toml", kConvergedLength,
                                         kConvergedFootprint, kConvergedRegionStrain);
}

// Weldox 460E at 300 m/s: measured −0.05 %, −1.82 %, −7.6 %.
TEST(TaylorValidation, WeldoxOnTheCentreGradedOgridMeetsTheImpactZoneBars) {
    expectCentreGradedOgridNearReference("Weldox 460E", "cases/taylor_bar/weldox_300.toml",
                                         kWeldoxLength, kWeldoxFootprint, kWeldoxRegionStrain);
}

// The quick start's layout (scripts/quickstart, scripts/validate's gsph-lip): a core of 6 cells
// a side, 3 radial cells finer towards the lip (0.7), 30 layers graded 1.08 towards the face;
// 3240 particles. Against the converged reference: length within 1 %, footprint within 3 %
// (measured −0.47 %, −2.59 %: closer than any uniform layout of docs/validation.md, up to
// 21172 particles, at −5.8 %), the face centre's strain within 25 % (measured −24.3 %: its
// core's cells are R/6 at the axis).
TEST(TaylorValidation, QuickStartLayoutMeetsTheLengthAndFootprintBars) {
    expectOgridNearReference("the quick start's layout (3240 particles)",
                             "--set n=6 --set nr=3 --set nz=30 --set grading=1.08 --set lip=0.7",
                             "cases/taylor_bar/case.toml", kConvergedLength, kConvergedFootprint,
                             kConvergedRegionStrain, 0.25);
}

}  // namespace
}  // namespace gsph
