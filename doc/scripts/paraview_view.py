"""Render a run's material points (and its membrane) to a PNG with ParaView.

    pvbatch doc/scripts/paraview_view.py RUN_DIR [-o OUT.png] [--field NAME]
                                          [--time T] [--size WxH]

Run with ParaView's pvbatch or pvpython (Debian: paraview, python3-paraview;
add --force-offscreen-rendering or run under xvfb-run without a display).
Reads RUN_DIR/particles.pvd (or particles.xdmf of Output/Format = hdf5) at
the output time nearest T (default: the last), shows the points as Point
Gaussian discs a little wider than half the points' spacing (from their
volumes: as single pixels they show nothing of a continuum), coloured by NAME (default
pressure; a vector field by its magnitude), with a colour bar, and the
membrane (membrane.pvd or membrane.xdmf, if the run has one) as black
lines; 2D runs are seen from the front. Writes OUT.png (default
RUN_DIR/view.png). The fields a run writes are in doc/running.md.
"""
import argparse
import os
import sys

from paraview import servermanager
from paraview import simple
from vtk.util import numpy_support

import numpy as np


def fail(message):
    sys.stderr.write("paraview_view.py: " + message + "\n")
    sys.exit(2)


def series_reader(run_dir, name):
    """The reader of RUN_DIR/name.pvd or name.xdmf, or None."""
    pvd = os.path.join(run_dir, name + ".pvd")
    xdmf = os.path.join(run_dir, name + ".xdmf")
    if os.path.exists(pvd):
        return simple.PVDReader(FileName=pvd)
    if os.path.exists(xdmf):
        return simple.XDMFReader(FileNames=[xdmf])
    return None


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("run_dir", metavar="RUN_DIR")
    ap.add_argument("-o", "--output", metavar="OUT.png")
    ap.add_argument("--field", default="pressure")
    ap.add_argument("--time", type=float, default=None)
    ap.add_argument("--size", default="1200x700")
    a = ap.parse_args()
    if not os.path.isdir(a.run_dir):
        fail("%s is not a directory" % a.run_dir)
    points = series_reader(a.run_dir, "particles")
    if points is None:
        fail("%s holds no particles.pvd or particles.xdmf" % a.run_dir)
    try:
        width, height = (int(v) for v in a.size.split("x"))
    except ValueError:
        fail("--size must be WIDTHxHEIGHT, e.g. 1200x700")
    output = a.output or os.path.join(a.run_dir, "view.png")

    times = list(points.TimestepValues) if points.TimestepValues else [0.0]
    time = times[-1] if a.time is None else min(
        times, key=lambda t: abs(t - a.time))
    if a.time is not None and abs(time - a.time) > 1e-9 * max(1, abs(time)):
        sys.stderr.write("paraview_view.py: warning: no output at t = %g s; "
                         "showing t = %g s\n" % (a.time, time))
    view = simple.GetActiveViewOrCreate("RenderView")
    view.ViewSize = [width, height]
    view.ViewTime = time
    if hasattr(view, "UseColorPaletteForBackground"):
        view.UseColorPaletteForBackground = 0
    view.Background = [1, 1, 1]
    view.OrientationAxesVisibility = 0
    points.UpdatePipeline(time)

    data = servermanager.Fetch(points)
    if data.IsA("vtkMultiBlockDataSet"):
        data = data.GetBlock(0)
    fields = data.GetPointData()
    names = [fields.GetArrayName(k) for k in range(fields.GetNumberOfArrays())]
    if a.field not in names:
        fail("the points have no field %s; they have: %s"
             % (a.field, ", ".join(names)))
    bounds = data.GetBounds()
    dim = 2 if bounds[5] - bounds[4] == 0 else 3
    radius = 0.0
    if "volume" in names:
        volume = numpy_support.vtk_to_numpy(fields.GetArray("volume"))
        # A little more than half the spacing: neighbouring splats overlap
        # and the body reads as a continuum.
        radius = 0.6 * float(np.median(volume)) ** (1.0 / dim)
    if not radius > 0:
        extent = max(bounds[1] - bounds[0], bounds[3] - bounds[2])
        radius = 0.6 * extent / max(np.sqrt(data.GetNumberOfPoints()), 1)

    display = simple.Show(points, view)
    display.SetRepresentationType("Point Gaussian")
    display.GaussianRadius = radius
    display.ShaderPreset = "Plain circle"
    simple.ColorBy(display, ("POINTS", a.field, "Magnitude"))
    display.RescaleTransferFunctionToDataRange(True, False)
    display.SetScalarBarVisibility(view, True)
    bar = simple.GetScalarBar(simple.GetColorTransferFunction(a.field), view)
    bar.Title = a.field
    bar.ComponentTitle = ""
    bar.TitleColor = bar.LabelColor = [0, 0, 0]

    membrane = series_reader(a.run_dir, "membrane")
    if membrane is not None:
        membrane.UpdatePipeline(time)
        lines = simple.Show(membrane, view)
        lines.SetRepresentationType("Wireframe")
        simple.ColorBy(lines, None)
        lines.AmbientColor = lines.DiffuseColor = [0, 0, 0]
        lines.LineWidth = 2.0

    if dim == 2:
        view.InteractionMode = "2D"
        view.CameraPosition = [0, 0, 1]
        view.CameraFocalPoint = [0, 0, 0]
        view.CameraViewUp = [0, 1, 0]
    simple.ResetCamera(view)
    simple.SaveScreenshot(output, view, ImageResolution=[width, height])
    print("paraview_view.py: t = %g s, %d points coloured by %s -> %s"
          % (time, data.GetNumberOfPoints(), a.field, output))


if __name__ == "__main__":
    main()
