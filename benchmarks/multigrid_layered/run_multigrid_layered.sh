#!/bin/bash
# The line-smoother study of README.md: runs build/benchmarks/multigrid_layered
# several times and writes results/multigrid_line.csv, each row labelled by
# its study:
#  side_by_side  every preconditioner on the same cases, one after the other
#                (nu 0.3, contrast 1:60, SM cells of aspect 20);
#  sweep         the line-smoothed V-cycle over nu, contrast and degree;
#  largest       the line-smoothed V-cycle up to 2.4M Q1 DoFs;
#  memory        one preconditioner per process on the 295k-DoF case, so that
#                memory_MB is that preconditioner's (with the matrix).
# Usage: benchmarks/multigrid_layered/run_multigrid_layered.sh [build folder]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
program=${1:-build}/benchmarks/multigrid_layered
out=$here/results/multigrid_line.csv
[ -x "$program" ] || { echo "build it first: cmake --build build --target multigrid_layered" >&2; exit 1; }
run() { # study, options...
  local study=$1; shift
  "$program" "$@" | tail -n +2 | sed "s/^/$study,/" | tee -a "$out"
}
echo "study,$("$program" q1=0 q2=0 amg=0 smoothers=none)" > "$out"
run side_by_side q1=3 q2=2 n=6 quick=1 smoothers=point,line amg=1 cholesky=1
run sweep q1=3 q2=2 n=6 smoothers=line amg=0 nu=0.3,0.45,0.49,0.4999
run largest q1=4 q2=0 n=6 quick=1 smoothers=line amg=0
for method in "smoothers=line amg=0" "smoothers=point amg=0" \
              "smoothers=none amg=1" "smoothers=none amg=0 cholesky=1"; do
  run memory q1=3 q2=0 n=6 quick=1 $method
done
