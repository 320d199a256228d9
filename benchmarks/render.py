"""Renders one output time of a run with ParaView, offscreen, on the
deformed configuration (Warp By Vector of the displacement), coloured by a
field, with the mesh edges.
Usage: xvfb-run -a pvpython benchmarks/render.py results/solution.pvd TIME
           FIELD out.png [x_min x_max y_min y_max]"""
import sys

from paraview.simple import (ColorBy, GetActiveViewOrCreate, GetColorTransferFunction,
                             PVDReader, SaveScreenshot, Show, WarpByVector)

pvd, t, field, png = sys.argv[1], float(sys.argv[2]), sys.argv[3], sys.argv[4]
box = [float(v) for v in sys.argv[5:9]] if len(sys.argv) >= 9 else None

reader = PVDReader(FileName=pvd)
warp = WarpByVector(Input=reader)
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
if box:
    cx, cy = 0.5 * (box[0] + box[1]), 0.5 * (box[2] + box[3])
    view.CameraPosition = [cx, cy, 10]
    view.CameraFocalPoint = [cx, cy, 0]
    view.CameraViewUp = [0, 1, 0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = 0.5 * max(box[3] - box[2], (box[1] - box[0]) * 0.6)
SaveScreenshot(png, view, ImageResolution=[1000, 600])
print("wrote " + png)
