#!/usr/bin/python3
"""Loads and supports given as functions of t, against exact answers, and
what a load that changes in time costs per step.

1. A bar [0, 10] x [0, 1] m (E = 100 Pa, rho = 1 kg/m^3, nu = 0: c = 10
   m/s) pushed at its left end with v = 0.01 m/s (Scene/Gmsh/Prescribed
   displacements = 12: v*t, 0 on a roller): the end's force against the 1D
   characteristics' rho c v H, on 40, 80 and 160 cells along (tau = h/2c).
2. A column [0, 1] x [0, 2] on rollers, viscous, its top pressed by p(t) =
   p0 min(t/0.5, 1) (Scene/Gmsh/Pressures): the mean vertical displacement
   against the static solution -p0/(lambda + 2 mu), and the energy balance.
3. Cost: the column of 2., elastic, 128 x 256 cells, under a constant
   pressure, a ramped one, and a ramped body force (evaluated in every
   cell at every step); the time loop's wall time per step of each, the
   least of three runs.

Writes doc/loads_and_motion.png and prints the figures of doc/results.md.
Usage, from the repository's top folder after tools/setup.sh:
    benchmarks/loads_and_motion.py [build/dyncontact]"""
import options  # noqa: F401 (--help prints the docstring above)
import csv
import os
import re
import subprocess
import sys

import matplotlib

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "prm", "meshes"))
import msh_blocks  # noqa: E402

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

executable = sys.argv[1] if len(sys.argv) > 1 else "build/dyncontact"
work = "results-loads-and-motion"
os.makedirs(work, exist_ok=True)


def write_block(file, x1, y1, nx, ny):
    """A block [0, x1] x [0, y1] of nx x ny cells: cells 1, bottom 10, top
    11, left 12, right 13."""
    msh_blocks.write(file, [dict(x0=0.0, x1=x1, y0=0.0, y1=y1, nx=nx, ny=ny, cells=1,
                                 bottom=10, top=11, left=12, right=13)])


def run(name, mesh, scene, material, tau, end):
    directory = os.path.join(work, name)
    prm = os.path.join(work, name + ".prm")
    with open(prm, "w") as out:
        out.write("set Dimension = 2\nset Output directory = %s\n" % os.path.abspath(directory))
        out.write("subsection Scene\n  set Name = gmsh\n  subsection Gmsh\n")
        out.write("    set Mesh file = %s\n%s  end\nend\n" % (os.path.abspath(mesh), scene))
        out.write("subsection Material\n%send\n" % material)
        out.write("subsection Time integration\n  set Time step = %g\n  set End time = %g\nend\n"
                  % (tau, end))
        out.write("subsection Output\n  set Write vtu = false\nend\n")
    subprocess.run([executable, prm], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(directory, "statistics.tsv")) as f:
        rows = list(csv.DictReader(f, delimiter="\t"))
    with open(os.path.join(directory, "summary.txt")) as f:
        summary = f.read()
    loop = float(re.search(r"of which the time loop ([0-9.e+-]+) s", summary).group(1))
    return rows, loop


def column(rows, name):
    return [float(r[name]) for r in rows]


figure, (left, right) = plt.subplots(1, 2, figsize=(11, 4))

# 1. the pushed bar
print("bar pushed at v = 0.01 m/s: the end's force, exact rho c v H = 0.1 N/m")
for cells in (40, 80, 160):
    mesh = os.path.join(work, "bar-%d.msh" % cells)
    write_block(mesh, 10.0, 1.0, cells, max(1, cells // 20))
    h = 10.0 / cells
    rows, _ = run("bar-%d" % cells, mesh,
                  "    set Dirichlet tags = 12: x\n"
                  "    set Prescribed displacements = 12: 0.01*t, 0\n",
                  "  set Young's modulus = 100\n", h / 20.0, 0.9)
    t, force = column(rows, "time"), column(rows, "prescribed_force_x")
    mean = sum(force[1:]) / (len(force) - 1)
    ripple = max(abs(f - 0.1) for f, s in zip(force[1:], t[1:]) if s > 0.2)
    balance = max(abs(b) for b in column(rows, "energy_balance"))
    print("  %3d cells: mean force %.5f N/m, largest deviation after t = 0.2 s %.4f, "
          "W_D %.4e J/m (exact %.4e), |energy_balance| <= %.1e J/m"
          % (cells, mean, ripple, float(rows[-1]["work_prescribed"]),
             0.1 * 0.01 * t[-1], balance))
    left.plot(t, force, label="%d cells along" % cells)
left.axhline(0.1, color="k", linestyle="--", label="ρcvH (1D characteristics)")
left.set_xlabel("t (s)")
left.set_ylabel("force of the pushed end (N/m)")
left.set_title("bar pushed at v = 0.01 m/s")
left.legend()

# 2. the column under a ramped pressure
mesh = os.path.join(work, "column.msh")
write_block(mesh, 1.0, 2.0, 4, 8)
material = ("  set Young's modulus = 100\n  set Poisson's ratio = 0.3\n"
            "  set Viscous shear modulus = 5\n  set Viscous Lame parameter = 5\n")
rows, _ = run("column", mesh,
              "    set Dirichlet tags = 10: y, 12: x, 13: x\n"
              "    set Pressures = 11: min(t/0.5, 1)\n", material, 0.01, 3.0)
lam, mu = 100 * 0.3 / (1.3 * 0.4), 100 / 2.6
static = -1.0 / (lam + 2 * mu)
t, mean = column(rows, "time"), column(rows, "mean_displacement_y")
print("column under p(t) = min(t/0.5, 1) Pa: mean u_y at t = 3 s %.8f m, static %.8f m; "
      "|energy_balance| <= %.1e J/m, W_load = %.5f J/m"
      % (mean[-1], static, max(abs(b) for b in column(rows, "energy_balance")),
         float(rows[-1]["work_load_change"])))
right.plot(t, mean, label="mean u_y")
right.axhline(static, color="k", linestyle="--", label="static −p₀/(λ+2μ)")
right.set_xlabel("t (s)")
right.set_ylabel("mean vertical displacement (m)")
right.set_title("column on rollers, pressure ramped in 0.5 s")
right.legend()
figure.tight_layout()
figure.savefig("doc/loads_and_motion.png", dpi=100)

# 3. what a load that changes in time costs
mesh = os.path.join(work, "column-fine.msh")
write_block(mesh, 1.0, 2.0, 128, 256)
elastic = "  set Young's modulus = 100\n  set Poisson's ratio = 0.3\n"
times = {}
for name, loads in (("constant pressure", "    set Pressures = 11: 1\n"),
                    ("ramped pressure", "    set Pressures = 11: min(t/0.5, 1)\n"),
                    ("ramped body force", "    set Pressures = 11: 1\n"
                                          "    set Body force = 0; -min(t/0.5, 1)\n")):
    # (the least of three runs: the machine's noise is of the order of the
    # differences)
    times[name] = min(run("cost-" + name.replace(" ", "-"), mesh,
                          "    set Dirichlet tags = 10: y, 12: x, 13: x\n" + loads,
                          elastic, 0.001, 0.05)[1] for _ in range(3)) / 50
print("column of 128 x 256 cells (66 306 DoFs), elastic, 50 steps: time loop per step " +
      ", ".join("%.1f ms with the %s" % (1e3 * v, k) for k, v in times.items()) +
      " (ratios %.2f and %.2f)" % (times["ramped pressure"] / times["constant pressure"],
                                   times["ramped body force"] / times["constant pressure"]))
