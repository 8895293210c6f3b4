#!/usr/bin/env bash
# `candela annual` through the command line, on a synthetic weather year
# (annual_check.py writes it: no third-party weather data):
#  - --sky cie_overcast: every hour of every point is DF x the hour's diffuse
#    horizontal illuminance, and DA300, UDI and EN 17037 per point and per
#    grid follow from DF and the file exactly (annual_check.py recomputes
#    them apart); DF itself against `candela solve` of the room made black
#    under the overcast sky with "daylight_factor";
#  - the occupancy as a daily range and as a file (each recomputed apart);
#  - the files: CSV, hourly file, the four maps, summary.json;
#  - --sky perez: the same bytes with 1 and 2 threads;
#  - refusals: a weather file a row short (exit 1, the count), an occupancy
#    file with a 2 on its line 5 and one a line short, a range out of order,
#    a scene with a luminaire (exit 1); --mf 3, --sky foo, no --weather (exit 2).
# ctest-timeout: 600
source "$(dirname "$0")/harness.sh"
py="$CANDELA_SOURCE_DIR/tests/tools/annual_check.py"
python3 "$py" epw "$tmp/w.epw"
python3 "$py" occupancy "$tmp/occ.csv"

# A 3 x 4 x 2.8 m room, a window of 1.6 x 1.2 m in its -y wall (no glass), a
# 3 x 4 desk grid; draft quality.
room='"surfaces": [{"type": "box", "min": [0,0,0], "max": [3,4,2.8], "inward": true,
  "reflectance": {"floor": 0.25, "walls": 0.55, "ceiling": 0.75}, "open": ["-y"]},
  {"type": "polygon", "vertices": [[0,0,0],[3,0,0],[3,0,2.8],[0,0,2.8]],
   "holes": [[[0.7,0,0.9],[2.3,0,0.9],[2.3,0,2.1],[0.7,0,2.1]]], "reflectance": 0.4}],
 "grids": [{"name": "desk", "type": "rect", "origin": [0.2,0.3,0.8], "u": [2.6,0,0], "v": [0,3.4,0], "nu": 3, "nv": 4}],
 "solver": {"quality": "draft", "seed": 2}'
printf '{"version": 1, %s}\n' "$room" > "$tmp/room.json"

"$CANDELA" annual "$tmp/room.json" --weather "$tmp/w.epw" --sky cie_overcast -o "$tmp/ov" --quiet > "$tmp/ov.out" 2> "$tmp/ov.err"; st=$?
check "overcast: exit 0 (got $st)" '[ $st -eq 0 ]' || cat "$tmp/ov.err"
for f in desk.csv desk.hourly.bin desk_DA300.png desk_UDI.png desk_ASE.png desk_EN17037.png annual.csv summary.json; do
  check "overcast: $f written" '[ -s "$tmp/ov/$f" ]'
done
check "overcast: no temporary file left" '[ -z "$(ls "$tmp/ov" | grep tmp)" ]'
check "overcast: every hour is DF x E_dh, the metrics recomputed (8-18)" \
  'python3 "$py" overcast "$tmp/ov" desk "$tmp/w.epw" 8-18 > "$tmp/ov.check"' || cat "$tmp/ov.check"
check "overcast: annual.csv's row as summary.json has it" 'python3 - "$tmp/ov" <<EOF
import csv, json, sys
row = list(csv.DictReader(open(sys.argv[1] + "/annual.csv")))[0]
g = json.load(open(sys.argv[1] + "/summary.json"))["grids"]["desk"]
ok = row["grid"] == "desk" and int(row["points"]) == g["count"]
for k in ["sDA300_percent", "ASE1000_percent", "DA300_mean_percent", "UDI_fell_short_percent", "UDI_percent", "UDI_exceeded_percent"]:
    ok &= float(row[k]) == g[k]
ok &= row["EN17037_level"] == g["EN17037"]["level"]
sys.exit(0 if ok else 1)
EOF'
check "overcast: 3650 occupied hours, 4380 daylight hours" \
  'grep -q "\"occupied_hours\":	3650" "$tmp/ov/summary.json" && grep -q "\"daylight_hours\":	4380" "$tmp/ov/summary.json"'

# the same under a schedule file
"$CANDELA" annual "$tmp/room.json" --weather "$tmp/w.epw" --sky cie_overcast --occupancy "$tmp/occ.csv" -o "$tmp/ovf" --quiet > /dev/null 2> "$tmp/ovf.err"; st=$?
check "occupancy file: exit 0 (got $st)" '[ $st -eq 0 ]' || cat "$tmp/ovf.err"
check "occupancy file: the metrics recomputed with it" \
  'python3 "$py" overcast "$tmp/ovf" desk "$tmp/w.epw" "$tmp/occ.csv" > "$tmp/ovf.check"' || cat "$tmp/ovf.check"
check "occupancy file: 2088 occupied hours (261 weekdays x 8)" 'grep -q "\"occupied_hours\":	2088" "$tmp/ovf/summary.json"'

# DF against candela solve under the overcast sky, in the room made black (the
# solve's interreflection under a sky through a window is slow; the
# coefficients' interreflection is held to the path tracer in
# tests/solver/daylight/test_daylight_coefficients.c): the solve's visible
# sky sampled to its target, the annual's exact over patches of 1.5 degrees.
black=$(echo "$room" | sed 's/"reflectance": {"floor": 0.25, "walls": 0.55, "ceiling": 0.75}/"reflectance": 0/; s/"reflectance": 0.4}/"reflectance": 0}/')
printf '{"version": 1, %s}\n' "$black" > "$tmp/black.json"
printf '{"version": 1, "luminaires": [{"type": "environment", "sky": "cie_overcast", "zenith_luminance_cd_m2": 3000}], %s}\n' \
  "$(echo "$black" | sed 's/"nv": 4}/"nv": 4, "outputs": ["daylight_factor"]}/; s/"quality": "draft"/"quality": "high"/')" > "$tmp/df.json"
"$CANDELA" annual "$tmp/black.json" --weather "$tmp/w.epw" --sky cie_overcast -o "$tmp/bk" --quiet > /dev/null 2> "$tmp/bk.err"; st=$?
check "black room, annual: exit 0 (got $st)" '[ $st -eq 0 ]' || cat "$tmp/bk.err"
"$CANDELA" solve "$tmp/df.json" -o "$tmp/df" --quiet > /dev/null 2> "$tmp/df.err"; st=$?
check "black room, solve with daylight_factor: exit 0 (got $st)" '[ $st -eq 0 ]' || cat "$tmp/df.err"
check "DF: annual's against solve's within 4 of the solve's sigmas and 1e-3 of DF (the patches)" 'python3 - "$tmp/bk/desk.csv" "$tmp/df/desk.csv" <<EOF
import csv, math, sys
a = list(csv.DictReader(open(sys.argv[1]))); b = list(csv.DictReader(open(sys.argv[2])))
ok = len(a) == len(b) == 12
for x, y in zip(a, b):
    da, db = float(x["DF_percent"]), float(y["DF_percent"])
    sb = float(y["E_stderr_lx"]) / float(y["E_lx"]) * db
    ok &= float(x["coefficient_rel_stderr"]) == 0.0 and abs(da - db) <= 4 * sb + 1e-3 * db
    print("DF %.6f (annual) %.6f +- %.2g (solve)" % (da, db, sb))
sys.exit(0 if ok else 1)
EOF'

# perez: the same bytes whatever the threads
for t in 1 2; do
  "$CANDELA" annual "$tmp/room.json" --weather "$tmp/w.epw" -o "$tmp/pz$t" --threads $t --quiet > /dev/null 2> "$tmp/pz$t.err"; st=$?
  check "perez, $t threads: exit 0 (got $st)" '[ $st -eq 0 ]' || cat "$tmp/pz$t.err"
done
check "perez: the same hourly bytes with 1 and 2 threads" 'cmp -s "$tmp/pz1/desk.hourly.bin" "$tmp/pz2/desk.hourly.bin"'
check "perez: the same CSV with 1 and 2 threads" 'cmp -s "$tmp/pz1/desk.csv" "$tmp/pz2/desk.csv"'
check "perez: a direct sun file" '[ -s "$tmp/pz1/desk.sun.bin" ]'

# refusals
# refused NAME STATUS FRAGMENT ARGS...: exit STATUS, stderr holds FRAGMENT
refused() {
  name=$1 want=$2 frag=$3
  shift 3
  "$CANDELA" annual "$@" -o "$tmp/r_$name" > /dev/null 2> "$tmp/$name.err"; st=$?
  check "$name: exit $want (got $st)" '[ $st -eq $want ]'
  check "$name: says '$frag'" 'grep -qF -- "$frag" "$tmp/$name.err"' || cat "$tmp/$name.err"
}
head -n 8766 "$tmp/w.epw" > "$tmp/short.epw"
refused short_epw 1 "short.epw: expected 8760 or 8784 hourly rows (a year), found 8758" \
  "$tmp/room.json" --weather "$tmp/short.epw" --sky cie_overcast
sed '5s/,0$/,2/;5s/,1$/,2/' "$tmp/occ.csv" > "$tmp/occ_bad.csv"
refused occ_value 1 "occ_bad.csv:5: expected 0 or 1 (occupied), found 2" \
  "$tmp/room.json" --weather "$tmp/w.epw" --sky cie_overcast --occupancy "$tmp/occ_bad.csv"
head -n 100 "$tmp/occ.csv" > "$tmp/occ_short.csv"
refused occ_count 1 "occ_short.csv: expected 8760 values (one per hour of the weather file), found 99" \
  "$tmp/room.json" --weather "$tmp/w.epw" --sky cie_overcast --occupancy "$tmp/occ_short.csv"
refused occ_range 1 "--occupancy: occupancy '18-8': expected a daily range A-B of whole hours, 0 <= A < B <= 24" \
  "$tmp/room.json" --weather "$tmp/w.epw" --occupancy 18-8
printf '{"version": 1, "luminaires": [{"type": "point", "position": [1,1,2], "intensity_cd": 100}], %s}\n' "$room" > "$tmp/lit.json"
refused luminaire 1 "lit.json: luminaires[0]: expected no luminaires in an annual study" \
  "$tmp/lit.json" --weather "$tmp/w.epw"
refused mf 2 "--mf: expected 1, 2 or 4, found '3'" "$tmp/room.json" --weather "$tmp/w.epw" --mf 3
refused sky 2 "--sky: expected perez or cie_overcast, found 'foo'" "$tmp/room.json" --weather "$tmp/w.epw" --sky foo
refused no_weather 2 "expected SCENE.json, --weather FILE.epw and -o OUTDIR" "$tmp/room.json"
exit $fail
