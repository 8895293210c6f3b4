#!/usr/bin/env bash
# Set up, build with warnings as errors, and run the whole test suite; then
# build again under AddressSanitizer + UndefinedBehaviorSanitizer and run it once more.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
bash "$root/scripts/setup.sh"
jobs=$(nproc)

cmake -S "$root" -B "$root/build-ci" -DCMAKE_BUILD_TYPE=Release -DCANDELA_WERROR=ON >/dev/null
cmake --build "$root/build-ci" -j "$jobs"
ctest --test-dir "$root/build-ci" --output-on-failure -j "$jobs"

cmake -S "$root" -B "$root/build-sanitize" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCANDELA_WERROR=ON \
      -DCANDELA_SANITIZE=ON >/dev/null
cmake --build "$root/build-sanitize" -j "$jobs"
ctest --test-dir "$root/build-sanitize" --output-on-failure -j "$jobs" -LE no-sanitize
