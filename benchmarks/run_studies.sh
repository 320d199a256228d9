#!/usr/bin/env bash
# Runs the studies of doc/results.md and makes their plots in doc/. From the
# repository's top folder after tools/setup.sh; takes about 10 minutes on
# one core. The CSVs go to results-study/*.csv.
set -euo pipefail
cd "$(dirname "$0")/.."
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
S="/usr/bin/python3 benchmarks/study.py --executable build/dyncontact --work results-study"
P="/usr/bin/python3 benchmarks/plot_study.py"
mkdir -p results-study

# 1. bar impact, fixed h (40 cells), tau -> 0, error against a reference
#    with tau/8 on the same mesh (the paper's setting)
$S --prm prm/bar_impact.prm --out results-study/bar_tau.csv --force-reference \
   --tau0 0.025 --tau-levels 0,1,2,3,4 --mesh-levels 0 --reference-factor 8 \
   --reference-pressure 1 --set "Scene/Bar impact/Initial gap=0.1037"
$P results-study/bar_tau.csv doc/study_bar_tau "bar impact, h = 1/40:"

# 2. bar impact, h and tau refined together, error against the exact solution
$S --prm prm/bar_impact.prm --out results-study/bar_joint.csv --joint \
   --tau0 0.025 --tau-levels 0,1,2,3 --mesh-levels 0,1,2,3 --h0 0.05 \
   --reference-pressure 1 --set "Scene/Bar impact/Cells along length=20" \
   --set "Scene/Bar impact/Initial gap=0.1037"
$P results-study/bar_joint.csv doc/study_bar_joint "bar impact, h and tau:"

# 3. the viscous bar (no exact solution): fixed h, reference tau/8
$S --prm prm/bar_impact.prm --out results-study/bar_viscous.csv \
   --tau0 0.025 --tau-levels 0,1,2,3 --mesh-levels 0 --reference-factor 8 \
   --set "Scene/Bar impact/Initial gap=0.1037" --set "Material/Viscous shear modulus=0.01"
$P results-study/bar_viscous.csv doc/study_bar_viscous "viscous bar:"

# 4. two bars, non-matching meshes (8 and 11 across), exact, joint
$S --prm prm/two_bars.prm --out results-study/two_bars.csv --joint \
   --tau0 0.025 --tau-levels 0,1,2 --mesh-levels 0,1,2 --h0 0.05 \
   --reference-pressure 1 --set "Scene/Two bars/Cells along length=20" \
   --set "Scene/Two bars/Cells across=4" --set "Scene/Two bars/Cells across body 2=6" \
   --set "Scene/Two bars/Initial gap=0.1037"
$P results-study/two_bars.csv doc/study_two_bars "two bars:"

# 5. the Hertz drop (reference tau/8 on the same mesh), to t = 0.4 s
$S --prm prm/hertz_drop.prm --out results-study/hertz.csv \
   --tau0 0.02 --tau-levels 0,1,2,3 --mesh-levels 0 --reference-factor 8 \
   --set "Time integration/End time=0.4"
$P results-study/hertz.csv doc/study_hertz "Hertz drop:"

# 6. a 3D case: two bars in 3D (2 and 3 cells across), exact, joint
$S --prm prm/two_bars.prm --out results-study/two_bars_3d.csv --joint \
   --tau0 0.05 --tau-levels 0,1,2 --mesh-levels 0,1,2 --h0 0.1 \
   --reference-pressure 1 --set "Dimension=3" --set "Scene/Two bars/Cells along length=10" \
   --set "Scene/Two bars/Cells across=1" --set "Scene/Two bars/Cells across body 2=2" \
   --set "Scene/Two bars/Initial gap=0.1037"
$P results-study/two_bars_3d.csv doc/study_two_bars_3d "3D two bars:"
