#!/usr/bin/env bash
# Glare through `candela solve`: glare.csv and summary.json's "glare" for
# observers and an observer grid, written atomically, their numbers the
# same in both; and the scenes refused with exit 1 and the JSON path: an
# eye inside a closed box, an eye on a surface, a view of zero length or
# tilted, a scene whose luminaires cannot be rated.
source "$(dirname "$0")/harness.sh"

# A Lambertian opening (I0 cos gamma on 0.3 x 0.6 m) every degree.
{
  printf 'IESNA:LM-63-2002\n[TEST] lambertian opening\nTILT=NONE\n1 -1 1 91 1 1 2 0.3 0.6 0\n1 1 0\n'
  awk 'BEGIN { for (k = 0; k <= 90; ++k) printf "%d\n", k; print 0; for (k = 0; k <= 90; ++k) printf "%.17g\n", 1200 * cos(k * 3.14159265358979323846 / 180) }'
} >"$tmp/lamb.ies"
room='"surfaces": [{"type": "box", "min": [-4, -1, 0], "max": [4, 9, 3.2], "inward": true, "reflectance": {"floor": 0.2, "walls": 0.5, "ceiling": 0.7}}]'
lums='"luminaires": [{"type": "goniometric", "file": "lamb.ies", "position": [0, 3, 3.19], "array": {"counts": [2, 2], "spacing": [2, 2]}}, {"type": "point", "position": [0, 6, 3], "intensity_cd": 50}]'
cat >"$tmp/room.json" <<EOF
{"version": 1, $room, $lums,
 "observers": [{"name": "desk", "eye": [0, 0, 1.2], "view": [0, 1, 0], "requirements": {"UGR_L": 19}}],
 "grids": [{"name": "work", "type": "rect", "origin": [-3, 0, 0.8], "u": [6, 0, 0], "v": [0, 8, 0], "nu": 3, "nv": 4},
           {"name": "map", "type": "observers", "origin": [-2, -0.5, 1.2], "u": [4, 0, 0], "v": [0, 1, 0], "nu": 2, "nv": 1, "view": [0, 1, 0]}],
 "solver": {"quality": "draft"}}
EOF
"$CANDELA" solve "$tmp/room.json" -o "$tmp/out" >"$tmp/stdout" 2>"$tmp/stderr"; rc=$?
check "a room with observers: exit 0" '[ $rc -eq 0 ]' || cat "$tmp/stderr"
check "glare.csv: the header" '[ "$(head -1 "$tmp/out/glare.csv")" = "name,x,y,z,view_x,view_y,view_z,ugr,ugr_stderr,background_cd_m2,background_stderr_cd_m2" ]'
check "glare.csv: desk, then the grid's map[0] and map[1]" '[ "$(cut -d, -f1 "$tmp/out/glare.csv" | tail -n +2 | xargs)" = "desk map[0] map[1]" ]'
check "only the expected files (written atomically: no temporary left)" '[ "$(ls "$tmp/out" | xargs)" = "glare.csv summary.json work.csv work.exr work.png" ]'
check "stdout: the desk's UGR against its UGR_L" 'grep -qE "^desk +UGR +[0-9.]+ \+- [0-9.e-]+ +Lb .* 4 sources in view +UGR_L 19: (pass|FAIL)" "$tmp/stdout"'
python3 - "$tmp/out/summary.json" "$tmp/out/glare.csv" >"$tmp/py.txt" 2>&1 <<'PY'
import csv, json, sys
g = json.load(open(sys.argv[1]))["glare"]
rows = list(csv.DictReader(open(sys.argv[2])))
assert [o["observer"] for o in g] == ["desk", "map[0]", "map[1]"], "names"
d = g[0]
assert set(d) == {"observer", "json_path", "eye", "view", "ugr", "ugr_stderr", "background_cd_m2",
                  "background_stderr_cd_m2", "UGR_L", "sources", "excluded"}, sorted(d)
assert d["UGR_L"] == 19 and g[1]["UGR_L"] is None and g[1]["json_path"] == "grids[1]"
assert len(d["sources"]) == 4 and all(set(s) == {"luminaire", "L_cd_m2", "omega_sr", "omega_stderr_sr", "omega_exact", "p", "term", "term_stderr"} for s in d["sources"])
assert d["excluded"] == [{"luminaire": "luminaires[1]", "reason": "no luminous area: a point source cannot be rated (CIE 117 weighs the luminance of the luminous parts)"}], d["excluded"]
assert d["sources"][0]["luminaire"] == "luminaires[0] (1 of 4)" and d["sources"][0]["omega_exact"] is True
# the background: the room's interreflection, stated with an error
assert d["background_cd_m2"] > 0 and 0 < d["background_stderr_cd_m2"] < 0.1 * d["background_cd_m2"]
for o, r in zip(g, rows):
    assert float(r["ugr"]) == o["ugr"] and float(r["ugr_stderr"]) == o["ugr_stderr"]
    assert float(r["background_cd_m2"]) == o["background_cd_m2"]
    assert [float(r[k]) for k in ("x", "y", "z")] == o["eye"]
print("ok")
PY
check "summary.json's glare: its keys, sources and exclusions, and glare.csv's numbers the same ($(tail -1 "$tmp/py.txt"))" '[ "$(tail -1 "$tmp/py.txt")" = ok ]'

# Refused: exit 1, the JSON path and what was expected; no glare.csv.
refuse() { # name json fragment
  name=$1 want=$3
  printf '%s\n' "$2" >"$tmp/$name.json"
  "$CANDELA" solve "$tmp/$name.json" -o "$tmp/out_$name" >/dev/null 2>"$tmp/$name.err"; st=$?
  check "$name: exit 1" '[ $st -eq 1 ]'
  check "$name: the message says where and why" 'grep -qF "$want" "$tmp/$name.err"' || cat "$tmp/$name.err"
  check "$name: no glare.csv" '[ ! -e "$tmp/out_$name/glare.csv" ]'
}
refuse inside_box '{"version": 1, '"$lums"', "surfaces": [{"name": "column", "type": "box", "min": [-1, 1, 0], "max": [1, 2, 3], "reflectance": 0.5}],
 "observers": [{"name": "stuck", "eye": [0, 1.5, 1.2], "view": [0, 1, 0]}]}' \
  'observers[0] (stuck): expected the eye in open air, found [0, 1.5, 1.2] inside surfaces[0] (a closed box)'
refuse on_surface '{"version": 1, '"$lums"', "surfaces": [{"type": "rect", "origin": [-5, -5, 1.2], "u": [10, 0, 0], "v": [0, 10, 0], "reflectance": 0.5}],
 "observers": [{"name": "flat", "eye": [0, 0, 1.2], "view": [0, 1, 0]}]}' \
  'observers[0] (flat): expected the eye in open air, found [0, 0, 1.2] on a surface'
refuse zero_view '{"version": 1, '"$lums"', "observers": [{"name": "a", "eye": [0, 0, 1.2], "view": [0, 0, 0]}]}' \
  'observers[0].view: expected a non-zero vector of 3 numbers, found the zero vector'
refuse tilted_view '{"version": 1, '"$lums"', "observers": [{"name": "a", "eye": [0, 0, 1.2], "view": [0, 1, 0.1]}]}' \
  'observers[0].view: expected a horizontal line of sight (within 1 degree'
refuse unrated '{"version": 1, "luminaires": [{"type": "point", "position": [0, 3, 3], "intensity_cd": 100}, {"type": "spot", "position": [0, 3, 3], "direction": [0, 0, -1], "intensity_cd": 100, "half_angle": 30}],
 "observers": [{"name": "a", "eye": [0, 0, 1.2], "view": [0, 1, 0]}]}' \
  'observers: expected a luminaire whose glare can be rated (a goniometric luminaire whose file gives a luminous opening, or an area luminaire), found luminaires[0]: no luminous area'
exit $fail
