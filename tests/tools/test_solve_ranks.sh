#!/usr/bin/env bash
# candela solve shared by MPI ranks gives the bytes one process gives: each
# scene is solved by the command alone, then under mpiexec with 1, 2 and 3
# ranks (one thread each), and every file must be identical (cmp) but
# summary.json, whose "seconds" and "ranks" (per-rank timing, threads,
# bytes received) legitimately differ: it is compared with those two keys
# (and settings.threads) removed. The scenes (tests/data/scene/ranks_*.json), small drafts: direct
# light only (a goniometric array, an area panel, a spot; ambient
# occlusion and the vertical outputs, sampled where the panel is seen; a
# polygon and a points grid); the irradiance cache's dense cube; a room
# path traced, with the sampled vertical outputs, luminance and an observer
# (glare); a room whose surfaces are mapped (the maps' CSV and scene.glb).
# Then a run with two threads per rank against one thread alone (the EXR
# records the thread count, so EXR apart), the per-rank report, and the
# report's cover.
# ctest-labels: mpi;slow
# ctest-timeout: 300
source "$(dirname "$0")/harness.sh"
source "$(dirname "$0")/mpi_env.sh"
scenes="$CANDELA_SOURCE_DIR/tests/data/scene"
cd "$tmp" || exit 1

# summary.json without its timing and its ranks (and the threads it was
# run with: settings.threads), one key a line.
strip_summary() {
  python3 -c 'import json, sys
d = json.load(open(sys.argv[1]))
for k in ("seconds", "ranks"):
    d.pop(k, None)
d["settings"].pop("threads", None)
print(json.dumps(d, indent=1, sort_keys=True))' "$1"
}
# same_outputs REF OUT [SKIP]: every file of REF in OUT with the same bytes
# (summary.json as above; files matching SKIP not compared), and no other.
same_outputs() {
  local f rel bad=0
  [ "$(cd "$1" && find . -type f | sort)" = "$(cd "$2" && find . -type f | sort)" ] || { echo "  files differ"; return 1; }
  while IFS= read -r f; do
    rel=${f#"$1"/}
    if [ "$(basename "$rel")" = summary.json ]; then
      cmp -s <(strip_summary "$f") <(strip_summary "$2/$rel") || { echo "  differs: $rel"; bad=1; }
    elif [ -n "${3:-}" ] && [[ "$rel" == $3 ]]; then
      continue
    else
      cmp -s "$f" "$2/$rel" || { echo "  differs: $rel"; bad=1; }
    fi
  done < <(find "$1" -type f | sort)
  return $bad
}

for s in direct cube paths maps; do
  "$CANDELA" solve "$scenes/ranks_$s.json" -o "$s.alone" --threads 1 --quiet > "$s.alone.txt" 2>&1; st=$?
  check "$s: alone: exit 0" '[ $st -eq 0 ]'
  [ $st -eq 0 ] || cat "$s.alone.txt"
  for n in 1 2 3; do
    "$CANDELA_MPIEXEC" -np $n "$CANDELA" solve "$scenes/ranks_$s.json" -o "$s.np$n" --threads 1 --quiet \
      > "$s.np$n.txt" 2>&1; st=$?
    check "$s: $n rank(s): exit 0" '[ $st -eq 0 ]'
    [ $st -eq 0 ] || cat "$s.np$n.txt"
    check "$s: $n rank(s): the same bytes as alone" 'same_outputs "$s.alone" "$s.np$n"'
  done
done
check "direct: the vertical outputs were written" 'head -1 direct.np3/workplane.csv | grep -q "Esz_stderr_lx"'
check "paths: the observer was rated" 'grep -q "^desk,.*" paths.np3/glare.csv'
check "maps: a map and scene.glb were written" '[ -s maps.np3/surfaces/room.csv ] && [ -s maps.np3/scene.glb ]'
check "cube: the cache gathered records" \
  'python3 -c "import json, sys; sys.exit(json.load(open(\"cube.np3/summary.json\"))[\"plan\"][\"interreflection\"][\"records\"] < 10)"'

# Threads and ranks together: 2 ranks of 2 threads, against 1 thread alone.
"$CANDELA_MPIEXEC" -np 2 "$CANDELA" solve "$scenes/ranks_cube.json" -o cube.np2t2 --threads 2 --quiet > t.txt 2>&1
st=$?
check "cube: 2 ranks x 2 threads: exit 0" '[ $st -eq 0 ]'
check "cube: 2 ranks x 2 threads: the same CSV and PNG bytes" 'same_outputs cube.alone cube.np2t2 "*.exr"'

# What summary.json says of the ranks: their count, threads, seconds, work
# and CPU seconds, the bytes each received (rank 0 the most: the grids'
# results), each one's peak memory (above a megabyte: a process holds its
# libraries); one process alone received nothing.
ranks_report() {
  python3 - "$1" "$2" <<'PY'
import json, sys
d = json.load(open(sys.argv[1]))
alone = json.load(open(sys.argv[2]))["ranks"]
r = d["ranks"]
ok = r["count"] == 3 and r["threads"] == [1, 1, 1]
ok = ok and all(len(r[k]) == 3 for k in ("seconds", "work_seconds", "work_cpu_seconds", "cpu_seconds", "bytes_received",
                                          "peak_rss_bytes"))
ok = ok and all(b > 1 << 20 for b in r["peak_rss_bytes"])
ok = ok and r["bytes_received"][0] > 0 and r["bytes_received"][0] == max(r["bytes_received"])
ok = ok and alone["count"] == 1 and alone["bytes_received"] == [0]
sys.exit(0 if ok else 1)
PY
}
check "summary.json: ranks count, threads, seconds, work, CPU, bytes and memory per rank" \
  'ranks_report paths.np3/summary.json paths.alone/summary.json'
check "stdout: rank 0 alone prints the results, naming the ranks" \
  '[ "$(grep -c "^method" paths.np3.txt)" = 1 ] && grep -q ", 3 ranks; results in" paths.np3.txt'
"$CANDELA" report paths.np3 > report.txt 2>&1; st=$?
check "candela report of a solve on 3 ranks: exit 0, the cover names the ranks" \
  '[ $st -eq 0 ] && grep -q "1 on each of 3 ranks (results depend on neither)" paths.np3/report.html'
exit $fail
