#!/usr/bin/env bash
# Installs what is missing (Debian packages), then configures and builds
# dyncontact in Release in ./build. Used by tools/run.sh and tools/test.sh.
#
#   bash tools/setup.sh          what a build and a run need: deal.II (with
#                                Trilinos, p4est, Open MPI), Ninja, mpirun,
#                                numdiff (deal.II's test macros refuse to
#                                configure without it)
#   bash tools/setup.sh --tests  and what the test suite needs besides:
#                                Python 3 with matplotlib (study plots),
#                                ParaView's pvpython and Xvfb (the ParaView
#                                test)
set -euo pipefail
cd "$(dirname "$0")/.."

packages=(libdeal.ii-dev ninja-build openmpi-bin numdiff)
if [ "${1:-}" = "--tests" ]; then
  packages+=(perl python3 python3-matplotlib
             paraview python3-paraview xvfb xauth)
fi
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
    || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "Installing: ${missing[*]}"
  SUDO=""
  [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q \
    --no-install-recommends "${missing[@]}"
fi

# Open MPI refuses to run as root unless told otherwise
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
cmake --build build -j "$(nproc)"
