# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""The ParaView scene of a dpmFoam2D case: the gas and the particles.

Run inside ParaView (`paraview --script=paraview_scene.py`) or pvbatch, as
dpmParaView does; it reads its settings from the environment:

    DPM_PARAVIEW_CASE        the case directory (required)
    DPM_PARAVIEW_TIME        the time to show (default: the latest)
    DPM_PARAVIEW_SCREENSHOT  save the view to this PNG and exit (off-screen)
    DPM_PARAVIEW_HEIGHT      the screenshot's height in pixels (default 1200)

The gas (case.foam, OpenFOAM reader) is shown as the cell voidage in grey
behind the particles (particles/particles.xdmf), drawn as spheres of their
true diameter (a glyph of radius 0.5 scaled by `diameter`) and coloured by
`class` with the colours of the project's snapshots. The camera looks at the
bed through its front face (z = 0), as the snapshots do.
"""

import os

import paraview.simple as ps

CLASS_COLOURS = [(0.894, 0.102, 0.110), (0.216, 0.494, 0.722)]
VOIDAGE_RANGE = (0.35, 1.0)

case = os.path.abspath(os.environ["DPM_PARAVIEW_CASE"])
screenshot = os.environ.get("DPM_PARAVIEW_SCREENSHOT", "")
height = int(os.environ.get("DPM_PARAVIEW_HEIGHT", "1200"))
wanted = os.environ.get("DPM_PARAVIEW_TIME", "")

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
classLut.Annotations = ["0", "class 0", "1", "class 1"]
classLut.IndexedColors = [c for colour in CLASS_COLOURS for c in colour]
sphereDisplay.SetScalarBarVisibility(view, True)
classBar = ps.GetScalarBar(classLut, view)
classBar.Title = "class"
for bar, y in ((voidageBar, 0.05), (classBar, 0.6)):
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    bar.WindowLocation = "Any Location"
    bar.Position = [0.78, y]
    bar.ScalarBarLength = 0.33

# The time: the latest particle time unless one is asked for
scene = ps.GetAnimationScene()
scene.UpdateAnimationUsingDataTimeSteps()
times = list(particles.TimestepValues) or [0.0]
t = times[-1] if not wanted else min(times, key=lambda s: abs(s - float(wanted)))
scene.AnimationTime = t

# The whole column in view, seen through its front face
view.CameraParallelProjection = 1
view.CameraPosition = [0, 0, 1]
view.CameraFocalPoint = [0, 0, 0]
view.CameraViewUp = [0, 1, 0]
view.ResetCamera(*bounds)
ps.Render(view)

if screenshot:
    aspect = (bounds[1] - bounds[0]) / max(bounds[3] - bounds[2], 1e-12)
    width = max(2, int(round(height * aspect)) + 300)   # room for the colour bars
    ps.SaveScreenshot(screenshot, view, ImageResolution=[width, height])
    print("dpmParaView: time %g written to %s" % (t, screenshot))
