#!/usr/bin/python3
"""Error against run time (the frontier), per scene and per polynomial degree
p = 1, 2, 3, on uniform and adaptive meshes, N-CS++, one core.

Run time is the time loop of summary.txt without its 'sampled norms' (the
error's own integration), so that a run is timed as a user would run it.

Scenes and what is measured (errors relative, except times and positions):
- bar: the 2D bar impact of prm/bar_impact.prm with H = 0.25 m to T = 2.5 s,
  against the exact solution. tau = h/(2 p c) with h the finest cell along
  the bar. Energy-norm error at T over sqrt(E(0)) (and its maximum over the
  output times), position error |d(T) - 0.3 m| of the mean displacement
  (the bar left the wall at 2.1 s with v0), the error of the release time
  (exact 2.1 s; the contact interval's start is t = 0.1 s to tau for every
  run), the pressure overshoot max p / (rho c v0) - 1 and the ripple
  max |p / (rho c v0) - 1| over the middle half of the contact, [0.6, 1.6] s.
  Both bars also run the uniform meshes with Time integration/Numerical
  dissipation = 0.05 (doc/algorithms.md), the dashed lines, and for p = 1
  with Mass matrix = blended (Consistent mass fraction 0.75 = 1/2 +
  (c tau/h)^2, the dispersion-reduced mass), the dash-dotted lines, up to
  twice the finest mesh's cells; and with the longest tau up to 0.98 h/c
  that ends at T in whole steps and the fraction 1/2 + (c tau/h)^2 (about
  1.46, a mass beyond the consistent one, Jacobi), the
  dotted lines, up to 448 cells along (the bar) and 160 (the two bars).
- two bars: prm/two_bars.prm (H = 0.1 m) to T = 2.5 s, exact solution; the
  same measures, the position of the second bar; square cells, n/10 across
  the first bar and n/10 + 1 across the second (non-matching) for n along.
- hertz: the 2D Hertz drop of prm/hertz_drop.prm to t = 0.6 s (no exact
  solution): against a uniform reference run with p = 2 and one global
  refinement more than the finest p = 2 run, same tau = 0.01 s (the spatial
  error): the largest difference of the contact force from the reference's
  over time relative to its peak, the position error of the falling body at
  T relative to its largest displacement in the reference, the peak force's
  error. The load keeps the bodies in contact: no release time.
- ball_drop: the 3D ball drop of prm/ball_drop_adaptive.prm (to 1.5 s,
  tau = 0.02 s) in the same way, p = 1 and 2 at 1 and 2 global
  refinements and adaptive up to 2, against p = 1 at 3 global refinements
  (1.2e5 DoFs), with the release-time error.
Adaptive meshes: the coarse mesh of the uniform run two levels coarser (one
for the two bars, whose coarse mesh across would be less than a cell),
refined up to the same finest level, every 2 steps (refine 20 %, coarsen
30 %, the defaults), by the Kelly or the recovery indicator of the
velocity; the Hertz drop and the ball drop as in benchmarks/adaptivity.py
(one global refinement, Kelly of the velocity on 2 % and the contact zone,
half of the cells coarsened), every 2 and every 16 steps, and every 16
steps from the coarse mesh (no global refinement, Minimum level 0: rows
"from level 0"). p >= 2 runs apply S matrix-free (Contact solver/Step matrix =
matrix-free, Jacobi), p = 1 runs assemble it.

The crossings of 0.10 and 0.05 count only where the error stays below on
every slower run of the variant (on the meshes run). Run times differ
between machines of the same kind (by a factor of 2 for the bar's runs on
2026-12-01, doc/results.md): compare runs of one machine.

Writes doc/work_precision_<scene>.png and prints the tables of
doc/results.md. Usage, from the repository's top folder after tools/setup.sh:
    benchmarks/work_precision.py [build/dyncontact] [scene ...]"""
import options  # noqa: F401 (--help prints the docstring above)
import csv
import math
import os
import re
import subprocess
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

executable = sys.argv[1] if len(sys.argv) > 1 else "build/dyncontact"
only = sys.argv[2:]
work = "results-work-precision"
os.makedirs(work, exist_ok=True)


def run(name, text):
    """Runs one prm (text), returns its statistics rows and summary."""
    directory = os.path.join(work, name.replace(" ", "-"))
    prm = directory + ".prm"
    with open(prm, "w") as f:
        f.write(text + "\nset Output directory = %s\n" % directory)
        f.write("subsection Output\n  set Write vtu = false\nend\n")
    subprocess.run([executable, prm], check=True, stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open(directory + "/statistics.tsv"), delimiter="\t"))
    summary = open(directory + "/summary.txt").read()
    return rows, summary


def run_time(summary):
    """Time loop without the sampled norms (s)."""
    loop = float(re.search(r"of which the time loop ([0-9.e+-]+) s", summary).group(1))
    sampled = re.search(r"\n\s*sampled norms\s+([0-9.e+-]+) s", summary)
    return loop - (float(sampled.group(1)) if sampled else 0.)


def contact_intervals(summary):
    line = re.search(r"contact intervals: (.*)", summary).group(1)
    return [(float(a), float(b)) for a, b in
            re.findall(r"\[([0-9.e+-]+), ([0-9.e+-]+)\]", line)]


def column(rows, name):
    return [float(r[name]) for r in rows]


def mean(values):
    return sum(values) / len(values)


def scene_prm(base, scene, entries):
    return base + "\nsubsection Scene\n  subsection %s\n%s  end\nend\n" % (
        scene, "".join("    set %s = %s\n" % e for e in entries))


def mesh_prm(p, tau, global_refinements=None, adaptive=None, interval=2, theta=0.,
             mass="lumped", beta=None):
    text = "set Polynomial degree = %d\n" % p
    if p >= 2:
        # the matrix-free S with Jacobi: cheaper than the assembled S for
        # p >= 2 (benchmarks/step_operator.py), the same results
        text += "subsection Contact solver\n  set Step matrix = matrix-free\nend\n"
    if beta is not None and beta > 1.:
        # Jacobi: 'automatic' takes AMG for a mass beyond the consistent
        # one, about twice the time here
        text += "subsection Contact solver\n  set Preconditioner = Jacobi\nend\n"
    text += ("subsection Time integration\n  set Time step = %.17g\n"
             "  set Numerical dissipation = %g\n"
             "  set Mass matrix = %s\n" % (tau, theta, mass))
    if beta is not None:
        text += "  set Consistent mass fraction = %.17g\n" % beta
    text += "end\n"
    if global_refinements is not None:
        text += "subsection Mesh\n  set Initial global refinements = %d\nend\n" % global_refinements
    if adaptive:
        text += ("subsection Mesh refinement\n  set Refinement interval = %d\n"
                 % interval)
        text += ("  set Maximum level = %d\n  set Minimum level = %d\n"
                 "  set Initial contact refinements = %d\n"
                 "  set Criteria = %s\n  set Refine fraction = %g\n"
                 "  set Coarsen fraction = %g\nend\n" % adaptive)
    return text


results = {}  # scene -> list of dicts
# the bars also run uniform meshes with this Time integration/Numerical
# dissipation
dissipation = 0.05
dissipative = "uniform theta = %g" % dissipation
# and p = 1 with the blended mass (its default fraction, 1/2 + (c tau/h)^2
# at tau = h/(2c))
blended = "uniform blended"
# and p = 1 with tau = 0.98 h/c and the fraction 1/2 + (c tau/h)^2 = 1.4604,
# beyond the consistent mass, where the trapezoidal rule's and the mass's
# phase errors nearly cancel to all orders (exactly at c tau/h = 1)
courant_long = 0.98
blended_long = "uniform blended, tau = %g h/c" % courant_long


def bar_measures(rows, summary, position_column):
    e0 = float(rows[0]["energy_total"])
    errors = [(float(r["time"]), float(r["error_energy_norm"])) for r in rows
              if not math.isnan(float(r["error_energy_norm"]))]
    intervals = contact_intervals(summary)
    pressure = column(rows, "max_contact_pressure")
    times = column(rows, "time")
    plateau = [p for t, p in zip(times, pressure) if 0.6 <= t <= 1.6]
    return {"error": errors[-1][1] / math.sqrt(e0),
            "error max": max(e for _, e in errors) / math.sqrt(e0),
            "position": abs(float(rows[-1][position_column]) - 0.3),
            "release": abs(intervals[-1][1] - 2.1) if intervals else float("nan"),
            "intervals": len(intervals),
            "overshoot": max(pressure) - 1.,
            "ripple": max(abs(p - 1.) for p in plateau)}


def bar_scene(key, base, scene, cells_list, long_cells, position_column, across, levels,
              criteria):
    """across(cells along) -> scene entries of the cells across."""
    def entries(cells):
        return [("Cells along length", cells)] + across(cells)

    for p in [1, 2, 3]:
        # uniform meshes, then the same with numerical dissipation
        # (doc/algorithms.md)
        # (theta, mass, c tau/h, name, suffix, cells along)
        variants = [(0., "lumped", 0.5, "uniform", "", cells_list[p]),
                    (dissipation, "lumped", 0.5, dissipative,
                     "-theta-%g" % dissipation, cells_list[p])]
        if p == 1:
            variants.append((0., "blended", 0.5, blended, "-blended",
                             cells_list[p] + [2 * cells_list[p][-1]]))
            variants.append((0., "blended", courant_long, blended_long,
                             "-blended-%g" % courant_long, long_cells))
        for theta, mass, courant, mesh, suffix, cells_of_variant in variants:
            for cells in cells_of_variant:
                tau, ratio = courant / cells / p, courant
                if mesh == blended_long:
                    # the longest tau up to courant h/c that ends at T =
                    # 2.5 s in whole steps (h/2c does)
                    tau = 2.5 / math.ceil(2.5 / tau - 1e-9)
                    ratio = tau * cells * p
                rows, summary = run("%s-p%d-uniform-%d%s" % (key, p, cells, suffix),
                                    scene_prm(base, scene, entries(cells)) +
                                    mesh_prm(p, tau, theta=theta, mass=mass,
                                             beta=0.5 + ratio ** 2
                                             if mass == "blended" else None))
                results.setdefault(key, []).append(dict(
                    p=p, mesh=mesh, finest=cells, dofs=mean(column(rows, "dofs")),
                    time=run_time(summary), **bar_measures(rows, summary, position_column)))
        cells = cells_list[p][-1]
        for name, crit in criteria:
            tau = 1. / cells / (2. * p)
            coarse = entries(cells // 2 ** levels)
            rows, summary = run("%s-p%d-%s-%d" % (key, p, name, cells),
                                scene_prm(base, scene, coarse) +
                                mesh_prm(p, tau, adaptive=(levels, 0, levels, crit, 0.2, 0.3)))
            results.setdefault(key, []).append(dict(
                p=p, mesh=name, finest=cells, dofs=mean(column(rows, "dofs")),
                time=run_time(summary), **bar_measures(rows, summary, position_column)))


bar = open("prm/bar_impact.prm").read()
if not only or "bar" in only:
    bar_scene("bar", bar, "Bar impact",
              {1: [16, 32, 64, 128], 2: [8, 16, 32, 64], 3: [8, 16, 32]},
              [32, 64, 128, 192, 256, 320, 352, 384, 416, 448], "mean_displacement_x",
              lambda cells: [("Height", 0.25)], 2,
              [("adaptive recovery", "recovery velocity"),
               ("adaptive kelly", "kelly velocity")])

two_bars = open("prm/two_bars.prm").read()
if not only or "two_bars" in only:
    bar_scene("two_bars", two_bars, "Two bars",
              {1: [20, 40, 80], 2: [10, 20, 40], 3: [10, 20]},
              [20, 40, 80, 120, 160], "mean_displacement_x_body2",
              lambda cells: [("Cells across", cells // 10),
                             ("Cells across body 2", cells // 10 + 1)], 1,
              [("adaptive recovery", "recovery velocity")])

def reference_scene(key, text, levels, reference_p, reference_level, tau, starts):
    """Uniform runs per p at the given levels, adaptive runs per p up to
    the finest of them: for each (coarsest, intervals) in starts, from
    global level coarsest if the finest is above it (Kelly of the velocity
    on 2 % and the contact zone, half coarsened, the coarsest level the
    Minimum level), one for each refinement interval in intervals; against
    a uniform run of degree reference_p at reference_level with the same
    tau."""
    reference_rows, reference_summary = run("%s-reference" % key,
                                            text + mesh_prm(reference_p, tau, reference_level))
    f_ref = column(reference_rows, "contact_force")
    peak = max(f_ref)
    d_ref = column(reference_rows, "mean_displacement_y_body1")
    travel = max(abs(d) for d in d_ref)
    end = float(reference_rows[-1]["time"])
    release_ref = contact_intervals(reference_summary)[-1][1]
    released = release_ref < end - 0.5 * tau

    def measures(rows, summary):
        intervals = contact_intervals(summary)
        values = {"error": max(abs(a - b) for a, b in
                               zip(column(rows, "contact_force"), f_ref)) / peak,
                  "position": abs(float(rows[-1]["mean_displacement_y_body1"]) - d_ref[-1]) / travel}
        if released:
            values["release"] = abs(intervals[-1][1] - release_ref) if intervals else float("nan")
        values["intervals"] = len(intervals)
        values["peak force"] = max(column(rows, "contact_force")) / peak - 1.
        return values

    for p in sorted(levels):
        for level in levels[p]:
            rows, summary = run("%s-p%d-uniform-%d" % (key, p, level),
                                text + mesh_prm(p, tau, level))
            results.setdefault(key, []).append(dict(
                p=p, mesh="uniform", finest=level, dofs=mean(column(rows, "dofs")),
                time=run_time(summary), **measures(rows, summary)))
        level = levels[p][-1]
        for coarsest, intervals in starts:
            if level <= coarsest:
                continue
            for interval in intervals:
                label = "adaptive kelly every %d" % interval + (
                    " from level %d" % coarsest if coarsest != starts[0][0] else "")
                rows, summary = run("%s-p%d-adaptive-%d-every-%d-from-%d"
                                    % (key, p, level, interval, coarsest),
                                    text + mesh_prm(p, tau, coarsest,
                                                    adaptive=(level, coarsest, level,
                                                              "kelly velocity, contact zone",
                                                              0.02, 0.5),
                                                    interval=interval))
                results.setdefault(key, []).append(dict(
                    p=p, mesh=label, finest=level,
                    dofs=mean(column(rows, "dofs")), time=run_time(summary),
                    **measures(rows, summary)))


if not only or "hertz" in only:
    hertz = open("prm/hertz_drop.prm").read().replace("set End time  = 1", "set End time  = 0.6")
    hertz += "\nsubsection Scene\n  subsection Hertz\n    set Contact zone refinements = 0\n  end\nend\n"
    reference_scene("hertz", hertz, {1: [2, 3, 4], 2: [1, 2, 3], 3: [1, 2]}, 2, 4, 0.01,
                    [(1, [2, 16]), (0, [16])])

if not only or "ball_drop" in only:
    ball = open("prm/ball_drop_adaptive.prm").read()
    ball = ball[:ball.index("subsection Mesh refinement")] + ball[ball.index("subsection Material\n"):]
    ball = ball.replace("set Output interval = 0.1", "set Output interval = 0.5")
    reference_scene("ball_drop", ball, {1: [1, 2], 2: [1, 2]}, 1, 3, 0.02,
                    [(1, [2, 16]), (0, [16])])

def crossing(runs, target):
    """(run time, position error, largest overshoot) where the error of
    the runs (one variant, by mesh) falls below target and stays below on
    every slower run: between the last run above it and the next,
    interpolated log-log (the error at T moves with the phase of the impact
    in a step, so it does not fall evenly from one mesh to the next); the
    overshoot is the largest of the runs from there on (the bars' runs all
    have one). The fastest run's own values if no run is above the target;
    None if the slowest run is."""
    runs = sorted(runs, key=lambda v: v["time"])
    above = [i for i, v in enumerate(runs) if v["error"] > target]
    if above and above[-1] + 1 == len(runs):
        return None
    below = runs[above[-1] + 1 if above else 0:]
    overshoot = max(v["overshoot"] for v in below)
    if not above:
        return below[0]["time"], below[0]["position"], overshoot
    a, b = runs[above[-1]], below[0]
    w = math.log(a["error"] / target) / math.log(a["error"] / b["error"])
    return tuple(math.exp((1 - w) * math.log(a[m]) + w * math.log(b[m]))
                 for m in ["time", "position"]) + (overshoot,)


def print_crossings(key, values):
    """The run time (position error, pressure overshoot) at which each
    uniform variant's energy-norm error reaches 0.10 and 0.05 (to stay; the
    targets for the bar: 0.05 in 30 s with a position error <= 0.005 m and
    an overshoot <= 10 %)."""
    print("\n%s: run time [s] (position error [m], overshoot) at an energy-norm "
          "error of\n" % key)
    print("| p | mesh | 0.10 | 0.05 |\n|---|---|---|---|")
    for p in [1, 2, 3]:
        for mesh in ["uniform", dissipative, blended, blended_long]:
            runs = [v for v in values if v["p"] == p and v["mesh"] == mesh]
            if not runs:
                continue
            cells = []
            for target in [0.10, 0.05]:
                at = crossing(runs, target)
                best = min(runs, key=lambda v: v["error"])
                cells.append("%.3g (%.2g, %.2g)" % at if at else
                             "not reached (%.3g at %.3g s)" % (best["error"], best["time"]))
            print("| %d | %s | %s | %s |" % (p, mesh, cells[0], cells[1]))


for key, values in results.items():
    print("\n%s:\n" % key)
    measures = [m for m in ["error", "error max", "position", "release", "intervals",
                            "overshoot", "ripple", "peak force"] if m in values[0]]
    print("| p | mesh | finest | mean DoFs | run time [s] | " + " | ".join(measures) + " |")
    print("|---" * (5 + len(measures)) + "|")
    for v in values:
        print("| %d | %s | %d | %.0f | %.3g | " % (v["p"], v["mesh"], v["finest"], v["dofs"], v["time"])
              + " | ".join("%d" % v[m] if m == "intervals" else "%.3g" % v[m] for m in measures) + " |")

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.5))
    for p, colour in [(1, "C0"), (2, "C1"), (3, "C2")]:
        uniform = [v for v in values if v["p"] == p and v["mesh"] == "uniform"]
        if not uniform:
            continue
        for ax, measure in zip(axes, ["error", "position"]):
            ax.loglog([v["time"] for v in uniform], [v[measure] for v in uniform], "o-",
                      color=colour, label="p = %d uniform" % p)
            for variant, style in [(dissipative, "x--"), (blended, "+-."),
                                   (blended_long, "*:")]:
                runs = [v for v in values if v["p"] == p and v["mesh"] == variant]
                if runs:
                    ax.loglog([v["time"] for v in runs], [v[measure] for v in runs], style,
                              color=colour, label="p = %d %s" % (p, variant))
            for v in values:
                if v["p"] == p and v["mesh"] not in ["uniform", dissipative, blended,
                                                     blended_long]:
                    ax.loglog([v["time"]], [v[measure]],
                              "s" if "recovery" in v["mesh"] else
                              "D" if "from level" in v["mesh"] else
                              "v" if "every 16" in v["mesh"] else "^",
                              color=colour, markerfacecolor="none", markersize=9,
                              label="p = %d %s" % (p, v["mesh"]))
    by_reference = key in ["hertz", "ball_drop"]
    axes[0].set_ylabel("contact force error / peak" if by_reference
                       else "energy-norm error at T / sqrt(E(0))")
    axes[1].set_ylabel("position error at T" + (" / travel" if by_reference else " [m]"))
    for ax in axes:
        ax.set_xlabel("run time (time loop) [s]")
        ax.grid(True, which="both", alpha=0.3)
        ax.set_title(key.replace("_", " "))
    axes[1].legend(fontsize=7)
    fig.tight_layout()
    fig.savefig("doc/work_precision_%s.png" % key, dpi=100)
    print("wrote doc/work_precision_%s.png" % key)
    if key in ["bar", "two_bars"]:
        print_crossings(key, values)
