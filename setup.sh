#!/usr/bin/env bash
# Sets bfemp up on Debian 12 and builds it; then runs what was asked:
#   ./setup.sh run     install what is missing, build, run prm/default.prm
#   ./setup.sh test    install what is missing, build, run the test suite
#   ./setup.sh build   install what is missing and build only
# Running it again only rebuilds what changed (and ccache keeps compiles).
set -euo pipefail
cd "$(dirname "$0")"
mode="${1:-build}"

packages=(libdeal.ii-dev libsuitesparse-dev libopenblas0-pthread gmsh cmake g++ make
          ccache numdiff perl
          python3-vtk9 python3-numpy python3-matplotlib)
missing=()
for package in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$package" 2>/dev/null |
    grep -q "install ok installed" || missing+=("$package")
done
if [ "${#missing[@]}" -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  sudo_cmd=""
  [ "$(id -u)" -eq 0 ] || sudo_cmd="sudo"
  $sudo_cmd apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $sudo_cmd apt-get install -y -qq "${missing[@]}"
fi

jobs="$(nproc)"
# The test categories (folders of tests/) of tests/debug_tests.txt, the unit
# tests that ./setup.sh test also runs in Debug.
debug_categories="$(grep -v '^#' tests/debug_tests.txt | cut -d/ -f1 | sort -u |
  paste -sd ';')"
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release > build.log 2>&1 ||
  { cat build.log; exit 1; }
cmake --build build -j "$jobs" ||
  { echo "setup: build failed"; exit 1; }
rm -f build.log
# Each phase reports its wall time: CI has a time limit, and these lines show
# where it goes.
echo "setup: set-up and Release build took ${SECONDS} s"

case "$mode" in
  run)
    build/bfemp prm/default.prm
    echo "setup: open output/default/particles.pvd in ParaView"
    ;;
  test)
    # "validation" holds the long runs; see doc/validation.md for them.
    status=0
    start=$SECONDS
    (cd build && ctest -j "$jobs" -LE validation --output-on-failure) ||
      status=1
    echo "setup: Release test suite took $((SECONDS - start)) s"
    # The unit tests of tests/debug_tests.txt again against a Debug build
    # (build-debug/: bfemp's Asserts and deal.II's debug checks run). The
    # scenes would take hours without optimization. No debug information:
    # this tree is for the checks, not for gdb, and -g is a third of its build.
    start=$SECONDS
    cmake -S . -B build-debug -DCMAKE_BUILD_TYPE=Debug -DBFEMP_DEBUG_INFO=OFF \
      "-DBFEMP_TEST_CATEGORIES=$debug_categories" > build-debug.log 2>&1 ||
      { cat build-debug.log; exit 1; }
    rm -f build-debug.log
    cmake --build build-debug -j "$jobs" ||
      { echo "setup: Debug build failed"; exit 1; }
    echo "setup: Debug build took $((SECONDS - start)) s"
    start=$SECONDS
    debug_tests="$(grep -v '^#' tests/debug_tests.txt |
      sed 's|^|^|; s|$|\\.debug$|' | paste -sd '|')"
    (cd build-debug && ctest -j "$jobs" -R "$debug_tests" --output-on-failure) ||
      status=1
    echo "setup: Debug unit tests took $((SECONDS - start)) s"
    exit "$status"
    ;;
  build) ;;
  *) echo "usage: ./setup.sh [run|test|build]"; exit 2 ;;
esac
