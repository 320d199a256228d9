#!/usr/bin/env python3
"""Refinement that follows a wave front, on the bar impact (H = 0.25 m, Q1,
N-CS++, lumped mass, tau = h/(2c) of 128 cells along, exact solution):
the uniform mesh of 128 cells along against adaptive meshes of 32 coarse
cells along and 2 levels, by Kelly's indicator of the velocity every 2 and
8 steps and by the velocity jump with the contact zone every 8 and 16 steps
with Front widening = 1; then with Numerical dissipation = 0.05 the
uniform mesh and the velocity jump every 16 and 8 steps (on deal.II's
serial triangulation, as the last run without dissipation too), beside
the uniform mesh of 64 cells along with it. Prints mean DoFs, the time
loop without the sampled norms, the energy-norm error at T over sqrt(E(0))
and the position error at T, one core.

Usage: benchmarks/front_widening.py build/dyncontact
"""
import options  # noqa: F401 (--help prints the docstring above)
import csv
import math
import os
import re
import subprocess
import sys

executable = sys.argv[1]
work = "results-front-widening"
os.makedirs(work, exist_ok=True)
base = open("prm/bar_impact.prm").read()


def run(name, cells, extra):
    directory = os.path.join(work, name)
    text = base + """
subsection Scene
  subsection Bar impact
    set Cells along length = %d
    set Height = 0.25
  end
end
subsection Time integration
  set Time step = %.17g
end
subsection Output
  set Write vtu = false
end
set Output directory = %s
""" % (cells, 1. / 256., directory) + extra
    with open(directory + ".prm", "w") as f:
        f.write(text)
    subprocess.run([executable, directory + ".prm"], check=True,
                   stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open(directory + "/statistics.tsv"),
                               delimiter="\t"))
    summary = open(directory + "/summary.txt").read()
    loop = float(re.search(r"of which the time loop ([0-9.e+-]+) s",
                           summary).group(1))
    sampled = re.search(r"\n\s*sampled norms\s+([0-9.e+-]+) s", summary)
    time = loop - (float(sampled.group(1)) if sampled else 0.)
    e0 = float(rows[0]["energy_total"])
    errors = [float(r["error_energy_norm"]) for r in rows
              if not math.isnan(float(r["error_energy_norm"]))]
    dofs = sum(float(r["dofs"]) for r in rows) / len(rows)
    position = abs(float(rows[-1]["mean_displacement_x"]) - 0.3)
    print("| %s | %.0f | %.2f | %.4f | %.4f |"
          % (name, dofs, time, errors[-1] / math.sqrt(e0), position),
          flush=True)


def adaptive(interval, widening, criteria):
    return """subsection Mesh refinement
  set Refinement interval = %d
  set Maximum level = 2
  set Initial contact refinements = 2
  set Criteria = %s
  set Front widening = %g
end
""" % (interval, criteria, widening)


print("| mesh | mean DoFs | run time [s] | error | position [m] |")
print("|---|---|---|---|---|")
run("uniform-128", 128, "")
run("kelly-every-2", 32, adaptive(2, 0, "kelly velocity"))
run("kelly-every-8", 32, adaptive(8, 0, "kelly velocity"))
run("jump-every-8-widened", 32,
    adaptive(8, 1, "velocity jump, contact zone"))
run("jump-every-16-widened", 32,
    adaptive(16, 1, "velocity jump, contact zone"))
theta = """subsection Time integration
  set Numerical dissipation = 0.05
end
"""
serial = """subsection Mesh
  set Triangulation = serial
end
"""
run("jump-every-16-widened-serial", 32,
    adaptive(16, 1, "velocity jump, contact zone") + serial)
run("uniform-128-theta", 128, theta)
run("uniform-64-theta", 64, theta)
run("jump-every-16-widened-serial-theta", 32,
    adaptive(16, 1, "velocity jump, contact zone") + serial + theta)
run("jump-every-8-widened-serial-theta", 32,
    adaptive(8, 1, "velocity jump, contact zone") + serial + theta)
