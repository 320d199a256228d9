#!/usr/bin/python3
"""Marking by an error tolerance over two decades: the Hertz drop of
prm/hertz_drop_adaptive.prm (to 1 s) with Mesh refinement/Error tolerance
delta = 0.4 to 0.002 and Maximum level 6, each compared at the output times
with the states of the uniform level-6 mesh (Reference solution; about
550 000 DoFs, the same tau). For each delta the script prints the largest
estimated error (the energy norm relative to sqrt(E), at the adaptations,
before they refine), the largest difference from the uniform level 6 in the
energy norm relative to sqrt(E(0)), the mean and largest DoFs, the wall
time less the comparisons with the reference states (timer section
"reference states"), and whether summary.txt says that the level limit
kept the tolerance from being met.

Usage, from the repository's top folder after tools/setup.sh (about 4
minutes on one core; the reference run about 3 of them):
    benchmarks/tolerance_decades.py [build/dyncontact]
        [--tolerances 0.4,0.2,0.1,0.05,0.02,0.01,0.004,0.002] [--level 6]"""
import options
import csv
import math
import os
import re
import subprocess
import sys

arguments = sys.argv[1:]
tolerances = options.take_option(
    arguments, "--tolerances", lambda v: [t for t in v.split(",") if t],
    ["0.4", "0.2", "0.1", "0.05", "0.02", "0.01", "0.004", "0.002"])
level = options.take_option(arguments, "--level", int, 6)
executable = os.path.abspath(arguments[0] if arguments else "build/dyncontact")
top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
work = os.path.abspath("results-tolerance-decades")
os.makedirs(work, exist_ok=True)
states = os.path.join(work, "reference-states")


def run(name, entries):
    prm = os.path.join(work, name + ".prm")
    with open(prm, "w") as f:
        f.write("include %s\n" %
                os.path.join(top, "prm", "hertz_drop_adaptive.prm"))
        f.write("set Output directory = %s\n" % os.path.join(work, name))
        f.write("subsection Output\n  set Write vtu = false\n"
                "  set Progress interval = 0\nend\n")
        f.write("subsection Checkpointing\n  set Interval in steps = 0\n"
                "  set Interval in minutes = 0\nend\n")
        f.write(entries)
    result = subprocess.run([executable, prm], capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("tolerance_decades: %s failed:\n%s%s" %
                 (name, result.stdout[-2000:], result.stderr[-2000:]))
    return result.stdout


def wall_time(name):
    # the run's wall time less its timer section "reference states"
    with open(os.path.join(work, name, "summary.txt")) as f:
        summary = f.read()
    wall = float(re.search(r"wall time: ([0-9.e+-]+) s", summary).group(1))
    states = re.search(r"reference states +([0-9.e+-]+) s", summary)
    return wall - (float(states.group(1)) if states else 0.)


def column(rows, name):
    return [float(r[name]) for r in rows
            if r.get(name) not in (None, "", "nan")]


run("uniform", "subsection Mesh\n  set Initial global refinements = %d\n"
    "end\nsubsection Mesh refinement\n  set Refinement interval = 0\n"
    "  set Initial contact refinements = 0\nend\n"
    "subsection Reference solution\n  set Write states = true\n"
    "  set Directory = %s\nend\n" % (level, states))
with open(os.path.join(work, "uniform", "statistics.tsv")) as f:
    uniform = list(csv.DictReader(f, delimiter="\t"))
scale = math.sqrt(column(uniform, "energy_total")[0])
print("uniform level %d: %d DoFs, %.3g s; sqrt(E(0)) = %.4g J^1/2/m^1/2" %
      (level, column(uniform, "dofs")[0], wall_time("uniform"), scale))
print("%-8s %10s %12s %10s %10s %10s  %s" %
      ("delta", "estimate", "difference", "mean DoFs", "max DoFs",
       "time (s)", "level limit"))
for delta in tolerances:
    name = "delta_" + delta
    run(name, "subsection Mesh refinement\n"
                 "  set Maximum level = %d\n  set Error tolerance = %s\nend\n"
                 "subsection Reference solution\n"
                 "  set Compare with states = true\n  set Directory = %s\n"
                 "end\n" % (level, delta, states))
    with open(os.path.join(work, name, "statistics.tsv")) as f:
        rows = list(csv.DictReader(f, delimiter="\t"))
    estimates = column(rows, "estimated_error")
    dofs = column(rows, "dofs")
    with open(os.path.join(work, name, "summary.txt")) as f:
        summary = f.read()
    print("%-8s %10.4f %12.4f %10.0f %10.0f %10.3g  %s" %
          (delta, max(estimates) if estimates else 0.,
           max(column(rows, "error_reference")) / scale,
           sum(dofs) / len(dofs), max(dofs),
           wall_time(name),
           "reached (NOT KEPT)" if "NOT KEPT" in summary else "-"))
