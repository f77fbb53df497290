# SPDX-FileCopyrightText: 2026 The dpmFoam2D authors
# SPDX-License-Identifier: GPL-3.0-or-later
"""Renders dpmFoam2D snapshots off-screen (run by dpmSnapshot and dpmMovie).

    dpmPvbatch render.py --case C --times T1 [T2 ...] \
        --out F1.png [F2.png ...] [--height PX] [--full]

For each particle time Ti: the gas voidage of the nearest gas time (OpenFOAM
reader on C/case.foam, cell values, grey: dark = dense, white = gas) behind
the particles of C/particles/<Ti>.h5 drawn as flat discs at true size (a
polygon of 32 sides per particle), small and large in two fixed colours, and
the time printed. The window is the bed: the mesh's width, from its floor to
a quarter above the highest particle top over all the times rendered (so the
frames of a movie share one window), or the whole column with --full; a band
on the right holds the legend and the voidage scale. Colours are unlit (ambient only), so every pixel of a disc
has exactly its class colour: tests count them.
"""

import argparse
import os
import sys

import numpy as np

from dpmfoam2d import particles as pio  # noqa: E402

import paraview.simple as ps  # noqa: E402
from vtkmodules.util.numpy_support import numpy_to_vtk, numpy_to_vtkIdTypeArray  # noqa: E402
from vtkmodules.vtkCommonCore import vtkPoints  # noqa: E402
from vtkmodules.vtkCommonDataModel import vtkCellArray, vtkPolyData  # noqa: E402

from dpmfoam2d.pictures.tools import CLASS_COLOURS, CLASS_NAMES  # noqa: E402
DISC_SIDES = 32
VOIDAGE_RANGE = (0.35, 1.0)


def discs(x, y, z, d):
    """Polydata of flat discs (regular polygons facing +z) at true size. The
    polygon's vertices lie on a circle whose radius makes the polygon's area
    equal the disc's area (pi r^2)."""
    n = len(x)
    k = DISC_SIDES
    a = 2 * np.pi * np.arange(k) / k
    # area of a regular k-gon of circumradius R: (k/2) R^2 sin(2 pi/k)
    R = 0.5 * d * np.sqrt(np.pi / (0.5 * k * np.sin(2 * np.pi / k)))
    px = (x[:, None] + R[:, None] * np.cos(a)[None, :]).ravel()
    py = (y[:, None] + R[:, None] * np.sin(a)[None, :]).ravel()
    pz = np.repeat(z, k)
    pts = vtkPoints()
    pts.SetData(numpy_to_vtk(np.column_stack([px, py, pz]).astype(np.float64), deep=True))
    cells = vtkCellArray()
    offsets = numpy_to_vtkIdTypeArray(np.arange(n + 1, dtype=np.int64) * k, deep=True)
    conn = numpy_to_vtkIdTypeArray(np.arange(n * k, dtype=np.int64), deep=True)
    cells.SetData(offsets, conn)
    pd = vtkPolyData()
    pd.SetPoints(pts)
    pd.SetPolys(cells)
    return pd


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--case", required=True)
    ap.add_argument("--times", nargs="+", type=float, required=True)
    ap.add_argument("--out", nargs="+", required=True)
    ap.add_argument("--height", type=int, default=1200,
                    help="picture height in pixels; the width follows the window")
    ap.add_argument("--full", action="store_true",
                    help="show the whole column, not just the bed")
    args = ap.parse_args()
    if len(args.out) != len(args.times):
        sys.exit("render.py: as many --out as --times are needed")
    case = os.path.abspath(args.case)
    # One pass for the extent of the particles over all frames (the window),
    # keeping only numbers; each frame is read again when drawn.
    paths = [pio.nearest_time(case, t)[1] for t in args.times]
    top, lo, hi = None, None, None
    for path in paths:
        f = pio.read_particles(path)
        if len(f["diameter"]):
            r = 0.5 * f["diameter"][:, None].astype(float)
            fl = np.min(f["position"][:, :2] - r, axis=0)
            fh = np.max(f["position"][:, :2] + r, axis=0)
            lo = fl if lo is None else np.minimum(lo, fl)
            hi = fh if hi is None else np.maximum(hi, fh)
            top = hi[1]

    view = ps.CreateView("RenderView")
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.UseFXAA = 0
    view.CameraParallelProjection = 1

    # Gas voidage behind (skipped when the case has no mesh).
    gas, bar, gasTimes, zFront = None, None, [], 0.0
    if os.path.isdir(os.path.join(case, "constant", "polyMesh")):
        gas = ps.OpenFOAMReader(FileName=os.path.join(case, "case.foam"))
        gas.MeshRegions = ["internalMesh"]
        gas.CellArrays = ["voidage"]
        # The solver writes the settled bed's voidage at 0; a 0/ without it
        # (a case set up by hand) would hide the field: the reader lists the
        # fields of its first time.
        gas.SkipZeroTime = 0 if any(os.path.isfile(os.path.join(case, "0", f))
                                    for f in ("voidage", "voidage.gz")) else 1
        ps.ReloadFiles(gas)         # (the time list is only rebuilt on a reload)
        gas.UpdatePipelineInformation()
        gasTimes = list(gas.TimestepValues) if gas.TimestepValues else [0.0]
        gas.UpdatePipeline(gasTimes[-1])
        bounds = gas.GetDataInformation().GetBounds()
        zFront = bounds[5]
        gd = ps.Show(gas, view)
        walls = ps.Show(ps.Outline(Input=gas), view)   # the column's walls
        walls.AmbientColor = walls.DiffuseColor = [0, 0, 0]
        walls.LineWidth = 2
        gd.Ambient, gd.Diffuse, gd.Specular = 1.0, 0.0, 0.0
        if "voidage" in gas.CellData.keys():
            ps.ColorBy(gd, ("CELLS", "voidage"))
            lut = ps.GetColorTransferFunction("voidage")
            lut.ColorSpace = "RGB"
            lut.AutomaticRescaleRangeMode = "Never"
            lut.RGBPoints = [VOIDAGE_RANGE[0], 0.3, 0.3, 0.3, VOIDAGE_RANGE[1], 1, 1, 1]
            bar = ps.GetScalarBar(lut, view)
            bar.Title = "voidage"
            bar.ComponentTitle = ""
            bar.TitleColor = bar.LabelColor = [0, 0, 0]
            bar.RangeLabelFormat = "%.2f"
            bar.WindowLocation = "Any Location"
            bar.Orientation = "Vertical"
            bar.ScalarBarLength = 0.3
            bar.Visibility = 1
        else:
            print("render.py: no voidage field in %s; the mesh is white" % case)
            gd.ColorArrayName = ["POINTS", ""]
            gd.AmbientColor = gd.DiffuseColor = [1, 1, 1]

    # The window: bed width (mesh, else particles), floor to bed top.
    if gas is not None:
        bx0, bx1, by0, by1 = bounds[0], bounds[1], bounds[2], bounds[3]
    else:
        print("render.py: no mesh in %s/constant/polyMesh; particles only" % case)
        if top is None:
            sys.exit("render.py: neither a mesh nor particles to show in %s" % case)
        bx0, bx1, by0, by1 = lo[0], hi[0], lo[1], hi[1]
    y1 = by1 if (args.full or top is None) else min(by1, top + max(0.25 * (top - by0), 0.01))
    W, H = bx1 - bx0, y1 - by0
    y0, y1 = by0 - 0.02 * H, y1 + 0.02 * H
    height = int(args.height)
    fontTime = max(18, round(height / 40))
    fontText = max(14, round(height / 70))
    pxPerM = height / (y1 - y0)
    # A band right of the bed for the time, the legend and the voidage scale.
    band = max(0.4 * W, 16 * fontText / pxPerM)
    x0, x1 = bx0 - 0.04 * W, bx1 + band
    width = 2 * int(round(0.5 * pxPerM * (x1 - x0)))
    view.ViewSize = [width, height]
    bandX = (bx1 + 0.04 * W - x0) / (x1 - x0)
    if bar is not None:
        bar.TitleFontSize = fontText
        bar.LabelFontSize = max(12, round(height / 85))
        bar.Position = [bandX, 0.3]

    # Particles: one producer per class, flat discs in front of the mesh.
    producers = {}
    for c, colour in CLASS_COLOURS.items():
        prod = ps.TrivialProducer()
        prod.GetClientSideObject().SetOutput(vtkPolyData())
        disp = ps.Show(prod, view)
        disp.ColorArrayName = ["POINTS", ""]
        disp.AmbientColor = disp.DiffuseColor = list(colour)
        disp.Ambient, disp.Diffuse, disp.Specular = 1.0, 0.0, 0.0
        producers[c] = prod

    text = ps.Text()
    td = ps.Show(text, view)
    td.Color = [0, 0, 0]
    td.FontSize = fontTime
    td.WindowLocation = "Any Location"
    td.Position = [bandX, 0.93]
    legend = ps.Text()
    ld = ps.Show(legend, view)
    ld.Color = [0, 0, 0]
    ld.FontSize = fontText
    ld.WindowLocation = "Any Location"
    ld.Position = [bandX, 0.86]

    # Camera: parallel projection, looking down -z at the window (after a
    # first render, which would otherwise reset it to the whole scene).
    ps.Render(view)
    xc, yc = 0.5 * (x0 + x1), 0.5 * (y0 + y1)
    view.CameraPosition = [xc, yc, zFront + 1.0]
    view.CameraFocalPoint = [xc, yc, zFront]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelScale = 0.5 * (y1 - y0)

    for path, out in zip(paths, args.out):
        p = pio.read_particles(path)
        pos = p["position"].astype(np.float64)
        d = p["diameter"].astype(np.float64)
        cls = p["class"].astype(int)
        z = zFront + 1.5 * (d.max() if len(d) else 0.0) + np.zeros(len(d))
        if len(d):
            # Spheres of a slab drawn as the camera (+z) sees the front wall
            # z = 0: the nearer a sphere to it, the higher its disc. 2D files
            # hold one z (half the depth), so nothing moves.
            z += pos[:, 2].max() - pos[:, 2]
        lines = []
        for c, prod in producers.items():
            m = cls == c
            prod.GetClientSideObject().SetOutput(discs(pos[m, 0], pos[m, 1], z[m], d[m]))
            prod.MarkModified(prod)
            lines.append("%s: %s, %d x %.2f mm" % (
                "red" if c == 0 else "blue", CLASS_NAMES[c], int(m.sum()),
                1e3 * float(np.median(d[m])) if m.any() else 0.0))
        label = "t = %.2f s" % p["time"]
        if gasTimes:
            tg = min(gasTimes, key=lambda g: abs(g - p["time"]))
            view.ViewTime = tg
            if abs(tg - p["time"]) > 1e-6 * max(1.0, abs(tg)):
                label += "\n(gas t = %.4g s)" % tg
        text.Text = label
        legend.Text = "\n".join(lines)
        ps.Render(view)
        os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
        ps.SaveScreenshot(out, view, ImageResolution=[width, height],
                          TransparentBackground=0)
        print("render.py: %s (particles t = %g, %d particles, %dx%d px)"
              % (out, p["time"], len(d), width, height))


main()
