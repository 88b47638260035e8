// SPDX-License-Identifier: MIT
#include "pictures.hpp"

#include <X11/Xlib.h>
#include <vtkActor.h>
#include <vtkAxis.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkChartLegend.h>
#include <vtkChartXY.h>
#include <vtkContextActor.h>
#include <vtkContextScene.h>
#include <vtkDataSetSurfaceFilter.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkLookupTable.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPen.h>
#include <vtkPlane.h>
#include <vtkPlot.h>
#include <vtkPointData.h>
#include <vtkPointGaussianMapper.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkScalarBarActor.h>
#include <vtkTable.h>
#include <vtkTableBasedClipDataSet.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkUnstructuredGrid.h>
#include <vtkWindowToImageFilter.h>
#include <Eigen/LU>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "vtk_output.hpp"

namespace gsph::post {
namespace {

// One X connection for every window of the process, opened here with retries: a fresh Xvfb on a
// loaded machine sometimes refuses a connection (measured: 1 run in 4 with four at once), and
// VTK's own XOpenDisplay aborts the process on the first refusal.
void* sharedDisplay() {
    static Display* display = [] {
        constexpr int kAttempts = 40;
        for (int attempt = 0; attempt < kAttempts; ++attempt) {
            if (Display* d = XOpenDisplay(nullptr)) return d;
            std::this_thread::sleep_for(std::chrono::milliseconds(250));
        }
        return static_cast<Display*>(nullptr);
    }();
    if (display == nullptr)
        throw IoError(std::string("cannot connect to the X server ") +
                      (std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "(DISPLAY unset)") +
                      " for the pictures");
    return display;
}

void savePng(vtkRenderWindow* window, const std::filesystem::path& png) {
    window->SetDisplayId(sharedDisplay());
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    grab->ReadFrontBufferOff();
    grab->Update();
    writeAtomically(png, [&](const std::filesystem::path& temp) {
        vtkNew<vtkPNGWriter> writer;
        writer->SetFileName(temp.c_str());
        writer->SetInputConnection(grab->GetOutputPort());
        writer->Write();
        if (writer->GetErrorCode() != 0 || !std::filesystem::exists(temp) ||
            std::filesystem::file_size(temp) == 0)
            throw IoError(png.string() + ": could not write the picture");
    });
}

}  // namespace

namespace {

// A piece of the solid at its current nodes, with `field` as its cells' scalars.
vtkSmartPointer<vtkUnstructuredGrid> pieceWithField(const HexSolid& solid, const SolidPiece& piece,
                                                    const Snapshot& s, const std::string& field,
                                                    Vec3& lo, Vec3& hi) {
    const std::vector<Vec3> x = solid.currentNodes(piece, s);
    vtkNew<vtkPoints> points;
    points->SetDataTypeToDouble();
    for (const Vec3& p : x) {
        points->InsertNextPoint(p.data());
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
    }
    const auto nc = static_cast<vtkIdType>(piece.cells());
    vtkNew<vtkDoubleArray> values;
    values->SetName(field.c_str());
    values->SetNumberOfTuples(nc);
    for (vtkIdType h = 0; h < nc; ++h)
        values->SetValue(
            h, scalarField(s, static_cast<std::size_t>(piece.particle[static_cast<std::size_t>(h)]),
                           field));
    auto grid = vtkSmartPointer<vtkUnstructuredGrid>::New();
    grid->SetPoints(points);
    grid->SetCells(solidCellType(piece), solidCells(piece));
    grid->GetCellData()->SetScalars(values);
    return grid;
}

}  // namespace

void renderSnapshot(const Snapshot& s, const std::string& field, const std::filesystem::path& png,
                    int width, int height, const HexSolid* solid) {
    if (!isScalarField(field)) throw InputError("unknown picture field '" + field + "'");
    const vtkIdType n = s.size();
    vtkNew<vtkPoints> points;
    vtkNew<vtkCellArray> vertices;
    vtkNew<vtkDoubleArray> values;
    values->SetName(field.c_str());
    vtkNew<vtkDoubleArray> radius;  // each particle drawn with its own current size
    radius->SetName("radius");
    Vec3 lo = Vec3::Constant(1e300), hi = Vec3::Constant(-1e300);
    for (vtkIdType a = 0; a < n; ++a) {
        const auto i = static_cast<std::size_t>(a);
        points->InsertNextPoint(s.state.x[i].data());
        vertices->InsertNextCell(1, &a);
        values->InsertNextValue(scalarField(s, i, field));
        radius->InsertNextValue(splatRadius(s, i));
        lo = lo.cwiseMin(s.state.x[i]);
        hi = hi.cwiseMax(s.state.x[i]);
    }
    vtkNew<vtkPolyData> cloud;
    cloud->SetPoints(points);
    cloud->SetVerts(vertices);
    cloud->GetPointData()->SetScalars(values);
    cloud->GetPointData()->AddArray(radius);

    double range[2];
    values->GetRange(range);
    // A field constant to round-off (a uniform stress) gets a range around its value, so the
    // colour bar does not label one value five times.
    const double scale = std::max(std::abs(range[0]), std::abs(range[1]));
    if (range[1] - range[0] <= 1e-9 * scale || range[1] <= range[0]) {
        const double half = scale > 0.0 ? 0.01 * scale : 0.5;
        range[0] -= half;
        range[1] += half;
    }
    vtkNew<vtkLookupTable> colours;
    colours->SetHueRange(0.667, 0.0);  // blue (low) to red (high)
    colours->SetTableRange(range);
    colours->Build();
    // Shaded discs of each particle's radius (fast for 1e6 particles, unlike sphere glyphs).
    vtkNew<vtkPointGaussianMapper> mapper;
    mapper->SetInputData(cloud);
    mapper->SetLookupTable(colours);
    mapper->SetScalarRange(range);
    mapper->SetScaleArray("radius");
    mapper->SetScaleFactor(1.0);
    mapper->EmissiveOff();
    mapper->SetSplatShaderCode(
        "//VTK::Color::Impl\n"
        "float dist = dot(offsetVCVSOutput.xy, offsetVCVSOutput.xy);\n"
        "if (dist > 1.0) { discard; } else {\n"
        "  float shade = sqrt(1.0 - dist);\n"
        "  ambientColor *= shade; diffuseColor *= shade; }\n");
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    // The solid instead of the particles: each space's hexahedra (a 2-D run's quadrilaterals,
    // seen face on), surface rendered; a compact 3-D body (every extent at least a quarter of
    // the largest) is cut through its middle (the half beyond the plane y = centre kept, the
    // cut face towards the camera), so the picture shows the inside too.
    std::vector<vtkSmartPointer<vtkActor>> solidActors;
    bool cut = false;
    if (solid != nullptr) {
        std::vector<vtkSmartPointer<vtkUnstructuredGrid>> grids;
        lo = Vec3::Constant(1e300);
        hi = Vec3::Constant(-1e300);
        for (const SolidPiece& piece : solid->pieces())
            grids.push_back(pieceWithField(*solid, piece, s, field, lo, hi));
        const Vec3 size = hi - lo;
        cut = size.minCoeff() >= 0.25 * size.maxCoeff();
        for (const auto& grid : grids) {
            vtkNew<vtkDataSetSurfaceFilter> surface;
            vtkNew<vtkPlane> plane;
            vtkNew<vtkTableBasedClipDataSet> clip;
            if (cut) {
                const Vec3 middle = 0.5 * (lo + hi);
                plane->SetOrigin(middle.data());
                plane->SetNormal(0.0, 1.0, 0.0);
                clip->SetInputData(grid);
                clip->SetClipFunction(plane);
                surface->SetInputConnection(clip->GetOutputPort());
            } else {
                surface->SetInputData(grid);
            }
            surface->Update();
            vtkNew<vtkPolyDataMapper> hexMapper;
            hexMapper->SetInputConnection(surface->GetOutputPort());
            hexMapper->SetLookupTable(colours);
            hexMapper->SetScalarModeToUseCellData();
            hexMapper->SetScalarRange(range);
            hexMapper->ScalarVisibilityOn();
            auto hexActor = vtkSmartPointer<vtkActor>::New();
            hexActor->SetMapper(hexMapper);
            hexActor->GetProperty()->SetAmbient(0.25);
            hexActor->GetProperty()->SetDiffuse(0.8);
            solidActors.push_back(hexActor);
        }
    }
    const Vec3 extent = (hi - lo).cwiseMax(1e-12);
    const int dims = (extent.array() > 1e-9 * extent.maxCoeff()).count();

    vtkNew<vtkScalarBarActor> bar;
    bar->SetLookupTable(colours);
    bar->SetTitle(field.c_str());
    bar->SetNumberOfLabels(5);
    bar->SetPosition(0.9, 0.1);
    bar->SetWidth(0.08);
    bar->SetHeight(0.8);
    bar->SetLabelFormat("%.3g");
    vtkNew<vtkTextActor> title;
    char text[128];
    std::snprintf(text, sizeof text, "t = %.4g s   (%d particles%s)", s.state.time,
                  static_cast<int>(n),
                  solid == nullptr          ? ""
                  : solid->dimension() == 2 ? ", the 2-D section"
                  : cut                     ? ", solid cut at mid-y"
                                            : ", solid");
    title->SetInput(text);
    title->GetTextProperty()->SetFontSize(22);
    title->GetTextProperty()->SetColor(0.1, 0.1, 0.1);
    title->SetDisplayPosition(20, height - 40);

    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(1.0, 1.0, 1.0);
    if (solid == nullptr) renderer->AddActor(actor);
    for (const auto& a : solidActors) renderer->AddActor(a);
    renderer->AddActor2D(bar);
    renderer->AddActor2D(title);
    vtkCamera* camera = renderer->GetActiveCamera();
    const Vec3 centre = 0.5 * (lo + hi);
    camera->SetFocalPoint(centre.data());
    const Vec3 eye = centre + Vec3(0.6, -1.0, 0.7) * extent.norm();
    camera->SetPosition(eye.data());
    camera->SetViewUp(0, 0, 1);
    if (dims == 2 && extent[2] < 1e-9 * extent.maxCoeff()) {  // a plane: look at it face on
        const Vec3 above = centre + Vec3(0, 0, 2.0 * extent.norm());
        camera->SetPosition(above.data());
        camera->SetViewUp(0, 1, 0);
    }
    renderer->ResetCamera();
    camera->Zoom(solid == nullptr ? 1.2 : 1.0);
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->SetSize(width, height);
    window->AddRenderer(renderer);
    savePng(window, png);
}

HistoryTable readHistory(const std::filesystem::path& csv) {
    std::ifstream in(csv);
    if (!in) throw InputError(csv.string() + ": cannot read");
    HistoryTable t;
    std::string header;
    std::getline(in, header);
    std::stringstream hs(header);
    for (std::string col; std::getline(hs, col, ',');) t.names.push_back(col);
    t.columns.resize(t.names.size());
    long lineNo = 1;
    for (std::string line; std::getline(in, line);) {
        ++lineNo;
        if (line.empty()) continue;
        std::stringstream ls(line);
        std::size_t c = 0;
        for (std::string cell; std::getline(ls, cell, ',') && c < t.columns.size(); ++c) {
            char* end = nullptr;
            const double value = std::strtod(cell.c_str(), &end);
            if (end == cell.c_str())
                throw InputError(csv.string() + ":" + std::to_string(lineNo) + ": '" + cell +
                                 "' is not a number");
            t.columns[c].push_back(value);
        }
        if (c != t.columns.size())
            throw InputError(csv.string() + ":" + std::to_string(lineNo) + ": " +
                             std::to_string(c) + " values for " + std::to_string(t.columns.size()) +
                             " columns");
    }
    return t;
}

const std::vector<double>* HistoryTable::column(const std::string& name) const {
    for (std::size_t c = 0; c < names.size(); ++c)
        if (names[c] == name) return &columns[c];
    return nullptr;
}

bool plotHistory(const HistoryTable& history, const std::vector<std::string>& wanted,
                 const std::string& yTitle, const std::filesystem::path& png, int width,
                 int height) {
    const std::vector<double>* time = history.column("time");
    std::vector<std::pair<std::string, const std::vector<double>*>> plotted;
    for (const std::string& name : wanted)
        if (const std::vector<double>* c = history.column(name)) plotted.emplace_back(name, c);
    if (time == nullptr || plotted.empty() || time->empty()) return false;
    vtkNew<vtkTable> table;
    vtkNew<vtkDoubleArray> t;
    t->SetName("time [s]");
    table->AddColumn(t);
    for (const auto& [name, c] : plotted) {
        vtkNew<vtkDoubleArray> column;
        column->SetName(name.c_str());
        table->AddColumn(column);
    }
    table->SetNumberOfRows(static_cast<vtkIdType>(time->size()));
    for (std::size_t r = 0; r < time->size(); ++r) {
        table->SetValue(static_cast<vtkIdType>(r), 0, (*time)[r]);
        for (std::size_t p = 0; p < plotted.size(); ++p)
            table->SetValue(static_cast<vtkIdType>(r), static_cast<vtkIdType>(p + 1),
                            (*plotted[p].second)[r]);
    }
    // A chart in a plain offscreen window: vtkContextView would add an X interactor, which
    // crashes (XSync) when several gsph-post run at once under xvfb-run.
    vtkNew<vtkChartXY> chart;
    vtkNew<vtkContextScene> scene;
    scene->AddItem(chart);
    vtkNew<vtkContextActor> actor;
    actor->SetScene(scene);
    vtkNew<vtkRenderer> renderer;
    renderer->SetBackground(1.0, 1.0, 1.0);
    renderer->AddActor(actor);
    scene->SetRenderer(renderer);
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->SetSize(width, height);
    window->AddRenderer(renderer);
    chart->SetShowLegend(true);
    // The legend beside the plot, not over the curves.
    chart->GetLegend()->SetInline(false);
    chart->GetLegend()->SetHorizontalAlignment(vtkChartLegend::RIGHT);
    chart->GetLegend()->SetVerticalAlignment(vtkChartLegend::CENTER);
    chart->GetAxis(vtkAxis::BOTTOM)->SetTitle("time [s]");
    chart->GetAxis(vtkAxis::LEFT)->SetTitle(yTitle);
    // Ten distinct colours (Tableau's), enough for every energy column; the total in black.
    const unsigned char palette[10][3] = {
        {31, 119, 180}, {255, 127, 14},  {44, 160, 44},   {214, 39, 40},  {148, 103, 189},
        {140, 86, 75},  {227, 119, 194}, {127, 127, 127}, {188, 189, 34}, {23, 190, 207}};
    for (std::size_t p = 0, colour = 0; p < plotted.size(); ++p) {
        vtkPlot* line = chart->AddPlot(vtkChart::LINE);
        line->SetInputData(table, 0, static_cast<vtkIdType>(p + 1));
        if (plotted[p].first == "total_energy") {
            line->SetColor(0, 0, 0, 255);
        } else {
            const unsigned char* c = palette[colour++ % 10];
            line->SetColor(c[0], c[1], c[2], 255);
        }
        line->SetWidth(2.0);
    }
    savePng(window, png);
    return true;
}

}  // namespace gsph::post
