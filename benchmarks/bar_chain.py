#!/usr/bin/python3
"""Runs the chain of bars of prm/bar_chain.prm (Newton's cradle: a striker
and K = 3 bars at rest) with N-CI, N-CS and N-CS++, prints for each pair the
interval in which it carries at least half the exact force rho c v0/2 H,
the bars' velocities at the end and the energy-norm error, and plots each
pair's mean contact pressure and each bar's mean velocity over time against
the exact solution (doc/bar_chain.png). Usage, from the repository's top
folder after tools/setup.sh:  benchmarks/bar_chain.py [build/dyncontact]"""
import options  # noqa: F401 (--help prints the docstring above)
import csv
import math
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

executable = sys.argv[1] if len(sys.argv) > 1 else "build/dyncontact"
base = open("prm/bar_chain.prm").read()
os.makedirs("results-bar-chain-schemes", exist_ok=True)
K, L, H, v0, g0, c = 3, 1.0, 0.1, 1.0, 0.1, 1.0
pressure = 0.5 * c * v0  # rho c v0 / 2
t0 = g0 / v0

fig, axes = plt.subplots(2, 2, figsize=(11, 7), sharex=True)
pressure_axes = {"N-CI": axes[0][0], "N-CS": axes[0][1], "N-CS++": axes[1][0]}
ax_v = axes[1][1]
colours = ["C0", "C1", "C2", "C3"]
for scheme, style in [("N-CI", "-"), ("N-CS", "--"), ("N-CS++", ":")]:
    ax_p = pressure_axes[scheme]
    directory = "results-bar-chain-schemes/" + scheme
    prm = directory + ".prm"
    with open(prm, "w") as f:
        f.write(base)
        f.write("\nset Output directory = %s\n" % directory)
        f.write("subsection Time integration\n  set Scheme = %s\nend\n" % scheme)
        f.write("subsection Output\n  set Write vtu = false\nend\n")
    subprocess.run([executable, prm], check=True, stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open(directory + "/statistics.tsv"), delimiter="\t"))
    t = [float(r["time"]) for r in rows]
    line = "%-7s" % scheme
    for k in range(1, K + 1):
        force = [float(r["contact_force_pair%d" % k]) for r in rows]
        pressed = [t[i] for i in range(len(t)) if force[i] >= 0.5 * pressure * H]
        line += "  pair %d: %.3f-%.3f (exact %.1f-%.1f)" % (
            k, pressed[0], pressed[-1], t0 + (k - 1) * L / c, t0 + (k + 1) * L / c)
        ax_p.plot(t, [f / H for f in force], "-", color=colours[k - 1],
                  linewidth=1.0, label="pair %d" % k)
    print(line)
    mass = L * H
    total = [float(r["momentum_x"]) for r in rows]
    velocities = []
    for b in range(1, K + 2):
        if b == 1:
            others = [sum(float(r["momentum_x_body%d" % j]) for j in range(2, K + 2))
                      for r in rows]
            v = [(p - o) / mass for p, o in zip(total, others)]
        else:
            v = [float(r["momentum_x_body%d" % b]) / mass for r in rows]
        velocities.append(v[-1])
        ax_v.plot(t, v, style, color=colours[b - 1], linewidth=1.2,
                  label=scheme if b == 1 else None)
    error = max(float(r["error_energy_norm"]) for r in rows
                if r["error_energy_norm"] != "nan")
    print("        velocities / v0 at T: %s; last bar's share of the energy %.3f; "
          "energy-norm error at most %.3f of sqrt(E(0))"
          % (", ".join("%.3f" % v for v in velocities),
             float(rows[-1]["energy_kinetic_body%d" % (K + 1)])
             / float(rows[0]["energy_total"]),
             error / math.sqrt(float(rows[0]["energy_total"]))))

T = t[-1]
for scheme, ax_p in pressure_axes.items():
    for k in range(1, K + 1):
        a, b = t0 + (k - 1) * L / c, t0 + (k + 1) * L / c
        ax_p.plot([0, a, a, b, b, T], [0, 0, pressure, pressure, 0, 0], "k-",
                  linewidth=0.6, label="exact" if k == 1 else None)
    ax_p.set_title("%s: mean contact pressure of each pair" % scheme)
    ax_p.set_ylabel("pressure [Pa]")
    ax_p.legend(fontsize=8)
# exact mean velocities: the striker v0 until t0, falling linearly to 0 by
# t0 + 2L/c (the pulse of length 2L leaves it); bar i rises to v0/2 over
# [t0 + (i-1) L/c, t0 + i L/c], stays, falls back over the next L/c; the last
# bar rises to v0/2, then to v0 by t0 + (K+1) L/c
for b in range(K + 1):
    a = t0 + (b - 1) * L / c
    if b == 0:
        ts, vs = [0, t0, t0 + 2 * L / c, T], [v0, v0, 0, 0]
    elif b < K:
        ts, vs = [0, a, a + L / c, a + 2 * L / c, a + 3 * L / c, T], [0, 0, v0 / 2, v0 / 2, 0, 0]
    else:
        ts, vs = [0, a, a + L / c, a + 2 * L / c, T], [0, 0, v0 / 2, v0, v0]
    ax_v.plot(ts, vs, "k-", linewidth=0.6, label="exact" if b == 0 else None)
ax_v.set_title("mean velocity of each bar (striker blue, bars 1-3\n"
               "orange, green, red)")
ax_v.set_ylabel("velocity [m/s]")
ax_v.legend(fontsize=8)
for ax in axes[1]:
    ax.set_xlabel("time t [s]")
fig.suptitle("Chain of 3 bars hit by a striker, 40 cells per bar, tau = h/(2c)")
fig.tight_layout()
fig.savefig("doc/bar_chain.png", dpi=110)
print("wrote doc/bar_chain.png")
