// SPDX-License-Identifier: MIT
#include "vtk_output.hpp"

#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkIntArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLUnstructuredGridWriter.h>
#include <Eigen/LU>

#include <cmath>
#include <cstdio>
#include <fstream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace gsph::post {
namespace {

vtkNew<vtkDoubleArray> vectorField(const char* name, int components, vtkIdType n) {
    vtkNew<vtkDoubleArray> a;
    a->SetName(name);
    a->SetNumberOfComponents(components);
    a->SetNumberOfTuples(n);
    return a;
}

}  // namespace

double vonMises(const Mat3& sigma) {
    const Mat3 s = sigma - sigma.trace() / 3.0 * Mat3::Identity();
    return std::sqrt(1.5 * s.squaredNorm());
}

void writeVtu(const std::filesystem::path& path, const Snapshot& snap) {
    const vtkIdType n = snap.size();
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    points->SetNumberOfPoints(n);
    vtkNew<vtkUnstructuredGrid> grid;
    grid->SetPoints(points);
    grid->Allocate(n);
    auto displacement = vectorField("displacement", 3, n);
    auto velocity = vectorField("velocity", 3, n);
    auto stress = vectorField("stress", 9, n);
    auto mises = vectorField("von_mises", 1, n);
    auto pressure = vectorField("pressure", 1, n);
    auto J = vectorField("J", 1, n);
    vtkNew<vtkIntArray> body, space;
    body->SetName("body");
    space->SetName("space");
    body->SetNumberOfTuples(n);
    space->SetNumberOfTuples(n);
    for (vtkIdType a = 0; a < n; ++a) {
        const auto i = static_cast<std::size_t>(a);
        points->SetPoint(a, snap.x[i].data());
        const vtkIdType id = a;
        grid->InsertNextCell(VTK_VERTEX, 1, &id);
        const Vec3 u = snap.x[i] - snap.X[i];
        displacement->SetTuple(a, u.data());
        velocity->SetTuple(a, snap.v[i].data());
        double s9[9];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) s9[3 * r + c] = snap.stress[i](r, c);
        stress->SetTuple(a, s9);
        mises->SetValue(a, vonMises(snap.stress[i]));
        pressure->SetValue(a, -snap.stress[i].trace() / 3.0);
        J->SetValue(a, snap.F[i].determinant());
        body->SetValue(a, snap.body[i]);
        space->SetValue(a, snap.space[i]);
    }
    vtkPointData* pd = grid->GetPointData();
    for (vtkDataArray* arr : std::initializer_list<vtkDataArray*>{displacement, velocity, stress,
                                                                  mises, pressure, J, body, space})
        pd->AddArray(arr);
    writeAtomically(path, [&](const std::filesystem::path& temp) {
        vtkNew<vtkXMLUnstructuredGridWriter> writer;
        writer->SetFileName(temp.c_str());
        writer->SetInputData(grid);
        writer->SetDataModeToAppended();
        writer->EncodeAppendedDataOff();
        if (writer->Write() != 1) throw IoError(path.string() + ": VTK could not write the file");
    });
}

void writePvd(const std::filesystem::path& path,
              const std::vector<std::pair<double, std::string>>& entries) {
    writeAtomically(path, [&](const std::filesystem::path& temp) {
        std::ofstream out(temp);
        out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n  "
               "<Collection>\n";
        for (const auto& [time, file] : entries) {
            char line[512];
            std::snprintf(line, sizeof line,
                          "    <DataSet timestep=\"%.9e\" part=\"0\" file=\"%s\"/>\n", time,
                          file.c_str());
            out << line;
        }
        out << "  </Collection>\n</VTKFile>\n";
        if (!out.flush()) throw IoError(path.string() + ": write failed");
    });
}

}  // namespace gsph::post
