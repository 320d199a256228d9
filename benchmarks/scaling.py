#!/usr/bin/python3
"""Scaling of the 3D bar impact with the number of unknowns: a bar of
length 1 m and height 0.2 m (E = rho = 1, v0 = 1 m/s, N-CS++, lumped mass),
N cells along it (N/2^k coarse cells refined k times, k as large as N
and N/5 allow: p4est's coarse mesh should have few cells), tau = h/2c,
8 free steps and 8 contact steps (the gap is 8 tau v0), VTU written at
the start and the end. From each run's
summary.txt (timer sections) and statistics.tsv (step wall times, CG
iterations) and /usr/bin/time (largest resident set size) it prints one
table: DoFs, set-up (DoFs, constraints, sparsity, contact rows, solver
set-up), assembly, the wall time of a free and of a contact step, CG
iterations per contact step, the every-step diagnostics per step in % of
the mean of a free and a contact step, the shares of those diagnostics, of
the sampled error norms and of output in the time loop, one VTU write in
steps, and RSS per DoF; then the exponents of a power-law fit against
DoFs, and the 1-vs-2-rank ratio of the time loop at the size nearest to
2.6e5 DoFs. With --tau T every size steps with the same tau = T (the
preconditioner at fixed tau: the CG iterations should not grow with the
DoFs), and no 2-rank run is made. --preconditioner P sets 'Contact
solver/Preconditioner' (default: the program's, automatic).
Usage, from the repository's top folder after tools/setup.sh:
    benchmarks/scaling.py [build/dyncontact] [--tau T] [--preconditioner P]
                          [N1 N2 ...]"""
import csv
import math
import os
import re
import subprocess
import sys

from options import take_option

arguments = sys.argv[1:]
fixed_tau = take_option(arguments, "--tau", float)
preconditioner = take_option(arguments, "--preconditioner")
executable = arguments[0] if arguments else "build/dyncontact"
sizes = [int(n) for n in arguments[1:]] or [60, 80, 100, 120, 160, 200]
os.makedirs("results-scaling", exist_ok=True)
env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
           OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")


def coarse_mesh(cells):
    """(cells along the coarse bar, global refinements) for N cells along
    and round(N/5) across."""
    across = max(1, round(cells * 0.2))
    k = 0
    while cells % 2 ** (k + 1) == 0 and across % 2 ** (k + 1) == 0 and \
            max(1, round(cells // 2 ** (k + 1) * 0.2)) == across // 2 ** (k + 1):
        k += 1
    return cells // 2 ** k, k


def run(cells, ranks=1):
    name = "bar3d-%d-np%d" % (cells, ranks) + \
        ("-tau%g" % fixed_tau if fixed_tau else "") + \
        ("-" + preconditioner if preconditioner else "")
    tau = fixed_tau or 0.5 / cells
    coarse, refinements = coarse_mesh(cells)
    directory = "results-scaling/" + name
    prm = directory + ".prm"
    with open(prm, "w") as f:
        f.write("""set Dimension = 3
set Output directory = %s
subsection Scene
  set Name = bar impact
  subsection Bar impact
    set Height = 0.2
    set Cells along length = %d
    set Initial gap = %.17g
  end
end
subsection Mesh
  set Initial global refinements = %d
end
subsection Time integration
  set Scheme = N-CS++
  set Time step = %.17g
  set End time = %.17g
end
subsection Output
  set Output interval = %.17g
end
""" % (directory, coarse, 8 * tau, refinements, tau, 16 * tau, 16 * tau) +
                ("subsection Contact solver\n  set Preconditioner = %s\nend\n"
                 % preconditioner if preconditioner else ""))
    command = ["/usr/bin/time", "-v"]
    if ranks > 1:
        command += ["mpirun", "-np", str(ranks)]
    result = subprocess.run(command + [executable, prm], env=env,
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, check=True)
    rss = int(re.search(r"Maximum resident set size \(kbytes\): (\d+)",
                        result.stderr).group(1)) * 1024.0
    summary = open(directory + "/summary.txt").read()
    sections = {m.group(1).strip(): (float(m.group(2)), float(m.group(3)))
                for m in re.finditer(r"^  (\S.*?)\s+([0-9.e+-]+) s\s+([0-9.]+) calls",
                                     summary, re.M)}
    loop = float(re.search(r"of which the time loop ([0-9.e+-]+) s", summary).group(1))
    rows = list(csv.DictReader(open(directory + "/statistics.tsv"), delimiter="\t"))[1:]
    free = [float(r["step_wall_time"]) for r in rows if float(r["active_nodes"]) == 0]
    contact = [float(r["step_wall_time"]) for r in rows if float(r["active_nodes"]) > 0]
    cg = sum(float(r["linear_iterations"]) for r in rows) / len(rows)
    cg_contact = [float(r["linear_iterations"]) for r in rows
                  if float(r["active_nodes"]) > 0]
    dofs = float(rows[-1]["dofs"])
    section = lambda s: sections.get(s, (0.0, 0))[0]
    setup_parts = {s: t for s, (t, calls) in sections.items()
                   if s.startswith("setup")}
    return dict(dofs=dofs, setup=sum(setup_parts.values()) + section("contact rows"),
                setup_parts=setup_parts,
                assembly=section("assembly"),
                free=sum(free) / max(len(free), 1),
                contact=sum(contact) / max(len(contact), 1), cg=cg,
                cg_contact=sum(cg_contact) / max(len(cg_contact), 1),
                diagnostics=section("diagnostics") / loop,
                diagnostics_per_step=section("diagnostics") / (len(rows) + 1),
                norms=section("sampled norms") / loop,
                output=section("output") / loop,
                write=section("output") / max(sections.get("output", (0, 1))[1], 1),
                rss=rss, loop=loop)


def fit(xs, ys):
    lx = [math.log(x) for x in xs]
    ly = [math.log(max(y, 1e-12)) for y in ys]
    mx, my = sum(lx) / len(lx), sum(ly) / len(ly)
    return sum((a - mx) * (b - my) for a, b in zip(lx, ly)) / \
        sum((a - mx) ** 2 for a in lx)


results = []
print("%9s %8s %8s %8s %8s %7s %8s %7s %7s %7s %9s %8s" %
      ("DoFs", "set-up", "assembly", "free", "contact", "CG/cst",
       "diagn/st", "diagn.", "norms", "output", "write/st", "RSS/DoF"))
for n in sizes:
    r = run(n)
    results.append(r)
    step = 0.5 * (r["free"] + r["contact"])
    print("%9d %7.2fs %7.2fs %7.3fs %7.3fs %7.1f %7.1f%% %6.1f%% %6.1f%% "
          "%6.1f%% %9.2f %6.2fkB" %
          (r["dofs"], r["setup"], r["assembly"], r["free"], r["contact"],
           r["cg_contact"], 100 * r["diagnostics_per_step"] / step,
           100 * r["diagnostics"], 100 * r["norms"], 100 * r["output"],
           r["write"] / step, r["rss"] / r["dofs"] / 1e3), flush=True)
    print("          set-up: " + ", ".join(
        "%s %.2f s" % (name[len("setup: "):] if name != "setup" else name, t)
        for name, t in sorted(r["setup_parts"].items())), flush=True)
if len(results) < 2:
    sys.exit(0)
dofs = [r["dofs"] for r in results]
print("exponents against DoFs: set-up %.2f, assembly %.2f, free step %.2f, "
      "contact step %.2f, CG per contact step %.2f" %
      (fit(dofs, [r["setup"] for r in results]),
       fit(dofs, [r["assembly"] for r in results]),
       fit(dofs, [r["free"] for r in results]),
       fit(dofs, [r["contact"] for r in results]),
       fit(dofs, [r["cg_contact"] for r in results])))
last = results[-1]
print("at %d DoFs: set-up + assembly = %.1f mean steps (%.1f contact steps)" %
      (last["dofs"], (last["setup"] + last["assembly"]) /
       (0.5 * (last["free"] + last["contact"])),
       (last["setup"] + last["assembly"]) / last["contact"]))
if fixed_tau:
    sys.exit(0)
nearest = min(sizes, key=lambda n: abs(results[sizes.index(n)]["dofs"] - 2.6e5))
one = results[sizes.index(nearest)]
two = run(nearest, 2)
print("1 vs 2 ranks at %d DoFs: time loop %.2f s vs %.2f s, speed-up %.2f" %
      (one["dofs"], one["loop"], two["loop"], one["loop"] / two["loop"]))
