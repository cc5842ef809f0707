#!/bin/bash
# A full disk: ssc runs tests/punch_small.prm into a 64 kB tmpfs, with and
# without the VTU fields. Each run must stop with exit status 1 and a first
# stderr line "ssc: error: Cannot write '<file>': No space left on device",
# with no summary.json and no temporary file left behind.
# Usage: disk_full.sh SSC PRM. Skips (exit 77) where no tmpfs can be
# mounted (neither as root nor in a user namespace).
set -u
SSC="$1"
PRM="$2"
MOUNT=$(mktemp -d)
trap 'umount "$MOUNT" 2>/dev/null; rmdir "$MOUNT"' EXIT

run_on_tmpfs() {
  mount -t tmpfs -o size=64k none "$MOUNT" || exit 77
  local status=0
  for fields in false true; do
    "$SSC" "$PRM" -s "Run/Output directory=$MOUNT" \
      -s "Run/Write fields=$fields" > "$MOUNT.out" 2> "$MOUNT.err"
    code=$?
    first=$(head -1 "$MOUNT.err")
    echo "Write fields = $fields: exit status $code: $first"
    [ "$code" -eq 1 ] || status=1
    case "$first" in
      "ssc: error: Cannot write '"*"': No space left on device"*) ;;
      *) status=1 ;;
    esac
    if [ -e "$MOUNT/punch_small/summary.json" ] ||
       ls "$MOUNT/punch_small/"*.tmp > /dev/null 2>&1; then
      echo "summary.json or a temporary file was left behind"
      status=1
    fi
    rm -rf "${MOUNT:?}"/* "$MOUNT.out" "$MOUNT.err"
  done
  umount "$MOUNT"
  exit $status
}

if [ "$(id -u)" -eq 0 ] && mount -t tmpfs -o size=64k none "$MOUNT" 2>/dev/null; then
  umount "$MOUNT"
  run_on_tmpfs
else
  unshare -r -m true 2>/dev/null || exit 77
  export -f run_on_tmpfs
  export SSC PRM MOUNT
  exec unshare -r -m bash -c run_on_tmpfs
fi
