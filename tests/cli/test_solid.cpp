// SPDX-License-Identifier: MIT
// The solid of gsph-post (post/hex_solid.hpp) on gsph-preproc's own particle files: the
// hexahedra read back with VTK's readers; under an affine motion their volume is Σ V J to
// round-off; the O-grid's periodic annulus closes (no free faces at its seam, no doubled
// nodes); a --lattice layout's nodes are its box's corners; a file without /spaces/nodes (an
// older gsph-preproc) still gives a closed solid from estimated nodes; overlapping spaces are
// separate blocks without the cut cells.
#include <gtest/gtest.h>
#include <vtkCellData.h>
#include <vtkCompositeDataSet.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkInformation.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkStringArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLMultiBlockDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>

#include "hex_solid.hpp"
#include "io/particle_file.hpp"
#include "support/process.hpp"
#include "tools/temp_dir.hpp"
#include "vtk_output.hpp"

namespace gsph {
namespace {

namespace fs = std::filesystem;
using test::runCommand;
using test::TempDir;

const fs::path kSource = GSPH_SOURCE_DIR;

// A coarse Taylor-bar O-grid: a Cartesian core and an annulus periodic in its angle.
ParticleFile ogrid(const TempDir& dir, const std::string& extra = "") {
    const fs::path out = dir / "ogrid.h5";
    const auto r = runCommand(std::string(GSPH_PREPROC_EXE) + " " +
                              (kSource / "geometries/taylor_bar.geo").string() +
                              " --set n=4 --set nr=2 --set nz=6 " + extra + " -o " + out.string());
    EXPECT_EQ(r.status, 0) << r.err;
    return readParticleFile(out);
}

// A snapshot of the particle file's particles moved by x = F X + c (uniform F), with fields.
Snapshot affineSnapshot(const ParticleFile& f, const Mat3& F, const Vec3& c) {
    Snapshot s;
    const auto n = static_cast<std::size_t>(f.size());
    s.state.time = 2.5e-5;
    s.X = f.X;
    s.state.x.resize(n);
    for (std::size_t a = 0; a < n; ++a) s.state.x[a] = F * f.X[a] + c;
    s.state.v.assign(n, Vec3(1.0, -2.0, 3.0));
    s.state.cauchy.resize(n);
    for (std::size_t a = 0; a < n; ++a)
        s.state.cauchy[a] = (Mat3() << 1.0 * a, 2, 3, 2, -4.0 * a, 5, 3, 5, 6).finished() * 1e6;
    s.state.F.assign(n, F);
    s.volume = f.volume;
    s.body = f.body;
    s.space = f.space;
    s.state.plasticStrain.assign(n, 0.0);
    for (std::size_t a = 0; a < n; ++a) s.state.plasticStrain[a] = 1e-3 * a;
    s.state.temperature.assign(n, 300.0);
    s.state.damage.assign(n, 0.0);
    s.transient.assign(n, 0);
    for (std::size_t a = 0; a < f.transient.size(); ++a) s.transient[a] = f.transient[a];
    s.bondDamage.assign(n, 0.0);
    return s;
}

double sumVJ(const ParticleFile& f, const Mat3& F) {
    double total = 0.0;
    for (double V : f.volume) total += V * F.determinant();
    return total;
}

// A piece read back: its hexahedra's exact volume, its free faces, its closest pair of nodes.
struct ReadBack {
    vtkIdType cells = 0, points = 0;
    double volume = 0.0;
    long freeFaces = 0;
    double closestNodes = INFINITY, size = 0.0;
};

ReadBack readPiece(const fs::path& vtu) {
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName(vtu.c_str());
    reader->Update();
    vtkUnstructuredGrid* g = reader->GetOutput();
    ReadBack r;
    r.cells = g->GetNumberOfCells();
    r.points = g->GetNumberOfPoints();
    std::map<std::array<vtkIdType, 4>, int> faces;
    static const int kFaces[6][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4},
                                     {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
    for (vtkIdType c = 0; c < r.cells; ++c) {
        EXPECT_EQ(g->GetCellType(c), VTK_HEXAHEDRON);
        vtkIdType npts = 0;
        const vtkIdType* ids = nullptr;
        g->GetCellPoints(c, npts, ids);
        std::array<Vec3, 8> x;
        for (int k = 0; k < 8; ++k) g->GetPoint(ids[k], x[k].data());
        r.volume += post::hexahedronVolume(x);
        for (const auto& f : kFaces) {
            std::array<vtkIdType, 4> key = {ids[f[0]], ids[f[1]], ids[f[2]], ids[f[3]]};
            std::sort(key.begin(), key.end());
            ++faces[key];
        }
    }
    for (const auto& [key, count] : faces) {
        EXPECT_LE(count, 2);
        r.freeFaces += count == 1;
    }
    std::vector<Vec3> p(static_cast<std::size_t>(r.points));
    Vec3 lo = Vec3::Constant(1e300), hi = -lo;
    for (vtkIdType i = 0; i < r.points; ++i) {
        g->GetPoint(i, p[static_cast<std::size_t>(i)].data());
        lo = lo.cwiseMin(p[static_cast<std::size_t>(i)]);
        hi = hi.cwiseMax(p[static_cast<std::size_t>(i)]);
    }
    r.size = (hi - lo).norm();
    std::sort(p.begin(), p.end(), [](const Vec3& a, const Vec3& b) { return a[0] < b[0]; });
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = i + 1; j < p.size() && p[j][0] - p[i][0] < r.closestNodes; ++j)
            r.closestNodes = std::min(r.closestNodes, (p[j] - p[i]).norm());
    return r;
}

// Free faces of a fully occupied space: both ends of every index that is not periodic.
long expectedFreeFaces(const LatticeSpace& s) {
    long total = 0;
    for (int d = 0; d < 3; ++d)
        if (!s.periodic[d]) total += 2L * s.cells[(d + 1) % 3] * s.cells[(d + 2) % 3];
    return total;
}

const Mat3 kF = (Mat3() << 1.1, 0.2, 0.05, -0.1, 0.9, 0.1, 0.03, 0.02, 1.2).finished();
const Vec3 kShift(1e-3, -2e-3, 5e-4);

// The O-grid under an affine motion: each space a .vtu piece of a .vtm, the hexahedra's volume
// Σ V J to round-off, the annulus closed across its periodic seam.
TEST(HexSolid, AffineMotionGivesSumOfVJAndThePeriodicAnnulusCloses) {
    TempDir dir;
    const ParticleFile f = ogrid(dir);
    ASSERT_FALSE(f.nodes.empty());
    ASSERT_EQ(f.spaces.size(), 2u);
    int periodicSpaces = 0;
    for (const LatticeSpace& s : f.spaces) periodicSpaces += s.periodic[0] || s.periodic[1];
    ASSERT_EQ(periodicSpaces, 1);  // the annulus

    const post::HexSolid solid(f, f.X, "ogrid.h5");
    EXPECT_FALSE(solid.estimatedNodes());
    EXPECT_EQ(solid.hexahedra(), static_cast<std::size_t>(f.size()));
    // Reference: the mesh's hexahedra, whose exact volumes are the particles' V.
    EXPECT_NEAR(solid.referenceVolume(), solid.particleVolume(), 1e-13 * solid.particleVolume());

    const Snapshot snap = affineSnapshot(f, kF, kShift);
    post::RunLabels labels{{"rod"}, {"free_end", "impact", "lateral"}};
    post::writeSolid(dir / "solid_000003.vtm", solid, snap, labels);
    const double written = solid.currentVolume(snap);
    const double expected = sumVJ(f, kF);
    double readVolume = 0.0;
    for (const post::SolidPiece& piece : solid.pieces()) {
        const ReadBack r =
            readPiece(dir / ("solid_000003_s" + std::to_string(piece.space) + ".vtu"));
        const LatticeSpace& s = f.spaces[static_cast<std::size_t>(piece.space)];
        EXPECT_EQ(r.cells, static_cast<vtkIdType>(s.cells[0]) * s.cells[1] * s.cells[2]);
        EXPECT_EQ(r.freeFaces, expectedFreeFaces(s)) << "space " << piece.space;
        EXPECT_GT(r.closestNodes, 1e-6 * r.size) << "two nodes at one place in " << piece.space;
        readVolume += r.volume;
    }
    std::printf(
        "[ measured ] affine F (J = %.6f): hexahedra %.15g m³, Σ V J %.15g m³, "
        "relative difference %.2e\n",
        kF.determinant(), readVolume, expected, (readVolume - expected) / expected);
    EXPECT_NEAR(readVolume, expected, 1e-12 * expected);
    EXPECT_NEAR(written, expected, 1e-12 * expected);

    // The multiblock file: one block per space, named after the body and the space.
    vtkNew<vtkXMLMultiBlockDataReader> reader;
    reader->SetFileName((dir / "solid_000003.vtm").c_str());
    reader->Update();
    auto* blocks = vtkMultiBlockDataSet::SafeDownCast(reader->GetOutput());
    ASSERT_NE(blocks, nullptr);
    ASSERT_EQ(blocks->GetNumberOfBlocks(), 2u);
    for (unsigned b = 0; b < 2; ++b) {
        EXPECT_EQ(std::string(blocks->GetMetaData(b)->Get(vtkCompositeDataSet::NAME())),
                  "rod space " + std::to_string(b));
        auto* grid = vtkUnstructuredGrid::SafeDownCast(blocks->GetBlock(b));
        ASSERT_NE(grid, nullptr);
        // Thresholding by space works on the cell data.
        vtkDataArray* space = grid->GetCellData()->GetArray("space");
        ASSERT_NE(space, nullptr);
        double range[2];
        space->GetRange(range);
        EXPECT_EQ(range[0], b);
        EXPECT_EQ(range[1], b);
    }
}

// Cell data and field data of a piece, read back with vtkXMLUnstructuredGridReader.
TEST(HexSolid, CellAndFieldDataReadBack) {
    TempDir dir;
    const ParticleFile f = ogrid(dir);
    const post::HexSolid solid(f, f.X, "ogrid.h5");
    const Snapshot snap = affineSnapshot(f, kF, kShift);
    post::RunLabels labels{{"rod"}, {"free_end", "impact", "lateral"}};
    post::writeSolid(dir / "solid_000001.vtm", solid, snap, labels);
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((dir / "solid_000001_s1.vtu").c_str());
    reader->Update();
    vtkUnstructuredGrid* g = reader->GetOutput();
    vtkCellData* cd = g->GetCellData();
    for (const char* name : {"displacement", "velocity", "stress", "von_mises", "pressure",
                             "plastic_strain", "temperature", "damage", "bond_damage", "J", "id",
                             "radius", "reference_volume", "body", "space", "transient"})
        EXPECT_NE(cd->GetAbstractArray(name), nullptr) << name;
    EXPECT_NE(g->GetPointData()->GetArray("node_displacement"), nullptr);
    const char* const components[] = {"XX", "XY", "XZ", "YX", "YY", "YZ", "ZX", "ZY", "ZZ"};
    for (int c = 0; c < 9; ++c)
        EXPECT_STREQ(cd->GetArray("stress")->GetComponentName(c), components[c]) << c;
    for (vtkIdType c = 0; c < g->GetNumberOfCells(); ++c) {
        const auto a = static_cast<std::size_t>(cd->GetArray("id")->GetTuple1(c));
        ASSERT_LT(a, snap.X.size());
        EXPECT_EQ(snap.space[a], 1);
        EXPECT_EQ(cd->GetArray("plastic_strain")->GetTuple1(c), snap.state.plasticStrain[a]);
        EXPECT_EQ(cd->GetArray("von_mises")->GetTuple1(c), post::vonMises(snap.state.cauchy[a]));
        EXPECT_EQ(cd->GetArray("stress")->GetComponent(c, 4), snap.state.cauchy[a](1, 1));
        EXPECT_EQ(cd->GetArray("J")->GetTuple1(c), kF.determinant());
    }
    vtkFieldData* fd = g->GetFieldData();
    ASSERT_NE(fd->GetArray("TimeValue"), nullptr);
    EXPECT_EQ(fd->GetArray("TimeValue")->GetTuple1(0), snap.state.time);
    auto strings = [&](const char* name) {
        std::vector<std::string> out;
        auto* a = vtkStringArray::SafeDownCast(fd->GetAbstractArray(name));
        if (a != nullptr)
            for (vtkIdType k = 0; k < a->GetNumberOfValues(); ++k) out.push_back(a->GetValue(k));
        return out;
    };
    EXPECT_EQ(strings("body_names"), std::vector<std::string>{"rod"});
    EXPECT_EQ(strings("set_names"), (std::vector<std::string>{"free_end", "impact", "lateral"}));
    const std::vector<std::string> units = strings("units");
    for (const char* u : {"stress=Pa", "von_mises=Pa", "displacement=m", "temperature=K",
                          "velocity=m/s", "TimeValue=s"})
        EXPECT_NE(std::find(units.begin(), units.end(), u), units.end()) << u;
}

// --lattice: one Cartesian space per body; its nodes are the box lattice's corners, so every
// hexahedron is the particle's box cell (volume V exactly, centre X).
TEST(HexSolid, LatticeLayoutNodesAreTheBoxCorners) {
    TempDir dir;
    const ParticleFile f = ogrid(dir, "--lattice 1e-3");
    ASSERT_EQ(f.spaces.size(), 1u);
    ASSERT_FALSE(f.nodes.empty());
    const post::HexSolid solid(f, f.X, "lattice.h5");
    ASSERT_EQ(solid.pieces().size(), 1u);
    const post::SolidPiece& piece = solid.pieces()[0];
    double worst = 0.0;
    for (std::size_t h = 0; h < piece.hexes.size(); ++h) {
        Vec3 centre = Vec3::Zero();
        for (Index n : piece.hexes[h]) centre += piece.nodeX[static_cast<std::size_t>(n)] / 8.0;
        worst = std::max(worst, (centre - f.X[static_cast<std::size_t>(piece.particle[h])]).norm());
    }
    EXPECT_LT(worst, 1e-15);
    EXPECT_NEAR(solid.referenceVolume(), solid.particleVolume(), 1e-12 * solid.particleVolume());
    // Fewer nodes than a box: only the corners of cells that hold particles.
    const auto m = nodeExtent(f.spaces[0]);
    EXPECT_LT(piece.nodeX.size(), m[0] * m[1] * m[2]);
}

// A particle file without /spaces/nodes (gsph-preproc before format 1.3): nodes estimated from
// the particles; the solid is still closed, affine motions still scale its volume by J
// exactly, and its volume is close to Σ V.
TEST(HexSolid, FileWithoutNodesEstimatesThem) {
    TempDir dir;
    ParticleFile f = ogrid(dir);
    f.nodes.clear();
    const post::HexSolid solid(f, f.X, "old.h5");
    EXPECT_TRUE(solid.estimatedNodes());
    const double reference = solid.referenceVolume(), particles = solid.particleVolume();
    std::printf("[ measured ] estimated nodes: hexahedra %.9g m³ against Σ V %.9g m³ (%+.3f %%)\n",
                reference, particles, 100.0 * (reference - particles) / particles);
    EXPECT_NEAR(reference, particles, 0.05 * particles);
    const Snapshot snap = affineSnapshot(f, kF, kShift);
    post::writeSolid(dir / "solid_000000.vtm", solid, snap, {});
    double volume = 0.0;
    for (const post::SolidPiece& piece : solid.pieces()) {
        const ReadBack r =
            readPiece(dir / ("solid_000000_s" + std::to_string(piece.space) + ".vtu"));
        EXPECT_EQ(r.freeFaces, expectedFreeFaces(f.spaces[static_cast<std::size_t>(piece.space)]));
        volume += r.volume;
    }
    EXPECT_NEAR(volume, kF.determinant() * reference, 1e-12 * volume);
}

// Overlapping spaces (two blocks, the coarser cut where the finer covers it): each space its
// own block, the cut cells left out, and Σ hexahedra = Σ V J still under an affine motion
// (hole cutting removes whole cells: no volume counted twice here).
TEST(HexSolid, OverlappingSpacesAreSeparateBlocksWithoutTheCutCells) {
    TempDir dir;
    const fs::path out = dir / "blocks.h5";
    const auto r = runCommand(std::string(GSPH_PREPROC_EXE) + " " +
                              (kSource / "geometries/two_blocks.geo").string() +
                              " --set overlap=2 --set plane=1 -o " + out.string());
    ASSERT_EQ(r.status, 0) << r.err;
    const ParticleFile f = readParticleFile(out);
    ASSERT_EQ(f.size(), 152);  // 160 hexahedra, 8 cut
    const post::HexSolid solid(f, f.X, "blocks.h5");
    ASSERT_EQ(solid.pieces().size(), 2u);
    EXPECT_EQ(solid.hexahedra(), 152u);
    const Snapshot snap = affineSnapshot(f, kF, kShift);
    post::writeSolid(dir / "solid_000002.vtm", solid, snap, {});
    double volume = 0.0;
    for (const post::SolidPiece& piece : solid.pieces()) {
        const ReadBack back =
            readPiece(dir / ("solid_000002_s" + std::to_string(piece.space) + ".vtu"));
        EXPECT_EQ(back.cells, static_cast<vtkIdType>(piece.hexes.size()));
        volume += back.volume;
    }
    EXPECT_NEAR(volume, sumVJ(f, kF), 1e-12 * volume);
}

// A particle file of another run is refused with a line that says so.
TEST(HexSolid, AnotherRunsParticleFileIsRefused) {
    TempDir dir;
    const ParticleFile f = ogrid(dir);
    std::vector<Vec3> X = f.X;
    X[5][2] += 1e-4;
    try {
        post::HexSolid solid(f, X, "other.h5");
        FAIL() << "a particle file that does not match must be refused";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("other.h5: particle 5 lies at"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("not the run's particle file"), std::string::npos);
    }
    X.pop_back();
    EXPECT_THROW(post::HexSolid(f, X, "other.h5"), InputError);
}

}  // namespace
}  // namespace gsph
