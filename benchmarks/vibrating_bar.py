#!/usr/bin/python3
"""A bar that lands already vibrating: the bar impact (L = 1 m, E = rho = 1,
v0 = 1 m/s, g0 = 0.1 m, Poisson's ratio 0, so the 2D bar is the 1D bar) with
a uniform initial strain eps0 and free ends. Release waves run through the
bar from t = 0 on, and the end lands with a velocity and a stress that jump
each time a wave arrives: the exact contact pressure is piecewise constant.

The exact pressure comes from d'Alembert's solution along the
characteristics: the 1D scheme u_i^{n+1} = u_{i+1}^n + u_{i-1}^n - u_i^{n-1}
with c tau = h is exact on its grid; a free end is its even reflection, an
end in contact its odd reflection about the wall, switched by the
Signorini conditions. It runs on 20 000 cells.

For each scheme and mesh (tau = h/2c, lumped mass) the table gives the
contact force against the exact one over the exact contact intervals:
relative L2 error in time, and the largest ripple, the largest deviation
from the exact value outside 2 h/c of its jumps, relative to rho c v0.
Usage, from the repository's top folder after tools/setup.sh:
    benchmarks/vibrating_bar.py [build/dyncontact] [eps0]"""
import options  # noqa: F401 (--help prints the docstring above)
import csv
import os
import subprocess
import sys

import numpy

executable = sys.argv[1] if len(sys.argv) > 1 else "build/dyncontact"
eps0 = float(sys.argv[2]) if len(sys.argv) > 2 else 0.3
L, v0, g0, height, end_time = 1.0, 1.0, 0.1, 0.1, 2.5
os.makedirs("results-vibrating-bar", exist_ok=True)


def exact_pressure(n=20000):
    """Times and contact pressure (Pa) of the 1D bar, on the grid c tau = h."""
    h = L / n
    old = eps0 * numpy.linspace(0.0, L, n + 1)
    # first step, exact for piecewise linear data: the mean of the neighbours
    # (even reflection at the free ends) plus tau v
    padded = numpy.concatenate(([old[1]], old, [old[n - 1]]))
    cur = 0.5 * (padded[:-2] + padded[2:]) - h * v0
    times, pressures = [0.0, h], [0.0, 0.0]
    t = h
    while t < end_time:
        new = numpy.empty_like(cur)
        new[1:n] = cur[2:] + cur[:-2] - old[1:n]
        new[n] = 2.0 * cur[n - 1] - old[n]
        free = 2.0 * cur[1] - old[0]
        in_contact = free < -g0
        new[0] = -g0 if in_contact else free
        # the pressure at the end, -E u_x of the first cell
        t += h
        times.append(t)
        pressures.append(max(0.0, -(new[1] - new[0]) / h) if in_contact else 0.0)
        old, cur = cur, new
    return times, pressures


def run(scheme, cells):
    name = "%s-%d" % (scheme, cells)
    prm = "results-vibrating-bar/%s.prm" % name
    with open(prm, "w") as f:
        f.write("""set Dimension = 2
set Output directory = results-vibrating-bar/%s
subsection Scene
  set Name = bar impact
  subsection Bar impact
    set Cells along length = %d
    set Initial strain = %g
  end
end
subsection Time integration
  set Scheme = %s
  set Time step = %g
  set End time = %g
end
subsection Output
  set Write vtu = false
end
""" % (name, cells, eps0, scheme, 0.5 / cells, end_time))
    subprocess.run([executable, prm], check=True, stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open("results-vibrating-bar/%s/statistics.tsv" % name),
                               delimiter="\t"))
    return ([float(r["time"]) for r in rows],
            [float(r["contact_force"]) / height for r in rows])


te, pe = exact_pressure()
dt_exact = te[1] - te[0]


def exact_at(t):
    return pe[min(len(pe) - 1, int(round(t / dt_exact)))]


jumps = [te[i] for i in range(1, len(pe)) if abs(pe[i] - pe[i - 1]) > 1e-3]
intervals = []
for i in range(1, len(pe)):
    if pe[i] > 0 and pe[i - 1] == 0:
        start = te[i]
    if pe[i] == 0 and pe[i - 1] > 0:
        intervals.append((start, te[i]))
print("eps0 = %g: exact contact intervals %s s, pressure levels %s Pa"
      % (eps0, ", ".join("[%.3f, %.3f]" % iv for iv in intervals),
         sorted(set(round(p, 3) for p in pe if p > 0))))
print("%-7s %6s %10s %10s" % ("scheme", "cells", "L2 rel.", "ripple"))
for scheme in ["N-CI", "N-CS", "N-CS++"]:
    for cells in [40, 80, 160, 320]:
        t, p = run(scheme, cells)
        h = L / cells
        num = den = ripple = 0.0
        for ti, pi in zip(t, p):
            if not any(a <= ti <= b for a, b in intervals):
                continue
            e = exact_at(ti)
            num += (pi - e) ** 2
            den += e ** 2
            if all(abs(ti - tj) > 2 * h for tj in jumps):
                ripple = max(ripple, abs(pi - e) / v0)
        print("%-7s %6d %10.3f %10.3f" % (scheme, cells, (num / den) ** 0.5, ripple))
