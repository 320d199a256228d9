"""Renders one output time of a run with ParaView, offscreen, on the
deformed configuration (Warp By Vector of the displacement), coloured by a
field, with the mesh edges.
Usage: xvfb-run -a pvpython benchmarks/render.py results/solution.pvd TIME
           FIELD out.png [x_min x_max y_min y_max] [--below=Y]
           [--camera=X,Y,Z --focus=X,Y,Z]
--below=Y keeps only the cells below the plane y = Y of the reference
configuration (in 3D: the block without the ball on it); --camera and
--focus give a 3D view: from the point X,Y,Z at the point X,Y,Z."""
import options  # noqa: F401 (--help prints the docstring above)
import sys

from paraview.simple import (Clip, ColorBy, GetActiveViewOrCreate, GetColorTransferFunction,
                             PVDReader, SaveScreenshot, Show, WarpByVector)

settings = dict(a[2:].split("=", 1) for a in sys.argv[1:] if a.startswith("--"))
args = [a for a in sys.argv[1:] if not a.startswith("--")]
pvd, t, field, png = args[0], float(args[1]), args[2], args[3]
box = [float(v) for v in args[4:8]] if len(args) >= 8 else None

reader = PVDReader(FileName=pvd)
source = reader
if "below" in settings:
    source = Clip(Input=reader)
    source.ClipType = "Plane"
    source.ClipType.Origin = [0, float(settings["below"]), 0]
    source.ClipType.Normal = [0, 1, 0]
warp = WarpByVector(Input=source)
warp.Vectors = ["POINTS", "displacement"]
view = GetActiveViewOrCreate("RenderView")
view.ViewTime = t
view.ViewSize = [1000, 600]
view.OrientationAxesVisibility = 0
display = Show(warp, view)
display.SetRepresentationType("Surface With Edges")
ColorBy(display, ("POINTS", field))
display.RescaleTransferFunctionToDataRange(True, False)
display.SetScalarBarVisibility(view, True)
GetColorTransferFunction(field).ApplyPreset("Viridis (matplotlib)", True)
view.ResetCamera()
if "camera" in settings:
    view.CameraPosition = [float(v) for v in settings["camera"].split(",")]
    view.CameraFocalPoint = [float(v) for v in settings["focus"].split(",")]
    view.CameraViewUp = [0, 1, 0]
elif box:
    cx, cy = 0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3])
    view.CameraPosition = [cx, cy, 10]
    view.CameraFocalPoint = [cx, cy, 0]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 0.5 * max(box[3] - box[2], (box[1] - box[0]) * 0.6)
SaveScreenshot(png, view, ImageResolution=[1000, 600])
print("wrote " + png)
