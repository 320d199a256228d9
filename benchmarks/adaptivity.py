#!/usr/bin/python3
"""Adaptive versus uniform meshes (N-CS++), error against DoFs and against
run time, on the bar impact (error in the energy norm against the exact
solution, maximum over time) and on the Hertz drop (no exact solution: the
maximum over time of the difference of the contact force from a fine
uniform reference run, relative to the reference's peak force). Writes
doc/adaptivity.png and prints the table of doc/results.md.
Usage, from the repository's top folder after tools/setup.sh:
    benchmarks/adaptivity.py [build/dyncontact]"""
import options  # noqa: F401 (--help prints the docstring above)
import csv
import os
import subprocess
import sys
import time

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

executable = sys.argv[1] if len(sys.argv) > 1 else "build/dyncontact"
os.makedirs("results-adaptivity", exist_ok=True)


def run(name, text):
    prm = "results-adaptivity/%s.prm" % name
    with open(prm, "w") as f:
        f.write(text + "\nset Output directory = results-adaptivity/%s\n" % name)
        f.write("subsection Output\n  set Write vtu = false\nend\n")
        f.write("subsection Postprocess\n  subsection Error energy norm\n"
                "    set Interval = every step\n  end\nend\n")
    start = time.time()
    subprocess.run([executable, prm], check=True, stdout=subprocess.DEVNULL)
    wall = time.time() - start
    rows = list(csv.DictReader(open("results-adaptivity/%s/statistics.tsv" % name),
                               delimiter="\t"))
    return rows, wall


def adaptive(max_level, interval, criteria, refine, coarsen, minimum=0):
    return ("subsection Mesh refinement\n  set Refinement interval = %d\n"
            "  set Minimum level = %d\n  set Maximum level = %d\n"
            "  set Refine fraction = %g\n  set Coarsen fraction = %g\n"
            "  set Criteria = %s\n  set Initial contact refinements = %d\nend\n"
            % (interval, minimum, max_level, refine, coarsen, criteria, max_level))


def mean(rows, column):
    return sum(float(r[column]) for r in rows) / len(rows)


results = {}
# bar impact: coarse mesh of 10 cells along, tau = h_finest / 2
bar = open("prm/bar_impact.prm").read()
for kind in ["uniform", "adaptive"]:
    for level in [1, 2, 3]:
        tau = 1.0 / (10 * 2 ** level) / 2
        text = bar + "\nsubsection Scene\n  subsection Bar impact\n    set Cells along length = 10\n  end\nend\n"
        text += "subsection Time integration\n  set Time step = %g\nend\n" % tau
        if kind == "uniform":
            text += "subsection Mesh\n  set Initial global refinements = %d\nend\n" % level
        else:
            text += adaptive(level, 2, "kelly displacement, kelly velocity, contact zone", 0.3, 0.1)
        rows, wall = run("bar-%s-%d" % (kind, level), text)
        error = max(float(r["error_energy_norm"]) for r in rows)
        results.setdefault(("bar", kind), []).append((level, mean(rows, "dofs"), wall, error))

# Hertz drop: reference = uniform, two levels finer than the finest below
hertz = open("prm/hertz_drop.prm").read().replace("set End time  = 1", "set End time  = 0.4")
hertz += "\nsubsection Scene\n  subsection Hertz\n    set Contact zone refinements = 0\n  end\nend\n"


def force_history(rows):
    return [float(r["contact_force"]) for r in rows]


reference, _ = run("hertz-reference", hertz + "subsection Mesh\n  set Initial global refinements = 5\nend\n")
f_ref = force_history(reference)
peak = max(f_ref)
for kind in ["uniform", "adaptive"]:
    for level in [2, 3, 4]:
        text = hertz
        if kind == "uniform":
            text += "subsection Mesh\n  set Initial global refinements = %d\nend\n" % level
        else:
            text += "subsection Mesh\n  set Initial global refinements = 1\nend\n"
            text += adaptive(level, 2, "kelly velocity, contact zone", 0.02, 0.5, minimum=1)
        rows, wall = run("hertz-%s-%d" % (kind, level), text)
        error = max(abs(a - b) for a, b in zip(force_history(rows), f_ref)) / peak
        results.setdefault(("hertz", kind), []).append((level, mean(rows, "dofs"), wall, error))

print("| scene | mesh | finest level | mean DoFs | wall time [s] | error |")
print("| --- | --- | --- | --- | --- | --- |")
for (scene, kind), values in results.items():
    for level, dofs, wall, error in values:
        print("| %s | %s | %d | %.0f | %.2f | %.4f |" % (scene, kind, level, dofs, wall, error))

fig, axes = plt.subplots(2, 2, figsize=(10, 8))
for row, scene, label in [(0, "bar", "energy-norm error (max over t)"),
                          (1, "hertz", "contact force error / peak force")]:
    for kind, style in [("uniform", "o-"), ("adaptive", "s--")]:
        values = results[(scene, kind)]
        axes[row][0].loglog([v[1] for v in values], [v[3] for v in values], style, label=kind)
        axes[row][1].loglog([v[2] for v in values], [v[3] for v in values], style, label=kind)
    axes[row][0].set_xlabel("mean DoFs")
    axes[row][1].set_xlabel("wall time [s]")
    for ax in axes[row]:
        ax.set_ylabel(label)
        ax.set_title("%s impact" % ("bar" if scene == "bar" else "Hertz"))
        ax.legend()
        ax.grid(True, which="both", alpha=0.3)
fig.tight_layout()
fig.savefig("doc/adaptivity.png", dpi=100)
print("wrote doc/adaptivity.png")
