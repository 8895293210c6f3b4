#!/usr/bin/env bash
# Set up, build, and run Candela's main job on the example in data/.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
cmake --build "$root/build" -j "$(nproc)" >/dev/null
out="$root/out/office"
"$root/build/candela" solve "$root/data/office/office.json" -o "$out"
echo "results: $out (CSV, EXR and PNG per grid, summary.json)"
