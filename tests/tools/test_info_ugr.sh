#!/usr/bin/env bash
# `candela info --ugr`: the CIE 190 UGR table through the public command,
# as text and JSON: CIE 190's worked example against its printed table,
# the JSON against the text, a symmetric luminaire's two views alike, and
# the files and options that cannot be rated.
source "$(dirname "$0")/harness.sh"
data=$CANDELA_SOURCE_DIR/tests/data/photometric

# CIE 190:2010's example luminaire at its SHR 1 against the table it prints
# (rounded to 0.1; CIE 190 sums 10-degree zones where the program integrates
# the table exactly: measured worst 0.12; tolerance 0.15).
"$CANDELA" info --ugr --ugr-shr 1 --json "$data/cie190_example.ldt" >"$tmp/cie.json"; rc=$?
check "CIE 190 example: exit 0" '[ $rc -eq 0 ]'
python3 - "$tmp/cie.json" "$data/cie190_example_ugr.csv" >"$tmp/cie.txt" 2>&1 <<'PY'
import json, sys
t = json.load(open(sys.argv[1]))["ugr_table"]
ref = [[float(v) for v in l.split(",")] for l in open(sys.argv[2]) if l.strip() and not l.startswith("#")]
assert t["spacing_to_height"] == 1 and t["height_m"] == 2 and len(t["rooms"]) == 19, "shape"
assert [(r["x_h"], r["y_h"]) for r in t["rooms"]][:3] == [(2, 2), (2, 3), (2, 4)], "room order"
assert [s["ceiling"] for s in t["reflectances"]] == [0.7, 0.7, 0.5, 0.5, 0.3], "reflectances"
worst = max(abs(v - ref[i][c]) for i, r in enumerate(t["rooms"]) for c, v in enumerate(r["crosswise"] + r["endwise"]))
print("worst %.3f" % worst)
assert worst <= 0.15
PY
py=$?
check "CIE 190 example: every cell within 0.15 of the printed table ($(tail -1 "$tmp/cie.txt"))" '[ $py -eq 0 ]'

# Text and JSON agree: the text rounds the JSON's numbers to 0.1.
"$CANDELA" info --ugr "$data/cie190_example.ldt" >"$tmp/ex.txt"; rc=$?
"$CANDELA" info --ugr --json "$data/cie190_example.ldt" >"$tmp/ex.json"
check "text: exit 0, the summary then the table" '[ $rc -eq 0 ] && grep -q "^flux " "$tmp/ex.txt" && grep -q "^UGR table" "$tmp/ex.txt"'
check "text: 19 rooms" '[ "$(grep -cE "^  [0-9]+H x [0-9]+H " "$tmp/ex.txt")" -eq 19 ]'
line=$(grep -E "^  4H x 8H " "$tmp/ex.txt")
want=$(python3 -c '
import json, sys
r = json.load(open(sys.argv[1]))["ugr_table"]["rooms"][10]
print(" ".join("%.1f" % v for v in r["crosswise"] + r["endwise"]))' "$tmp/ex.json")
got=$(echo "$line" | tr -d '|' | awk '{ $1 = $2 = $3 = ""; print }' | xargs)
check "text: 4H x 8H is the JSON's row rounded ($got)" '[ "$got" = "$want" ]'
check "json: the summary's keys are kept" 'grep -q "\"flux_lm\"" "$tmp/ex.json" && grep -q "\"ugr_table\"" "$tmp/ex.json"'

# A luminaire with the same light in every C plane and a square opening
# looks the same crosswise and endwise: the two halves of every row match.
{
  printf 'IESNA:LM-63-2002\n[TEST] square Lambertian opening\nTILT=NONE\n1 -1 1 91 1 1 2 0.6 0.6 0\n1 1 0\n'
  awk 'BEGIN { for (k = 0; k <= 90; ++k) printf "%d\n", k; print 0; for (k = 0; k <= 90; ++k) printf "%.17g\n", 2000 * cos(k * 3.14159265358979323846 / 180) }'
} >"$tmp/square.ies"
"$CANDELA" info --ugr --json "$tmp/square.ies" >"$tmp/square.json"; rc=$?
python3 -c '
import json, sys
rooms = json.load(open(sys.argv[1]))["ugr_table"]["rooms"]
assert all(abs(a - b) < 1e-9 for r in rooms for a, b in zip(r["crosswise"], r["endwise"]))' "$tmp/square.json"
py=$?
check "square Lambertian opening: crosswise = endwise in every room" '[ $rc -eq 0 ] && [ $py -eq 0 ]'

# Files that cannot be rated: exit 1, the file named, nothing on stdout.
"$CANDELA" info --ugr "$CANDELA_SOURCE_DIR/tests/data/photometric/iso_1000cd.ies" >"$tmp/out" 2>"$tmp/err"; rc=$?
check "a point (no opening): exit 1" '[ $rc -eq 1 ]'
check "a point: the message names the file and says why" 'grep -q "iso_1000cd.ies: cannot rate glare: the file gives no luminous opening" "$tmp/err"'
check "a point: nothing on stdout" '[ ! -s "$tmp/out" ]'
sed 's/^\[TEST\] square Lambertian opening/[TEST] UV\n[_INTENSITYUNITS] mW\/sr/' "$tmp/square.ies" >"$tmp/uv.ies"
"$CANDELA" info --ugr "$tmp/uv.ies" >"$tmp/out" 2>"$tmp/err"; rc=$?
check "radiant intensity (mW/sr): exit 1, said" '[ $rc -eq 1 ] && grep -q "radiant intensity" "$tmp/err"'

# Options: one file only; --ugr-shr with --ugr, a ratio that divides the rooms.
"$CANDELA" info --ugr "$data/cie190_example.ldt" "$data/warn_lorl.ldt" >/dev/null 2>"$tmp/err"; rc=$?
check "--ugr with two files: usage error" '[ $rc -eq 2 ] && grep -q "\-\-ugr: expected one luminaire file" "$tmp/err"'
"$CANDELA" info --ugr-shr 1 "$data/cie190_example.ldt" >/dev/null 2>"$tmp/err"; rc=$?
check "--ugr-shr without --ugr: usage error" '[ $rc -eq 2 ]'
"$CANDELA" info --ugr --ugr-shr 0.3 "$data/cie190_example.ldt" >/dev/null 2>"$tmp/err"; rc=$?
check "--ugr-shr 0.3 (not a divisor of the rooms): usage error, said" '[ $rc -eq 2 ] && grep -q "does not divide" "$tmp/err"'
"$CANDELA" info --ugr --ugr-shr none "$data/cie190_example.ldt" >/dev/null 2>"$tmp/err"; rc=$?
check "--ugr-shr none: usage error" '[ $rc -eq 2 ] && grep -q "expected a spacing to height ratio" "$tmp/err"'
exit $fail
