#!/usr/bin/python3
"""Hertz impact in 3D: prm/ball_drop_adaptive.prm (a half ball, R = 1 m,
E = 100 Pa on a block, 0.1 m/s) with each scheme and a given finest
level and time step, against Hertz's quasi-static impact theory: contact
duration t_c = 2.94 alpha_max / v and peak force
F_max = 4/3 E* sqrt(R) alpha_max^(3/2), alpha_max = (15 m v^2 /
(16 E* sqrt(R)))^(2/5), m the mesh's half-ball mass (4 times the quarter's,
from its kinetic energy). Prints one table row per run: the ratios to
Hertz, the rebound velocity at the end time (momentum of the ball over
its mass) and the energy left in the bodies as vibration (the total
energy less the ball's rigid kinetic energy), in % of the impact energy.
Usage, from the repository's top folder after tools/setup.sh:
    benchmarks/hertz_impact.py [build/dyncontact] [ranks] [levels] [taus]
        [schemes] [prm]
e.g. benchmarks/hertz_impact.py build/dyncontact 2 4,5 0.02,0.01
A level is the adaptive mesh's finest level (an integer), or a fixed mesh
gGzZ[pP]: G global refinements, Z refinements of the scene's contact zone
(Scene/Ball on block/Contact zone refinements, sized from Hertz's impact),
polynomial degree P (1 if not given), e.g. g1z3,g2z2,g1z2p2.
(prm: another version of prm/ball_drop_adaptive.prm, e.g. a larger block;
the formulas assume its E, nu and v)."""
import options  # noqa: F401 (--help prints the docstring above)
import csv
import math
import os
import re
import subprocess
import sys
import time

executable = sys.argv[1] if len(sys.argv) > 1 else "build/dyncontact"
ranks = int(sys.argv[2]) if len(sys.argv) > 2 else 1
levels = (sys.argv[3] if len(sys.argv) > 3 else "4").split(",")
taus = [float(x) for x in (sys.argv[4] if len(sys.argv) > 4 else "0.02").split(",")]
schemes = sys.argv[5].split(",") if len(sys.argv) > 5 else ["N-CI", "N-CS", "N-CS++"]
os.makedirs("results-hertz-impact", exist_ok=True)
base = open(sys.argv[6] if len(sys.argv) > 6 else "prm/ball_drop_adaptive.prm").read()
E, nu, R, v = 100.0, 0.3, 1.0, 0.1
E_star = 1.0 / (2 * (1 - nu * nu) / E)

print("| scheme | finest level | τ (s) | mean DoFs | t_c / Hertz | F_max / Hertz "
      "| rebound v (m/s) | vibration (% of E0) | wall (s) |")
print("|---|---|---|---|---|---|---|---|---|")
for level in levels:
    for tau in taus:
        for scheme in schemes:
            name = "%s-%s-%g" % (scheme, level, tau)
            prm = "results-hertz-impact/%s.prm" % name
            fixed = re.fullmatch(r"g(\d+)z(\d+)(?:p(\d+))?", level)
            with open(prm, "w") as f:
                f.write(base)
                f.write("\nset Output directory = results-hertz-impact/%s\n" % name)
                f.write("subsection Output\n  set Write vtu = false\nend\n")
                if fixed:
                    f.write("set Polynomial degree = %s\n" % (fixed.group(3) or "1"))
                    f.write("subsection Mesh\n  set Initial global refinements = %s\nend\n"
                            "subsection Mesh refinement\n  set Refinement interval = 0\n"
                            "  set Initial contact refinements = 0\nend\n"
                            "subsection Scene\n  subsection Ball on block\n"
                            "    set Contact zone refinements = %s\n  end\nend\n"
                            % (fixed.group(1), fixed.group(2)))
                else:
                    f.write("subsection Mesh refinement\n  set Maximum level = %d\n"
                            "  set Initial contact refinements = %d\nend\n"
                            % (int(level), int(level) - 1))
                f.write("subsection Time integration\n  set Scheme = %s\n"
                        "  set Time step = %g\nend\n" % (scheme, tau))
            command = [executable, prm]
            if ranks > 1:
                command = ["mpirun", "-np", str(ranks)] + command
            start = time.time()
            subprocess.run(command, check=True, stdout=subprocess.DEVNULL)
            wall = time.time() - start
            rows = list(csv.DictReader(
                open("results-hertz-impact/%s/statistics.tsv" % name), delimiter="\t"))
            E0 = float(rows[0]["energy_kinetic"])
            m = 4 * 2 * E0 / v ** 2
            alpha = (15 * m * v * v / (16 * E_star * math.sqrt(R))) ** 0.4
            t_c = 2.94 * alpha / v
            F_max = 4.0 / 3.0 * E_star * math.sqrt(R) * alpha ** 1.5
            active = [float(r["time"]) for r in rows if float(r["active_nodes"]) > 0]
            # contact from the first to the last step with active nodes,
            # each end taken in the middle of its step
            duration = active[-1] - active[0] + tau
            force = 4 * max(float(r["contact_force"]) for r in rows)
            last = rows[-1]
            # the ball's momentum: all bodies' minus the block's
            rebound = (float(last["momentum_y"]) - float(last["momentum_y_body2"])) / (m / 4)
            vibration = (float(last["energy_total"]) - 0.5 * (m / 4) * rebound ** 2) / E0
            dofs = sum(float(r["dofs"]) for r in rows) / len(rows)
            print("| %s | %s | %g | %.0f | %.3f | %.3f | %.4f | %.2f | %.0f |"
                  % (scheme, level, tau, dofs, duration / t_c, force / F_max,
                     rebound, 100 * vibration, wall), flush=True)
