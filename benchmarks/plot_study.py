#!/usr/bin/python3
"""Plots a study CSV (benchmarks/study.py) as three PNGs:
  <prefix>_work_precision.png  error against wall time, one curve per scheme
  <prefix>_tau.png             error against tau at the finest mesh level,
                               with the fitted rates in the legend
  <prefix>_critical.png        sum of meas Gamma* (eq. 40) against tau:
                               Assumption 4.7 holds where it stays bounded
Usage: benchmarks/plot_study.py study.csv prefix ["title"]"""
import options  # noqa: F401 (--help prints the docstring above)
import csv
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

rows = list(csv.DictReader(open(sys.argv[1])))
prefix = sys.argv[2]
title = sys.argv[3] if len(sys.argv) > 3 else ""
schemes = list(dict.fromkeys(r["scheme"] for r in rows))
finest = max(int(r["mesh_level"]) for r in rows)
styles = {"N-CI": "o-", "N-CS": "s--", "N-CS++": "^:"}


def fit(x, y):
    """Least-squares slope of log y over log x."""
    lx, ly = [math.log(v) for v in x], [math.log(v) for v in y]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    den = sum((a - mx) ** 2 for a in lx)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / den if den > 0 else float("nan")


fig, ax = plt.subplots(figsize=(6, 4.5))
for s in schemes:
    r = [x for x in rows if x["scheme"] == s]
    ax.loglog([float(x["wall_time"]) for x in r], [float(x["error_max"]) for x in r],
              styles.get(s, "o-"), label=s)
ax.set_xlabel("wall time [s]")
ax.set_ylabel("error in the energy norm (max over t)")
ax.set_title(title + " work-precision")
ax.legend()
ax.grid(True, which="both", alpha=0.3)
fig.tight_layout()
fig.savefig(prefix + "_work_precision.png", dpi=100)

fig, ax = plt.subplots(figsize=(6, 4.5))
for s in schemes:
    r = sorted([x for x in rows if x["scheme"] == s and int(x["mesh_level"]) == finest],
               key=lambda x: float(x["tau"]))
    if not r:
        continue
    tau = [float(x["tau"]) for x in r]
    err = [float(x["error_max"]) for x in r]
    rate = fit(tau, err) if len(r) > 1 else float("nan")
    ax.loglog(tau, err, styles.get(s, "o-"), label="%s (rate %.2f)" % (s, rate))
ax.set_xlabel("time step tau [s]")
ax.set_ylabel("error in the energy norm (max over t)")
ax.set_title(title + " error against tau, mesh level %d" % finest)
ax.legend()
ax.grid(True, which="both", alpha=0.3)
fig.tight_layout()
fig.savefig(prefix + "_tau.png", dpi=100)

fig, ax = plt.subplots(figsize=(6, 4.5))
for s in schemes:
    r = sorted([x for x in rows if x["scheme"] == s and int(x["mesh_level"]) == finest],
               key=lambda x: float(x["tau"]))
    ax.semilogx([float(x["tau"]) for x in r], [float(x["critical_measure_sum"]) for x in r],
                styles.get(s, "o-"), label=s)
ax.set_xlabel("time step tau [s]")
ax.set_ylabel("sum over steps of meas Gamma*")
ax.set_title(title + " Assumption 4.7: bounded as tau -> 0?")
ax.legend()
ax.grid(True, which="both", alpha=0.3)
fig.tight_layout()
fig.savefig(prefix + "_critical.png", dpi=100)
print("wrote %s_work_precision.png, %s_tau.png, %s_critical.png" % (prefix, prefix, prefix))
