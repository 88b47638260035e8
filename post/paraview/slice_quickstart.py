# SPDX-License-Identifier: MIT
"""The quick start's Taylor bar in ParaView: the solid sliced through its axis, coloured by von Mises.

Opens RUNDIR/post/solid.pvd (gsph-post's hexahedra, one block per generalized space), goes to
the last time, cuts the solid with the plane through the rod's axis (the plane y = 0 of
geometries/taylor_bar.geo, whose axis is z), colours the cut by the cells' von Mises stress
and saves a PNG.

Usage (pvpython, e.g. the private one of scripts/paraview-private):

    /opt/paraview-private/pvpython post/paraview/slice_quickstart.py \
        [RUNDIR (run/quickstart)] [PNG (docs/images/slice_quickstart.png)]
"""
import os
import sys

from paraview.simple import (ColorBy, CreateView, GetColorTransferFunction, GetScalarBar,
                             MergeBlocks, OpenDataFile, Render, SaveScreenshot, Show, Slice,
                             UpdatePipeline)

run = sys.argv[1] if len(sys.argv) > 1 else "run/quickstart"
png = sys.argv[2] if len(sys.argv) > 2 else "docs/images/slice_quickstart.png"
series = os.path.join(run, "post", "solid.pvd")
if not os.path.exists(series):
    sys.exit(f"slice_quickstart: {series} not found: run scripts/quickstart (gsph-post writes it)")

solid = OpenDataFile(series)
times = solid.TimestepValues  # a property: a list-like of the .pvd's timesteps, or one value
try:
    last = list(times)[-1]
except TypeError:
    last = float(times)
UpdatePipeline(time=last, proxy=solid)

# One dataset of both spaces (the core and the annulus), then the cut through the axis.
merged = MergeBlocks(Input=solid)
cut = Slice(Input=merged)
cut.SliceType = "Plane"
# 10 µm off the axis: the plane y = 0 itself runs along the core's cell faces (an even number of
# cells across), where a slice would give each face twice, once from each side.
cut.SliceType.Origin = [0.0, 1e-5, 0.0]
cut.SliceType.Normal = [0.0, 1.0, 0.0]
UpdatePipeline(time=last, proxy=cut)

view = CreateView("RenderView")
view.ViewSize = [1000, 1000]
view.ViewTime = last
view.Background = [1.0, 1.0, 1.0]
view.OrientationAxesVisibility = 0
try:  # ParaView ≥ 5.10 takes the background from the colour palette unless told otherwise
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass

shown = Show(cut, view)
ColorBy(shown, ("CELLS", "von_mises"))
colours = GetColorTransferFunction("von_mises")
colours.ApplyPreset("Jet", True)
shown.RescaleTransferFunctionToDataRange(False, True)
bar = GetScalarBar(colours, view)
bar.Title = "von Mises [Pa]"
bar.ComponentTitle = ""
bar.TitleColor = bar.LabelColor = [0.1, 0.1, 0.1]
bar.RangeLabelFormat = "%-#.3g"
shown.SetScalarBarVisibility(view, True)

# Look at the cut face on (along +y), the axis upright, the impact face at the bottom.
view.CameraPosition = [0.0, -0.1, 0.008]
view.CameraFocalPoint = [0.0, 0.0, 0.008]
view.CameraViewUp = [0.0, 0.0, 1.0]
view.ResetCamera()
Render(view)
os.makedirs(os.path.dirname(os.path.abspath(png)), exist_ok=True)
# Under a temporary name, then renamed: never a half-written picture.
temp = os.path.join(os.path.dirname(os.path.abspath(png)),
                    f".{os.path.basename(png)}.tmp-{os.getpid()}.png")
SaveScreenshot(temp, view, ImageResolution=[1000, 1000], TransparentBackground=0)
os.replace(temp, png)
cells = cut.GetDataInformation().GetNumberOfCells()
print(f"slice_quickstart: t = {last:.6g} s, {cells} cells on the cut -> {png}")
