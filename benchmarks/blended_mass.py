#!/usr/bin/python3
"""The blended mass (Time integration/Mass matrix = blended) against the
lumped mass on the three scenes with a moving velocity jump and an exact
solution: the 2D bar impact (H = 0.25 m), the two bars (H = 0.1 m, n/10
and n/10 + 1 cells across, non-matching) and the chain of bars
(prm/bar_chain.prm: a striker and 3 bars, T = 5 s), p = 1, N-CS++,
tau = h/(2c), one core, and the mass beyond the consistent one (Jacobi)
with the longest tau up to 0.98 h/c that ends at End time in whole steps
and Consistent mass fraction 1/2 + (c tau/h)^2 (about 1.46). Prints per
scene and mesh the energy-norm error at
T over sqrt(E(0)), its rate from the mesh before, the position error (bar
and two bars: |d(T) - 0.3 m| of the mean displacement of the bar that
leaves; chain: the last bar's mean displacement's change from the mesh
before, the exact one is not printed by the program) and the run time (the
time loop less the sampled error norms).
Then on the bar: beta = 1/2 + (c tau/h)^2 for c tau/h up to 1/2 ... 0.99
(each the longest tau up to it in whole steps)
(128 and 256 cells along, with the pressure's overshoot and the CG
iterations); the fraction beta = 1/2 + (c tau/h)^2 against others at
tau = h/(4c), h/(2c) and h/(sqrt(2) c) with 64 cells along; beta = 0.75
with Numerical dissipation = 0.05 (128 cells); p = 2 (matrix-free S,
Jacobi) with the lumped, the blended (0.75) and the consistent mass at
tau = h/(4c) and h/(8c), 16 and 32 cells along.
Usage, from the repository's top folder after tools/setup.sh:
    benchmarks/blended_mass.py [build/dyncontact]"""
import options  # noqa: F401 (--help prints the docstring above)
import csv
import math
import os
import re
import subprocess
import sys

executable = sys.argv[1] if len(sys.argv) > 1 else "build/dyncontact"
work = "results-blended-mass"
os.makedirs(work, exist_ok=True)

scenes = {
    # key: prm, scene subsection, entries across, position column, exact
    "bar": ("prm/bar_impact.prm", "Bar impact",
            lambda n: "    set Height = 0.25\n", "mean_displacement_x", 0.3,
            [16, 32, 64, 128, 256]),
    "two bars": ("prm/two_bars.prm", "Two bars",
                 lambda n: "    set Cells across = %d\n    set Cells across body 2 = %d\n"
                 % (n // 10, n // 10 + 1), "mean_displacement_x_body2", 0.3,
                 [20, 40, 80, 160]),
    "chain": ("prm/bar_chain.prm", "Bar chain",
              lambda n: "    set Cells across = %d\n" % max(n // 10, 1),
              "mean_displacement_x_body4", None, [20, 40, 80, 160]),
}


def run(key, cells, mass, beta=None, courant=0.5, p=1, extra="", formula=False):
    """formula: tau is the longest step up to courant h/c that ends at End
    time in whole steps, and beta = 1/2 + (c tau/h)^2 with it."""
    prm_file, subsection, across, position, exact, _ = scenes[key]
    if formula:
        end = float(re.search(r"set End time\s*=\s*([0-9.e+-]+)",
                              open(prm_file).read()).group(1))
        steps = math.ceil(end * cells * p / courant - 1e-9)
        courant = end * cells * p / steps
        beta = 0.5 + courant ** 2
    name = "%s-%d-%s%s-%g-p%d%s" % (key.replace(" ", "-"), cells, mass,
                                   "" if beta is None else "-%g" % beta, courant, p,
                                   "-extra" if extra else "")
    directory = os.path.join(work, name)
    text = open(prm_file).read() + (
        "\nset Output directory = %s\n"
        "subsection Scene\n  subsection %s\n    set Cells along length = %d\n%s  end\nend\n"
        "subsection Time integration\n  set Time step = %.17g\n  set Mass matrix = %s\n"
        % (directory, subsection, cells, across(cells), courant / cells / p, mass))
    if beta is not None:
        text += "  set Consistent mass fraction = %.17g\n" % beta
    text += "end\nsubsection Output\n  set Write vtu = false\nend\n"
    text += "set Polynomial degree = %d\n" % p + extra
    if p >= 2:
        text += "subsection Contact solver\n  set Step matrix = matrix-free\nend\n"
    if beta is not None and beta > 1.:
        # 'automatic' takes AMG for a mass beyond the consistent one
        text += "subsection Contact solver\n  set Preconditioner = Jacobi\nend\n"
    with open(directory + ".prm", "w") as f:
        f.write(text)
    subprocess.run([executable, directory + ".prm"], check=True, stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open(directory + "/statistics.tsv"), delimiter="\t"))
    summary = open(directory + "/summary.txt").read()
    loop = float(re.search(r"of which the time loop ([0-9.e+-]+) s", summary).group(1))
    sampled = re.search(r"\n\s*sampled norms\s+([0-9.e+-]+) s", summary)
    errors = [float(r["error_energy_norm"]) for r in rows
              if not math.isnan(float(r["error_energy_norm"]))]
    return {"error": errors[-1] / math.sqrt(float(rows[0]["energy_total"])),
            "position": float(rows[-1][position]),
            "time": loop - (float(sampled.group(1)) if sampled else 0.),
            # (the bar's pressure over rho c v0 = 1)
            "overshoot": max(float(r["max_contact_pressure"]) for r in rows) - 1.,
            "cg": int(re.search(r"iterations: .* CG ([0-9]+)", summary).group(1))}


# beyond the consistent mass: tau up to 0.98 h/c in whole steps to End
# time, beta = 1/2 + (c tau/h)^2 (about 1.46)
long_courant = 0.98
variants = {"lumped": ("lumped", None, 0.5), "blended": ("blended", 0.75, 0.5),
            "beyond": ("blended", None, long_courant)}
print("| scene | cells along | lumped: error | rate | position | run time [s] "
      "| blended 0.75: error | rate | position | run time [s] "
      "| tau <= %g h/c, beta = 1/2 + (c tau/h)^2: error | rate | position "
      "| run time [s] |" % long_courant)
print("|---" * 14 + "|")
cg = {}
for key, (_, _, _, _, exact, cells_list) in scenes.items():
    before = {}
    for cells in cells_list:
        line = "| %s | %d |" % (key, cells)
        for mass in ["lumped", "blended", "beyond"]:
            matrix, beta, courant = variants[mass]
            r = run(key, cells, matrix, beta, courant, formula=mass == "beyond")
            rate = (math.log2(before[mass]["error"] / r["error"])
                    if mass in before else float("nan"))
            if exact is not None:
                position = abs(r["position"] - exact)
            else:
                position = (abs(r["position"] - before[mass]["position"])
                            if mass in before else float("nan"))
            line += " %.3g | %.2f | %.2g | %.3g |" % (r["error"], rate, position, r["time"])
            before[mass] = r
            if key == "bar" and cells == 128:
                cg[mass] = r["cg"]
        print(line, flush=True)
print("\nbar, 128 cells along: CG iterations in all (the projection's included): "
      "lumped %d, blended %d, beyond %d" % (cg["lumped"], cg["blended"], cg["beyond"]))

print("\nbar: beta = 1/2 + C^2 per C = c tau/h (above 1/sqrt(2) beyond the "
      "consistent mass, Jacobi): the energy-norm error at T, the pressure's "
      "overshoot, CG iterations in all, run time [s]\n")
print("| C | beta | 128 cells: error | overshoot | CG | run time | 256 cells: error "
      "| overshoot | CG | run time |")
print("|---" * 10 + "|")
for courant in [0.5, 1. / math.sqrt(2.), 0.9, 0.95, 0.98, 0.99]:
    line = "| %.3g | %.4g |" % (courant, 0.5 + courant ** 2)
    for cells in [128, 256]:
        r = run("bar", cells, "blended", None, courant, formula=True)
        line += " %.3g | %.3f | %d | %.3g |" % (r["error"], r["overshoot"], r["cg"], r["time"])
    print(line, flush=True)

print("\nbar, 64 cells along: the energy-norm error at T (the pressure's "
      "overshoot) per beta and tau\n")
print("| c tau/h | lumped | " + " | ".join("beta = %g" % b for b in [0.5625, 0.75, 1.]) + " |")
print("|---" * 5 + "|")
for courant in [0.25, 0.5, 1. / math.sqrt(2.)]:
    r = run("bar", 64, "lumped", courant=courant)
    line = "| %.3g | %.3g (%.2f) |" % (courant, r["error"], r["overshoot"])
    for beta in [0.5625, 0.75, 1.]:
        r = run("bar", 64, "blended", beta, courant)
        line += " %.3g (%.2f) |" % (r["error"], r["overshoot"])
    print(line, flush=True)

theta = run("bar", 128, "blended", 0.75,
            extra="subsection Time integration\n  set Numerical dissipation = 0.05\nend\n")
print("\nbar, 128 cells along, beta = 0.75 and Numerical dissipation = 0.05: "
      "error %.3g, position %.2g m" % (theta["error"], abs(theta["position"] - 0.3)))

print("\nbar, p = 2 (c tau/h with h/2, the node spacing, for h): the energy-norm "
      "error at T, run time [s]\n")
print("| c tau/h | cells along | lumped | blended 0.75 | consistent |")
print("|---" * 5 + "|")
for courant in [0.5, 0.25]:
    for cells in [16, 32]:
        line = "| %.3g | %d |" % (courant, cells)
        for mass in ["lumped", "blended", "consistent"]:
            r = run("bar", cells, mass, 0.75 if mass == "blended" else None, courant, p=2)
            line += " %.3g, %.3g |" % (r["error"], r["time"])
        print(line, flush=True)
