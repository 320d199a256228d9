# Loads a bar impact run's solution.pvd in ParaView (pvpython), checks that
# every field is there, warps the mesh by the displacement (ParaView's Warp By
# Vector, as a user would view the deformed configuration) and checks that the
# bar's end x = 0 sits where the exact solution puts it: at t = 0.05 s (free
# flight) at x = -0.05 m, at t = 1.1 s (in contact) at the wall x = -0.1 m,
# and at t = 2.5 s (released) at x = -0.1 + 0.4 m up to the scheme's error.
# Then the velocity, von Mises stress, contact pressure and critical set
# fields against the exact solution in free flight and behind and ahead of
# the compression front, and the critical set at every output time against
# the measure that the statistics give of it.
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

# the critical set field against the statistics: at each output time the
# nodes it marks, each weighted by its share of the bar's end (the
# trapezoidal rule on the end's nodes), measure what the statistics say of
# that step (critical_measure) to 1e-6 (the VTU's points are in single
# precision); it is 0 or 1 and marks no node off the end
with open(directory + "/statistics.tsv") as f:
    rows = [line.rstrip("\n").split("\t") for line in f if not line.startswith("#")]
column = {name: i for i, name in enumerate(rows[0])}
measure_of_step = {round(float(r[column["time"]]), 9): float(r[column["critical_measure"]])
                   for r in rows[1:]}
worst, marked_times, valid = 0., [], True
for t in times:
    data = fetch(reader, t)
    x, y = data.Points[:, 0], data.Points[:, 1]
    critical = data.PointData["critical_set"]
    valid = valid and all(abs(c) <= 1e-12 or abs(c - 1.) <= 1e-12 for c in critical) \
        and all(x[critical > 0.5] < 1e-9)
    end = sorted(set(round(float(v), 12) for v in y[x < 1e-9]))
    share = {v: 0.5 * ((end[min(i + 1, len(end) - 1)] - end[max(i - 1, 0)]))
             for i, v in enumerate(end)}
    marked = set(round(float(v), 12) for v in y[(x < 1e-9) & (critical > 0.5)])
    measure = sum(share[v] for v in marked)
    worst = max(worst, abs(measure - measure_of_step[round(t, 9)]))
    if marked:
        marked_times.append("t = %.3g: %d nodes, %.3g" % (t, len(marked), measure))
print("critical_set at %d output times against critical_measure (1e-6): %s; "
      "marked at %s: %s"
      % (len(times), "below 1e-6" if worst <= 1e-6 else "%.1g" % worst, ", ".join(marked_times) or "none",
         "OK" if valid and worst <= 1e-6 and len(marked_times) == 1 else "FAILED"))

data = fetch(reader, 1.1)
p = data.PointData["contact_pressure"]
print("t = 1.1: max contact pressure %.2g (exact 1): %s" % (p.max(), "OK" if abs(p.max() - 1.) < 0.15 else "FAILED"))
print("t = 1.1: active nodes shown: %d" % int(round(data.PointData["active_set"].max())))
s = data.PointData["subdomain"]
print("subdomains %d to %d, cells %d" % (s.min(), s.max(), data.GetNumberOfCells()))
