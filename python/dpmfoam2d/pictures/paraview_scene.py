# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The ParaView scene of a dpmFoam2D case: the gas and the particles.

Run inside ParaView (`paraview --script=paraview_scene.py`) or pvbatch, as
dpmParaView does; it reads its settings from the environment:

    DPM_PARAVIEW_CASE        the case directory (required)
    DPM_PARAVIEW_TIME        the time to show (default: the latest)
    DPM_PARAVIEW_SCREENSHOT  save the view to this PNG and exit (off-screen)
    DPM_PARAVIEW_HEIGHT      the screenshot's height in pixels (default 1200)
    DPM_PARAVIEW_CLASSES     the classes' labels, one a line, in their order
                             (default: class 0, class 1, ...)

The gas (case.foam, OpenFOAM reader) is shown as the cell voidage in grey
behind the particles (particles/particles.xdmf), drawn as spheres of their
true diameter (a glyph of radius 0.5 scaled by `diameter`) and coloured by
`class` with the colours of the project's snapshots. The camera looks at the
bed through its front face (z = 0), as the snapshots do, framed on the bed:
the column's width, from its bottom to a tenth of the bed's height above its
highest particle (at least half the width), the walls outlined; the colour legends (the classes by
name and diameter, the voidage) and the time stand beside it.
"""

import os

import paraview.simple as ps

CLASS_COLOURS = [(0.894, 0.102, 0.110), (0.216, 0.494, 0.722)]
VOIDAGE_RANGE = (0.35, 1.0)
LEGEND_WIDTH = 0.22     # of the picture's height: the column beside the bed
FONT = 0.018            # of the picture's height

case = os.path.abspath(os.environ["DPM_PARAVIEW_CASE"])
screenshot = os.environ.get("DPM_PARAVIEW_SCREENSHOT", "")
height = int(os.environ.get("DPM_PARAVIEW_HEIGHT", "1200"))
wanted = os.environ.get("DPM_PARAVIEW_TIME", "")
labels = [l for l in os.environ.get("DPM_PARAVIEW_CLASSES", "").split("\n") if l] or \
    ["class %d" % k for k in range(len(CLASS_COLOURS))]
font = max(8, int(round(FONT * height)))

view = ps.GetActiveViewOrCreate("RenderView")
view.OrientationAxesVisibility = 0
view.Background = [1, 1, 1]
try:                      # ParaView 5.10 and later keep a palette background
    view.UseColorPaletteForBackground = 0
except AttributeError:
    pass

gas = ps.OpenFOAMReader(registrationName="gas", FileName=os.path.join(case, "case.foam"))
gas.MeshRegions = ["internalMesh"]
gas.CellArrays = ["voidage"]
# The gas as its back face (z at the mesh's lowest), so that the particles,
# which lie in front of it, are not hidden inside the one-cell-thick mesh
gas.UpdatePipeline()
bounds = gas.GetDataInformation().GetBounds()
zBack = bounds[4] + 1e-3*(bounds[5] - bounds[4])   # inside: a face cuts to nothing
back = ps.Slice(registrationName="gasBackFace", Input=gas)
back.SliceType = "Plane"
back.SliceType.Origin = [0, 0, zBack]
back.SliceType.Normal = [0, 0, 1]
gasDisplay = ps.Show(back, view)
gasDisplay.Ambient, gasDisplay.Diffuse = 1.0, 0.0   # the colour map's greys, unlit
ps.ColorBy(gasDisplay, ("CELLS", "voidage"))
voidageLut = ps.GetColorTransferFunction("voidage")
voidageLut.ApplyPreset("Grayscale", True)
voidageLut.RescaleTransferFunction(*VOIDAGE_RANGE)
voidageLut.AutomaticRescaleRangeMode = "Never"
gasDisplay.SetScalarBarVisibility(view, True)
voidageBar = ps.GetScalarBar(voidageLut, view)
voidageBar.Title = "voidage"
voidageBar.ComponentTitle = ""
voidageBar.RangeLabelFormat = "%-#.2f"

particles = ps.XDMFReader(registrationName="particles",
                          FileNames=[os.path.join(case, "particles", "particles.xdmf")])
spheres = ps.Glyph(registrationName="spheres", Input=particles, GlyphType="Sphere")
spheres.ScaleArray = ["POINTS", "diameter"]
spheres.ScaleFactor = 1.0          # the sphere source's radius is 0.5: true size
spheres.OrientationArray = ["POINTS", "No orientation array"]
spheres.GlyphMode = "All Points"
spheres.GlyphType.ThetaResolution = 16
spheres.GlyphType.PhiResolution = 12
sphereDisplay = ps.Show(spheres, view)
ps.ColorBy(sphereDisplay, ("POINTS", "class"))
classLut = ps.GetColorTransferFunction("class")
classLut.InterpretValuesAsCategories = 1
classLut.Annotations = [x for k, label in enumerate(labels) for x in (str(k), label)]
classLut.IndexedColors = [c for colour in CLASS_COLOURS for c in colour]
sphereDisplay.SetScalarBarVisibility(view, True)
classBar = ps.GetScalarBar(classLut, view)
classBar.Title = "class"
outline = ps.Outline(registrationName="walls", Input=gas)
outlineDisplay = ps.Show(outline, view)
outlineDisplay.AmbientColor = outlineDisplay.DiffuseColor = [0, 0, 0]
outlineDisplay.LineWidth = 2

# The time: the latest particle time unless one is asked for
scene = ps.GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
times = list(particles.TimestepValues) or [0.0]
t = times[-1] if not wanted else min(times, key=lambda s: abs(s - float(wanted)))
scene.AnimationTime = t

# The frame: the column's width, from its bottom to a tenth of the bed's
# height above the highest particle (the whole column if it is full)
spheres.UpdatePipeline(t)
top = spheres.GetDataInformation().GetBounds()[3]
x0, x1, y0 = bounds[0], bounds[1], bounds[2]
y1 = min(bounds[3], top + 0.1 * (top - y0)) if top > y0 else bounds[3]
# at least half as tall as wide (a shallow bed: the legends keep their size)
y1 = min(bounds[3], max(y1, y0 + 0.5 * (x1 - x0)))
pad = 0.02 * (y1 - y0)
frameHeight = y1 - y0 + 2 * pad
bedWidth = int(round(height * (x1 - x0 + 2 * pad) / frameHeight))
legend = int(round(LEGEND_WIDTH * height))
width = max(2, bedWidth + legend)

# Parallel projection: the view's height is the frame's, the bed at the left
metres = frameHeight / height                       # per pixel
view.CameraParallelProjection = 1
view.CameraParallelScale = 0.5 * frameHeight
centre = [x0 - pad + 0.5 * width * metres, 0.5 * (y0 + y1), 0]
view.CameraFocalPoint = centre
view.CameraPosition = [centre[0], centre[1], centre[2] + 1]
view.CameraViewUp = [0, 1, 0]
view.ViewSize = [width, height]
ps._DisableFirstRenderCameraReset()     # the camera set here, not reset to all

# The legends and the time in the column beside the bed
left = (bedWidth + 0.12 * legend) / width
for bar, y, length in ((classBar, 0.58, 0.28), (voidageBar, 0.08, 0.38)):
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.TitleFontSize = font
    bar.LabelFontSize = font
    bar.ScalarBarThickness = max(4, font)
    bar.WindowLocation = "Any Location"
    bar.Orientation = "Vertical"
    bar.TextPosition = "Ticks right/top, annotations left/bottom" if bar is voidageBar \
        else "Ticks left/bottom, annotations right/top"
    bar.Position = [left, y]
    bar.ScalarBarLength = length
voidageBar.RangeLabelFormat = "%.2f"
voidageBar.UseCustomLabels = 1
voidageBar.CustomLabels = [0.4, 0.6, 0.8]
voidageBar.LabelFormat = "%.1f"
clock = ps.Text(registrationName="time", Text="t = %g s" % t)
clockDisplay = ps.Show(clock, view)
clockDisplay.Color = [0, 0, 0]
clockDisplay.FontSize = font
clockDisplay.WindowLocation = "Any Location"
clockDisplay.Position = [left, 0.93]
ps.Render(view)

if screenshot:
    ps.SaveScreenshot(screenshot, view, ImageResolution=[width, height])
    print("dpmParaView: classes %s; the bed in columns 0-%d of %d px, the legends beside it"
          % (", ".join(labels), bedWidth, width))
    print("dpmParaView: time %g written to %s" % (t, screenshot))
