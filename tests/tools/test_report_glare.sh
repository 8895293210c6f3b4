#!/usr/bin/env bash
# candela report with observers: the glare section (each observer's UGR
# against its UGR_L: pass, FAIL, "within the stated error" when the margin
# is smaller than the stated error; an observer grid by its worst
# observer), the observers on the plan (an inline SVG named for them), and
# the luminaire's UGR table in the schedule, its numbers `candela info
# --ugr`'s; a glare.csv that disagrees with summary.json, or is missing,
# exits 1 naming it.
# ctest-timeout: 240
source "$(dirname "$0")/harness.sh"
cp "$CANDELA_SOURCE_DIR/tests/data/photometric/cie190_example.ldt" "$tmp/panel.ldt"
scene() { # UGR_L of the desk
  cat <<EOF
{"version": 1,
 "surfaces": [{"type": "box", "min": [-4, -1, 0], "max": [4, 9, 3.2], "inward": true, "reflectance": {"floor": 0.2, "walls": 0.5, "ceiling": 0.7}}],
 "luminaires": [{"type": "goniometric", "file": "panel.ldt", "position": [-2, 1.5, 3.19], "array": {"counts": [3, 3], "spacing": [2, 3]}}],
 "observers": [{"name": "desk", "eye": [0, -0.5, 1.2], "view": [0, 1, 0], "requirements": {"UGR_L": $1}},
               {"name": "side", "eye": [-3.5, 4, 1.2], "view": [1, 0, 0], "requirements": {"UGR_L": 25}},
               {"name": "free", "eye": [3.5, 4, 1.2], "view": [-1, 0, 0]}],
 "grids": [{"name": "work", "type": "rect", "origin": [-3.5, -0.5, 0.8], "u": [7, 0, 0], "v": [0, 9, 0], "nu": 7, "nv": 9},
           {"name": "map", "type": "observers", "origin": [-3, 0, 1.2], "u": [6, 0, 0], "v": [0, 6, 0], "nu": 3, "nv": 3, "view": [0, 1, 0], "requirements": {"UGR_L": 19}}],
 "solver": {"quality": "draft"}}
EOF
}
scene 19 >"$tmp/room.json"
"$CANDELA" solve "$tmp/room.json" -o "$tmp/out" --quiet >/dev/null 2>&1; st=$?
check "solved" '[ $st -eq 0 ]'
"$CANDELA" report "$tmp/out" >/dev/null 2>"$tmp/err"; st=$?
check "report: exit 0" '[ $st -eq 0 ]' || cat "$tmp/err"
pdftotext -layout "$tmp/out/report.pdf" "$tmp/report.txt"
ugr() { python3 -c "import json,sys; g=[o for o in json.load(open(sys.argv[1]))['glare'] if o['observer']==sys.argv[2]][0]; print(g[sys.argv[3]])" "$tmp/out/summary.json" "$@"; }
desk=$(ugr desk ugr) desk_err=$(ugr desk ugr_stderr)
check "the glare section" 'grep -q "Glare (UGR)$" "$tmp/report.txt"'
verdict=$(awk -v u="$desk" 'BEGIN { print (u <= 19 ? "pass" : "FAIL") }')
check "desk: its verdict against UGR_L 19 ($verdict at UGR $desk)" 'grep -qE "^desk .* 19 +$verdict: [0-9.]+ (above|below)" "$tmp/report.txt"'
check "side: pass against 25" 'grep -qE "^side .* 25 +pass: " "$tmp/report.txt"'
check "free: no limit given" 'grep -qE "^free .* - +no limit given" "$tmp/report.txt"'
worst=$(python3 -c "
import json,sys; g=[o for o in json.load(open(sys.argv[1]))['glare'] if o['observer'].startswith('map[')]
print(max(g, key=lambda o: o['ugr'])['observer'])" "$tmp/out/summary.json")
check "the observer grid as one row, its worst observer named ($worst)" 'grep -qF "map (9 observers; the worst: $worst)" "$tmp/report.txt"'
check "the plan: an inline SVG titled for the observers" 'grep -q "Glare: the observers on the plan" "$tmp/out/report.html"'
# The UGR table of the schedule is candela info --ugr's, room 4H x 8H.
info=$("$CANDELA" info --ugr "$tmp/panel.ldt" | grep -E "^  4H x 8H " | tr -d '|' | awk '{ $1 = $2 = $3 = ""; print }' | xargs)
row=$(grep -E "^ *4H x 8H " "$tmp/report.txt" | tail -1 | awk '{ $1 = $2 = $3 = ""; print }' | xargs)
check "the schedule's UGR table: room 4H x 8H as candela info --ugr prints it ($row)" '[ -n "$row" ] && [ "$row" = "$info" ]'

# A limit within the stated error of the UGR: the verdict says so.
near=$(awk -v u="$desk" -v e="$desk_err" 'BEGIN { printf "%.10g", u + 0.5 * e }')
scene "$near" >"$tmp/room2.json"
"$CANDELA" solve "$tmp/room2.json" -o "$tmp/out2" --quiet >/dev/null 2>&1
"$CANDELA" report "$tmp/out2" >/dev/null 2>&1; st=$?
pdftotext -layout "$tmp/out2/report.pdf" "$tmp/report2.txt"
# (the table's cell may wrap: the row and the next line read as one)
row2=$(grep -A1 -E "^desk " "$tmp/report2.txt" | tr -s ' \n' ' ')
check "a limit half a stated error above the UGR: pass, within the stated error" '[ $st -eq 0 ] && grep -qE "pass: [0-9.]+ below \(within the .*stated error\)" <<<"$row2"'

# glare.csv stale or missing: exit 1 naming it, no report written.
rm -f "$tmp/out2/report.html" "$tmp/out2/report.pdf"
sed -i '2s/^\(desk,[^,]*,[^,]*,[^,]*,[^,]*,[^,]*,[^,]*,\)[^,]*/\1 9.5/' "$tmp/out2/glare.csv"
"$CANDELA" report "$tmp/out2" >/dev/null 2>"$tmp/err2"; st=$?
check "glare.csv changed: exit 1 naming it" '[ $st -eq 1 ] && grep -q "glare.csv: expected the UGR and background luminance of summary.json for observer 0 (desk)" "$tmp/err2"'
check "glare.csv changed: no report written" '[ ! -e "$tmp/out2/report.html" ] && [ ! -e "$tmp/out2/report.pdf" ]'
rm "$tmp/out2/glare.csv"
"$CANDELA" report "$tmp/out2" >/dev/null 2>"$tmp/err3"; st=$?
check "glare.csv missing: exit 1 naming it" '[ $st -eq 1 ] && grep -q "glare.csv" "$tmp/err3"'
exit $fail
