#!/usr/bin/python3
"""The step matrix assembled or matrix-free ('Contact solver/Step matrix'),
per polynomial degree, on the 3D bar impact of benchmarks/scaling.py
(length 1 m, height 0.2 m, E = rho = 1, v0 = 1 m/s, N-CS++, lumped mass,
tau = h/2c with h the cell size, 8 free and 8 contact steps, no VTU): the
same number of nodes for every p (N = 120/p cells along, N/5 across, about
2.3e5 DoFs; --cells M sets 120 to M). For each p and each choice it prints
the DoFs, the set-up of the step operator (the timer sections 'setup: DoFs
and sparsity' and 'setup: step matrix and preconditioner'), the mean wall
time of a contact step, that time per DoF, CG iterations per contact step,
the preconditioner, and the peak resident set per DoF (/usr/bin/time -v;
it includes the libraries, about 165 MB); then, per p, the ratios
matrix-free / assembled measured in this run, and each contact step per DoF
against the assembled p = 1 step.
Usage, from the repository's top folder after tools/setup.sh:
    benchmarks/step_operator.py [build/dyncontact] [--cells M] [p ...]"""
import csv
import os
import re
import subprocess
import sys

arguments = sys.argv[1:]
cells_p1 = 120
if "--cells" in arguments:
    k = arguments.index("--cells")
    cells_p1 = int(arguments[k + 1])
    del arguments[k:k + 2]
executable = arguments[0] if arguments else "build/dyncontact"
degrees = [int(p) for p in arguments[1:]] or [1, 2, 3]
os.makedirs("results-step-operator", exist_ok=True)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
           OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def run(p, step_matrix):
    cells = cells_p1 // p
    tau = 0.5 / cells
    directory = "results-step-operator/bar3d-p%d-%s" % (p, step_matrix)
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
end
subsection Contact solver
  set Step matrix = %s
end
subsection Output
  set Write vtu = false
end
""" % (p, directory, cells, 8 * tau, tau, 16 * tau, step_matrix))
    result = subprocess.run(["/usr/bin/time", "-v", executable, prm], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, check=True)
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)",
                        result.stderr).group(1)) * 1024.0
    summary = open(directory + "/summary.txt").read()
    sections = {m.group(1).strip(): float(m.group(2))
                for m in re.finditer(r"^  (\S.*?)\s+([0-9.e+-]+) s\s+[0-9.]+ calls",
                                     summary, re.M)}
    preconditioner = re.search(r"^preconditioner: (\w+)", summary,
                               re.M).group(1)
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
                preconditioner=preconditioner, rss=rss / dofs / 1024.)


results = {}
print("%2s %12s %8s %9s %9s %12s %7s %7s %8s" %
      ("p", "step matrix", "DoFs", "set-up", "c. step", "us/(DoF st)",
       "CG/st", "prec.", "RSS/DoF"))
for p in degrees:
    for choice in ("assembled", "matrix-free"):
        r = run(p, choice)
        results[(p, choice)] = r
        print("%2d %12s %8d %8.3fs %8.3fs %12.2f %7.1f %7s %6.2fkB" %
              (p, choice, r["dofs"], r["setup"], r["step"], r["per_dof"],
               r["cg"], r["preconditioner"], r["rss"]), flush=True)

print("\nratios in this run (matrix-free / assembled), and the contact step "
      "per DoF against the assembled p = 1 step:")
print("%2s %8s %8s %8s %14s %14s" % ("p", "set-up", "c. step", "RSS/DoF",
                                     "assembled/p1", "matrix-free/p1"))
base = results.get((1, "assembled"))
for p in degrees:
    a, m = results[(p, "assembled")], results[(p, "matrix-free")]
    print("%2d %8.2f %8.2f %8.2f %14s %14s" %
          (p, m["setup"] / a["setup"], m["step"] / a["step"],
           m["rss"] / a["rss"],
           "%.2f" % (a["per_dof"] / base["per_dof"]) if base else "-",
           "%.2f" % (m["per_dof"] / base["per_dof"]) if base else "-"))
