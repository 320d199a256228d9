# Loads the outputs of an adaptive bar impact in ParaView and finds, at
# every output time while the compression front runs through the bar, the
# refinement levels of the cells that hold the front. The outputs are
# written at the steps after which the mesh adapts, before it adapts: each
# shows the mesh of the adaptation one interval earlier, with the front
# moved on by c tau n. In the reference configuration the front stands at
# x = c (t - t0), t0 = g0/v0 the time of impact, until it reaches the free
# end x = L at t0 + L/c.
# A cell is refined by one level per adaptation: from a coarse mesh k levels
# below the maximum the front reaches the maximum level k adaptations after
# the impact; the output times from @p from on are checked.
# Usage: pvpython check_front.py results-directory maximum-level t0 L c from
#        inside|leaves
# inside: the front's cells are at the maximum level at every output time;
# leaves: at some output time a cell of the front is coarser (what a
# refined zone that does not follow the front does).
import sys

from paraview import servermanager
from paraview.simple import PVDReader
from vtk.numpy_interface import dataset_adapter as dsa

reader = PVDReader(FileName=sys.argv[1] + "/solution.pvd")
maximum = int(sys.argv[2])
t0, length, c, start = (float(a) for a in sys.argv[3:7])
expect = sys.argv[7]
times = [t for t in reader.TimestepValues
         if start <= t and c * (t - t0) < length]
misses = 0
for t in times:
    reader.UpdatePipeline(t)
    grid = servermanager.Fetch(reader)
    data = dsa.WrapDataObject(grid)
    level = data.PointData["refinement_level"]
    front = c * (t - t0)
    coarsest = maximum
    for i in range(grid.GetNumberOfCells()):
        cell = grid.GetCell(i)
        x0, x1 = cell.GetBounds()[0:2]
        if x0 <= front <= x1:
            coarsest = min(coarsest, int(level[cell.GetPointId(0)]))
    misses += coarsest < maximum
if expect == "inside":
    print("the front's cells at the maximum level %d at all %d output times "
          "before an adaptation: %s"
          % (maximum, len(times),
             "OK" if misses == 0 and len(times) > 5 else
             "FAILED (%d misses)" % misses))
else:
    print("without widening the front leaves the refined zone at some of "
          "%d output times: %s" % (len(times), "OK" if misses > 0 and
                                   len(times) > 5 else "FAILED"))
