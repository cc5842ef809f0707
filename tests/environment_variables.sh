#!/bin/bash
# A rank or thread count that is not a whole number in range (SSC_RANKS 1
# to the cores, DEAL_II_NUM_THREADS at least 1) ends in exit status 1 and
# an "ssc: error:" line naming the variable: from ssc.sh before it installs,
# builds or starts anything, and from the ssc executable itself before
# deal.II, which reads DEAL_II_NUM_THREADS as it is loaded, aborts on it.
# Usage: environment_variables.sh SSC_SH SSC PRM
set -u
SSC_SH="$1"
SSC="$2"
PRM="$3"
status=0
check() {
  local label="$1" variable="$2" value="$3" code first
  shift 3
  first=$(env "$variable=$value" "$@" 2>&1 > /dev/null | head -1)
  env "$variable=$value" "$@" > /dev/null 2>&1
  code=$?
  echo "$label $variable='$value': exit status $code: $first"
  [ "$code" -eq 1 ] || status=1
  case "$first" in
    "ssc: error: $variable='$value' must be a whole number"*) ;;
    *) status=1 ;;
  esac
}
for value in 0 -1 abc "" 1.5 100000; do
  check ssc.sh SSC_RANKS "$value" bash "$SSC_SH" run
done
for value in 0 abc "" -2; do
  check ssc.sh DEAL_II_NUM_THREADS "$value" bash "$SSC_SH" run
  check ssc DEAL_II_NUM_THREADS "$value" "$SSC" --check "$PRM"
done
# a valid count runs
DEAL_II_NUM_THREADS=1 "$SSC" --check "$PRM" > /dev/null ||
  { echo "DEAL_II_NUM_THREADS=1 refused"; status=1; }
exit $status
