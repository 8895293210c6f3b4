#!/usr/bin/env bash
# candela bench shared by MPI ranks: every solve of the ladder (and the
# reference) is shared by 2 ranks, rank 0 decides from its clock what fits
# the budget, writes and prints. On the integrating sphere of
# test_bench_cli.sh (8 points, the cache's ladder): bench.csv is one
# process's but for its seconds column, the reference and every rung's CSV
# have the same bytes; a second run on 3 ranks reuses the reference, and a
# changed reflectance is refused on every rank (exit 1, once on stderr).
# ctest-labels: mpi
# ctest-timeout: 240
source "$(dirname "$0")/harness.sh"
source "$(dirname "$0")/mpi_env.sh"
source "$(dirname "$0")/sphere_scene.sh"
sphere_points 8
scene() { sphere_scene "$1"; }
cd "$tmp" || exit 1
scene 0.5 > sphere.json
args=(--methods icache --budget 200 --threads 1 --quiet)

"$CANDELA" bench sphere.json -o alone "${args[@]}" > alone.txt 2>&1; st=$?
check "alone: exit 0" '[ $st -eq 0 ]'
"$CANDELA_MPIEXEC" -np 2 "$CANDELA" bench sphere.json -o two "${args[@]}" > two.txt 2>&1; st=$?
check "2 ranks: exit 0" '[ $st -eq 0 ]'
[ $st -eq 0 ] || cat two.txt
no_seconds() { cut -d, -f1-4,6- "$1"; }
check "2 ranks: bench.csv is one process's but for its seconds" 'cmp -s <(no_seconds alone/bench.csv) <(no_seconds two/bench.csv)'
check "2 ranks: five rungs ran" '[ "$(grep -c "^icache_" two/bench.csv)" = 5 ]'
same_csv() {
  local f bad=0
  while IFS= read -r f; do cmp -s "alone/$f" "two/$f" || { echo "  differs: $f"; bad=1; }; done \
    < <(cd alone && find reference runs -name '*.csv' | sort)
  [ "$(cd alone && find reference runs -name '*.csv' | sort)" = "$(cd two && find reference runs -name '*.csv' | sort)" ] && [ $bad -eq 0 ]
}
check "2 ranks: the reference and every rung's CSV have the same bytes" 'same_csv'
check "2 ranks: rank 0 alone printed the table" '[ "$(grep -c "^results in two" two.txt)" = 1 ]'

"$CANDELA_MPIEXEC" -np 3 "$CANDELA" bench sphere.json -o two "${args[@]}" > again.txt 2>&1; st=$?
check "3 ranks, same folder: exit 0, the reference reused" '[ $st -eq 0 ] && grep -q "^reference: reused two/reference" again.txt'
check "3 ranks: bench.csv unchanged but for its seconds" 'cmp -s <(no_seconds alone/bench.csv) <(no_seconds two/bench.csv)'

scene 0.6 > changed.json
"$CANDELA_MPIEXEC" -np 2 "$CANDELA" bench changed.json -o two "${args[@]}" > changed.txt 2>&1; st=$?
check "changed reflectance on 2 ranks: exit 1, said once" \
  '[ $st -eq 1 ] && [ "$(grep -c "the reference there was made for another scene" changed.txt)" = 1 ]'
exit $fail
