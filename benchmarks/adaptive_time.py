#!/usr/bin/python3
"""Work-precision of 'Time step control = adaptive' against fixed tau.

Bar problems (a prm with 'Cells along length': prm/bar_impact.prm or
prm/two_bars.prm; E = rho = v = 1): Initial gap = 0.1037 m, so that the
contact starts at t = 0.1037 s, off the time grid. For each number of cells
along the bar: fixed tau = h/2c and h/4c, and adaptive tau (levels
h/2c * 2^k from h/16c to 4h/c) at each tolerance; the error is
error_energy_norm (exact solution) at the end time.

Other prm (e.g. prm/hertz_drop.prm), on its own mesh: the numbers given are
fixed time steps; adaptive runs start at the prm's Time step with levels
from 1/8 to 8 times it; the error is error_reference at the end time,
against a reference run with a 16 times smaller fixed step than the
smallest given (same mesh).

Prints one table row per run: DoFs, steps, wall time of the time loop (from
the summary: the loop alone, not the start-up), the error at the end time,
and for the bars how far the first contact step starts from the exact
contact time (in h/2c); then, for each adaptive run, the ratio of the
fixed-tau error at the same loop time (interpolated log-log along the fixed
runs: tau = h/2c over the meshes, resp. over the given steps) to its own.
Writes doc/adaptive_time_<prm name>.png if matplotlib is there.
Usage, from the repository's top folder after tools/setup.sh:
    benchmarks/adaptive_time.py [build/dyncontact] [prm] [cells or taus]
        [tolerances] [Subsection/Entry=value ...]
(each Subsection/Entry=value is added to every run's input)
e.g. benchmarks/adaptive_time.py build/dyncontact prm/bar_impact.prm \\
         160,320 0.01,0.003,0.001
     benchmarks/adaptive_time.py build/dyncontact prm/hertz_drop.prm \\
         0.02,0.01,0.005 0.01,0.003,0.001 "Mesh/Initial global refinements=3"
"""
import options  # noqa: F401 (--help prints the docstring above)
import csv
import math
import os
import re
import subprocess
import sys

executable = sys.argv[1] if len(sys.argv) > 1 else "build/dyncontact"
base_file = sys.argv[2] if len(sys.argv) > 2 else "prm/bar_impact.prm"
sizes = [float(x) for x in (sys.argv[3] if len(sys.argv) > 3 else "160,320").split(",")]
tols = [float(x) for x in (sys.argv[4] if len(sys.argv) > 4 else "0.01,0.003,0.001").split(",")]
problem = os.path.splitext(os.path.basename(base_file))[0]
base = open(base_file).read()
for setting in sys.argv[5:]:
    path, value = setting.split("=", 1)
    *subsections, name = path.split("/")
    base += "".join("subsection %s\n" % x for x in subsections)
    base += "  set %s = %s\n" % (name, value) + "end\n" * len(subsections)
is_bar = re.search(r"(?m)^\s*set Cells along length\s*=", base) is not None
g0 = 0.1037
os.makedirs("results-adaptive-time", exist_ok=True)


def entry(name):
    return float(re.search(r"(?m)^\s*set %s\s*=\s*(\S+)" % name, base).group(1))


def run(name, settings, extra_time="", extra=""):
    """Runs base with 'set <key> = <value>' replaced for each of settings,
    extra_time added to 'Time integration' and extra appended; returns the
    statistics rows and the loop time."""
    name = "results-adaptive-time/" + name
    prm = base
    for key, value in [("Output directory", name)] + settings:
        prm, n = re.subn(r"(?m)^(\s*set %s\s*=).*$" % key, r"\g<1> " + value, prm)
        if n != 1:
            sys.exit("%s: no single 'set %s' line" % (base_file, key))
    prm = prm.replace("subsection Time integration\n",
                      "subsection Time integration\n" + extra_time, 1)
    # no output times inside the run: adaptive steps would end at them
    prm += ("subsection Output\n  set Write vtu = false\n  set Progress interval = 0\n"
            "  set Output interval = %.17g\nend\n" % entry("End time"))
    prm += extra
    with open(name + ".prm", "w") as f:
        f.write(prm)
    out = subprocess.run([executable, name + ".prm"], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(out.stdout + out.stderr)
    loop = float(re.search(r"of which the time loop ([0-9.e+-]+) s", out.stdout).group(1))
    return list(csv.DictReader(open(name + "/statistics.tsv"), delimiter="\t")), loop


def adaptive(tau, tol):
    return ("  set Time step control = adaptive\n"
            "  set Minimum time step = %.17g\n  set Maximum time step = %.17g\n"
            "  set Time step tolerance = %g\n" % (tau / 8, tau * 8, tol))


def row(rows, loop, size, label, error_column, miss):
    return {"size": size, "dofs": int(float(rows[0]["dofs"])), "steps": len(rows) - 1,
            "loop": loop, "error": float(rows[-1][error_column]), "miss": miss,
            "label": label}


results = []
if is_bar:
    for nx in [int(x) for x in sizes]:
        h2c = 1.0 / (2 * nx)
        for tau, tol in [(h2c, None), (h2c / 2, None)] + [(h2c, t) for t in tols]:
            label = ("fixed τ = h/%dc" % round(1 / (tau * nx)) if tol is None
                     else "adaptive, tol %g" % tol)
            rows, loop = run("%s_nx%d_tau%g_%s" % (problem, nx, tau, tol or "fixed"),
                             [("Initial gap", "%g" % g0), ("Cells along length", "%d" % nx),
                              ("Time step", "%.17g" % tau)],
                             adaptive(tau, tol) if tol else "")
            start = next(float(rows[i - 1]["time"]) for i in range(1, len(rows))
                         if float(rows[i]["active_nodes"]) > 0)
            results.append(row(rows, loop, nx, label, "error_energy_norm",
                               "%.3f" % (abs(start - g0) / h2c)))
    fixed = [r for r in results if r["label"] == "fixed τ = h/2c"]
    size_name, along = "cells along", "between meshes"
else:
    end = entry("End time")
    reference = ("subsection Reference solution\n  set Directory = %s\n"
                 "  set Interval = %.17g\n  set %%s = true\nend\n"
                 % (os.path.abspath("results-adaptive-time/%s_states" % problem), end))
    run("%s_reference" % problem, [("Time step", "%.17g" % (min(sizes) / 16))],
        extra=reference % "Write states")
    for tau in sizes:
        rows, loop = run("%s_tau%g_fixed" % (problem, tau), [("Time step", "%.17g" % tau)],
                         extra=reference % "Compare with states")
        results.append(row(rows, loop, tau, "fixed τ", "error_reference", "-"))
    tau = entry("Time step")
    for tol in tols:
        rows, loop = run("%s_tau%g_%g" % (problem, tau, tol), [("Time step", "%.17g" % tau)],
                         adaptive(tau, tol), reference % "Compare with states")
        results.append(row(rows, loop, tau, "adaptive, tol %g" % tol, "error_reference", "-"))
    fixed = [r for r in results if r["label"] == "fixed τ"]
    size_name, along = "τ (s)", "between the fixed steps"

print("| %s | DoFs | τ control | steps | time loop (s) | error at T "
      "| contact start − g0/v (in h/2c) |" % size_name)
print("|---|---|---|---|---|---|---|")
for r in results:
    print("| %g | %d | %s | %d | %.3f | %.4g | %s |" % (
        r["size"], r["dofs"], r["label"], r["steps"], r["loop"], r["error"], r["miss"]))

fixed = sorted(fixed, key=lambda r: r["loop"])
print("\nadaptive against fixed τ at the same time-loop cost (log-log "
      "interpolation %s; '-' outside their range):" % along)
for r in results:
    if not r["label"].startswith("adaptive"):
        continue
    ratio = "-"
    for a, b in zip(fixed, fixed[1:]):
        if a["loop"] <= r["loop"] <= b["loop"]:
            s = math.log(r["loop"] / a["loop"]) / math.log(b["loop"] / a["loop"])
            e = math.exp(math.log(a["error"]) + s * math.log(b["error"] / a["error"]))
            ratio = "%.2f" % (e / r["error"])
    print("  %s %g, %s: fixed error / adaptive error = %s"
          % (size_name, r["size"], r["label"], ratio))

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for label in dict.fromkeys(r["label"] for r in results):
        pts = sorted([r for r in results if r["label"] == label], key=lambda r: r["loop"])
        ax.loglog([p["loop"] for p in pts], [p["error"] for p in pts], "o-", label=label)
    ax.set_xlabel("wall time of the time loop (s)")
    ax.set_ylabel("energy-norm error at the end time")
    ax.set_title(problem + (", g0 = 0.1037 m (off the time grid)" if is_bar
                            else ", error against a reference run"))
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig("doc/adaptive_time_%s.png" % problem, dpi=110)
    print("wrote doc/adaptive_time_%s.png" % problem)
except ImportError:
    pass
