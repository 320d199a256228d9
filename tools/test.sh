#!/usr/bin/env bash
# Set-up (tools/setup.sh), then the whole ctest suite in ./build.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh --tests
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cmake --build build --target test_executables -j "$(nproc)"
# ninja compacts its logs when they hold many stale records (after
# incremental builds); this serial call does it, not two tests' concurrent
# ones ("ninja: error: opening deps log" fails a test otherwise)
cmake --build build --target test_executables
# deal.II's run_test.cmake takes a guard file it finds when a test starts
# for the sign of an interrupted run and relinks the test's executable. A
# build leaves one for every test: leave them as a finished run does, so
# that ctest runs what was just built. (The variants of one executable,
# <name>.mpirun=1 and .mpirun=2, run one after the other: tests/CMakeLists.txt
# refuses a plain <name>.output beside them.)
find build/tests -name interrupt_guard.cc -exec mv -f {} {}_bck \;
cd build
ctest --output-on-failure -j "$(nproc)"
