// SPDX-License-Identifier: MIT
// gsph-post on a real run: the arrays read back from the .vtu with VTK's reader equal the
// snapshot's, the .pvd lists every snapshot, and the pictures are real (expected size, not
// blank). Bad input gets a one-line error.
#include <gtest/gtest.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPointData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <Eigen/LU>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "io/snapshot.hpp"
#include "support/sample_run.hpp"
#include "tools/temp_dir.hpp"
#include "vtk_output.hpp"

namespace gsph {
namespace {

namespace fs = std::filesystem;
using test::runCommand;
using test::TempDir;

class PostRun : public ::testing::Test {
  protected:
    static void SetUpTestSuite() {
        dir_ = new TempDir;
        auto r = test::makeSampleParticles(*dir_ / "particles.h5");
        ASSERT_EQ(r.status, 0) << r.err;
        r = test::runSampleCase(*dir_ / "particles.h5", *dir_ / "run");
        ASSERT_EQ(r.status, 0) << r.err;
        r = runCommand(std::string(GSPH_POST_EXE) + " " + (*dir_ / "run").string());
        ASSERT_EQ(r.status, 0) << r.err;
    }
    static void TearDownTestSuite() { delete dir_; }
    static TempDir* dir_;
};
TempDir* PostRun::dir_ = nullptr;

TEST_F(PostRun, VtuArraysEqualTheSnapshot) {
    const Snapshot snap = readSnapshot(*dir_ / "run/snapshot_000007.h5");
    vtkNew<vtkXMLUnstructuredGridReader> reader;
    reader->SetFileName((*dir_ / "run/post/snapshot_000007.vtu").c_str());
    reader->Update();
    vtkUnstructuredGrid* grid = reader->GetOutput();
    ASSERT_EQ(grid->GetNumberOfPoints(), snap.size());
    vtkPointData* pd = grid->GetPointData();
    for (const char* name :
         {"displacement", "velocity", "stress", "von_mises", "pressure", "J", "body", "space"})
        ASSERT_NE(pd->GetArray(name), nullptr) << name;
    double worst = 0.0;
    for (vtkIdType a = 0; a < snap.size(); ++a) {
        const auto i = static_cast<std::size_t>(a);
        double p[3];
        grid->GetPoint(a, p);
        worst = std::max(worst, (Vec3(p[0], p[1], p[2]) - snap.x[i]).norm());
        const double* v = pd->GetArray("velocity")->GetTuple3(a);
        worst = std::max(worst, (Vec3(v[0], v[1], v[2]) - snap.v[i]).norm());
        const double* s = pd->GetArray("stress")->GetTuple9(a);
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) EXPECT_EQ(s[3 * r + c], snap.stress[i](r, c));
        EXPECT_EQ(pd->GetArray("von_mises")->GetTuple1(a), post::vonMises(snap.stress[i]));
        EXPECT_EQ(pd->GetArray("J")->GetTuple1(a), snap.F[i].determinant());
    }
    EXPECT_EQ(worst, 0.0);  // written as float64: exact round trip
}

TEST_F(PostRun, PvdListsEverySnapshot) {
    std::ifstream in(*dir_ / "run/post/run.pvd");
    std::stringstream ss;
    ss << in.rdbuf();
    const std::string pvd = ss.str();
    for (int k = 0; k <= 10; ++k) {
        char name[32];
        std::snprintf(name, sizeof name, "snapshot_%06d.vtu", k);
        EXPECT_NE(pvd.find(name), std::string::npos) << name;
        EXPECT_TRUE(fs::exists(*dir_ / "run/post" / name)) << name;
    }
}

// A picture is real: the expected size, and neither blank nor a single colour.
void expectRealPicture(const fs::path& png, int width, int height) {
    ASSERT_TRUE(fs::exists(png)) << png;
    vtkNew<vtkPNGReader> reader;
    reader->SetFileName(png.c_str());
    reader->Update();
    vtkImageData* image = reader->GetOutput();
    int dims[3];
    image->GetDimensions(dims);
    EXPECT_EQ(dims[0], width);
    EXPECT_EQ(dims[1], height);
    const int comps = image->GetNumberOfScalarComponents();
    long nonWhite = 0, coloured = 0;
    for (int y = 0; y < dims[1]; ++y)
        for (int x = 0; x < dims[0]; ++x) {
            const auto* px = static_cast<unsigned char*>(image->GetScalarPointer(x, y, 0));
            const int r = px[0], g = px[1 % comps], b = px[2 % comps];
            nonWhite += (r + g + b < 3 * 250);
            coloured += (std::max({r, g, b}) - std::min({r, g, b}) > 60);
        }
    const double total = static_cast<double>(dims[0]) * dims[1];
    EXPECT_GT(nonWhite / total, 0.02) << png << " is (nearly) blank";
    EXPECT_GT(coloured / total, 0.005) << png << " has no colour";
}

TEST_F(PostRun, PicturesAreReal) {
    expectRealPicture(*dir_ / "run/post/final_von_mises.png", 1200, 800);
    expectRealPicture(*dir_ / "run/post/history.png", 1000, 600);
}

TEST(PostCli, MissingRunFolderIsAClearError) {
    TempDir dir;
    const auto r = runCommand(std::string(GSPH_POST_EXE) + " " + (dir / "nothing").string());
    EXPECT_EQ(r.status, 1);
    EXPECT_NE(r.err.find("gsph-post: error: "), std::string::npos) << r.err;
    EXPECT_NE(r.err.find("no such run folder"), std::string::npos) << r.err;
    fs::create_directories(dir / "empty");
    const auto e = runCommand(std::string(GSPH_POST_EXE) + " " + (dir / "empty").string());
    EXPECT_EQ(e.status, 1);
    EXPECT_NE(e.err.find("no snapshot_*.h5"), std::string::npos) << e.err;
}

}  // namespace
}  // namespace gsph
