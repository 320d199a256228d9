#!/usr/bin/python3
"""Jacobi or AMG: every dynamic example of prm/ and prm/extreme/ (the static
ones, ball_on_block and hertz_static, always take AMG) run three times, with
'Contact solver/Preconditioner' = AMG, Jacobi and automatic, VTU off. Prints
per example the time loop's wall time and the CG iterations of each run,
Jacobi's time over AMG's, and what 'automatic' took with the bound of the
condition number it decided by (from summary.txt). One core, one run each:
the times of the small examples are a few milliseconds and vary by 10-20%.
Usage, from the repository's top folder after tools/setup.sh:
    benchmarks/preconditioners.py [build/dyncontact] [prm ...]"""
import options  # noqa: F401 (--help prints the docstring above)
import glob
import os
import re
import subprocess
import sys

arguments = sys.argv[1:]
executable = os.path.abspath(arguments[0] if arguments else "build/dyncontact")
top = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
files = [os.path.abspath(f) for f in arguments[1:]] or \
    sorted(glob.glob(top + "/prm/*.prm")) + \
    sorted(glob.glob(top + "/prm/extreme/*.prm"))
work = os.path.abspath("results-preconditioners")
os.makedirs(work, exist_ok=True)


def run(prm, choice):
    """(time loop in s, CG iterations, the summary's preconditioner line)"""
    name = os.path.splitext(os.path.basename(prm))[0]
    directory = "%s/%s-%s" % (work, name, choice)
    # the example's own folder, so that its relative file names still hold
    text = open(prm).read() + """
set Output directory = %s
subsection Output
  set Write vtu = false
end
subsection Contact solver
  set Preconditioner = %s
end
""" % (directory, choice)
    variant = os.path.join(os.path.dirname(prm), ".preconditioners-%s.prm" % name)
    with open(variant, "w") as f:
        f.write(text)
    try:
        subprocess.run([executable, variant], stdout=subprocess.DEVNULL,
                       stderr=subprocess.DEVNULL, check=True, cwd=work)
    finally:
        os.remove(variant)
    summary = open(directory + "/summary.txt").read()
    loop = float(re.search(r"of which the time loop ([0-9.e+-]+) s", summary).group(1))
    cg = int(float(re.search(r"^iterations: .*CG ([0-9.e+]+)", summary, re.M).group(1)))
    line = re.search(r"^preconditioner: (.*)$", summary, re.M).group(1)
    return loop, cg, line


print("%-24s %10s %7s %10s %7s %7s   %s" %
      ("example", "AMG loop", "CG", "Jacobi", "CG", "J/AMG", "automatic"))
for prm in files:
    name = os.path.splitext(os.path.basename(prm))[0]
    if re.search(r"(?m)^\s*set Scheme\s*=\s*static", open(prm).read()):
        continue
    amg, jacobi, automatic = (run(prm, c) for c in ("AMG", "Jacobi", "automatic"))
    bound = re.search(r"at most ([0-9.e+-]+)", automatic[2])
    print("%-24s %9.4fs %7d %9.4fs %7d %7.2f   %s%s" %
          (name, amg[0], amg[1], jacobi[0], jacobi[1], jacobi[0] / amg[0],
           automatic[2].split()[0],
           " (bound %s)" % bound.group(1) if bound else ""), flush=True)
