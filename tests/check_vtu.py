# Loads a bar impact run's solution.pvd in ParaView (pvpython), checks that
# every field is there, warps the mesh by the displacement (ParaView's Warp By
# Vector, as a user would view the deformed configuration) and checks that the
# bar's end x = 0 sits where the exact solution puts it: at t = 0.05 s (free
# flight) at x = -0.05 m, at t = 1.1 s (in contact) at the wall x = -0.1 m,
# and at t = 2.5 s (released) at x = -0.1 + 0.4 m up to the scheme's error.
# Usage: pvpython check_vtu.py results-directory
import sys

from paraview import servermanager
from paraview.simple import PVDReader, WarpByVector
from vtk.numpy_interface import dataset_adapter as dsa

directory = sys.argv[1]
reader = PVDReader(FileName=directory + "/solution.pvd")
times = list(reader.TimestepValues)
print("output times: %d, first %.3g, last %.3g" % (len(times), times[0], times[-1]))

fields = sorted(reader.PointData.keys())
print("fields: " + ", ".join(fields))
expected = ["active_set", "contact_pressure", "critical_set", "displacement",
            "subdomain", "velocity", "von_mises_stress"]
print("all fields present: %s" % ("OK" if all(a in fields for a in expected) else "FAILED"))

warp = WarpByVector(Input=reader)
warp.Vectors = ["POINTS", "displacement"]


def fetch(proxy, t):
    proxy.UpdatePipeline(t)
    return dsa.WrapDataObject(servermanager.Fetch(proxy))


for t, exact, tolerance in [(0.05, -0.05, 1e-6), (1.1, -0.1, 1e-6), (2.5, 0.3, 0.05)]:
    reference = fetch(reader, t)
    deformed = fetch(warp, t)
    end = reference.Points[:, 0] < 1e-9  # the nodes of the bar's end x = 0
    x = deformed.Points[end, 0]
    print("t = %.3g: deformed end at x = %.3g to %.3g (exact %.3g): %s"
          % (t, x.min(), x.max(), exact,
             "OK" if abs(x.min() - exact) <= tolerance and abs(x.max() - exact) <= tolerance
             else "FAILED"))

data = fetch(reader, 1.1)
p = data.PointData["contact_pressure"]
print("t = 1.1: max contact pressure %.2g (exact 1): %s" % (p.max(), "OK" if abs(p.max() - 1.) < 0.15 else "FAILED"))
print("t = 1.1: active nodes shown: %d" % int(round(data.PointData["active_set"].max())))
s = data.PointData["subdomain"]
print("subdomains %d to %d, cells %d" % (s.min(), s.max(), data.GetNumberOfCells()))
