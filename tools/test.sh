#!/usr/bin/env bash
# Set-up (tools/setup.sh), then the whole ctest suite in ./build.
set -euo pipefail
cd "$(dirname "$0")/.."
bash tools/setup.sh
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
cmake --build build --target test_executables -j "$(nproc)"
cd build
ctest --output-on-failure -j "$(nproc)"
