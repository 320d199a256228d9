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
#                                test), installed while the library and the
#                                test executables are built
set -euo pipefail
cd "$(dirname "$0")/.."

missing() {
  for p in "$@"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" \
      || echo "$p"
  done
}
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
updated=false
install_packages() {
  echo "Installing: $*"
  if [ "$updated" = false ]; then
    $SUDO apt-get update -q
    updated=true
  fi
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q \
    --no-install-recommends "$@"
}

build_packages=($(missing libdeal.ii-dev ninja-build openmpi-bin numdiff))
test_packages=()
if [ "${1:-}" = "--tests" ]; then
  test_packages=($(missing perl python3 python3-matplotlib \
                           paraview python3-paraview xvfb xauth))
fi
[ ${#build_packages[@]} -eq 0 ] || install_packages "${build_packages[@]}"

# the test packages (ParaView is most of the download) while the build runs
mkdir -p build
installer=""
if [ ${#test_packages[@]} -gt 0 ]; then
  install_packages "${test_packages[@]}" > build/install-test-packages.log 2>&1 &
  installer=$!
  echo "Installing the test packages in the background (build/install-test-packages.log)"
fi

# Open MPI refuses to run as root unless told otherwise
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# with --tests, the test executables too: they need none of the test
# packages, which are installed meanwhile
targets=(all)
[ "${1:-}" = "--tests" ] && targets+=(test_executables)
status=0
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release \
  && cmake --build build -j "$(nproc)" --target "${targets[@]}" || status=$?
if [ -n "$installer" ]; then
  if ! wait "$installer"; then
    cat build/install-test-packages.log
    echo "tools/setup.sh: installing the test packages failed (above)" >&2
    exit 1
  fi
  echo "The test packages are installed."
fi
exit $status
