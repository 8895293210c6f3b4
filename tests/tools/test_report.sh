#!/usr/bin/env bash
# candela report: the example office (at draft quality, so the test stays
# short) and a two-grid scene with requirements (one passing, one failing)
# give report.html (self-contained: every figure an inline SVG) and
# report.pdf (A4, at least 2 pages) carrying every grid's Em and U0 as
# summary.json has them, to the precision the stated error justifies
# (report_check.py); the same folder gives the same bytes. Bad input (not a
# solve's folder, a summary from another version, a missing or stale CSV, a
# scene gone, bad requirements) exits 1 naming what is wrong and writes
# nothing; an earlier report stays as it was. Runs under the sanitizers too
# (the browser's check is test_report_browser.sh).
# ctest-timeout: 300
source "$(dirname "$0")/harness.sh"
here=$(dirname "$0")
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }

# 1. The example office, at draft quality.
mkdir -p "$tmp/office"
cp "$CANDELA_SOURCE_DIR"/data/office/*.ies "$tmp/office/"
python3 -c "
import json, sys
d = json.load(open(sys.argv[1])); d['solver']['quality'] = 'draft'
json.dump(d, open(sys.argv[2], 'w'), indent=1)" "$CANDELA_SOURCE_DIR/data/office/office.json" "$tmp/office/office.json"
"$CANDELA" solve "$tmp/office/office.json" -o "$tmp/office/out" --quiet > /dev/null 2>&1; st=$?
check "office: solved" '[ $st -eq 0 ]'
(cd / && "$CANDELA" report "$tmp/office/out" > "$tmp/office.out" 2> "$tmp/office.err"); st=$?
check "office: report exit 0 (run from another folder: the scene found by its absolute path)" '[ $st -eq 0 ]'
check "office: prints both files" '[ "$(cat "$tmp/office.out")" = "$tmp/office/out/report.html
$tmp/office/out/report.pdf" ]'
out="$tmp/office/out"
pdfinfo "$out/report.pdf" > "$tmp/office.pdfinfo" 2>&1
check "office: the PDF is A4" 'grep -q "^Page size: *595.276 x 841.89 pts (A4)" "$tmp/office.pdfinfo"'
check "office: the PDF has at least 2 pages" '[ "$(sed -n "s/^Pages: *//p" "$tmp/office.pdfinfo")" -ge 2 ]'
pdftotext -layout "$out/report.pdf" "$tmp/office.txt"
python3 "$here/report_check.py" "$out" "$tmp/office.txt" > "$tmp/office.check"; st=$?
while read -r line; do check "office: ${line#* }" '[[ "$line" == ok* ]]'; done < "$tmp/office.check"
check "office: every grid's Em and U0 checked (4 grids, HTML and PDF)" '[ $st -eq 0 ] && [ $(grep -c "^ok PDF .*: Em .* and U0" "$tmp/office.check") -eq 4 ]'
# Self-contained: no script, no link, no external source; 3 maps and 2 polar diagrams inline.
check "office: HTML self-contained (no script, link or external source)" '! grep -qiE "<script|<link|src=\"(https?:|//|file:)" "$out/report.html"'
check "office: every image an inline SVG" '[ $(grep -o "<img " "$out/report.html" | wc -l) -eq $(grep -o "<img [^>]*src=\"data:image/svg+xml;base64," "$out/report.html" | wc -l) ]'
for grid in workplane floor north_wall; do
  check "office: a map of $grid" 'grep -q "alt=\"$grid: illuminance E in lx, isolux lines, plan and luminaires\"" "$out/report.html" && grep -q "$grid: illuminance E in lx" "$tmp/office.txt"'
done
check "office: no map of the points grid" '! grep -q "alt=\"desk_probes:" "$out/report.html"'
check "office: polar diagrams of both luminaire files" 'grep -q "alt=\"Polar intensity diagram: downlight.ies (cd/klm, nadir down)\"" "$out/report.html" && grep -q "alt=\"Polar intensity diagram: linear.ies" "$out/report.html"'
check "office: the schedule counts 4 downlights, 2 linear, 1 area" 'grep -q "downlight.ies.*Candela example" "$tmp/office.txt" && python3 - "$out/report.html" <<PY
import re, sys
t = open(sys.argv[1]).read()
rows = re.findall(r"<tr><td>(downlight.ies|linear.ies|luminaires\[6\] area)</td>(.*?)</tr>", t)
counts = {n: re.findall(r"<td[^>]*>([^<]*)</td>", r)[-1] for n, r in rows}
assert counts == {"downlight.ies": "4", "linear.ies": "2", "luminaires[6] area": "1"}, counts
PY'
check "office: the cover names scene, version, method, quality, seed and solve time" 'for k in "Scene" "Candela" "Method" "Quality *draft" "Seed *1" "Solve time"; do grep -q "$k" "$tmp/office.txt" || exit 1; done'
check "office: method and accuracy section with the plan's reasons" 'grep -q "Method and accuracy" "$tmp/office.txt" && grep -q "records interpolated cost less" "$out/report.html" && grep -q "Error statement" "$out/report.html"'
cp "$out/report.html" "$tmp/first.html"; cp "$out/report.pdf" "$tmp/first.pdf"
"$CANDELA" report "$out" > /dev/null 2>&1
check "office: the same folder gives the same bytes" 'cmp -s "$out/report.html" "$tmp/first.html" && cmp -s "$out/report.pdf" "$tmp/first.pdf"'
"$CANDELA" report "$out" --title "Office, level 2 & annex" > /dev/null 2>&1; st=$?
check "--title: in the HTML (escaped) and the PDF" '[ $st -eq 0 ] && grep -q "<title>Office, level 2 &amp; annex</title>" "$out/report.html" && pdftotext "$out/report.pdf" - | grep -q "Office, level 2 & annex"'

# 2. Two grids with requirements: the desk's in the scene passes, the
# aisle's (from a file) fails. Direct light only: exact, 4 significant digits.
cat > "$tmp/two.json" <<'JSON'
{"version": 1,
 "surfaces": [{"name": "room", "type": "box", "min": [0,0,0], "max": [6,4,3], "inward": true, "reflectance": 0}],
 "luminaires": [{"type": "point", "position": [3,2,2.8], "intensity_cd": 1000}],
 "grids": [{"name": "desk", "type": "rect", "origin": [1,1,0.8], "u": [4,0,0], "v": [0,2,0], "nu": 8, "nv": 4,
            "requirements": {"Em_lx": 100, "U0": 0.3}},
           {"name": "aisle", "type": "polygon", "vertices": [[0.2,0.2,0],[0.8,0.2,0],[0.8,3.8,0],[0.2,3.8,0]], "spacing": 0.3}]}
JSON
"$CANDELA" solve "$tmp/two.json" -o "$tmp/two" --quiet > /dev/null 2>&1; st=$?
check "two grids: solved" '[ $st -eq 0 ]'
"$CANDELA" report "$tmp/two" > /dev/null 2> "$tmp/two.err"; st=$?
check "two grids, scene requirements: exit 0" '[ $st -eq 0 ]'
check "two grids, scene requirements: desk passes, aisle has none" 'grep -q "<td class=\"pass\">pass: Em +[0-9.]* %, U0 +0.[0-9]*; Em &gt;= 100 lx, U0 &gt;= 0.3</td>" "$tmp/two/report.html" && grep -q "<td>none given</td>" "$tmp/two/report.html"'
printf '{"aisle": {"Em_lx": 5000}}\n' > "$tmp/req.json"
"$CANDELA" report "$tmp/two" --requirements "$tmp/req.json" > /dev/null 2> "$tmp/two.err"; st=$?
check "two grids, requirements file: exit 0" '[ $st -eq 0 ]'
pdftotext -layout "$tmp/two/report.pdf" "$tmp/two.txt"
python3 "$here/report_check.py" "$tmp/two" "$tmp/two.txt" > "$tmp/two.check"; st=$?
while read -r line; do check "two grids: ${line#* }" '[[ "$line" == ok* ]]'; done < "$tmp/two.check"
check "two grids: Em and U0 of both grids checked" '[ $st -eq 0 ] && [ $(grep -c "^ok PDF .*: Em .* and U0" "$tmp/two.check") -eq 2 ]'
aisle_em=$(json "$tmp/two/summary.json" "d['grids']['aisle']['E_avg_lx']")
margin=$(python3 -c "print('%+.1f' % (100 * ($aisle_em / 5000 - 1)))")
check "two grids: the aisle fails by $margin % of 5000 lx (HTML and PDF)" 'grep -q "<td class=\"fail\">FAIL: Em $margin %; Em &gt;= 5000 lx</td>" "$tmp/two/report.html" && grep -q "FAIL: Em $margin %" "$tmp/two.txt"'
check "two grids: the desk still passes (PDF)" 'grep -q "pass: Em +" "$tmp/two.txt"'
check "two grids: exact values, 4 significant digits (Em of the desk)" 'grep -q "<tr><td>desk</td><td class=\"num\">[0-9][0-9][0-9].[0-9]</td>" "$tmp/two/report.html"'

# 3. Bad input: exit 1, the message names what is wrong, nothing written.
bad() { # name, expected message (grep -E), folder, extra arguments
  local name=$1 says=$2 dir=$3
  "$CANDELA" report "$dir" "${@:4}" > /dev/null 2> "$tmp/$name.err"; local st=$?
  check "bad input $name: exit 1" '[ $st -eq 1 ]'
  check "bad input $name: says $says" 'grep -qE -- "$says" "$tmp/$name.err"'
  check "bad input $name: no report, no temporary file left" '[ ! -e "$dir/report.html" ] && [ ! -e "$dir/report.pdf" ] && ! ls "$dir" 2>/dev/null | grep -q "\.tmp\."'
}
copy() { rm -rf "$tmp/$1"; cp -r "$tmp/two" "$tmp/$1"; rm -f "$tmp/$1"/report.*; }
bad nofolder "$tmp/none: expected the folder of a solve's results" "$tmp/none"
mkdir -p "$tmp/empty"
bad empty "$tmp/empty: not the output of .candela solve.: summary.json is missing" "$tmp/empty"
copy version; sed -i 's/"candela_version":[[:space:]]*"[^"]*"/"candela_version": "0.0.9"/' "$tmp/version/summary.json"
bad version "summary.json: written by Candela 0.0.9, this is Candela [0-9.]+: solve the scene again" "$tmp/version"
copy nocsv; rm "$tmp/nocsv/desk.csv"
bad nocsv "nocsv/desk.csv: missing \(summary.json lists grid desk" "$tmp/nocsv"
copy stale; python3 - "$tmp/stale/desk.csv" <<'PY'
import sys
lines = open(sys.argv[1]).read().split("\n")
f = lines[3].split(","); f[6] = repr(float(f[6]) * 1.01); lines[3] = ",".join(f)
open(sys.argv[1], "w").write("\n".join(lines))
PY
bad stale "stale/desk.csv: stale: its E_avg_lx is .*, .*summary.json says" "$tmp/stale"
copy moved; python3 - "$tmp/moved/summary.json" <<'PY'
import json, sys
d = json.load(open(sys.argv[1])); d["scene"] = "/nonexistent/two.json"; d["scene_absolute_path"] = "/nonexistent/two.json"
json.dump(d, open(sys.argv[1], "w"))
PY
bad moved "the scene it names, /nonexistent/two.json, is missing" "$tmp/moved"
copy badreq; printf '{"atrium": {"Em_lx": 300}}\n' > "$tmp/badreq.json"
bad badreq "badreq.json: atrium: the scene .* has no grid of that name" "$tmp/badreq" --requirements "$tmp/badreq.json"
copy badu0; printf '{"desk": {"U0": 1.5}}\n' > "$tmp/badu0.json"
bad badu0 "badu0.json: desk.U0: expected a number > 0 and <= 1" "$tmp/badu0" --requirements "$tmp/badu0.json"
# An earlier report stays as it was when a later run fails.
cp "$tmp/two/report.html" "$tmp/kept.html"
rm "$tmp/two/aisle.csv"
"$CANDELA" report "$tmp/two" > /dev/null 2>&1; st=$?
check "a failed run keeps the earlier report" '[ $st -eq 1 ] && cmp -s "$tmp/two/report.html" "$tmp/kept.html"'
"$CANDELA" report > /dev/null 2>&1; st=$?
check "no OUTDIR: usage error (exit 2)" '[ $st -eq 2 ]'

# 4. The scene's "requirements" key is checked by the loader.
sed 's/"requirements": {"Em_lx": 100, "U0": 0.3}/"requirements": {"Em": 100}/' "$tmp/two.json" > "$tmp/badkey.json"
"$CANDELA" solve "$tmp/badkey.json" -o "$tmp/badkey" --quiet > /dev/null 2> "$tmp/badkey.err"; st=$?
check "scene requirements with an unknown key: exit 1 naming it" '[ $st -eq 1 ] && grep -q "grids\[0\].requirements" "$tmp/badkey.err"'
sed 's/"requirements": {"Em_lx": 100, "U0": 0.3}/"requirements": {}/' "$tmp/two.json" > "$tmp/emptyreq.json"
"$CANDELA" solve "$tmp/emptyreq.json" -o "$tmp/emptyreq" --quiet > /dev/null 2> "$tmp/emptyreq.err"; st=$?
check "scene requirements empty: exit 1" '[ $st -eq 1 ] && grep -q "at least one of Em_lx and U0" "$tmp/emptyreq.err"'
exit $fail
