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

# Bounded fuzzing (libFuzzer, clang): the photometric readers and the
# writers' round trip, seeded from the test fixtures and the real files of
# ../shared/photometric; then scene loading, geometry and the direct solve,
# seeded from the project's scenes. 100 s each. Quiet on success; on a
# finding it prints the end of the log and leaves the input in
# build-fuzz/artifacts/.
fuzz_dir="$root/build-fuzz"
fuzz_log="$fuzz_dir/fuzz.log"
mkdir -p "$fuzz_dir/artifacts"
if ! { CC=clang CXX=clang++ cmake -S "$root" -B "$fuzz_dir" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCANDELA_FUZZ=ON &&
       cmake --build "$fuzz_dir" -j "$jobs" --target fuzz_photometry fuzz_scene; } >"$fuzz_log" 2>&1; then
  tail -n 40 "$fuzz_log" >&2
  echo "test.sh: building the fuzz harnesses failed" >&2
  exit 1
fi
# run_fuzz NAME EXTRA-OPTIONS... -- SEED-DIRS...: libFuzzer writes new inputs
# into its first corpus folder, a fresh temporary one, never the sources.
run_fuzz() {
  local name=$1; shift
  local opts=()
  while [ "$1" != "--" ]; do opts+=("$1"); shift; done
  shift
  local work
  work=$(mktemp -d)
  # (LeakSanitizer: the suppressions of the tests, fontconfig's process-wide configuration)
  if ! LSAN_OPTIONS="suppressions=$root/tests/lsan.supp:print_suppressions=0" "$fuzz_dir/tests/fuzz/$name" -max_total_time=100 -timeout=10 -rss_limit_mb=2048 "${opts[@]}" \
       -artifact_prefix="$fuzz_dir/artifacts/" "$work" "$@" >"$fuzz_log" 2>&1; then
    tail -n 60 "$fuzz_log" >&2
    echo "test.sh: $name found a problem; the input is in $fuzz_dir/artifacts/" >&2
    rm -rf "$work"
    exit 1
  fi
  rm -rf "$work"
}
photometry_seeds=("$root/tests/data/photometric")
[ -d "$root/../shared/photometric" ] && photometry_seeds+=("$root/../shared/photometric")
run_fuzz fuzz_photometry -- "${photometry_seeds[@]}"
run_fuzz fuzz_scene -dict="$fuzz_dir/tests/fuzz/scene.dict" -max_len=6000 -- "$fuzz_dir/tests/fuzz/scene_seeds"
