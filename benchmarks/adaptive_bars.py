#!/usr/bin/python3
"""Accuracy of adaptive runs where the waves run through the whole bodies:
the two bars (prm/two_bars.prm) and the chain of three bars
(prm/bar_chain.prm), against the uniform mesh of their finest level.

Coarse meshes of 10 cells along (2 and 3 across the two bars, 1 across the
chain), adapted every 4 steps between levels 0 and 2 by Kelly's indicator of
the velocity and the contact zone (refine 20 %, coarsen 30 %), two initial
contact refinements, Mesh refinement/Contact zone/Distance 0.3 m (the two
bars are 0.2 m apart at t = 0, the chain's first gap is 0.1 m). tools/study.py
--refine h --levels 5 runs the uniform meshes of levels 0 to 4 (the level-4
run is the reference) and the adaptive runs of finest levels 2 and 3 (and
4, the reference's level, which take about two thirds of the time and are
not reported: tools/study.py runs every level up to the reference's): as
given, by the criterion energy error, by velocity jump (Front widening 1),
by velocity jump with Front widening 2 and Position tolerance 1e-4 m (every
4 and every 8 steps), and marked by Error tolerance 0.1. For each scene and
finest level the script prints the ratios of the estimated errors (energy
norm, contact force, position; largest over time) to the uniform run's of
that level, the release's steps off the reference, and the ratio of the
run times.

Usage, from the repository's top folder after tools/setup.sh (about 6
minutes on one core):
    benchmarks/adaptive_bars.py [build/dyncontact] [two_bars] [chain]"""
import options  # noqa: F401 (--help prints the docstring above)
import study_ratios
import os
import subprocess
import sys

arguments = sys.argv[1:]
executable = os.path.abspath(arguments[0] if arguments and
                             arguments[0] not in ("two_bars", "chain")
                             else "build/dyncontact")
scenes = [a for a in arguments if a in ("two_bars", "chain")] or \
    ["two_bars", "chain"]
top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
work = os.path.abspath("results-adaptive-bars")
os.makedirs(work, exist_ok=True)

mesh = {"two_bars": ("Two bars", "    set Cells along length  = 10\n"
                     "    set Cells across        = 2\n"
                     "    set Cells across body 2 = 3\n"),
        "chain": ("Bar chain", "    set Cells along length = 10\n"
                  "    set Cells across       = 1\n")}
files = {"two_bars": "two_bars.prm", "chain": "bar_chain.prm"}
adaptation = """subsection Mesh refinement
  set Refinement interval         = 4
  set Maximum level               = 2
  set Criteria                    = kelly velocity, contact zone
  set Refine fraction             = 0.2
  set Coarsen fraction            = 0.3
  set Initial contact refinements = 2
  subsection Contact zone
    set Distance = 0.3
  end
end
subsection Output
  set Write vtu = false
end
"""
jump = ("Mesh refinement/Criteria=velocity jump, contact zone;"
        "Mesh refinement/Front widening=")
variants = [
    "energy error:Mesh refinement/Criteria=energy error, contact zone",
    "velocity jump:" + jump + "1",
    "jump, widening 2, position:" + jump + "2;"
    "Mesh refinement/Position tolerance=1e-4",
    "jump, widening 2, position, every 8:" + jump + "2;"
    "Mesh refinement/Position tolerance=1e-4;"
    "Mesh refinement/Refinement interval=8",
    "delta 0.1:Mesh refinement/Error tolerance=0.1"]
for scene in scenes:
    prm = os.path.join(work, scene + ".prm")
    subsection, entries = mesh[scene]
    with open(prm, "w") as f:
        f.write("include %s\n" % os.path.join(top, "prm", files[scene]))
        f.write("subsection Scene\n  subsection %s\n%s  end\nend\n"
                % (subsection, entries))
        f.write(adaptation)
    command = [sys.executable, os.path.join(top, "tools", "study.py"), prm,
               "--refine", "h", "--levels", "5",
               "--out", os.path.join(work, scene), "--executable", executable]
    for v in variants:
        command += ["--adaptive-variant", v]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit("adaptive_bars: the study of %s failed:\n%s"
                 % (scene, result.stderr))
    print("%s (%s):" % (scene, prm))
    study_ratios.print_ratios(os.path.join(work, scene, "study.csv"),
                              lambda level: 2 + level)
    print()
