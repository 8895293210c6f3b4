#!/usr/bin/env bash
# The report a client accepts: a named office with a project
# block, an array of linear luminaires and an aimed wall washer, a box room
# with a window (open face), grids asking for Ez, Esz, L and AO, solved at
# draft quality. report_client_check.py holds the report to the scene,
# summary.json and the CSVs: title, project block, every quantity's row and
# map, the luminaire list at the array's positions, room data, power,
# method table, --values. Then: --project replaces fields of the scene's
# block; a scene changed after the solve (a maintenance factor, a
# reflectance, a photometric file's content, the seed) is refused naming
# what changed, and nothing is written; what no result depends on (threads,
# requirements, the name, the project) may change; a bad project file is
# refused naming the file and the key.
# ctest-timeout: 300
source "$(dirname "$0")/harness.sh"
here=$(dirname "$0")

mkdir -p "$tmp/s"
cp "$CANDELA_SOURCE_DIR"/data/office/linear.ies "$CANDELA_SOURCE_DIR"/data/office/downlight.ies "$tmp/s/"
cat > "$tmp/s/client.json" <<'JSON'
{"version": 1,
 "name": "Open-plan office, level 2",
 "project": {"project": "Refurbishment 2026", "client": "ACME Ltd", "designer": "J. Doe",
             "date": "2026-11-26", "notes": "Maintenance factor 0.8: cleaned every 2 years."},
 "surfaces": [{"name": "room", "type": "box", "min": [0, 0, 0], "max": [8, 6, 3], "inward": true,
               "reflectance": {"floor": 0.2, "walls": 0.5, "ceiling": 0.7}, "open": ["-y"]},
              {"name": "desk", "type": "rect", "origin": [3, 2.5, 0.72], "u": [1.6, 0, 0], "v": [0, 0.8, 0],
               "reflectance": 0.4}],
 "luminaires": [{"name": "Row A", "type": "goniometric", "file": "linear.ies", "position": [2, 1.5, 2.8],
                 "array": {"counts": [2, 2], "spacing": [4, 3]}, "maintenance_factor": 0.8},
                {"name": "Wall washer", "type": "goniometric", "file": "downlight.ies", "position": [7.5, 5.5, 2.9],
                 "aim": [4, 3, 0], "maintenance_factor": 0.7}],
 "grids": [{"name": "workplane", "type": "rect", "origin": [0.5, 0.5, 0.8], "u": [7, 0, 0], "v": [0, 5, 0],
            "nu": 14, "nv": 10, "outputs": ["cylindrical", "ao"], "requirements": {"Em_lx": 300, "U0": 0.4}},
           {"name": "floor", "type": "polygon", "vertices": [[0, 0, 0], [8, 0, 0], [8, 6, 0], [0, 6, 0]],
            "spacing": 1.0, "outputs": ["luminance"]},
           {"name": "view", "type": "rect", "origin": [1, 0.05, 1.2], "u": [6, 0, 0], "v": [0, 0, 1],
            "nu": 12, "nv": 2, "normal": [0, 1, 0], "outputs": ["semicylindrical"]}],
 "solver": {"quality": "draft", "seed": 1}}
JSON
scene="$tmp/s/client.json"
out="$tmp/s/out"
"$CANDELA" solve "$scene" -o "$out" --quiet > /dev/null 2> "$tmp/solve.err"; st=$?
check "solved" '[ $st -eq 0 ]'
"$CANDELA" report "$out" --values > /dev/null 2> "$tmp/report.err"; st=$?
check "report --values: exit 0" '[ $st -eq 0 ]'
pdftotext -layout "$out/report.pdf" "$tmp/report.txt"
python3 "$here/report_client_check.py" "$scene" "$out" "$tmp/report.txt" > "$tmp/check.txt"; st=$?
while read -r line; do check "${line#* }" '[[ "$line" == ok* ]]'; done < "$tmp/check.txt"
check "every check of the client's report passed ($(grep -c '^ok' "$tmp/check.txt") of them)" '[ $st -eq 0 ] && [ $(grep -c "^ok" "$tmp/check.txt") -ge 60 ]'
check "the same folder gives the same bytes" 'cp "$out/report.pdf" "$tmp/first.pdf" && "$CANDELA" report "$out" --values > /dev/null && cmp -s "$out/report.pdf" "$tmp/first.pdf"'

# --project: its fields replace the scene's one by one.
printf '{"client": "Globex plc", "date": "December 2026"}\n' > "$tmp/project.json"
"$CANDELA" report "$out" --project "$tmp/project.json" > /dev/null 2>&1; st=$?
pdftotext -layout "$out/report.pdf" "$tmp/project.txt"
check "--project: exit 0" '[ $st -eq 0 ]'
check "--project: its client and date replace the scene's" 'grep -qE "^Client +Globex plc$" "$tmp/project.txt" && grep -qE "^Date +December 2026$" "$tmp/project.txt" && ! grep -q "ACME" "$tmp/project.txt"'
check "--project: the scene's designer and project stay" 'grep -qE "^Designer +J. Doe$" "$tmp/project.txt" && grep -qE "^Project +Refurbishment 2026$" "$tmp/project.txt"'
printf '{"client": "Globex", "architect": "X"}\n' > "$tmp/badproject.json"
"$CANDELA" report "$out" --project "$tmp/badproject.json" > /dev/null 2> "$tmp/badproject.err"; st=$?
check "--project with an unknown key: exit 1 naming the file and the key" '[ $st -eq 1 ] && grep -q "badproject.json: architect" "$tmp/badproject.err"'
printf '{"client": ' > "$tmp/broken.json"
"$CANDELA" report "$out" --project "$tmp/broken.json" > /dev/null 2> "$tmp/broken.err"; st=$?
check "--project not JSON: exit 1 naming the file" '[ $st -eq 1 ] && grep -q "broken.json: invalid JSON" "$tmp/broken.err"'

# A scene changed after the solve: refused, naming what changed; nothing written.
edit() { # python expression on the scene d, then the report; prints its exit status
  cp "$scene" "$tmp/kept.json"
  python3 -c "
import json, sys
d = json.load(open(sys.argv[1])); $1
json.dump(d, open(sys.argv[1], 'w'), indent=1)" "$scene"
  rm -f "$out/report.html" "$out/report.pdf"
  "$CANDELA" report "$out" > /dev/null 2> "$tmp/edit.err"; echo $?
  cp "$tmp/kept.json" "$scene"
}
stale() { # what, python edit, the message expected
  local st says=$3; st=$(edit "$2")
  check "stale ($1): exit 1" '[ "$st" -eq 1 ]'
  check "stale ($1): says $says" 'grep -qF -- "$says" "$tmp/edit.err" && grep -q "changed since the solve" "$tmp/edit.err"'
  check "stale ($1): no report written" '[ ! -e "$out/report.html" ] && [ ! -e "$out/report.pdf" ]'
}
stale "maintenance factor 0.8 -> 0.5" "d['luminaires'][0]['maintenance_factor'] = 0.5" "luminaires[0].maintenance_factor changed"
stale "a wall's reflectance" "d['surfaces'][0]['reflectance']['walls'] = 0.6" "surfaces[0].reflectance changed"
stale "the seed" "d['solver']['seed'] = 2" "solver.seed changed"
stale "a luminaire added" "d['luminaires'].append({'type': 'point', 'position': [1, 1, 2], 'intensity_cd': 100})" "luminaires[2] added"
cp "$tmp/s/downlight.ies" "$tmp/downlight.kept"
sed -i '0,/^TILT=NONE/!{0,/ 1 /s/ 1 / 2 /}' "$tmp/s/downlight.ies"
rm -f "$out/report.html"; "$CANDELA" report "$out" > /dev/null 2> "$tmp/file.err"; st=$?
check "stale (the photometric file's content): exit 1 naming the entry and the file" '[ $st -eq 1 ] && grep -q "luminaires\[1\].file content changed (.*downlight.ies)" "$tmp/file.err" && ! cmp -s "$tmp/s/downlight.ies" "$tmp/downlight.kept"'
cp "$tmp/downlight.kept" "$tmp/s/downlight.ies"

# What no result depends on may change after the solve.
fine() { # what, python edit
  local st; st=$(edit "$2")
  check "not stale ($1): exit 0" '[ "$st" -eq 0 ]'
}
fine "threads" "d['solver']['threads'] = 1"
fine "a grid's requirements" "d['grids'][0]['requirements'] = {'Em_lx': 100}"
fine "the name and the project" "d['name'] = 'Office 2'; d['project']['client'] = 'Initech'"
fine "whitespace and key order" "d['luminaires'][0] = dict(reversed(list(d['luminaires'][0].items())))"
exit $fail
