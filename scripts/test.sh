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

# Bounded fuzzing (libFuzzer, clang) of the photometric readers and the
# writers' round trip, seeded from the test fixtures and the real files of
# ../shared/photometric. Quiet on success; on a finding it prints the end of
# the log and leaves the input in build-fuzz/artifacts/.
fuzz_dir="$root/build-fuzz"
fuzz_log="$fuzz_dir/fuzz.log"
mkdir -p "$fuzz_dir/artifacts"
if ! { CC=clang CXX=clang++ cmake -S "$root" -B "$fuzz_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCANDELA_FUZZ=ON &&
       cmake --build "$fuzz_dir" -j "$jobs" --target fuzz_photometry; } >"$fuzz_log" 2>&1; then
  tail -n 40 "$fuzz_log" >&2
  echo "test.sh: building the fuzz harness failed" >&2
  exit 1
fi
fuzz_work=$(mktemp -d)
fuzz_seeds=("$root/tests/data/photometric")
[ -d "$root/../shared/photometric" ] && fuzz_seeds+=("$root/../shared/photometric")
if ! "$fuzz_dir/tests/fuzz/fuzz_photometry" -max_total_time=150 -timeout=10 -rss_limit_mb=2048 \
     -artifact_prefix="$fuzz_dir/artifacts/" "$fuzz_work" "${fuzz_seeds[@]}" >"$fuzz_log" 2>&1; then
  tail -n 60 "$fuzz_log" >&2
  echo "test.sh: fuzz_photometry found a problem; the input is in $fuzz_dir/artifacts/" >&2
  rm -rf "$fuzz_work"
  exit 1
fi
rm -rf "$fuzz_work"
