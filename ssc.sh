#!/bin/bash
# ssc.sh: set-up, build, run and test in one place (see README.md).
#   ./ssc.sh run [FILE.prm] [ssc options]   install, build, run a scene (by
#                                           default the forearm indentation,
#                                           with its plots) into output/
#   ./ssc.sh test                           install, build, run the test suite
#   ./ssc.sh test-debug                     the fast tests against Debian's
#                                           debug deal.II (Asserts on), in
#                                           build-debug/
#   ./ssc.sh format-check                   every C++ file formatted with
#                                           the deal.II .clang-format, and
#                                           the folder include rule kept?
#   ./ssc.sh build                          install and build only
# SSC_RANKS sets the MPI ranks of "run" (default: one per core, or one for
# a scene with a direct factor, whose cell loops then take every core as
# threads; DEAL_II_NUM_THREADS limits them).
set -euo pipefail
ROOT="$(cd "$(dirname "$0")" && pwd)"
BUILD="${SSC_BUILD_DIR:-$ROOT/build}"
JOBS="${SSC_JOBS:-2}"
RANKS="${SSC_RANKS:-$(nproc)}"
MAIN_SCENE="$ROOT/prm/forearm_indentation.prm"

PACKAGES="libdeal.ii-dev libcgal-dev libeigen3-dev libboost-dev
  nlohmann-json3-dev libsuitesparse-dev libmumps-dev libopenblas0-serial
  numdiff cmake ninja-build ccache openmpi-bin calculix-ccx
  python3-matplotlib python3-numpy"

install_packages() {
  local missing=""
  for p in $PACKAGES; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" ||
      missing="$missing $p"
  done
  if [ -n "$missing" ]; then
    echo "ssc.sh: installing Debian packages:$missing"
    local sudo=""
    [ "$(id -u)" -eq 0 ] || sudo="sudo"
    $sudo apt-get update -qq
    DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -qq \
      --no-install-recommends $missing
  fi
}

# configure BUILD_DIR BUILD_TYPE [cmake options]
configure() {
  local dir="$1" type="$2"
  shift 2
  export CCACHE_DIR="${CCACHE_DIR:-$HOME/.cache/ccache}"
  # paths below the project relative and the build folder out of the hash,
  # so that a fresh clone elsewhere (CI) reuses what an earlier build
  # compiled (deal.II's flags carry -g, which hashes the folder otherwise)
  export CCACHE_BASEDIR="$ROOT" CCACHE_NOHASHDIR=1
  mkdir -p "$dir"
  cmake -S "$ROOT" -B "$dir" -G Ninja -DCMAKE_BUILD_TYPE="$type" \
    -DSSC_ENABLE_TESTS=ON "$@" > "$dir/cmake.log" 2>&1 ||
    { cat "$dir/cmake.log"; exit 1; }
}

build() {
  install_packages
  configure "$BUILD" Release
  cmake --build "$BUILD" --target ssc_app -- -j "$JOBS"
}

# uses_direct_factor FILE.prm: whether FILE or a file it includes sets
# "Preconditioner = cholesky" (a serial factorisation): one MPI rank
uses_direct_factor() {
  local file="$1" included
  grep -qiE '^[[:space:]]*set[[:space:]]+Preconditioner[[:space:]]*=[[:space:]]*cholesky' "$file" &&
    return 0
  for included in $(sed -nE 's/^[[:space:]]*include[[:space:]]+([^[:space:]#]+).*/\1/p' "$file"); do
    uses_direct_factor "$(dirname "$file")/$included" && return 0
  done
  return 1
}

# direct_factor_override [ssc options]: the Preconditioner a -s override
# sets (lower case), or nothing; the last one wins, as in ssc
direct_factor_override() {
  local argument choice="" pattern='Preconditioner[[:space:]]*=[[:space:]]*([A-Za-z]+)'
  for argument in "$@"; do
    [[ "$argument" =~ $pattern ]] && choice="${BASH_REMATCH[1],,}"
  done
  echo "$choice"
}

# The variables that choose ranks and threads: a whole number or an error
# naming the variable (deal.II aborts on a bad DEAL_II_NUM_THREADS before
# ssc can say anything, mpirun starts any number of ranks).
check_environment() {
  if [ -n "${DEAL_II_NUM_THREADS+set}" ] &&
     ! [[ "$DEAL_II_NUM_THREADS" =~ ^[1-9][0-9]*$ ]]; then
    echo "ssc: error: DEAL_II_NUM_THREADS='$DEAL_II_NUM_THREADS' must be" \
      "a whole number of threads, at least 1 (unset it to use every core)." >&2
    exit 1
  fi
  if [ -n "${SSC_RANKS+set}" ] &&
     { ! [[ "$SSC_RANKS" =~ ^[1-9][0-9]*$ ]] || [ "$SSC_RANKS" -gt "$(nproc)" ]; }; then
    echo "ssc: error: SSC_RANKS='$SSC_RANKS' must be a whole number of MPI" \
      "ranks from 1 to the $(nproc) cores of this machine (unset it for" \
      "one per core)." >&2
    exit 1
  fi
}
check_environment

# mpirun refuses root unless told; CI runs as root.
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
export OMPI_MCA_rmaps_base_oversubscribe=1
# mpirun binds each job's ranks to the first cores, so two jobs at once
# (ctest -j, benchmarks side by side) would share one core: do not bind
export OMPI_MCA_hwloc_base_binding_policy=none

case "${1:-run}" in
  build)
    build
    ;;
  run)
    shift || true
    build
    cd "$ROOT"
    if [ $# -gt 0 ] && [[ "$1" != -* ]]; then
      prm="$1"; shift
    else
      prm="$MAIN_SCENE"
    fi
    # one MPI rank per core unless SSC_RANKS says otherwise; a scene that
    # factorises its tangents on one process (Preconditioner = cholesky)
    # runs on one rank, its cell loops on threads on the cores the ranks
    # leave free; ldlt (the factor distributed over the ranks) and gmg (the
    # distributed V-cycle) take them all
    if [ -z "${SSC_RANKS:-}" ]; then
      override=$(direct_factor_override "$@")
      if [ "$override" = cholesky ] ||
         { [ -z "$override" ] && uses_direct_factor "$prm"; }; then
        RANKS=1
      fi
    fi
    if [ "$RANKS" -gt 1 ]; then
      mpirun -np "$RANKS" "$BUILD/bin/ssc" "$prm" "$@"
    else
      "$BUILD/bin/ssc" "$prm" "$@"
    fi
    # pictures of the main scene (force-depth, surface profile, section)
    if [ "$prm" = "$MAIN_SCENE" ] && [ $# -eq 0 ]; then
      /usr/bin/python3 "$ROOT/scripts/plot_indentation.py" \
        "$ROOT/output/forearm_indentation"
    fi
    # the incision scenes' pictures (wound outlines, skin stress); their
    # Run/Name is the file's name
    case "$prm" in
      *incision*.prm | *excision*.prm | *closure*.prm)
        folder="$ROOT/output/$(basename "$prm" .prm)"
        if [ -f "$folder/wound_lips.csv" ]; then
          /usr/bin/python3 "$ROOT/scripts/plot_incision.py" "$folder"
        fi
        ;;
      *creep*.prm | *relaxation*.prm | *cyclic*.prm)
        folder="$ROOT/output/$(basename "$prm" .prm)"
        if [ -f "$folder/time_history.csv" ]; then
          /usr/bin/python3 "$ROOT/scripts/plot_time_history.py" "$folder"
        fi
        ;;
    esac
    ;;
  test)
    build
    cd "$BUILD"
    # builds the test programs and runs them (deal.II test driver)
    ctest --output-on-failure -j "$JOBS" --timeout 900
    ;;
  test-debug)
    # The fast tests (tests/CMakeLists.txt: SSC_DEBUG_TESTS) built and run
    # against Debian's debug deal.II, so that every Assert is checked.
    install_packages
    DEBUG_BUILD="${SSC_DEBUG_BUILD_DIR:-$ROOT/build-debug}"
    configure "$DEBUG_BUILD" Debug -DSSC_DEBUG_TESTS_ONLY=ON
    cmake --build "$DEBUG_BUILD" --target ssc_app -- -j "$JOBS"
    cd "$DEBUG_BUILD"
    ctest --output-on-failure -j "$JOBS" --timeout 900
    ;;
  format-check)
    command -v clang-format > /dev/null || PACKAGES="clang-format" install_packages
    cd "$ROOT"
    bad=$(git ls-files '*.h' '*.cc' | while read -r f; do
      clang-format --dry-run -Werror "$f" > /dev/null 2>&1 || echo "$f"
    done)
    if [ -n "$bad" ]; then
      echo "ssc.sh: not formatted with .clang-format (run scripts/indent):"
      echo "$bad"
      exit 1
    fi
    echo "ssc.sh: every C++ file is formatted"
    # the folder rule of docs/architecture.md: each folder includes only
    # earlier ones
    python3 "$ROOT/scripts/check_includes.py"
    ;;
  *)
    echo "usage: $0 run [FILE.prm] [-s ...] | test | test-debug | format-check | build" >&2
    exit 1
    ;;
esac
