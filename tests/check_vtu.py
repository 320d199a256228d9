# Loads a bar impact run's solution.pvd in ParaView (pvpython), checks that
# every field is there, warps the mesh by the displacement (ParaView's Warp By
# Vector, as a user would view the deformed configuration) and checks that the
# bar's end x = 0 sits where the exact solution puts it: at t = 0.05 s (free
# flight) at x = -0.05 m, at t = 1.1 s (in contact) at the wall x = -0.1 m,
# and at t = 2.5 s (released) at x = -0.1 + 0.4 m up to the scheme's error.
# Then the velocity, von Mises stress, contact pressure and critical set
# fields against the exact solution in free flight and behind and ahead of
# the compression front.
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

# the fields against the exact solution: in free flight (t = 0.05) every
# node moves at -v0 = -1 unstressed, nothing is in contact or critical; at
# t = 0.6 the compression front (from the contact at t = 0.1, speed c = 1)
# is at x = 0.5: behind it (x < 0.3) the bar rests under the uniaxial stress
# rho c v0 = 1 (von Mises 1 with nu = 0): each node within 0.12 (the wake
# of the front, which the scheme smears over a few cells), their means
# within 0.02; ahead of it (x > 0.65) it still flies unstressed (0.05)
free = fetch(reader, 0.05)
v = free.PointData["velocity"]
print("t = 0.05: velocity (-1, 0), von Mises stress, contact pressure and "
      "critical set 0 at every node (1e-9): %s"
      % ("OK" if abs(v[:, 0] + 1.).max() <= 1e-9 and abs(v[:, 1]).max() <= 1e-9
         and abs(free.PointData["von_mises_stress"]).max() <= 1e-9
         and abs(free.PointData["contact_pressure"]).max() <= 1e-9
         and abs(free.PointData["critical_set"]).max() <= 1e-9 else "FAILED"))
front = fetch(reader, 0.6)
x = front.Points[:, 0]
v = front.PointData["velocity"][:, 0]
m = front.PointData["von_mises_stress"]
behind, ahead = x < 0.3, x > 0.65
print("t = 0.6: behind the front velocity %.2g to %.2g, mean %.2g (0), von "
      "Mises %.2g to %.2g, mean %.3g (1); ahead velocity %.2g to %.2g (-1), "
      "von Mises below %.2g (0): %s"
      % (v[behind].min(), v[behind].max(), v[behind].mean(), m[behind].min(),
         m[behind].max(), m[behind].mean(), v[ahead].min(), v[ahead].max(),
         m[ahead].max(),
         "OK" if abs(v[behind]).max() <= 0.12 and abs(v[behind].mean()) <= 0.02
         and abs(m[behind] - 1.).max() <= 0.12 and abs(m[behind].mean() - 1.) <= 0.02
         and abs(v[ahead] + 1.).max() <= 0.05 and m[ahead].max() <= 0.05
         else "FAILED"))

data = fetch(reader, 1.1)
p = data.PointData["contact_pressure"]
print("t = 1.1: max contact pressure %.2g (exact 1): %s" % (p.max(), "OK" if abs(p.max() - 1.) < 0.15 else "FAILED"))
print("t = 1.1: active nodes shown: %d" % int(round(data.PointData["active_set"].max())))
s = data.PointData["subdomain"]
print("subdomains %d to %d, cells %d" % (s.min(), s.max(), data.GetNumberOfCells()))
