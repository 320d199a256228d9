#!/usr/bin/env bash
# Set-up (tools/setup.sh), then the default scene prm/bar_impact.prm, written
# to ./results-bar-impact (VTU/PVTU/PVD and statistics.tsv).
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
./build/dyncontact prm/bar_impact.prm
