# Loads a two-bars run (matching meshes, bars at x in [-1.1,-0.1] and
# [0.1,1.1], +-1 m/s, exact contact pressure 1 Pa from t = 0.1 s to 2.1 s) in
# ParaView and checks the per-body contact output: the gap field on the slave
# face is the initial distance 0.2 m at t = 0 and 0 in contact; the contact
# pressure is there on both sides (the master side from the rows' weights),
# close to 1 Pa, and equal on the two sides.
# Usage: pvpython check_two_bodies.py results-directory
import sys

from paraview import servermanager
from paraview.simple import PVDReader
from vtk.numpy_interface import dataset_adapter as dsa

reader = PVDReader(FileName=sys.argv[1] + "/solution.pvd")


def fetch(t):
    reader.UpdatePipeline(t)
    return dsa.WrapDataObject(servermanager.Fetch(reader))


data = fetch(0.0)
fields = sorted(data.PointData.keys())
print("gap field present: %s" % ("OK" if "gap" in fields else "FAILED"))
X = data.Points
slave = abs(X[:, 0] - 0.1) < 1e-9   # the second bar's face: the slave here
master = abs(X[:, 0] + 0.1) < 1e-9
g = data.PointData["gap"][slave]
print("t = 0: gap on the slave face %.3g to %.3g (0.2): %s"
      % (g.min(), g.max(), "OK" if abs(g.min() - 0.2) < 1e-6 and abs(g.max() - 0.2) < 1e-6 else "FAILED"))

data = fetch(1.1)
g = data.PointData["gap"][slave]
p_s = data.PointData["contact_pressure"][slave]
p_m = data.PointData["contact_pressure"][master]
print("t = 1.1: gap on the slave face %.2g: %s" % (abs(g).max(), "OK" if abs(g).max() < 1e-6 else "FAILED"))
print("t = 1.1: pressure slave side %.3g to %.3g, master side %.3g to %.3g: %s"
      % (p_s.min(), p_s.max(), p_m.min(), p_m.max(),
         "OK" if abs(p_s.max() - 1) < 0.15 and abs(p_m.max() - 1) < 0.15
         and abs(p_s.min() - 1) < 0.15 and abs(p_m.min() - 1) < 0.15 else "FAILED"))
