#!/usr/bin/python3
"""Accuracy of an adaptive run on an input nobody tuned, against the uniform
mesh of its finest level: the Hertz drop run through impact, rebound and
release (prm/hertz_drop_adaptive.prm with stiffer bodies, E = 100 Pa, dropped
at 0.5 m/s without a load: contact from 0.024 s to about 0.67 s, flight to
2 s, 500 steps of 0.004 s; the example's adaptive settings with Maximum
level 4; every run on deal.II's serial triangulation, which adapts in less
time than p4est's on one rank).

tools/study.py runs the uniform meshes of levels 1 to 5 (h alone, the same
tau) and the adaptive run (levels 1 to 4) as given and with each Mesh
refinement/Coarsening tolerance of --tolerances, with each Mesh
refinement/Position tolerance (m) of --position-tolerances, by the
criterion energy error instead of Kelly's, with the criterion curved
boundary added (to Kelly's, to energy error, and to the split by volume
with delta 0.4), by velocity jump with curved boundary and the contact
zone (Front widening 1; and Front widening 2 with Position tolerance
1e-4 m, every 2 and every 8 steps), the same with Front widening 1 and
Contact zone/Keep distance 0.3 m (alone, with Keep body motion, and with
both every 4 steps, and with both adapting every 32 steps while no
contact is near: Refinement interval without contact), and, marked by a tolerance instead of the
fractions, with each Mesh refinement/Error tolerance of --error-tolerances
(the middle one also adapting every 4 steps instead of 2) and of
--volume-tolerances with Error tolerance split = by volume, all compared with the uniform level-5 run. For each
adaptive run the script prints, against the uniform level-4 run (study
estimates of both errors: the difference from the level-5 run plus that
run's own estimated error): the ratios of the energy-norm error (largest
over time), of the contact-force error (largest over time / peak) and of the position error
(the bodies' mean displacement, largest over time), the release time's
difference in steps, and the ratio of the run times (wall time less the
comparisons).

Usage, from the repository's top folder after tools/setup.sh (about 18
minutes on one core):
    benchmarks/adaptive_accuracy.py [build/dyncontact] [--tolerances 1e-3,1e-4]
        [--position-tolerances 1e-3,1e-4] [--error-tolerances 0.2,0.1,0.05]
        [--volume-tolerances 0.4,0.2]"""
import options
import study_ratios
import os
import subprocess
import sys

arguments = sys.argv[1:]
tolerances = options.take_option(arguments, "--tolerances",
                                 lambda v: [t for t in v.split(",") if t],
                                 ["1e-3", "1e-4", "1e-5"])
error_tolerances = options.take_option(arguments, "--error-tolerances",
                                       lambda v: [t for t in v.split(",") if t],
                                       ["0.2", "0.1", "0.05"])
position_tolerances = options.take_option(
    arguments, "--position-tolerances",
    lambda v: [t for t in v.split(",") if t], ["1e-3", "1e-4"])
volume_tolerances = options.take_option(
    arguments, "--volume-tolerances", lambda v: [t for t in v.split(",") if t],
    ["0.4", "0.2"])
executable = os.path.abspath(arguments[0] if arguments else "build/dyncontact")
top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
work = os.path.abspath("results-adaptive-accuracy")
os.makedirs(work, exist_ok=True)
prm = os.path.join(work, "hertz_long_drop.prm")
with open(prm, "w") as f:
    f.write("include %s\n" % os.path.join(top, "prm", "hertz_drop_adaptive.prm"))
    f.write("""subsection Scene
  subsection Hertz
    set Drop velocity = 0.5
    set Load          = 0
    set Initial gap   = 0.01
  end
end
subsection Mesh
  set Triangulation = serial
end
subsection Mesh refinement
  set Maximum level               = 4
  set Initial contact refinements = 3
end
subsection Material
  set Young's modulus        = 100
  set Viscous shear modulus  = 0.1
  set Viscous Lame parameter = 0.1
end
subsection Material of body 2
  set Young's modulus = 100
end
subsection Time integration
  set Time step = 0.004
  set End time  = 2
end
""")
command = [sys.executable, os.path.join(top, "tools", "study.py"), prm,
           "--refine", "h", "--levels", "5", "--samples", "20",
           "--out", os.path.join(work, "study"), "--executable", executable]
for t in tolerances:
    command += ["--adaptive-variant",
                "tolerance %s:Mesh refinement/Coarsening tolerance=%s" % (t, t)]
command += ["--adaptive-variant",
            "energy error:Mesh refinement/Criteria=energy error, contact zone"]
command += ["--adaptive-variant",
            "curved boundary:Mesh refinement/Criteria=kelly velocity, "
            "contact zone, curved boundary"]
command += ["--adaptive-variant",
            "curved boundary and energy error:Mesh refinement/Criteria=energy "
            "error, contact zone, curved boundary"]
command += ["--adaptive-variant",
            "curved boundary and delta 0.4 by volume:Mesh refinement/"
            "Criteria=kelly velocity, contact zone, curved boundary;Mesh "
            "refinement/Error tolerance=0.4;Mesh refinement/Error tolerance "
            "split=by volume"]
jump = ("Mesh refinement/Criteria=velocity jump, contact zone, curved "
        "boundary;Mesh refinement/Front widening=")
command += ["--adaptive-variant",
            "velocity jump and curved boundary:" + jump + "1"]
command += ["--adaptive-variant",
            "velocity jump widened 2, curved boundary, position 1e-4:" +
            jump + "2;Mesh refinement/Position tolerance=1e-4"]
command += ["--adaptive-variant",
            "the same every 8:" + jump + "2;Mesh refinement/Position "
            "tolerance=1e-4;Mesh refinement/Refinement interval=8"]
keep = jump + "1;Mesh refinement/Contact zone/Keep distance=0.3"
command += ["--adaptive-variant",
            "velocity jump, curved boundary, keep 0.3 m:" + keep]
command += ["--adaptive-variant",
            "the same keeping body motion:" + keep +
            ";Mesh refinement/Keep body motion=true"]
command += ["--adaptive-variant",
            "the same every 4:" + keep + ";Mesh refinement/Keep body "
            "motion=true;Mesh refinement/Refinement interval=4"]
command += ["--adaptive-variant",
            "the same, without contact every 32:" + keep +
            ";Mesh refinement/Keep body motion=true;Mesh refinement/"
            "Refinement interval without contact=32"]
for t in position_tolerances:
    command += ["--adaptive-variant",
                "position %s:Mesh refinement/Position tolerance=%s" % (t, t)]
for t in error_tolerances:
    command += ["--adaptive-variant",
                "delta %s:Mesh refinement/Error tolerance=%s" % (t, t)]
for t in volume_tolerances:
    command += ["--adaptive-variant",
                "delta %s by volume:Mesh refinement/Error tolerance=%s;"
                "Mesh refinement/Error tolerance split=by volume" % (t, t)]
if error_tolerances:
    t = error_tolerances[len(error_tolerances) // 2]
    command += ["--adaptive-variant",
                "delta %s every 4:Mesh refinement/Error tolerance=%s;"
                "Mesh refinement/Refinement interval=4" % (t, t)]
result = subprocess.run(command, capture_output=True, text=True)
print(result.stdout)
if result.returncode != 0:
    sys.exit("adaptive_accuracy: the study failed:\n" + result.stderr)

study_ratios.print_ratios(os.path.join(work, "study", "study.csv"),
                          lambda level: 4 + level)
