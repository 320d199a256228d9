#!/usr/bin/python3
"""Runs the stiff and extreme suite (prm/extreme/*.prm) with N-CI, N-CS and
N-CS++ and prints the table of doc/results.md: active-set iterations per
step (mean and maximum), the largest increase of E_total + dissipation
between steps (relative to the largest energy; positive: energy gained),
the maximum penetration, and the maximum contact pressure (relative to
rho c v0 for the bar cases).
Usage (from the top folder, after tools/setup.sh):
    benchmarks/extreme_table.py [build/dyncontact]"""
import options  # noqa: F401 (--help prints the docstring above)
import csv
import glob
import os
import re
import subprocess
import sys

executable = sys.argv[1] if len(sys.argv) > 1 else "build/dyncontact"
print("| case | scheme | active-set its (mean / max) | energy increase | max penetration [m] | max pressure |")
print("| --- | --- | --- | --- | --- | --- |")
for prm in sorted(glob.glob("prm/extreme/*.prm")):
    name = os.path.splitext(os.path.basename(prm))[0]
    text = open(prm).read()
    bar = "bar impact" in text
    v0 = float(re.search(r"Impact velocity\s*=\s*(\S+)", text).group(1)) if bar else 0
    for scheme in ["N-CI", "N-CS", "N-CS++"]:
        run = "prm/extreme/.%s-%s.prm" % (name, scheme)
        directory = "results-extreme/%s-%s" % (name, scheme)
        with open(run, "w") as f:
            f.write(text + "\nset Output directory = %s\n" % directory)
            f.write("subsection Time integration\n  set Scheme = %s\nend\n" % scheme)
        subprocess.run([executable, run], check=True, stdout=subprocess.DEVNULL)
        os.remove(run)
        rows = list(csv.DictReader(open(directory + "/statistics.tsv"), delimiter="\t"))
        its = [float(r["active_set_iterations"]) for r in rows[1:]]
        e = [float(r["energy_total"]) + float(r["dissipation_viscous"])
             + float(r.get("dissipation_numerical", 0.)) for r in rows]
        scale = max(abs(float(r["energy_total"])) for r in rows)
        growth = max(b - a for a, b in zip(e, e[1:])) / scale
        pen = max(float(r["max_penetration"]) for r in rows)
        p = max(float(r["max_contact_pressure"]) for r in rows)
        pressure = ("%.2f rho c v0" % (p / v0)) if bar and v0 > 0 else "%.3g Pa" % p
        print("| %s | %s | %.2f / %d | %.1e | %.1e | %s |"
              % (name, scheme, sum(its) / len(its), max(its), growth, pen, pressure))
