#!/usr/bin/python3
"""Convergence and work-precision study: runs a base prm for several
schemes, time steps tau0/2^k and mesh levels (global refinements), in
Release, and writes a CSV with one row per run.

Errors: against the scene's exact solution (column error_energy_norm) if it
has one; otherwise against a reference run on the same mesh with a much
smaller time step (the paper's setting: fixed h, tau -> 0), computed once per
mesh level, cached in <work>/cache, and compared by the program itself
(subsection Reference solution).

Usage (from the repository's top folder, after tools/setup.sh):
  benchmarks/study.py --prm prm/bar_impact.prm --out study.csv \\
      --schemes N-CI,N-CS,N-CS++ --tau0 0.025 --tau-levels 0,1,2 \\
      --mesh-levels 0,1 [--joint] [--reference-factor 16] \\
      [--reference-pressure 1] [--set "Scene/Bar impact/Initial gap=0.1037"] ...
--joint pairs tau level k with mesh level k (h and tau refined together);
otherwise every tau level is run on every mesh level. --set overrides
entries of the base prm (subsection/.../entry=value)."""
import argparse
import csv
import hashlib
import math
import os
import subprocess
import time

parser = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
parser.add_argument("--prm", required=True)
parser.add_argument("--out", required=True)
parser.add_argument("--executable", default="build/dyncontact")
parser.add_argument("--work", default="results-study",
                    help="runs go to <work>/<name of the CSV>, references to <work>/cache")
parser.add_argument("--schemes", default="N-CI,N-CS,N-CS++")
parser.add_argument("--tau0", type=float, required=True)
parser.add_argument("--tau-levels", default="0,1,2")
parser.add_argument("--mesh-levels", default="0")
parser.add_argument("--joint", action="store_true")
parser.add_argument("--h0", type=float, default=1.0,
                    help="cell size of mesh level 0, for the CSV's h column")
parser.add_argument("--reference-factor", type=int, default=16)
parser.add_argument("--reference-pressure", type=float, default=0.0,
                    help="exact contact pressure for the overshoot; 0: the "
                         "reference run's maximum")
parser.add_argument("--set", action="append", default=[])
parser.add_argument("--force-reference", action="store_true",
                    help="errors against the reference run even where the "
                         "scene has an exact solution (the time error at fixed h)")
parser.add_argument("--mpi", type=int, default=1, help="MPI ranks per run")
args = parser.parse_args()

base = open(args.prm).read()
# every study gets its own folder of runs; the reference cache is shared
cache = os.path.join(args.work, "cache")
args.work = os.path.join(args.work, os.path.splitext(os.path.basename(args.out))[0])
os.makedirs(cache, exist_ok=True)
os.makedirs(args.work, exist_ok=True)


def overrides(entries):
    """prm text setting subsection/entry=value pairs (later entries win)."""
    text = ""
    for item in entries:
        path, value = item.split("=", 1)
        parts = [p.strip() for p in path.split("/")]
        for sub in parts[:-1]:
            text += "subsection %s\n" % sub
        text += "set %s = %s\n" % (parts[-1], value.strip())
        text += "end\n" * (len(parts) - 1)
    return text


def run(name, entries, directory):
    text = base + "\n" + overrides(args.set + entries + [
        "Output directory=" + directory, "Output/Write vtu=false",
        "Postprocess/Error energy norm/Interval=every step"])
    prm = directory + ".prm"
    with open(prm, "w") as f:
        f.write(text)
    command = [args.executable, prm]
    if args.mpi > 1:
        command = ["mpirun", "-np", str(args.mpi)] + command
    start = time.time()
    subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
    wall = time.time() - start
    rows = list(csv.DictReader(open(directory + "/statistics.tsv"), delimiter="\t"))
    return rows, wall


schemes = args.schemes.split(",")
tau_levels = [int(k) for k in args.tau_levels.split(",")]
mesh_levels = [int(m) for m in args.mesh_levels.split(",")]
pairs = (list(zip(mesh_levels, tau_levels)) if args.joint
         else [(m, k) for m in mesh_levels for k in tau_levels])
smallest_tau = args.tau0 / 2 ** max(tau_levels)
interval = args.tau0  # a multiple of every time step of the sweep


def mesh_entry(m):
    return "Mesh/Initial global refinements=%d" % m


references = {}


def reference(m):
    """Reference run on mesh level m (cached): tau_min / factor."""
    if m in references:
        return references[m]
    entries = [mesh_entry(m),
               "Time integration/Time step=%.17g" % (smallest_tau / args.reference_factor),
               "Reference solution/Write states=true",
               "Reference solution/Interval=%.17g" % interval]
    key = hashlib.sha1((base + repr(args.set) + repr(entries) + str(args.mpi)).encode()).hexdigest()[:12]
    directory = os.path.join(cache, key)
    entries.append("Reference solution/Directory=" + directory + "/states")
    if os.path.exists(directory + "/statistics.tsv"):
        rows = list(csv.DictReader(open(directory + "/statistics.tsv"), delimiter="\t"))
    else:
        rows, _ = run("reference", entries, directory)
    references[m] = (directory + "/states", rows)
    return references[m]


exact = None
with open(args.out, "w", newline="") as out:
    writer = csv.writer(out)
    writer.writerow(["scheme", "mesh_level", "h", "tau", "dofs", "steps", "wall_time",
                     "error_end", "error_max", "error_source", "energy_lost",
                     "pressure_overshoot", "critical_measure_sum",
                     "velocity_correction_sum", "mean_active_set_iterations"])
    for scheme in schemes:
        for m, k in pairs:
            tau = args.tau0 / 2 ** k
            entries = [mesh_entry(m), "Time integration/Scheme=" + scheme,
                       "Time integration/Time step=%.17g" % tau]
            name = "%s-m%d-k%d" % (scheme, m, k)
            directory = os.path.join(args.work, name)
            if exact is None or not exact:
                rows, wall = run(name, entries, directory)
                exact = "error_energy_norm" in rows[0] and not args.force_reference
                if not exact:
                    states, _ = reference(m)
                    rows, wall = run(name, entries + [
                        "Reference solution/Compare with states=true",
                        "Reference solution/Directory=" + states,
                        "Reference solution/Interval=%.17g" % interval], directory)
            else:
                rows, wall = run(name, entries, directory)
            column = "error_energy_norm" if exact else "error_reference"
            errors = [float(r[column]) for r in rows if not math.isnan(float(r[column]))]
            p_ref = args.reference_pressure
            if p_ref <= 0:
                p_ref = max(float(r["max_contact_pressure"]) for r in reference(m)[1])
            p_max = max(float(r["max_contact_pressure"]) for r in rows)
            e0 = float(rows[0]["energy_total"])
            e_end = (float(rows[-1]["energy_total"]) + float(rows[-1]["dissipation_viscous"])
                     + float(rows[-1].get("dissipation_numerical", 0.)))
            steps = len(rows) - 1
            writer.writerow([scheme, m, args.h0 / 2 ** m, tau,
                             int(max(float(r["dofs"]) for r in rows)), steps,
                             "%.4g" % wall, "%.6g" % errors[-1], "%.6g" % max(errors),
                             "exact" if exact else "reference",
                             "%.6g" % ((e0 - e_end) / abs(e0) if e0 != 0 else 0.),
                             "%.6g" % (p_max / p_ref - 1. if p_ref > 0 else float("nan")),
                             "%.6g" % float(rows[-1]["critical_measure_sum"]),
                             "%.6g" % sum(float(r["velocity_correction"]) for r in rows),
                             "%.4g" % (sum(float(r["active_set_iterations"]) for r in rows[1:]) / max(steps, 1))])
            out.flush()
            print("%-7s mesh %d tau %-10.4g error %.4g (%s)" % (scheme, m, tau, max(errors),
                                                               "exact" if exact else "reference"))
print("wrote " + args.out)
