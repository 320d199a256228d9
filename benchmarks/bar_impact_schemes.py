#!/usr/bin/python3
"""Runs the bar impact of prm/bar_impact.prm with N-CI, N-CS and N-CS++ and
plots the contact pressure over time against the exact rho c v0
(doc/bar_impact_pressure.png). Usage, from the repository's top folder after
tools/setup.sh:  benchmarks/bar_impact_schemes.py [build/dyncontact]"""
import options  # noqa: F401 (--help prints the docstring above)
import csv
import os
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

executable = sys.argv[1] if len(sys.argv) > 1 else "build/dyncontact"
base = open("prm/bar_impact.prm").read()
os.makedirs("results-schemes", exist_ok=True)

fig, ax = plt.subplots(figsize=(8, 4.5))
for scheme, style in [("N-CI", "-"), ("N-CS", "--"), ("N-CS++", ":")]:
    directory = "results-schemes/" + scheme
    prm = directory + ".prm"
    with open(prm, "w") as f:
        f.write(base)
        f.write("\nset Output directory = %s\n" % directory)
        f.write("subsection Time integration\n  set Scheme = %s\nend\n" % scheme)
        f.write("subsection Output\n  set Write vtu = false\nend\n")
    subprocess.run([executable, prm], check=True, stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open(directory + "/statistics.tsv"), delimiter="\t"))
    t = [float(r["time"]) for r in rows]
    p = [float(r["max_contact_pressure"]) for r in rows]
    print("%-7s max pressure / (rho c v0) = %.3f, energy after release / before = %.4f"
          % (scheme, max(p), float(rows[-1]["energy_total"]) / float(rows[0]["energy_total"])))
    ax.plot(t, p, style, label=scheme, linewidth=1.5)

ax.plot([0, 0.1, 0.1, 2.1, 2.1, 2.5], [0, 0, 1, 1, 0, 0], "k-", linewidth=0.8,
        label="exact")
ax.set_xlabel("time t [s]")
ax.set_ylabel("contact pressure [Pa]  (rho c v0 = 1)")
ax.set_title("Bar impact, 40 cells, tau = h/(2c), lumped mass")
ax.legend()
fig.tight_layout()
fig.savefig("doc/bar_impact_pressure.png", dpi=110)
print("wrote doc/bar_impact_pressure.png")
