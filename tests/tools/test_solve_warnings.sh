#!/usr/bin/env bash
# No silent zeros: a luminaire that adds nothing to any grid (facing away,
# above the ceiling, millimetres typed into a scene in metres), a dark grid
# and a scene without light are named on stderr and in summary.json's
# "warnings"; --strict refuses them (exit 1, no results). Installed power
# and W/m2 from the luminaire files' input watts, times the copies placed,
# per grid of the luminaires over it. No false alarms: a luminaire that
# lights every point through its near field only, a luminaire 2 m above a
# one-point grid in an empty scene.
# ctest-timeout: 300
source "$(dirname "$0")/harness.sh"
cp "$CANDELA_SOURCE_DIR/data/office/downlight.ies" "$tmp/"
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }

room='{"name": "room", "type": "box", "min": [0,0,0], "max": [4,4,3], "inward": true, "reflectance": 0}'
grid='{"name": "desk", "type": "rect", "origin": [0.5,0.5,0.8], "u": [3,0,0], "v": [0,3,0], "nu": 6, "nv": 6}'
solve() { # name, scene json, extra args
  printf '%s\n' "$2" > "$tmp/$1.json"
  "$CANDELA" solve "$tmp/$1.json" -o "$tmp/$1" --quiet "${@:3}" > "$tmp/$1.out" 2> "$tmp/$1.err"
}

# 1. A spot facing the ceiling next to one that lights the desk.
solve away '{"version": 1, "surfaces": ['"$room"'], "luminaires": [
  {"name": "up", "type": "spot", "position": [2,2,2.5], "direction": [0,0,1], "intensity_cd": 500, "half_angle": 30},
  {"name": "down", "type": "spot", "position": [2,2,2.5], "direction": [0,0,-1], "intensity_cd": 500, "half_angle": 60}],
  "grids": ['"$grid"'], "solver": {"method": "direct"}}'; st=$?
check "facing away: solved (exit 0)" '[ $st -eq 0 ]'
check "facing away: named on stderr with why" 'grep -q "warning: luminaires\[0\] (up) adds nothing to any grid: its light meets no grid point" "$tmp/away.err"'
check "facing away: the lit one is not named" '! grep -q "luminaires\[1\]" "$tmp/away.err"'
check "facing away: in summary.json" '[ "$(json "$tmp/away/summary.json" "len(d[\"warnings\"])")" = 1 ] && json "$tmp/away/summary.json" "d[\"warnings\"][0]" | grep -q "^luminaires\[0\] (up) adds nothing"'
solve away_strict "$(cat "$tmp/away.json")" --strict; st=$?
check "facing away --strict: exit 1" '[ $st -eq 1 ]'
check "facing away --strict: said as an error, no results" 'grep -q "error: luminaires\[0\] (up) adds nothing" "$tmp/away_strict.err" && grep -q "refused under --strict" "$tmp/away_strict.err" && [ ! -e "$tmp/away_strict/summary.json" ]'

# 2. Above the ceiling of a closed room, in an array: every copy named.
solve ceiling '{"version": 1, "surfaces": ['"$room"'], "luminaires": [
  {"name": "attic", "type": "point", "position": [1,1,3.4], "intensity_cd": 800, "array": {"counts": [2,1], "spacing": [2,0]}},
  {"type": "point", "position": [2,2,2.9], "intensity_cd": 800}],
  "grids": ['"$grid"'], "solver": {"method": "direct"}}'; st=$?
# (the room is a closed box holding the grid: the attic's lights are left out of the solve, and said so)
check "above the ceiling: exit 0, both copies named as hidden" '[ $st -eq 0 ] && [ $(grep -c "luminaires\[0\] (attic, [12] of 2) adds nothing to any grid: it lies outside surfaces\[0\], a closed box that holds every point of the solve" "$tmp/ceiling.err") -eq 2 ]'

# 3. Millimetres in a scene in metres.
solve mm '{"version": 1, "surfaces": ['"$room"'], "luminaires": [
  {"type": "goniometric", "file": "downlight.ies", "position": [2000,2000,2950]},
  {"type": "goniometric", "file": "downlight.ies", "position": [2,2,2.95]}],
  "grids": ['"$grid"'], "solver": {"method": "direct"}}'; st=$?
check "millimetres: exit 0, said so" '[ $st -eq 0 ] && grep -q "luminaires\[0\] adds nothing.*looks like millimetres: the scene is in metres" "$tmp/mm.err"'

# A point light in millimetres with nothing around still lights the desk a
# little from 3.5 km away: the slip is named all the same.
solve mm_open '{"version": 1, "luminaires": [{"type": "point", "position": [2000,2000,2950], "intensity_cd": 800},
  {"type": "point", "position": [2,2,2.9], "intensity_cd": 800}], "grids": ['"$grid"'], "solver": {"method": "direct"}}'; st=$?
check "millimetres, lit: still warned" '[ $st -eq 0 ] && grep -q "warning: luminaires\[0\]: its position \[2000, 2000, 2950\] lies far outside the scene and looks like millimetres" "$tmp/mm_open.err"'

# 4. No light at all; and a grid in shadow while another is lit.
solve dark '{"version": 1, "surfaces": ['"$room"'], "grids": ['"$grid"']}'; st=$?
check "no light: exit 0 but said" '[ $st -eq 0 ] && grep -q "warning: the scene has no luminaire and no emitting surface: every grid is at 0 lx" "$tmp/dark.err"'
check "no light: --strict refuses" '"$CANDELA" solve "$tmp/dark.json" -o "$tmp/dark2" --quiet --strict 2>/dev/null; [ $? -eq 1 ]'
solve shade '{"version": 1, "surfaces": ['"$room"'], "luminaires": [{"type": "point", "position": [2,2,2.9], "intensity_cd": 800}],
  "grids": ['"$grid"', {"name": "outside", "type": "rect", "origin": [5,0,0.8], "u": [1,0,0], "v": [0,1,0], "nu": 2, "nv": 2}],
  "solver": {"method": "direct"}}'; st=$?
check "grid in shadow: named" '[ $st -eq 0 ] && grep -q "warning: grid .outside. (grids\[1\]) is dark: 0 lx at every one of its 4 points" "$tmp/shade.err" && ! grep -q "desk" "$tmp/shade.err"'

# 5. A lit scene says nothing; power from the file (20 W) times 12 copies over 4 x 4 m.
solve power '{"version": 1, "surfaces": ['"$room"'], "luminaires": [
  {"type": "goniometric", "file": "downlight.ies", "position": [0.5,0.5,2.95], "array": {"counts": [4,3], "spacing": [1,1.5]}}],
  "grids": [{"name": "floor", "type": "rect", "origin": [0,0,0.8], "u": [4,0,0], "v": [0,4,0], "nu": 8, "nv": 8}],
  "solver": {"method": "direct"}}'; st=$?
watts=$(awk 'NR==13 {print $3}' "$tmp/downlight.ies" | tr -d '\r')
check "power: exit 0, no warning" '[ $st -eq 0 ] && [ ! -s "$tmp/power.err" ] && [ "$(json "$tmp/power/summary.json" "d[\"warnings\"]")" = "[]" ]'
check "power: installed = 12 x the file's $watts W" '[ "$(json "$tmp/power/summary.json" "abs(d[\"power\"][\"installed_w\"] - 12 * $watts) < 1e-9")" = True ]'
check "power: W/m2 over the 16 m2 grid" '[ "$(json "$tmp/power/summary.json" "abs(d[\"grids\"][\"floor\"][\"power_density_w_m2\"] - 12 * $watts / 16) < 1e-9")" = True ]'
check "power: printed" 'grep -q "installed power $((12 * ${watts%.*})) W (12 luminaires)" "$tmp/power.out"'
# A point light has no wattage: no total, and the reason.
check "power unknown: null with why" '[ "$(json "$tmp/shade/summary.json" "d[\"power\"][\"installed_w\"]")" = None ] && grep -q "not every luminaire" "$tmp/shade/summary.json"'

# 6. Power density belongs to the grid the luminaires hang over: two rooms
# side by side, each 4 x 4 m, 12 downlights over the first, 4 over the
# second; each work plane's W/m2 counts only its own (the whole scene's
# 16 x the file's watts over one room's area was the old, wrong figure).
solve rooms '{"version": 1, "luminaires": [
  {"type": "goniometric", "file": "downlight.ies", "position": [0.5,0.5,2.95], "array": {"counts": [4,3], "spacing": [1,1.5]}},
  {"type": "goniometric", "file": "downlight.ies", "position": [5,1,2.95], "array": {"counts": [2,2], "spacing": [2,2]}}],
  "grids": [{"name": "a", "type": "rect", "origin": [0,0,0.8], "u": [4,0,0], "v": [0,4,0], "nu": 4, "nv": 4},
            {"name": "b", "type": "polygon", "vertices": [[4,0,0.8],[8,0,0.8],[8,4,0.8],[4,4,0.8]], "spacing": 1},
            {"name": "wall", "type": "rect", "origin": [0,0,0], "u": [0,0,3], "v": [8,0,0], "nu": 2, "nv": 4}],
  "solver": {"method": "direct"}}'; st=$?
check "rooms: exit 0" '[ $st -eq 0 ]'
check "rooms: a counts its own 12 luminaires, 12 x $watts W over 16 m2" '[ "$(json "$tmp/rooms/summary.json" "d[\"grids\"][\"a\"][\"luminaires_over\"] == 12 and abs(d[\"grids\"][\"a\"][\"power_density_w_m2\"] - 12 * $watts / 16) < 1e-9")" = True ]'
check "rooms: b (a polygon) counts its own 4, 4 x $watts W over 16 m2" '[ "$(json "$tmp/rooms/summary.json" "d[\"grids\"][\"b\"][\"luminaires_over\"] == 4 and abs(d[\"grids\"][\"b\"][\"power_density_w_m2\"] - 4 * $watts / 16) < 1e-9")" = True ]'
check "rooms: the wall has no luminaire over it, so no W/m2" '[ "$(json "$tmp/rooms/summary.json" "d[\"grids\"][\"wall\"][\"luminaires_over\"] == 0 and \"power_density_w_m2\" not in d[\"grids\"][\"wall\"]")" = True ]'
check "rooms: the scene's installed power is all 16" '[ "$(json "$tmp/rooms/summary.json" "abs(d[\"power\"][\"installed_w\"] - 16 * $watts) < 1e-9")" = True ]'

# 7. A luminaire whose light reaches every point through its opening (a
# box with luminous sides, 0.62 m, 2.95 m up over a 6 x 4 m room: every
# point within its near-field distance) lights the grid: no warning, and
# --strict solves it.
# (an LM-63-2002 file: W L H = 0.62 0.62 0.06 m, positive: a box with
# luminous sides; I = 1000 cos(gamma) cd below the horizontal, as the
# PERLUCE of the corpus is shaped)
python3 - "$tmp/perluce.ies" <<'PY'
import math, sys
rows = ["IESNA:LM-63-2002", "[TEST] box with luminous sides", "TILT=NONE",
        "1 -1 1 19 1 1 2 0.62 0.62 0.06", "1 1 42",
        " ".join(str(10 * g) for g in range(19)), "0",
        " ".join("%.6g" % (1000 * math.cos(math.radians(10 * g)) if g < 9 else 0) for g in range(19))]
open(sys.argv[1], "w").write("\n".join(rows) + "\n")
PY
solve perluce '{"version": 1, "surfaces": [{"type": "box", "min": [0,0,0], "max": [6,4,3], "inward": true, "reflectance": 0}],
  "luminaires": [{"type": "goniometric", "file": "perluce.ies", "position": [3,2,2.95]}],
  "grids": [{"name": "work", "type": "rect", "origin": [0,0,0.8], "u": [6,0,0], "v": [0,4,0], "nu": 6, "nv": 4}],
  "solver": {"method": "direct", "quality": "draft"}}' --strict; st=$?
check "near field only: --strict solves it (exit 0), no warning" '[ $st -eq 0 ] && ! grep -q "adds nothing" "$tmp/perluce.err"'

# 8. A luminaire 2 m above a one-point grid in an empty scene is not
# millimetres, and --strict does not refuse it.
solve probe '{"version": 1, "luminaires": [{"type": "goniometric", "file": "downlight.ies", "position": [0,0,2]}],
  "grids": [{"name": "p", "type": "points", "points": [{"p": [0,0,0], "n": [0,0,1]}]}], "solver": {"method": "direct"}}' --strict; st=$?
check "one probe 2 m under a luminaire: solved under --strict, nothing about millimetres" '[ $st -eq 0 ] && ! grep -q "millimetres" "$tmp/probe.err"'

# The map's scale: linear by default, logarithmic on request, said in the PNG's description.
check "map: linear by default" 'grep -aq "floor: illuminance in lux, false colour on a linear scale" "$tmp/power/floor.png"'
"$CANDELA" solve "$tmp/power.json" -o "$tmp/powerlog" --quiet --map-scale log > /dev/null 2>&1; st=$?
check "map: --map-scale log" '[ $st -eq 0 ] && grep -aq "on a logarithmic scale" "$tmp/powerlog/floor.png"'
"$CANDELA" solve "$tmp/power.json" -o "$tmp/powerbad" --quiet --map-scale cubic > /dev/null 2> "$tmp/bad.err"; st=$?
check "map: an unknown scale is a usage error" '[ $st -eq 2 ] && grep -q "expected linear or log" "$tmp/bad.err"'
exit $fail
