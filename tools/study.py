#!/usr/bin/python3
"""A convergence study of any input: error against run time.

Runs the input on N successive refinements of its coarse mesh (Mesh/Initial
global refinements + k, k = 0 .. N-1) and, with --refine h+tau (the
default), its Time step halved with each level (tau c/h kept), with
--refine h the same Time step, with --refine tau the same mesh and tau/2^k.
The finest run of the input as given (uniform, its p and theta) is the
reference: it writes its states (mesh, u, udot) at the sample times, and
every other run compares with them on the reference's mesh (subsection
Reference solution: its state is prolongated through the nested meshes and
the difference integrated in the physical energy norm). Configurations
besides the input as given: --degree-plus-one (p + 1, the same meshes),
--theta T (Time integration/Numerical dissipation = T), and, where the
input adapts its mesh, the adaptive runs (Minimum and Maximum level + k;
the uniform runs switch the adaptation off).

For each run: DoFs, steps, the run's wall time (without the
comparison with the reference states, counted apart as the study's
overhead), and its difference from the reference: in the energy norm (at
the end and the largest over the sample times, relative to sqrt(E) with E
the largest total energy of the reference), in the contact force of each
pair (largest and L1 over time, relative to the reference's peak), in the
position of each body (mean displacement, largest over time, in m), and in
the first contact and the last release time of each pair (s).

From the levels of the reference's configuration, per measure: the observed
rate r and an estimate of the reference's own error, by one of two models
of the differences e_k = |u_k - u_ref|: 'one shape' (Richardson: errors
C h_k^r of one shape give e_(N-3)/e_(N-2) = 2^r + 1, the reference's error
e_(N-2)/(2^r - 1), every run's estimate its difference plus the
reference's error), or 'uncorrelated' (errors of different shapes, as the
dispersive oscillations behind wave fronts: the difference is the run's
own error, e_k = C h_k^r, the reference's error C h_ref^r extrapolated).
With four levels or more the rate of the levels before decides the model
and the reliability: 'asymptotic' if it agrees within 25 %, otherwise 'not
asymptotic' (the estimate is then only the order of magnitude); 'not
converging' if the differences do not fall. With three levels nothing
decides: the larger of the two estimates is taken and the other printed.

Writes <out>/study.csv, <out>/study.png (estimated energy-norm error
against run time, one curve per configuration) and prints the table and
which run reaches a stated error (--target, relative) fastest. A study that
was interrupted is resumed by running the same command: finished runs (a
'done' file in their folder) are not repeated.

Usage:
  tools/study.py input.prm --levels N [--refine h+tau|h|tau]
      [--degree-plus-one] [--theta T] [--no-adaptive] [--samples K]
      [--target E] [--mpi R] [--out DIR] [--executable build/dyncontact]
      [--adaptive-variant LABEL:ENTRY=VALUE[;ENTRY=VALUE...]] ...
"""
import argparse
import csv
import hashlib
import math
import os
import re
import shutil
import signal
import subprocess
import sys
import time


def fail(message):
    sys.stderr.write("study: error: %s\n" % message)
    sys.exit(1)


parser = argparse.ArgumentParser(
    description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("prm")
parser.add_argument("--levels", type=int, required=True,
                    help="number of refinement levels N (>= 2; >= 3 for "
                         "rates and estimates)")
parser.add_argument("--refine", default="h+tau", choices=["h+tau", "h", "tau"])
parser.add_argument("--degree-plus-one", action="store_true")
parser.add_argument("--theta", type=float, default=None)
parser.add_argument("--no-adaptive", action="store_true",
                    help="only uniform runs for an input that adapts")
parser.add_argument("--samples", type=int, default=10,
                    help="sample times of the energy norm: K equal "
                         "intervals of the End time (default 10; 0: the "
                         "input's Output interval)")
parser.add_argument("--target", type=float, default=None,
                    help="relative energy-norm error for the advice "
                         "(default: twice the reference's estimate)")
parser.add_argument("--adaptive-variant", action="append", default=[],
                    metavar="LABEL:ENTRY=VALUE[;ENTRY=VALUE...]",
                    help="an adaptive configuration more: the input with "
                    "these entries (e.g. 'tol:Mesh refinement/Coarsening "
                    "tolerance=1e-4'); repeatable")
parser.add_argument("--mpi", type=int, default=1, help="MPI ranks per run")
parser.add_argument("--out", default=None,
                    help="folder of the study (default: study-<input name>)")
parser.add_argument("--executable", default=None)
args = parser.parse_args()

here = os.path.dirname(os.path.abspath(__file__))
executable = os.path.abspath(args.executable or
                             os.path.join(here, "..", "build", "dyncontact"))
if not os.access(executable, os.X_OK):
    fail("no program '%s' (build it, or give --executable)" % executable)
if not os.path.isfile(args.prm):
    fail("the input '%s' does not exist" % args.prm)
if args.levels < 2:
    fail("--levels must be at least 2 (now %d): the finest run is the "
         "reference of the others" % args.levels)
if args.samples < 0:
    fail("--samples must be >= 0 (now %d)" % args.samples)
if args.theta is not None and not 0 < args.theta <= 0.5:
    fail("--theta must be in (0, 0.5] (now %g)" % args.theta)


signal.signal(signal.SIGINT, lambda *_: fail(
    "interrupted: the finished runs are kept; run the same command again "
    "to go on"))


# --- the input's entries (subsection/entry -> value), includes expanded
def read_prm(path, entries, section=(), lines=None):
    base = os.path.dirname(os.path.abspath(path)) if path else "."
    path_stack = list(section)
    for raw in (lines if lines is not None else open(path)):
        line = raw.split("#", 1)[0].strip()
        while line.endswith("\\"):
            line = line[:-1]
        if not line:
            continue
        words = line.split(None, 1)
        if words[0] == "subsection":
            path_stack.append(words[1].strip())
        elif words[0] == "end":
            path_stack.pop()
        elif words[0] == "set":
            name, value = words[1].split("=", 1)
            entries["/".join(path_stack + [name.strip()])] = value.strip()
        elif words[0] == "include":
            read_prm(os.path.join(base, words[1].strip()), entries, path_stack)
    return entries


# the program's defaults (its --help prints every entry), then the input's
defaults = subprocess.run([executable, "--help"], capture_output=True,
                          text=True).stdout.splitlines()
defaults = [line for line in defaults
            if line.strip().startswith(("set ", "subsection ", "end"))]
prm = read_prm(None, {}, lines=defaults)
known_entries = set(prm)
prm.update(read_prm(args.prm, {}))
input_text = open(args.prm).read()


def entry(name, default):
    return prm.get(name, default)


if entry("Checkpointing/Resume", "false").lower() == "true":
    fail("the input resumes from a checkpoint (Checkpointing/Resume = true): "
         "a study runs the input from its start on every mesh; set it to "
         "false")
if entry("Reference solution/Write states", "false").lower() == "true" or \
        entry("Reference solution/Compare with states", "false").lower() == "true":
    fail("the input writes or compares reference states itself (subsection "
         "Reference solution): the study sets them; remove them")
scheme = entry("Time integration/Scheme", "N-CS++")
static = scheme.lower().startswith("static")
if static:
    fail("the input is static (Scheme = %s): the study compares the states "
         "of dynamic runs at sample times (the program writes no reference "
         "states of a static problem)" % scheme)
g0 = int(entry("Mesh/Initial global refinements", "0"))
tau0 = float(entry("Time integration/Time step", "0.01"))
end_time = float(entry("Time integration/End time", "1"))
degree = int(entry("Polynomial degree", "1"))
adaptive_input = int(entry("Mesh refinement/Refinement interval", "0")) > 0
min0 = int(entry("Mesh refinement/Minimum level", "0"))
max0 = int(entry("Mesh refinement/Maximum level", "10"))
interval = end_time / args.samples if args.samples else \
    float(entry("Output/Output interval", "0.1"))
if interval < tau0 * (1 - 1e-9):
    fail("the sample interval %g s is shorter than the Time step %g s: "
         "give --samples K with End time / K a multiple of the Time step"
         % (interval, tau0))
if abs(interval / tau0 - round(interval / tau0)) > 1e-6:
    fail("the sample interval %g s (Output interval, or End time / "
         "--samples) is no multiple of the Time step %g s" % (interval, tau0))
if entry("Mesh/Triangulation", "distributed") == "serial" and args.mpi > 1:
    fail("the input uses Mesh/Triangulation = serial: run the study with "
         "--mpi 1")

out = os.path.abspath(args.out or "study-" +
                      os.path.splitext(os.path.basename(args.prm))[0])
os.makedirs(out, exist_ok=True)
states = os.path.join(out, "reference-states")
N = args.levels
finest = N - 1


def level_entries(k):
    """Overrides of level k (mesh and tau)."""
    mesh_level = g0 + (k if args.refine != "tau" else 0)
    tau = tau0 / 2 ** k if args.refine != "h" else tau0
    items = ["Mesh/Initial global refinements=%d" % mesh_level]
    items.append("Time integration/Time step=%r" % tau)
    return items, mesh_level, tau


# files named relative to the input's folder, named absolutely in the runs'
# inputs (which live in the study's folder)
input_folder = os.path.dirname(os.path.abspath(args.prm))
files = []
if prm.get("Scene/Gmsh/Mesh file", "").strip():
    files.append("Scene/Gmsh/Mesh file=" +
                 os.path.join(input_folder, prm["Scene/Gmsh/Mesh file"]))
if "cad " in prm.get("Scene/Gmsh/Manifolds", ""):
    items = []
    for item in prm["Scene/Gmsh/Manifolds"].split(","):
        words = item.split()
        if "cad" in words and words.index("cad") + 1 < len(words):
            i = words.index("cad") + 1
            words[i] = os.path.join(input_folder, words[i])
        items.append(" ".join(words))
    files.append("Scene/Gmsh/Manifolds=" + ", ".join(items))

configurations = [("uniform p=%d" % degree, [])]
if adaptive_input:
    configurations[0] = ("uniform p=%d" % degree,
                         ["Mesh refinement/Refinement interval=0",
                          "Mesh refinement/Initial contact refinements=0"])
base_uniform = configurations[0][1]
if args.degree_plus_one:
    configurations.append(("uniform p=%d" % (degree + 1),
                           base_uniform + ["Polynomial degree=%d" % (degree + 1)]))
if args.theta is not None:
    configurations.append(("uniform theta=%g" % args.theta, base_uniform +
                           ["Time integration/Numerical dissipation=%r" % args.theta]))
if adaptive_input and not args.no_adaptive:
    configurations.append(("adaptive", []))
for variant in args.adaptive_variant:
    label, _, entries = variant.partition(":")
    items = [e.strip() for e in entries.split(";") if e.strip()]
    if not label.strip() or not items or any("=" not in e for e in items):
        fail("--adaptive-variant '%s': give LABEL:ENTRY=VALUE[;ENTRY=VALUE...], "
             "e.g. 'tol:Mesh refinement/Coarsening tolerance=1e-4'" % variant)
    if not adaptive_input or args.no_adaptive:
        fail("--adaptive-variant needs an input that adapts its mesh (Mesh "
             "refinement/Refinement interval > 0) and no --no-adaptive")
    for item in items:
        # an entry of a subsection the program declares must be one of its
        # entries (refused here, not after the other runs)
        path = "/".join(p.strip() for p in item.split("=", 1)[0].split("/"))
        parent = path.rsplit("/", 1)[0] if "/" in path else ""
        if path not in known_entries and \
                any(k.startswith(parent + "/") for k in known_entries):
            fail("--adaptive-variant '%s': '%s' is no entry of the program "
                 "(dyncontact --help lists them)" % (variant, path))
        if path == "Mesh refinement/Refinement interval" and \
                item.split("=", 1)[1].strip() == "0":
            print("   warning: --adaptive-variant '%s' switches the "
                  "adaptation off: its runs are uniform" % variant)
    configurations.append(("adaptive " + label.strip(), items))


def overrides(items):
    text = ""
    for item in items:
        path, value = item.split("=", 1)
        parts = [p.strip() for p in path.split("/")]
        text += "".join("subsection %s\n" % s for s in parts[:-1])
        text += "set %s = %s\n" % (parts[-1], value.strip())
        text += "end\n" * (len(parts) - 1)
    return text


def run(name, items, reference):
    directory = os.path.join(out, name)
    text = "include %s\n" % os.path.abspath(args.prm) + overrides(files + items + [
        "Output directory=" + directory,
        "Output/Write vtu=false",
        "Output/Progress interval=0",
        "Checkpointing/Interval in steps=0",
        "Checkpointing/Interval in minutes=0",
        "Reference solution/Directory=" + states,
        "Reference solution/Interval=%r" % interval,
        "Reference solution/" + ("Write states" if reference else
                                 "Compare with states") + "=true"])
    # a run is done if it ran this text on this input (and, if it compares,
    # against this reference)
    identity = hashlib.sha256((text + input_text + reference_identity)
                              .encode()).hexdigest()
    done = os.path.join(directory, "done")
    if os.path.exists(done) and open(done).readline().strip() == identity:
        print("   %-28s done before (not repeated)" % name, flush=True)
        return directory, identity
    shutil.rmtree(directory, ignore_errors=True)
    os.makedirs(directory)
    prm_file = directory + ".prm"
    with open(prm_file, "w") as f:
        f.write(text)
    command = [executable, prm_file]
    if args.mpi > 1:
        command = ["mpirun", "-np", str(args.mpi)] + command
    start = time.time()
    result = subprocess.run(command, capture_output=True, text=True,
                            cwd=os.path.dirname(os.path.abspath(args.prm)))
    if result.returncode < 0:
        fail("the run %s was killed by signal %d (its input: %s)" %
             (name, -result.returncode, prm_file))
    if result.returncode != 0:
        message = (result.stderr.strip() or result.stdout.strip()).splitlines()
        fail("the run %s failed (its input: %s):\n%s" %
             (name, prm_file, "\n".join(message[-8:])))
    with open(done, "w") as f:
        f.write("%s\n%.3f s\n" % (identity, time.time() - start))
    print("   %-28s %.1f s" % (name, time.time() - start), flush=True)
    return directory, identity


# --- the runs: the reference first (the others compare with its states)
plan = []  # (configuration, level, name, items)
for c, (label, items) in enumerate(configurations):
    for k in range(N):
        level, mesh_level, tau = level_entries(k)
        extra = list(items)
        if label.startswith("adaptive"):
            shift = k if args.refine != "tau" else 0
            reference_level = level_entries(finest)[1]
            if max0 + shift > reference_level:
                if args.refine == "tau":
                    print("   %s level %d left out: its Maximum level %d "
                          "is finer than the reference's level %d, which "
                          "--refine tau keeps (use --refine h+tau or h)" %
                          (label, k, max0, reference_level))
                else:
                    print("   %s level %d left out: its Maximum level %d "
                          "is finer than the reference's level %d (a study "
                          "of %d levels or more compares it)" %
                          (label, k, max0 + k, reference_level,
                           max0 + k - g0 + 1))
                continue
            extra += ["Mesh refinement/Minimum level=%d" % (min0 + shift),
                      "Mesh refinement/Maximum level=%d" % (max0 + shift)]
        if c == 0 and k == finest:
            continue
        plan.append((label, k, "%s-level%d" % (re.sub(r"[^A-Za-z0-9_.+-]", "",
                                                      label.replace(" ", "_")), k),
                     level + extra, mesh_level, tau))
# distinct configurations must not share a folder (labels that differ
# only in characters a folder name leaves out)
folders = {}
for label, k, name, *_ in plan:
    if name in folders and folders[name] != label:
        fail("the configurations '%s' and '%s' would share the run folder "
             "'%s': give --adaptive-variant labels that differ in letters or "
             "digits" % (folders[name], label, name))
    folders[name] = label
if len(set(c[0] for c in configurations)) != len(configurations):
    fail("two configurations have the same label: give every "
         "--adaptive-variant its own label")
reference_name = "reference-level%d" % finest
print("study of %s: %d levels (%s), %d configuration(s), in %s" %
      (args.prm, N, args.refine, len(configurations), out), flush=True)
if os.path.exists(os.path.join(out, reference_name, "done")) and \
        not os.path.exists(os.path.join(states, "state_00000.header")):
    os.remove(os.path.join(out, reference_name, "done"))
level, ref_mesh_level, ref_tau = level_entries(finest)
reference_identity = ""
reference_dir, reference_identity = run(reference_name,
                                        level + configurations[0][1], True)
directories = {}
for label, k, name, items, mesh_level, tau in plan:
    directories[(label, k)] = (run(name, items, False)[0], mesh_level, tau)
directories[(configurations[0][0], finest)] = (reference_dir, ref_mesh_level, ref_tau)


# --- what each run measured
def table(directory):
    with open(os.path.join(directory, "statistics.tsv")) as f:
        rows = list(csv.DictReader(f, delimiter="\t"))
    return rows


def timers(directory):
    """(wall time, reference states) in s from summary.txt (the state at
    t = 0 is compared before the time loop: the run's time is its whole
    wall time less the comparisons)."""
    loop, overhead = float("nan"), 0.
    for line in open(os.path.join(directory, "summary.txt")):
        if line.startswith("wall time:"):
            loop = float(line.split()[2])
        elif line.strip().startswith("reference states"):
            overhead = float(line.split()[2])
    return loop, overhead


def series(rows, column):
    return [(float(r["time"]), float(r[column])) for r in rows]


def interpolate(points, t):
    """Linear interpolation of [(t, v)] sorted by t."""
    lo, hi = 0, len(points) - 1
    if t <= points[0][0]:
        return points[0][1]
    if t >= points[-1][0]:
        return points[-1][1]
    while hi - lo > 1:
        mid = (lo + hi) // 2
        if points[mid][0] <= t:
            lo = mid
        else:
            hi = mid
    (t0, v0), (t1, v1) = points[lo], points[hi]
    return v0 + (v1 - v0) * (t - t0) / (t1 - t0) if t1 > t0 else v1


def force_columns(rows):
    return sorted(c for c in rows[0] if c.startswith("contact_force"))


def bodies(rows):
    names = sorted({c.rsplit("_", 1)[1] for c in rows[0]
                    if c.startswith("mean_displacement_x_body")})
    if names:
        return [("_" + b, b) for b in names]
    return [("", "body1")] if "mean_displacement_x" in rows[0] else []


def time_difference(a, b):
    """|a - b| of two event times, inf if only one of them happened."""
    if a != a and b != b:
        return 0.
    if a != a or b != b:
        return float("inf")
    return abs(a - b)


def contact_times(points):
    """First contact and last release of a force history (nan if none)."""
    on = [t for t, f in points if f > 0]
    if not on:
        return float("nan"), float("nan")
    last = max(t for t, f in points if f > 0)
    after = [t for t, f in points if t > last]
    return min(on), (after[0] if after else float("nan"))


reference_rows = table(reference_dir)
energy_scale = math.sqrt(max(float(r["energy_total"]) for r in reference_rows))
forces = force_columns(reference_rows)
body_columns = bodies(reference_rows)
reference_force = {c: series(reference_rows, c) for c in forces}


def measures(directory, is_reference):
    rows = table(directory)
    loop, overhead = timers(directory)
    m = {"dofs": max(int(float(r["dofs"])) for r in rows),
         "steps": len(rows) - 1, "time": loop - overhead, "overhead": overhead}
    if is_reference:
        m.update({"energy end": 0., "energy max": 0., "force max": 0.,
                  "force L1": 0., "position max": 0., "position end": 0.,
                  "contact": 0., "release": 0.})
        return m
    errors = [(float(r["time"]), float(r["error_reference"])) for r in rows
              if r["error_reference"] != "nan"]
    m["energy end"] = errors[-1][1] / energy_scale
    m["energy max"] = max(e for _, e in errors) / energy_scale
    force_max, force_l1, contact, release = 0., 0., 0., 0.
    for c in forces:
        mine = series(rows, c)
        ref = reference_force[c]
        peak = max(abs(f) for _, f in ref) or 1.
        differences = [abs(f - interpolate(ref, t)) for t, f in mine]
        force_max = max(force_max, max(differences) / peak)
        l1 = sum(0.5 * (differences[i] + differences[i + 1]) *
                 (mine[i + 1][0] - mine[i][0]) for i in range(len(mine) - 1))
        force_l1 = max(force_l1, l1 / (peak * (mine[-1][0] - mine[0][0])))
        a, b = contact_times(mine), contact_times(ref)
        contact = max(contact, time_difference(a[0], b[0]))
        release = max(release, time_difference(a[1], b[1]))
    m.update({"force max": force_max, "force L1": force_l1,
              "contact": contact, "release": release})
    position_max, position_end = 0., 0.
    for suffix, _ in body_columns:
        axes = [a for a in "xyz" if "mean_displacement_%s%s" % (a, suffix) in rows[0]]
        mine = [series(rows, "mean_displacement_%s%s" % (a, suffix)) for a in axes]
        ref = [series(reference_rows, "mean_displacement_%s%s" % (a, suffix)) for a in axes]
        distance = [math.sqrt(sum((mine[d][i][1] - interpolate(ref[d], mine[d][i][0])) ** 2
                                  for d in range(len(axes))))
                    for i in range(len(mine[0]))]
        position_max = max(position_max, max(distance))
        position_end = max(position_end, distance[-1])
    m.update({"position max": position_max, "position end": position_end})
    return m


results = {}
for key, (directory, mesh_level, tau) in directories.items():
    results[key] = dict(measures(directory, directory == reference_dir),
                        mesh_level=mesh_level, tau=tau)

# --- rates and Richardson estimates from the reference's configuration
keys = ["energy end", "energy max", "force max", "force L1", "position max",
        "position end", "contact", "release"]
base = configurations[0][0]


def rate_aligned(e_a, e_b, gap):
    """Errors of one shape, C h^r: the differences from the reference of two
    successive levels, the second @p gap levels below the reference, have
    e_a/e_b = (q^(gap+1) - 1)/(q^gap - 1) with q = 2^r; returns q."""
    ratio = e_a / e_b if e_b > 0 else float("nan")
    if not ratio == ratio:
        return float("nan")
    lo, hi = 1. + 1e-9, 1e3  # ratio(q) grows from (gap+1)/gap to infinity
    f = lambda q: (q ** (gap + 1) - 1) / (q ** gap - 1) - ratio
    if f(lo) >= 0:
        return float("nan")
    for _ in range(200):
        mid = math.sqrt(lo * hi)
        lo, hi = (mid, hi) if f(mid) < 0 else (lo, mid)
    return lo


def estimate(e):
    """(model, rate, reference's error, note) from the differences e of the
    levels 0 .. N-2 of the reference's configuration.

    'one shape' (Richardson): e_k = C (h_k^r - h_ref^r); the reference's
    error C h_ref^r, every run's error e_k + C h_ref^r. 'uncorrelated': the
    errors of the levels do not share their shape (the dispersive
    oscillations behind wave fronts), the difference from the reference is
    the run's own error (|e_k - E_k| <= E_ref), e_k = C h_k^r, and the
    reference's error is extrapolated, C h_ref^r = e_(N-2)^2 / e_(N-3). The
    model whose rate the levels before confirm best is taken; with three
    levels, which cannot tell them apart, the larger estimate."""
    n = len(e)
    if n < 2:
        return ("-", float("nan"), float("nan"), "two levels: no rate")
    if e[-1] <= 0:
        return ("-", float("nan"), 0., "no difference")
    candidates = []
    q = rate_aligned(e[-2], e[-1], 1)
    if q == q and q > 1.02:
        check = rate_aligned(e[-3], e[-2], 2) if n >= 3 else float("nan")
        candidates.append(("one shape", math.log2(q), e[-1] / (q - 1.),
                           math.log2(check) if check == check else float("nan")))
    if e[-2] > e[-1] * 1.02:
        r = math.log2(e[-2] / e[-1])
        check = math.log2(e[-3] / e[-2]) if n >= 3 and e[-2] > 0 and e[-3] > 0 \
            else float("nan")
        candidates.append(("uncorrelated", r, e[-1] * e[-1] / e[-2], check))
    if not candidates:
        return ("-", float("nan"), float("nan"), "not converging")
    def unconfirmed(model, r, error, note):
        # an 'uncorrelated' rate that the levels before do not confirm: the
        # reference's error lies between the extrapolation (the rate holds)
        # and the last difference (the last refinement gained nothing); the
        # estimate is their geometric middle (half the rate), the range is
        # printed
        if model != "uncorrelated":
            return (model, r, error, note)
        middle = math.sqrt(error * e[-1])
        return (model, r, middle, "%s; range %.3g-%.3g" % (note, error, e[-1]))

    if n < 3:
        # no level before to decide: the larger estimate, and the other
        model, r, error, _ = max(candidates, key=lambda c: c[2])
        others = [c for c in candidates if c[0] != model]
        return unconfirmed(model, r, error, "unchecked (three levels%s)" % (
            "; %s: rate %.2f, %.3g" % (others[0][0], others[0][1],
                                       others[0][2]) if others else ""))
    spread = lambda c: abs(c[3] - c[1]) / c[1] if c[3] == c[3] else float("inf")
    # the models that the levels before confirm (their rate within 25 %):
    # of these the larger estimate, as with three levels
    confirmed = [c for c in candidates if spread(c) <= 0.25]
    if confirmed:
        model, r, error, check = max(confirmed, key=lambda c: c[2])
        return (model, r, error, "asymptotic (rate %.2f before)" % check)
    model, r, error, check = min(candidates, key=spread)
    return unconfirmed(model, r, error,
                       "not asymptotic (rate %.2f before)" % check)


estimates = {}
for key in keys:
    model, r, error, note = estimate(
        [results[(base, k)][key] for k in range(finest)])
    estimates[key] = (r, error, note, model)


def estimated(key, value):
    """A run's estimated error from its difference @p value."""
    r, error, note, model = estimates[key]
    if model == "uncorrelated":
        return max(value, error)
    return value + error


# --- the table, the CSV, the plot
columns = ["configuration", "level", "mesh_level", "tau", "dofs", "steps",
           "time", "overhead"] + [k.replace(" ", "_") for k in keys] + \
          ["estimated_" + k.replace(" ", "_") for k in keys]
lines = []
for label, _ in configurations:
    for k in range(N):
        if (label, k) not in results:
            continue
        m = results[(label, k)]
        row = [label, k, m["mesh_level"], m["tau"], m["dofs"], m["steps"],
               m["time"], m["overhead"]] + [m[key] for key in keys]
        row += [estimated(key, m[key]) for key in keys]
        lines.append(row)
with open(os.path.join(out, "study.csv"), "w", newline="") as f:
    writer = csv.writer(f)
    writer.writerow(columns)
    writer.writerows(lines)

print("\nDifferences from the reference (the finest uniform run, %d DoFs, "
      "tau %g s), energy relative to sqrt(E) = %.4g:" %
      (results[(base, finest)]["dofs"], ref_tau, energy_scale))
print("%-18s %5s %9s %9s %8s | %9s %9s %9s %9s %9s %9s %9s" %
      ("configuration", "level", "DoFs", "steps", "time/s", "energy", "energy*",
       "force", "force L1", "pos./m", "contact", "release"))
for row in lines:
    m = dict(zip(columns, row))
    print("%-18s %5d %9d %9d %8.3g | %9.3g %9.3g %9.3g %9.3g %9.3g %9.3g %9.3g" %
          (m["configuration"], m["level"], m["dofs"], m["steps"], m["time"],
           m["energy_end"], m["energy_max"], m["force_max"], m["force_L1"],
           m["position_max"], m["contact"], m["release"]))
print("(energy: at the end; energy*: largest over the sample times; force "
      "and force L1 relative to the reference's peak; position: largest over "
      "time; contact, release: first contact and last release, s)")
print("\nRates and the reference's own error (from levels %d-%d of %s):"
      % (max(finest - 2, 0), finest, base))
for key in keys:
    r, e, note, model = estimates[key]
    print("   %-13s rate %6s  reference's error %9s  %-13s %s" %
          (key, "%.2f" % r if r == r else "-", "%.3g" % e if e == e else "-",
           model, note))
total = sum(m["time"] for m in results.values())
overhead = sum(m["overhead"] for m in results.values())
print("\nRuns: %.1f s of runs (wall time); the study's own work (writing and "
      "comparing states): %.1f s (%.0f %%)" %
      (total, overhead, 100 * overhead / max(total, 1e-300)))

estimated = [(m["configuration"], m["level"], m["time"],
              m["estimated_energy_max"]) for m in (dict(zip(columns, r)) for r in lines)]
target = args.target
if target is None and estimates["energy max"][1] == estimates["energy max"][1]:
    target = 2 * estimates["energy max"][1]
if target is not None and target == target:
    reach = [e for e in estimated if e[3] <= target]
    if reach:
        best = min(reach, key=lambda e: e[2])
        print("Fastest to an estimated energy-norm error (largest over time) "
              "of %.3g: %s, level %d, %.3g s" % (target, best[0], best[1], best[2]))
    else:
        print("No run reaches an estimated energy-norm error of %.3g" % target)
reference_error = estimates["energy max"][1]
unresolved = ["%s level %d" % (m["configuration"], m["level"])
              for m in (dict(zip(columns, r)) for r in lines)
              if m["energy_max"] > 0 and reference_error == reference_error
              and m["energy_max"] < 1.2 * reference_error]
if unresolved:
    print("Differences from the reference below 1.2 times its own estimated "
          "error (%.3g): %s; their errors are not resolved by this "
          "reference (their estimates are its error): add a level"
          % (reference_error, ", ".join(unresolved)))

try:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    figure, axis = plt.subplots(figsize=(6, 4.5))
    for label, _ in configurations:
        points = sorted((e[2], e[3]) for e in estimated if e[0] == label)
        points = [p for p in points if p[1] == p[1] and p[1] > 0]
        if points:
            axis.loglog(*zip(*points), "o-", label=label)
    axis.set_xlabel("wall time of the run [s]")
    axis.set_ylabel("estimated energy-norm error (max over time) / sqrt(E)")
    axis.set_title(os.path.basename(args.prm))
    axis.grid(True, which="both", alpha=0.3)
    axis.legend()
    figure.tight_layout()
    figure.savefig(os.path.join(out, "study.png"), dpi=100)
    print("Wrote %s and %s" % (os.path.join(out, "study.csv"),
                               os.path.join(out, "study.png")))
except ImportError:
    print("Wrote %s (no matplotlib: no plot)" % os.path.join(out, "study.csv"))
