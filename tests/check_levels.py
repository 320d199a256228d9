# Loads the last output of an adaptive Hertz drop in ParaView and checks the
# adapted mesh: the cells at the contact point (within 0.05 m of the origin)
# reach the maximum refinement level, the far field (more than 2 m from it)
# stays at most one level above the initial mesh.
# Usage: pvpython check_levels.py results-directory maximum-level initial-level
import sys

from paraview import servermanager
from paraview.simple import PVDReader
from vtk.numpy_interface import dataset_adapter as dsa

reader = PVDReader(FileName=sys.argv[1] + "/solution.pvd")
maximum, initial = int(sys.argv[2]), int(sys.argv[3])
t = reader.TimestepValues[-1]
reader.UpdatePipeline(t)
# deal.II writes cell data on the points of each cell's patch: every point
# belongs to one cell and carries its level
data = dsa.WrapDataObject(servermanager.Fetch(reader))
r = (data.Points[:, 0] ** 2 + data.Points[:, 1] ** 2) ** 0.5
level = data.PointData["refinement_level"]
near, far = level[r < 0.05], level[r > 2.0]
print("contact zone: finest level %d (maximum %d): %s"
      % (near.max(), maximum, "OK" if near.max() == maximum else "FAILED"))
print("far field: finest level %d (at most %d): %s"
      % (far.max(), initial + 1, "OK" if far.max() <= initial + 1 else "FAILED"))
