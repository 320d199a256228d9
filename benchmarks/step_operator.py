#!/usr/bin/python3
"""The step matrix assembled or matrix-free ('Contact solver/Step matrix'),
per polynomial degree, on the 3D bar impact of benchmarks/scaling.py
(length 1 m, height 0.2 m, E = rho = 1, v0 = 1 m/s, N-CS++, lumped mass,
tau = h/2c with h the cell size, 8 free and 8 contact steps, no VTU): the
same number of nodes for every p (N = 120/p cells along, N/5 across, about
2.3e5 DoFs; --cells M sets 120 to M; --tau-ratio R sets tau = R h/c, and
the run to 4 free and 4 contact steps if R > 1; --mass blended or
consistent sets Time integration/Mass matrix instead of lumped, --fraction
F its Consistent mass fraction, for blended; --assembled-preconditioner
P the assembled S's Preconditioner instead of automatic). For each p it runs the
assembled S ('Preconditioner = automatic': Jacobi, or AMG where S is far
from its mass), the matrix-free S with Jacobi and, for p >= 2, the
matrix-free S with the p-multigrid ('Preconditioner = multigrid'). For each
run it prints
the DoFs, the set-up of the step operator (the timer sections 'setup: DoFs
and sparsity' and 'setup: step matrix and preconditioner'), the mean wall
time of a contact step, that time per DoF, CG iterations per contact step,
the preconditioner, and the peak resident set per DoF (/usr/bin/time -v;
it includes the libraries, about 165 MB); then, per p, the ratios
matrix-free / assembled and multigrid / assembled measured in this run, and
each contact step per DoF against the assembled p = 1 step.
Usage, from the repository's top folder after tools/setup.sh:
    benchmarks/step_operator.py [build/dyncontact] [--cells M]
                                [--tau-ratio R] [--mass M] [--fraction F]
                                [--assembled-preconditioner P] [p ...]"""
import csv
import os
import re
import subprocess
import sys

from options import take_option

arguments = sys.argv[1:]
cells_p1 = take_option(arguments, "--cells", int, 120)
tau_ratio = take_option(arguments, "--tau-ratio", float, 0.5)
mass = take_option(arguments, "--mass", str, "lumped")
if mass not in ("lumped", "blended", "consistent"):
    sys.exit("step_operator: --mass must be lumped, blended or consistent")
fraction = take_option(arguments, "--fraction", float, None)
if fraction is not None and mass != "blended":
    sys.exit("step_operator: --fraction is for --mass blended")
assembled_preconditioner = take_option(arguments, "--assembled-preconditioner",
                                       str, "automatic")
if assembled_preconditioner not in ("automatic", "Jacobi", "AMG"):
    sys.exit("step_operator: --assembled-preconditioner must be automatic, "
             "Jacobi or AMG")
steps = 8 if tau_ratio <= 1 else 4
executable = arguments[0] if arguments else "build/dyncontact"
degrees = [int(p) for p in arguments[1:]] or [1, 2, 3]
os.makedirs("results-step-operator", exist_ok=True)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
           OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def run(p, step_matrix, preconditioner):
    cells = cells_p1 // p
    tau = tau_ratio / cells
    directory = "results-step-operator/bar3d-p%d-%s-%s-%g%s" % (
        p, step_matrix, preconditioner, tau_ratio,
        "" if mass == "lumped" else "-" + mass) + (
        "" if fraction is None else "-%g" % fraction)
    prm = directory + ".prm"
    with open(prm, "w") as f:
        f.write("""set Dimension = 3
set Polynomial degree = %d
set Output directory = %s
subsection Scene
  set Name = bar impact
  subsection Bar impact
    set Height = 0.2
    set Cells along length = %d
    set Initial gap = %.17g
  end
end
subsection Time integration
  set Scheme = N-CS++
  set Time step = %.17g
  set End time = %.17g
  set Mass matrix = %s
%send
subsection Contact solver
  set Step matrix = %s
  set Preconditioner = %s
end
subsection Output
  set Write vtu = false
end
""" % (p, directory, cells, steps * tau, tau, 2 * steps * tau, mass,
       "" if fraction is None else "  set Consistent mass fraction = %.17g\n" % fraction,
       step_matrix, preconditioner))
    result = subprocess.run(["/usr/bin/time", "-v", executable, prm], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, check=True)
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)",
                        result.stderr).group(1)) * 1024.0
    summary = open(directory + "/summary.txt").read()
    sections = {m.group(1).strip(): float(m.group(2))
                for m in re.finditer(r"^  (\S.*?)\s+([0-9.e+-]+) s\s+[0-9.]+ calls",
                                     summary, re.M)}
    used = re.search(r"^preconditioner: (\S+)", summary, re.M).group(1)
    rows = list(csv.DictReader(open(directory + "/statistics.tsv"),
                               delimiter="\t"))[1:]
    contact = [r for r in rows if float(r["active_nodes"]) > 0]
    dofs = float(rows[-1]["dofs"])
    step = sum(float(r["step_wall_time"]) for r in contact) / len(contact)
    return dict(dofs=dofs,
                setup=sections.get("setup: DoFs and sparsity", 0.) +
                sections.get("setup: step matrix and preconditioner", 0.),
                step=step, per_dof=step / dofs * 1e6,
                cg=sum(float(r["linear_iterations"]) for r in contact) /
                len(contact),
                preconditioner=used, rss=rss / dofs / 1024.)


choices = [("assembled", assembled_preconditioner), ("matrix-free", "automatic"),
           ("matrix-free", "multigrid")]
results = {}
print("tau = %g h/c, %s mass%s" % (tau_ratio, mass, "" if fraction is None
                                   else " (fraction %g)" % fraction))
print("%2s %12s %8s %9s %9s %12s %7s %11s %8s" %
      ("p", "step matrix", "DoFs", "set-up", "c. step", "us/(DoF st)",
       "CG/st", "prec.", "RSS/DoF"))
for p in degrees:
    for choice in choices:
        if choice[1] == "multigrid" and p < 2:
            continue
        r = run(p, *choice)
        results[(p, choice[1] if choice[1] == "multigrid" else choice[0])] = r
        print("%2d %12s %8d %8.3fs %8.3fs %12.2f %7.1f %11s %6.2fkB" %
              (p, choice[0], r["dofs"], r["setup"], r["step"], r["per_dof"],
               r["cg"], r["preconditioner"], r["rss"]), flush=True)

print("\nratios in this run (matrix-free with Jacobi and with the multigrid "
      "over assembled), and the contact step per DoF against the assembled "
      "p = 1 step:")
print("%2s %13s %8s %8s %8s %9s %8s %8s %14s %14s %14s" % (
    "p", "", "set-up", "c. step", "RSS/DoF", "MG set-up", "MG step",
    "MG RSS", "assembled/p1", "matrix-free/p1", "multigrid/p1"))
base = results.get((1, "assembled"))
for p in degrees:
    a, m = results[(p, "assembled")], results[(p, "matrix-free")]
    g = results.get((p, "multigrid"))
    print("%2d %13s %8.2f %8.2f %8.2f %9s %8s %8s %14s %14s %14s" %
          (p, "", m["setup"] / a["setup"], m["step"] / a["step"],
           m["rss"] / a["rss"],
           "%.2f" % (g["setup"] / a["setup"]) if g else "-",
           "%.2f" % (g["step"] / a["step"]) if g else "-",
           "%.2f" % (g["rss"] / a["rss"]) if g else "-",
           "%.2f" % (a["per_dof"] / base["per_dof"]) if base else "-",
           "%.2f" % (m["per_dof"] / base["per_dof"]) if base else "-",
           "%.2f" % (g["per_dof"] / base["per_dof"]) if g and base else "-"))
