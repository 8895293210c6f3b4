#!/usr/bin/env bash
# candela solve through the command line: the example office end to end,
# the files DESIGN.md promises, relative paths, errors, atomic outputs, and
# identical results for any thread count.
# ctest-timeout: 300
source "$(dirname "$0")/harness.sh"
office="$CANDELA_SOURCE_DIR/data/office/office.json"

# Run from another folder: paths in the scene resolve against the scene file.
(cd "$tmp" && "$CANDELA" solve "$office" -o out --quiet > stdout.txt 2> stderr.txt); st=$?
check "office solves (exit 0)" '[ $st -eq 0 ]'
[ $st -eq 0 ] || cat "$tmp/stderr.txt"
out="$tmp/out"
for g in workplane floor north_wall; do
  for ext in csv exr png; do check "$g.$ext written" '[ -s "$out/$g.$ext" ]'; done
done
check "points grid gets a CSV" '[ -s "$out/desk_probes.csv" ]'
check "points grid gets no EXR" '[ ! -e "$out/desk_probes.exr" ]'
check "summary.json written" '[ -s "$out/summary.json" ]'
check "no temporary files left" '[ -z "$(ls "$out" | grep -F .tmp.)" ]'

header=$(head -n 1 "$out/workplane.csv")
check "CSV header as DESIGN.md" '[ "$header" = "x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_stderr_lx" ]'
check "AO and its error when asked" '[ "$(head -n 1 "$out/north_wall.csv")" = "x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_stderr_lx,AO,AO_stderr" ]'
rows=$(($(wc -l < "$out/workplane.csv") - 1))
check "one row per point (20 x 12)" '[ $rows -eq 240 ]'
check "PNG signature" '[ "$(head -c 8 "$out/workplane.png" | od -An -tx1 | tr -d " \n")" = "89504e470d0a1a0a" ]'
check "EXR magic" '[ "$(head -c 4 "$out/workplane.exr" | od -An -tx1 | tr -d " \n")" = "762f3101" ]'
for key in '"grids"' '"workplane"' '"count"' '"E_avg_lx"' '"E_min_lx"' '"E_max_lx"' '"U0"' '"Ud"' \
           '"method"' '"quality"' '"settings"' '"seconds"' '"rays"' '"plan"' '"interreflection"'; do
  check "summary.json has $key" 'grep -q "$key" "$out/summary.json"'
done
# (summary.json's keys hold such letters, "maintenance_factor": its values must not)
check "no NaN anywhere" '! grep -qi "nan\|inf" "$out/workplane.csv" && python3 -c "import json, sys; json.load(open(sys.argv[1]), parse_constant=lambda c: sys.exit(\"%s in summary.json\" % c))" "$out/summary.json"'
check "stdout names the results folder" 'grep -q "results in out" "$tmp/stdout.txt"'

# The example has interreflection, each grid by the method auto chose.
check "office: interreflection modelled" 'grep -q "\"modelled\":[[:space:]]*true" "$out/summary.json"'
check "office: indirect light in the work plane" 'awk -F, "NR > 1 && \$9 > 0 { n++ } END { exit !(n == 240) }" "$out/workplane.csv"'

# Same scene (at draft, to save time), 1 and 3 threads: the same bytes.
mkdir -p "$tmp/draft" && cp "$CANDELA_SOURCE_DIR"/data/office/* "$tmp/draft/"
sed 's/"quality": "normal"/"quality": "draft"/' "$office" > "$tmp/draft/office.json"
"$CANDELA" solve "$tmp/draft/office.json" -o "$tmp/t1" --quiet --threads 1 >/dev/null 2>&1
"$CANDELA" solve "$tmp/draft/office.json" -o "$tmp/t3" --quiet --threads 3 >/dev/null 2>&1
for g in workplane floor north_wall desk_probes; do
  check "$g.csv identical for 1 and 3 threads" 'cmp -s "$tmp/t1/$g.csv" "$tmp/t3/$g.csv"'
done

# Bad input: exit 1, message with the JSON path; earlier results untouched.
cp "$out/workplane.csv" "$tmp/before.csv"
mkdir -p "$tmp/office" && cp "$CANDELA_SOURCE_DIR"/data/office/* "$tmp/office/"
sed 's/"position": \[1.5, 0.9, 2.78\]/"position": [1.5, 0.9]/' "$office" > "$tmp/office/bad.json"
"$CANDELA" solve "$tmp/office/bad.json" -o "$out" --quiet > /dev/null 2> "$tmp/err.txt"; st=$?
check "bad scene exits 1" '[ $st -eq 1 ]'
check "error names the JSON path" 'grep -q "luminaires\[0\].position" "$tmp/err.txt"'
check "earlier results intact after a failed run" 'cmp -s "$out/workplane.csv" "$tmp/before.csv"'
"$CANDELA" solve "$tmp/does-not-exist.json" -o "$out" --quiet >/dev/null 2>"$tmp/err.txt"; st=$?
check "missing scene exits 1" '[ $st -eq 1 ]'
check "missing scene is named" 'grep -q "does-not-exist.json" "$tmp/err.txt"'
"$CANDELA" solve "$office" --quiet >/dev/null 2>&1; st=$?
check "missing -o is a usage error" '[ $st -eq 2 ]'
"$CANDELA" solve "$office" -o "$out" --threads lots >/dev/null 2>&1; st=$?
check "bad --threads is a usage error" '[ $st -eq 2 ]'

# An interrupted run: kill a solve part-way; every file is either the old
# complete one or a new complete one (CSV rows intact, summary parses to its end).
for i in 1 2 3; do
  "$CANDELA" solve "$office" -o "$out" --quiet --threads 1 >/dev/null 2>&1 &
  pid=$!
  sleep 0.0$((i * 3))
  kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
  check "after kill $i: workplane.csv complete" '[ $(($(wc -l < "$out/workplane.csv") - 1)) -eq 240 ]'
  check "after kill $i: summary.json complete" '[ "$(tail -c 2 "$out/summary.json" | head -c 1)" = "}" ]'
done
# A point at the foot of a wall is reported on stderr and in summary.json; the
# office's own grids have none.
check "office: no edge points" '[ $(grep -c "\"edge_points\":[[:space:]]*0" "$out/summary.json") -ge 4 ]'
cat > "$tmp/edge.json" <<'JSON'
{"version": 1,
 "surfaces": [{"type": "box", "min": [0, 0, 0], "max": [4, 4, 3], "inward": true, "reflectance": 0.5}],
 "luminaires": [{"type": "point", "position": [2, 2, 2.9], "intensity_cd": 1000}],
 "grids": [{"name": "foot", "type": "points", "points": [{"p": [2, 2, 0], "n": [0, 0, 1]}, {"p": [0, 2, 0], "n": [0, 0, 1]}]}],
 "solver": {"method": "direct"}}
JSON
"$CANDELA" solve "$tmp/edge.json" -o "$tmp/edge" --quiet > /dev/null 2> "$tmp/edge.err"; st=$?
check "edge point: solved (exit 0), warned" '[ $st -eq 0 ] && grep -q "warning: grid .foot.: 1 point lies where two surfaces meet (the first is point 1 at (0, 2, 0))" "$tmp/edge.err"'
check "edge point: summary.json counts it" 'grep -q "\"edge_points\":[[:space:]]*1" "$tmp/edge/summary.json"'
exit $fail
