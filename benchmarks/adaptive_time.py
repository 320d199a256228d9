#!/usr/bin/python3
"""Work-precision of 'Time step control = adaptive' against fixed tau on the
bar impact with an impact time off the time grid (g0 = 0.1037 m, v = 1 m/s,
E = rho = 1, N-CS++, lumped mass, VTU off): for each number of cells along
the bar, fixed tau = h/2c and h/4c, and adaptive tau (levels h/2c * 2^k from
h/16c to 4h/c) at a few tolerances. Prints one table row per run: DoFs,
steps, wall time of the time loop (from the summary: the loop alone, not the
start-up), the energy-norm error at T = 2.5 s and how far the first contact
step starts from the exact contact time; then, for each adaptive run, the
ratio of the fixed-tau error at the same loop time (interpolated log-log
between the fixed runs of its mesh and the next finer) to its own. Writes
doc/adaptive_time_work_precision.png if matplotlib is there.
Usage, from the repository's top folder after tools/setup.sh:
    benchmarks/adaptive_time.py [build/dyncontact] [cells,...] [tols]
e.g. benchmarks/adaptive_time.py build/dyncontact 160,320 0.01,0.003,0.001"""
import csv
import math
import os
import re
import subprocess
import sys

executable = sys.argv[1] if len(sys.argv) > 1 else "build/dyncontact"
cells = [int(x) for x in (sys.argv[2] if len(sys.argv) > 2 else "160,320").split(",")]
tols = [float(x) for x in (sys.argv[3] if len(sys.argv) > 3 else "0.01,0.003,0.001").split(",")]
g0 = 0.1037
os.makedirs("results-adaptive-time", exist_ok=True)


def run(nx, tau, adaptive_tol=None):
    name = "results-adaptive-time/nx%d_tau%g_%s" % (nx, tau, adaptive_tol or "fixed")
    control = ""
    if adaptive_tol is not None:
        control = ("  set Time step control = adaptive\n"
                   "  set Minimum time step = %.17g\n  set Maximum time step = %.17g\n"
                   "  set Time step tolerance = %g\n" % (tau / 8, tau * 8, adaptive_tol))
    prm = ("set Dimension = 2\nset Output directory = %s\n"
           "subsection Scene\n  set Name = bar impact\n  subsection Bar impact\n"
           "    set Length = 1\n    set Height = 0.1\n    set Impact velocity = 1\n"
           "    set Initial gap = %g\n    set Cells along length = %d\n  end\nend\n"
           "subsection Material\n  set Young's modulus = 1\n  set Poisson's ratio = 0\n"
           "  set Density = 1\nend\n"
           "subsection Time integration\n  set Scheme = N-CS++\n  set Time step = %.17g\n"
           "  set End time = 2.5\n  set Mass matrix = lumped\n%send\n"
           "subsection Output\n  set Write vtu = false\n  set Progress interval = 0\nend\n"
           % (name, g0, nx, tau, control))
    with open(name + ".prm", "w") as f:
        f.write(prm)
    out = subprocess.run([executable, name + ".prm"], capture_output=True, text=True)
    if out.returncode != 0:
        sys.exit(out.stdout + out.stderr)
    loop = float(re.search(r"of which the time loop ([0-9.e+-]+) s", out.stdout).group(1))
    rows = list(csv.DictReader(open(name + "/statistics.tsv"), delimiter="\t"))
    start = next(float(rows[i - 1]["time"]) for i in range(1, len(rows))
                 if float(rows[i]["active_nodes"]) > 0)
    return {"nx": nx, "dofs": int(float(rows[0]["dofs"])), "steps": len(rows) - 1,
            "loop": loop, "error": float(rows[-1]["error_energy_norm"]),
            "miss": abs(start - g0) / tau,
            "label": "fixed τ = h/%dc" % round(1 / (tau * nx)) if adaptive_tol is None
            else "adaptive, tol %g" % adaptive_tol}


results = []
for nx in cells:
    h2c = 1.0 / (2 * nx)
    results.append(run(nx, h2c))
    results.append(run(nx, h2c / 2))
    for tol in tols:
        results.append(run(nx, h2c, tol))

print("| cells along | DoFs | τ control | steps | time loop (s) | error at T "
      "| contact start − g0/v (in h/2c) |")
print("|---|---|---|---|---|---|---|")
for r in results:
    print("| %d | %d | %s | %d | %.3f | %.4g | %.3f |" % (
        r["nx"], r["dofs"], r["label"], r["steps"], r["loop"], r["error"], r["miss"]))

# the fixed tau = h/2c runs over the meshes: error against loop time
fixed = sorted([r for r in results if r["label"] == "fixed τ = h/2c"], key=lambda r: r["loop"])
print("\nadaptive against fixed τ = h/2c at the same time-loop cost "
      "(log-log interpolation between meshes; '-' outside their range):")
for r in results:
    if not r["label"].startswith("adaptive"):
        continue
    ratio = "-"
    for a, b in zip(fixed, fixed[1:]):
        if a["loop"] <= r["loop"] <= b["loop"]:
            s = math.log(r["loop"] / a["loop"]) / math.log(b["loop"] / a["loop"])
            e = math.exp(math.log(a["error"]) + s * math.log(b["error"] / a["error"]))
            ratio = "%.2f" % (e / r["error"])
    print("  %d cells, %s: fixed error / adaptive error = %s" % (r["nx"], r["label"], ratio))

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 4.5))
    for label in dict.fromkeys(r["label"] for r in results):
        pts = sorted([r for r in results if r["label"] == label], key=lambda r: r["loop"])
        ax.loglog([p["loop"] for p in pts], [p["error"] for p in pts], "o-", label=label)
    ax.set_xlabel("wall time of the time loop (s)")
    ax.set_ylabel("energy-norm error at T = 2.5 s")
    ax.set_title("bar impact, g0 = 0.1037 m (off the time grid), N-CS++")
    ax.legend(fontsize=8)
    ax.grid(True, which="both", alpha=0.3)
    fig.tight_layout()
    fig.savefig("doc/adaptive_time_work_precision.png", dpi=110)
    print("wrote doc/adaptive_time_work_precision.png")
except ImportError:
    pass
