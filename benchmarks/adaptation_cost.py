#!/usr/bin/python3
"""What one mesh adaptation costs, in time steps of the same mesh. Runs the bar impact (N-CS++, lumped mass,
H = 0.25, adapted every 2 steps up to 2 levels above the coarse mesh,
tau = h_min / (2 p c)) in 2D and 3D for p = 1, 2, 3 with each velocity
criterion, Kelly's and the gradient recovery, and the recovery again with
'Contact solver/Step matrix = matrix-free' (criterion 'recovery mf'; the
same meshes as the recovery's, whose indicators do not see round-off),
both again with 'Mesh/Triangulation = serial' (criteria 'recovery serial'
and 'recovery mf serial': deal.II's serial Triangulation instead of
p4est's, the same meshes), and prints from summary.txt's
TimerOutput sections the milliseconds per step and per adaptation that
changes the mesh (n of them: the calls of 'adaptation: constraints
restored'), split into its parts:
  indicators  'adaptation: indicators and flags', per call (every
              adaptation computes them, also one that then marks no cell
              and stops there)
  refine      'adaptation: refinement and transfer' (p4est or the serial
              triangulation, u and udot)
  dofs        'adaptation: DoFs and sparsity'
  assembly    'adaptation: assembly' and 'adaptation: contact rows'
  S           'adaptation: step matrix and preconditioner'
  restore     'adaptation: constraints restored'
  energy      'adaptation: energy transfer' (the energy before and after
              the transfer; the one after computes A u on the new mesh, the
              product that the first step there would otherwise make)
each but the first over n, and their sum in steps of the same run.
--tau-ratio R sets tau = R h_min / (p c) (default 1/2; the node spacing
is h_min / p) and the runs to at least 60 steps, leaves out the Kelly
runs, 3D p = 1 unless --dim 3 asks for it (2.5e5 DoFs, 6 minutes per
run), the 3D assembled S (Q2 with AMG about 30 s per step, Q1 with AMG
left out with it) and the bar below,
and adds for p >= 2 the recovery runs with 'Contact solver/Preconditioner
= multigrid' (criterion 'recovery mg'), the preconditioner for large tau;
without --only it runs 'recovery', 'recovery mf' and 'recovery mg'.
Then the adaptive bar of doc/results.md (H = 0.25) to T = 2.5 s (2D, p = 1, 32 cells along, levels 0 to 2,
tau = 1/256) with each criterion against the uniform mesh of its finest
level: the energy-norm error at T, the mean DoFs and the time loop's wall
time (summary.txt) without the sampled error norms, also with the serial
triangulation. --only LABELS runs the criteria of the comma-separated
labels only (e.g. 'recovery mf,recovery mf serial'); with --only,
--scale, --tau-ratio or --floor the bar is left out.
--scale F multiplies the cells along the bar by F and divides the
initial gap and the end time by F (tau falls with h_min): the same
number of steps and adaptations, and the front crosses as many cells, on
a mesh of about F^dim times the DoFs (F = 3 and 10 in 2D, 2 and 4 in 3D
for 1e5 and 1e6); it leaves out the Kelly runs and the bar below.
--dim D runs the cases of dimension D only.
--floor runs each case once (whatever --repeat says; not with
--tau-ratio) under 'perf record' (the Debian package linux-perf; perf
must be allowed to record the process) and prints, instead of the
sections, where the samples of an adaptation that changes the mesh go,
in steps of the same run (the samples of the steps, with the initial
solve, over the calls of 'time step'): the indicators as the section
'adaptation: indicators and flags' counts them (per call, over all
calls), then deal.II's set-up passes, each a pass over the mesh
('MatrixFree' MatrixFree::reinit, 'DoFs' DoFHandler::distribute_dofs,
'refinement' the triangulation's execute_coarsening_and_refinement,
'flags' its smoothing of the flags before the transfer; on the serial
triangulation with the matrix-free S each runs once per adaptation, an
assembled S or the multigrid numbers a second set of DoFs), the energy's
product with A, and the rest, the program's own work (with the deal.II
and Trilinos calls it makes itself). 'floor' is the sum of the
indicators and deal.II's passes, what an adaptation costs before the
program's own work, 'floor + energy' with the energy's product. Samples
land where perf's stacks show them: a few hundred per adaptation, so
that single runs differ by about 0.1 step.
--repeat N runs each case N times (default 1) and prints the median over
the runs of 'ms per step' and of each part, their sum as 'adaptation
(ms)', and as 'in steps' the median of the runs' own ratios (which need
not be the sum over the step) with their smallest and largest value;
mean DoFs and the adaptations are those of the last run (the runs have
the same meshes). At 10^4 DoFs only 2 to 11 adaptations change the mesh,
and single runs of one case differ by up to 0.9 step.
One rank, Release build.
Usage, from the repository's top folder after tools/setup.sh:
    benchmarks/adaptation_cost.py [build/dyncontact]
                                  [--tau-ratio R] [--only LABELS]
                                  [--scale F] [--dim D] [--repeat N]
                                  [--floor]"""
import csv
import os
import re
import shutil
import subprocess
import sys

from options import take_option

arguments = sys.argv[1:]
tau_ratio = take_option(arguments, "--tau-ratio", float)
only = take_option(arguments, "--only")
scale = take_option(arguments, "--scale", float)
only_dim = take_option(arguments, "--dim", int)
repeat = take_option(arguments, "--repeat", int, 1)
floor = "--floor" in arguments
if floor:
    arguments.remove("--floor")
    if not shutil.which("perf"):
        sys.exit("--floor needs perf (Debian package linux-perf)")
    if tau_ratio is not None:
        sys.exit("--floor does not run with --tau-ratio (runs of minutes, "
                 "too long to record)")
unknown_options = [a for a in arguments if a.startswith("-")]
if unknown_options or len(arguments) > 1:
    sys.exit("unknown options or more than one program: %s (see --help)"
             % " ".join(unknown_options or arguments[1:]))
if tau_ratio is not None and not tau_ratio > 0:
    sys.exit("--tau-ratio must be > 0; got %g" % tau_ratio)
if only is not None and not only.strip(" ,"):
    sys.exit("--only needs at least one label")
if repeat < 1:
    sys.exit("--repeat must be at least 1; got %d" % repeat)
if only_dim is not None and only_dim not in (2, 3):
    sys.exit("--dim must be 2 or 3; got %d" % only_dim)
if scale is not None and not scale > 0:
    sys.exit("--scale must be > 0; got %g" % scale)
executable = arguments[0] if arguments else "build/dyncontact"
if not (os.path.isfile(executable) and os.access(executable, os.X_OK)):
    sys.exit("no executable program at '%s' (build it first: "
             "bash tools/setup.sh)" % executable)
folder = "results-adaptation-cost"
os.makedirs(folder, exist_ok=True)

# (dimension, degree, coarse cells along the length, end time)
cases = [(2, 1, 128, 0.15), (2, 2, 64, 0.15), (2, 3, 32, 0.15),
         (3, 1, 32, 0.125), (3, 2, 16, 0.125)]
# (label, criterion, step matrix, preconditioner, triangulation)
criteria = [("kelly", "kelly velocity", "assembled", "automatic",
             "distributed"),
            ("recovery", "recovery velocity", "assembled", "automatic",
             "distributed"),
            ("recovery mf", "recovery velocity", "matrix-free", "automatic",
             "distributed"),
            ("recovery serial", "recovery velocity", "assembled",
             "automatic", "serial"),
            ("recovery mf serial", "recovery velocity", "matrix-free",
             "automatic", "serial")]
if tau_ratio:
    # (3D p = 1 at large tau: 2.5e5 DoFs, about 5 s per step matrix-free,
    # 6 minutes per run: only with --dim 3)
    if only_dim != 3:
        cases = [case for case in cases if case[:2] != (3, 1)]
    criteria = criteria[1:] + [("recovery mg", "recovery velocity",
                                "matrix-free", "multigrid", "distributed")]
    if not only:
        only = "recovery,recovery mf,recovery mg"
if scale:
    cases = [(dim, degree, int(round(cells * scale)), end / scale)
             for dim, degree, cells, end in cases]
    criteria = [c for c in criteria if c[0] != "kelly"]
if only_dim:
    cases = [case for case in cases if case[0] == only_dim]
if only:
    labels = [l.strip() for l in only.split(",") if l.strip()]
    unknown = [l for l in labels if l not in [c[0] for c in criteria]]
    if unknown:
        sys.exit("--only: no criterion labelled %s; the labels are %s"
                 % (", ".join(unknown), ", ".join(c[0] for c in criteria)))
    criteria = [c for c in criteria if c[0] in labels]
    if tau_ratio and only_dim == 3 and all(c[2] == "assembled"
                                           for c in criteria):
        sys.exit("--tau-ratio in 3D runs no assembled S (Q2 with AMG: about "
                 "30 s per step); choose a matrix-free criterion")
parts = [("indicators", ["adaptation: indicators and flags"]),
         ("refine", ["adaptation: refinement and transfer"]),
         ("dofs", ["adaptation: DoFs and sparsity"]),
         ("assembly", ["adaptation: assembly", "adaptation: contact rows"]),
         ("S", ["adaptation: step matrix and preconditioner"]),
         ("restore", ["adaptation: constraints restored"]),
         ("energy", ["adaptation: energy transfer"])]


def median(values):
    values = sorted(values)
    n = len(values)
    return 0.5 * (values[(n - 1) // 2] + values[n // 2])


# (label, pattern of a frame): the first that matches a sample of
# DiscreteProblem::adapt_mesh counts it ('indicators' as the section
# 'adaptation: indicators and flags' does at every call: the criterion and
# the marking, and the scan for flags, adapt_mesh's first lambda)
triangulation_class = (r"dealii::(parallel::distributed::)?"
                       r"Triangulation<\d, \d>")
floor_parts = [
    ("indicators", re.compile(r"MeshAdaptor<\d>::mark_cells|"
                              r"adapt_mesh\(.*\)::\{lambda\(\)#1\}")),
    ("MatrixFree", re.compile(r"dealii::MatrixFree<.*>::reinit")),
    ("DoFs", re.compile(r"dealii::DoFHandler<\d, \d>::distribute_dofs")),
    ("refinement", re.compile(
        triangulation_class + "::execute_coarsening_and_refinement")),
    ("flags", re.compile(
        triangulation_class + "::prepare_coarsening_and_refinement")),
    ("energy", re.compile(r"SemiDiscreteSystem<\d>::total_energy")),
    ("own", re.compile(r""))]


def perf_samples(data):
    """The samples of 'perf record' in data: those of the steps
    (DiscreteProblem::take_step, and the initial solve, which the section
    'time step' counts as one of its calls) and those of each of
    floor_parts within DiscreteProblem::adapt_mesh."""
    script = subprocess.run(["perf", "script", "-i", data, "--no-inline"],
                            check=True, capture_output=True, text=True).stdout
    counts = dict((part, 0) for part, _ in floor_parts)
    counts["steps"] = 0
    for sample in script.split("\n\n"):
        if re.search(r"DiscreteProblem<\d>::take_step|"
                     r"dyncontact::TimeIntegrator::initialize", sample):
            counts["steps"] += 1
        elif re.search(r"DiscreteProblem<\d>::adapt_mesh", sample):
            for part, pattern in floor_parts:
                if pattern.search(sample):
                    counts[part] += 1
                    break
    os.remove(data)
    return counts


def run(name, dim, degree, cells, end, criterion, tau=None, levels=2,
        step_matrix="assembled", preconditioner="automatic",
        triangulation="distributed"):
    h_min = 1.0 / (cells * 2 ** levels)
    if not tau:
        tau = (tau_ratio or 0.5) * h_min / degree
        if tau_ratio:
            end = max(end, 60 * tau)
    prm = os.path.join(folder, name + ".prm")
    sections = {}
    with open(prm, "w") as f:
        f.write("""set Dimension = %d
set Polynomial degree = %d
set Output directory = %s
subsection Scene
  set Name = bar impact
  subsection Bar impact
    set Length = 1
    set Height = 0.25
    set Impact velocity = 1
    set Initial gap = %g
    set Cells along length = %d
  end
end
subsection Material
  set Young's modulus = 1
  set Poisson's ratio = 0
  set Density = 1
end
subsection Time integration
  set Scheme = N-CS++
  set Time step = %.10g
  set End time = %g
  set Mass matrix = lumped
end
subsection Contact solver
  set Step matrix = %s%s
end
subsection Mesh
  set Triangulation = %s
end
subsection Output
  set Output interval = 0.5
  set Write vtu = false
end
""" % (dim, degree, os.path.join(folder, name), 0.1 / (scale or 1),
       cells, tau, end,
       step_matrix,
       "\n  set Preconditioner = " + preconditioner
       if preconditioner != "automatic" else "", triangulation))
        if criterion:
            f.write("""subsection Mesh refinement
  set Refinement interval = 2
  set Maximum level = %d
  set Initial contact refinements = %d
  set Criteria = %s
end
""" % (levels, levels, criterion))
    command = [executable, prm]
    if floor:
        data = os.path.join(folder, name + ".perf")
        # (fewer samples per second on larger meshes: about as many in all)
        frequency = max(200, int(10000 / (scale or 1) ** dim))
        command = ["perf", "record", "-q", "-o", data, "-F", str(frequency),
                   "--call-graph", "dwarf,16384"] + command
    status = subprocess.run(command, stdout=subprocess.DEVNULL).returncode
    if status != 0:
        sys.exit("'%s' failed with exit code %d%s" % (
            " ".join(command), status,
            " (is perf allowed to record? see the kernel setting "
            "perf_event_paranoid)" if floor else ""))
    if floor:
        sections["samples"] = perf_samples(data)
    for line in open(os.path.join(folder, name, "summary.txt")):
        m = re.match(r"^  (\S.*?)\s+([0-9.e+-]+) s\s+(\d+) calls", line)
        if m:
            sections[m.group(1)] = (float(m.group(2)), int(m.group(3)))
        m = re.match(r"^wall time: .* the time loop ([0-9.e+-]+) s", line)
        if m:
            sections["time loop"] = (float(m.group(1)), 1)
    rows = list(csv.DictReader(
        open(os.path.join(folder, name, "statistics.tsv")), delimiter="\t"))
    dofs = sum(float(r["dofs"]) for r in rows) / len(rows)
    errors = [r["error_energy_norm"] for r in rows if r["error_energy_norm"]]
    return sections, dofs, float(errors[-1]) if errors else None


if floor:
    print("| dim | p | criterion | mean DoFs | adaptations changing the mesh "
          "| samples per step | %s | floor | floor + energy |"
          % " | ".join(part for part, _ in floor_parts))
    print("|---|---|---|---|---|---|%s---|---|" % ("---|" * len(floor_parts)))
else:
    print("| dim | p | criterion | mean DoFs | adaptations changing the "
          "mesh | ms per step | indicators | refine | dofs | assembly | S "
          "| restore | energy | adaptation (ms) | in steps |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|")
for dim, degree, cells, end in cases:
    for label, criterion, step_matrix, preconditioner, triangulation in \
            criteria:
        if preconditioner == "multigrid" and degree < 2:
            continue
        if tau_ratio and dim == 3 and step_matrix == "assembled":
            continue  # Q2 with AMG: about 30 s per step at 3e5 DoFs, and Q1
        name = "%dd_q%d_%s%s%s" % (dim, degree, label.replace(" ", "_"),
                                   "_tau%g" % tau_ratio if tau_ratio else "",
                                   "_scale%g" % scale if scale else "")
        if floor:
            sections, dofs, _ = run(name, dim, degree, cells, end,
                                    criterion, step_matrix=step_matrix,
                                    preconditioner=preconditioner,
                                    triangulation=triangulation)
            samples = sections["samples"]
            attempts = sections["adaptation: indicators and flags"][1]
            changes = sections.get("adaptation: constraints restored",
                                   (0, 0))[1]
            if changes == 0 or samples["steps"] == 0:
                print("| %d | %d | %s | %.0f | 0 of %d | (no adaptation "
                      "changed the mesh, or no step was sampled) |"
                      % (dim, degree, label, dofs, attempts))
                continue
            per_step = samples["steps"] / sections["time step"][1]
            steps = [samples[part] / per_step
                     / (attempts if part == "indicators" else changes)
                     for part, _ in floor_parts]
            print("| %d | %d | %s | %.0f | %d of %d | %.0f | %s | %.2f "
                  "| %.2f |"
                  % (dim, degree, label, dofs, changes, attempts, per_step,
                     " | ".join("%.2f" % x for x in steps),
                     sum(steps[:5]), sum(steps[:6])))
            sys.stdout.flush()
            continue
        runs = []  # (ms per step, ms per part, in steps) of each run
        for _ in range(repeat):
            sections, dofs, _ = run(name, dim, degree, cells, end,
                                    criterion, step_matrix=step_matrix,
                                    preconditioner=preconditioner,
                                    triangulation=triangulation)
            time, calls = sections["time step"]
            step = time / calls
            attempts = sections["adaptation: indicators and flags"][1]
            changes = sections.get("adaptation: constraints restored",
                                   (0, 0))[1]
            if changes == 0:
                break
            costs = []
            for part, names in parts:
                costs.append(sum(sections[n][0] for n in names
                                 if n in sections)
                             / (attempts if part == "indicators"
                                else changes))
            runs.append((step, costs, sum(costs) / step))
        if not runs:
            print("| %d | %d | %s | %.0f | 0 of %d | (no adaptation changed "
                  "the mesh) |" % (dim, degree, label, dofs, attempts))
            continue
        step = median([r[0] for r in runs])
        costs = [median([r[1][k] for r in runs]) for k in range(len(parts))]
        steps = sorted(r[2] for r in runs)
        print("| %d | %d | %s | %.0f | %d of %d | %.1f | %s | %.0f | %s |"
              % (dim, degree, label, dofs, changes, attempts,
                 1e3 * step,
                 " | ".join("%.1f" % (1e3 * c) for c in costs),
                 1e3 * sum(costs),
                 "%.1f" % median(steps) if repeat == 1 else
                 "%.1f (%.1f–%.1f)" % (median(steps), steps[0], steps[-1])))
        sys.stdout.flush()

if tau_ratio or only or scale or floor:
    sys.exit(0)
print()
print("| bar to T = 2.5 s | error at T | mean DoFs | time loop without "
      "sampled norms (s) |")
print("|---|---|---|---|")
for name, label, cells, criterion, levels, triangulation in [
        ("uniform", "uniform, 128 cells along", 128, "", 0, "distributed"),
        ("kelly", "adaptive, kelly velocity", 32, "kelly velocity", 2,
         "distributed"),
        ("recovery", "adaptive, recovery velocity", 32, "recovery velocity",
         2, "distributed"),
        ("recovery_serial", "adaptive, recovery velocity, serial", 32,
         "recovery velocity", 2, "serial")]:
    sections, dofs, error = run("bar_" + name, 2, 1, cells, 2.5, criterion,
                                tau=1.0 / 256, levels=levels,
                                triangulation=triangulation)
    loop = sections["time loop"][0] - sections.get("sampled norms", (0, 0))[0]
    print("| %s | %.4f | %.0f | %.2f |" % (label, error, dofs, loop))
    sys.stdout.flush()
