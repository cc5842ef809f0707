#!/bin/bash
# Builds the geometry of every region (prm/<region>_geometry.prm) into
# output/<region>_geometry/ and renders its septa and ligaments to
# prm/regions/<region>.png (linked from the README). Needs a build
# (./ssc.sh build) and Debian's python3 with matplotlib.
set -euo pipefail
cd "$(dirname "$0")/.."
for prm in prm/*_geometry.prm; do
  region=$(basename "$prm" _geometry.prm)
  build/bin/ssc "$prm" > /dev/null
  /usr/bin/python3 scripts/render_microstructure.py "output/${region}_geometry" \
    --out "prm/regions/${region}.png" --dpi 75
done
