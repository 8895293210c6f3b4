#!/usr/bin/env bash
# The example scenes of data/ (classroom, corridor, floodlit yard) solve,
# at draft quality here, under --strict: no luminaire lights nothing, no
# grid is dark. What each shows is checked against its own inputs: the
# classroom's installed power (12 linear luminaires of 36 W and 2 board
# lights of 20 W, from their files) over its 8 x 6 m work plane, and its
# observers' glare in glare.csv; the
# corridor's polygon floor, whose area_m2 column adds up to its area
# (24 x 2.4 + 2.4 x 5.6 m^2); the yard's cylindrical and semicylindrical
# columns and its luminance on the ground (L = rho E / pi, rho 0.15). The
# README's complete scene solves too, its downlights (an array in world
# axes, turned 90 degrees) all inside the room, over the work plane.
# ctest-timeout: 300
source "$(dirname "$0")/harness.sh"
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }

# A copy at draft quality, its files named by absolute path.
draft() { # scene.json out.json
  python3 - "$1" "$2" <<'PY'
import json, os, sys
src, dst = sys.argv[1], sys.argv[2]
d = json.load(open(src))
base = os.path.dirname(os.path.abspath(src))
for l in d.get("luminaires", []):
    if "file" in l: l["file"] = os.path.join(base, l["file"])
d["solver"]["quality"] = "draft"
d.pop("$schema", None)
json.dump(d, open(dst, "w"), indent=1)
PY
}

# The README's scene, as a user would save it at the top of the repository.
python3 - "$CANDELA_SOURCE_DIR/README.md" "$tmp/readme_scene.json" "$CANDELA_SOURCE_DIR" <<'PY'
import json, os, re, sys
text = open(sys.argv[1]).read()
block = re.search(r"A complete scene:.*?```json\n(.*?)```", text, re.S).group(1)
d = json.loads(block)
for l in d["luminaires"]:
    if "file" in l: l["file"] = os.path.join(sys.argv[3], l["file"])
d["solver"]["quality"] = "draft"
json.dump(d, open(sys.argv[2], "w"), indent=1)
PY
check "README scene: extracted" '[ -s "$tmp/readme_scene.json" ]'
"$CANDELA" solve "$tmp/readme_scene.json" -o "$tmp/readme" --quiet --strict > /dev/null 2> "$tmp/readme.err"; st=$?
check "README scene: solves under --strict" '[ $st -eq 0 ]' || cat "$tmp/readme.err"
check "README scene: all 6 downlights over the work plane (world-axis rows inside the room)" \
  '[ "$(json "$tmp/readme/summary.json" "d[\"grids\"][\"workplane\"][\"luminaires_over\"]")" = 6 ]'

for name in classroom corridor yard; do
  scene="$CANDELA_SOURCE_DIR/data/$name/$name.json"
  check "$name: the example exists" '[ -s "$scene" ]'
  draft "$scene" "$tmp/$name.json"
  "$CANDELA" solve "$tmp/$name.json" -o "$tmp/$name" --quiet --strict > "$tmp/$name.out" 2> "$tmp/$name.err"; st=$?
  check "$name: solves under --strict (no warning)" '[ $st -eq 0 ] && [ "$(json "$tmp/$name/summary.json" "d[\"warnings\"]")" = "[]" ]' || cat "$tmp/$name.err"
done

check "classroom: installed power 12 x 36 W + 2 x 20 W from the files" '[ "$(json "$tmp/classroom/summary.json" "d[\"power\"][\"installed_w\"]")" = 472 ]'
check "classroom: W/m2 over the 48 m2 work plane" '[ "$(json "$tmp/classroom/summary.json" "abs(d[\"grids\"][\"workplane\"][\"power_density_w_m2\"] - 472 / 48) < 1e-9")" = True ]'
check "classroom: its two observers rated for glare (glare.csv: pupil and teacher with a UGR each)" 'python3 -c "
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert [r[\"name\"] for r in rows] == [\"pupil\", \"teacher\"] and all(float(r[\"ugr\"]) > 10 for r in rows)" "$tmp/classroom/glare.csv"'
check "classroom: the board is lit by its aimed lights" '[ "$(json "$tmp/classroom/summary.json" "d[\"grids\"][\"board\"][\"E_min_lx\"] > 0")" = True ]'
check "corridor: area_m2 adds up to the floor (71.04 m2)" 'python3 -c "
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
assert abs(sum(float(r[\"area_m2\"]) for r in rows) - 71.04) < 1e-9" "$tmp/corridor/floor.csv"'
check "yard: Ez_lx and Esz_lx columns with their stated errors (ground-reflected light sampled), L_cd_m2 on the ground" '[ "$(head -1 "$tmp/yard/faces_north.csv")" = "x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_stderr_lx,Ez_lx,Ez_stderr_lx,Esz_lx,Esz_stderr_lx" ] && [ "$(head -1 "$tmp/yard/yard.csv")" = "x,y,z,nx,ny,nz,E_lx,E_direct_lx,E_indirect_lx,E_stderr_lx,L_cd_m2" ]'
check "yard: L = 0.15 E / pi at every ground point" 'python3 -c "
import csv, sys, math
for r in csv.DictReader(open(sys.argv[1])):
    assert abs(float(r[\"L_cd_m2\"]) - 0.15 * float(r[\"E_lx\"]) / math.pi) <= 1e-12 * float(r[\"E_lx\"]) + 1e-300" "$tmp/yard/yard.csv"'
check "yard: summary has the cylindrical statistics" '[ "$(json "$tmp/yard/summary.json" "sorted(k for k in d[\"grids\"][\"faces_north\"] if k.startswith(\"Ez\"))")" = "['"'"'Ez_U0'"'"', '"'"'Ez_avg_lx'"'"', '"'"'Ez_max_lx'"'"', '"'"'Ez_min_lx'"'"', '"'"'Ez_stderr_max_lx'"'"']" ]'
exit $fail
