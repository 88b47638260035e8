// SPDX-License-Identifier: MIT
// The copper Taylor bar (cases/taylor_bar, 190 m/s, 80 µs) in 3-D on the GSPH O-grid and as an
// axisymmetric section (cases/taylor_bar_axisymmetric) at matched resolution — the O-grid of
// scripts/validate's gsph-medium (8 cells per quarter of arc, 4 from the core to the surface,
// 40 along the axis: about 8 across the radius; 7680 particles) and 8 cells across the radius
// (424 particles) — measured alike by scripts/validation/taylor.py: final length and footprint
// diameter agree within 1 % (measured −0.3 % and −0.1 %; the O-grids of 6 and 10 across give
// −0.5 / −1.8 % and −0.2 / +1.1 % against the section at 6 and 10: docs/validation.md).
#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>

#include "support/process.hpp"
#include "tools/temp_dir.hpp"

namespace gsph {
namespace {

namespace fs = std::filesystem;
const fs::path kSource = GSPH_SOURCE_DIR;

struct Shape {
    double length = 0.0, footprint = 0.0;  // [mm]
};

Shape runTaylor(const fs::path& dir, const std::string& geometry, const std::string& sets,
                const std::string& caseFile) {
    const fs::path particles = dir / "particles.h5", out = dir / "run";
    const auto p = test::runCommand(std::string(GSPH_PREPROC_EXE) + " " +
                                    test::quote((kSource / geometry).string()) + " " + sets +
                                    " -q -o " + test::quote(particles.string()));
    EXPECT_EQ(p.status, 0) << p.err;
    const auto s = test::runCommand(
        std::string(GSPH_SOLVE_EXE) + " " + test::quote((kSource / caseFile).string()) +
        " --particles " + test::quote(particles.string()) + " -o " + test::quote(out.string()));
    EXPECT_EQ(s.status, 0) << s.err;
    const auto m = test::runCommand(
        "/usr/bin/python3 " + test::quote((kSource / "scripts/validation/taylor.py").string()) +
        " " + test::quote(particles.string()) + " " +
        test::quote((out / "snapshot_000010.h5").string()));
    EXPECT_EQ(m.status, 0) << m.err;
    Shape shape;
    const std::size_t l = m.out.find("length "), d = m.out.find("footprint diameter ");
    EXPECT_NE(l, std::string::npos) << m.out;
    EXPECT_NE(d, std::string::npos) << m.out;
    if (l != std::string::npos) shape.length = std::stod(m.out.substr(l + 7));
    if (d != std::string::npos) shape.footprint = std::stod(m.out.substr(d + 19));
    return shape;
}

TEST(TaylorValidation, AxisymmetricSectionAndOgridAgreeOnLengthAndFootprint) {
    test::TempDir ogrid, section;
    const Shape three = runTaylor(ogrid.path(), "geometries/taylor_bar.geo",
                                  "--set n=8 --set nr=4 --set nz=40", "cases/taylor_bar/case.toml");
    const Shape axi = runTaylor(section.path(), "geometries/taylor_bar_axisymmetric.geo",
                                "--set nr=8", "cases/taylor_bar_axisymmetric/case.toml");
    std::printf(
        "[taylor] O-grid (7680 particles): length %.3f mm, footprint %.3f mm; "
        "axisymmetric (424): %.3f mm, %.3f mm (%+.2f %%, %+.2f %%)\n",
        three.length, three.footprint, axi.length, axi.footprint,
        100 * (three.length / axi.length - 1), 100 * (three.footprint / axi.footprint - 1));
    EXPECT_NEAR(three.length / axi.length, 1.0, 0.01);
    EXPECT_NEAR(three.footprint / axi.footprint, 1.0, 0.01);
}

}  // namespace
}  // namespace gsph
