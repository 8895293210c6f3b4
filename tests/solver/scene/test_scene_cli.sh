#!/usr/bin/env bash
# Bad scenes through `candela solve`: exit status 1, nothing written, and a
# message naming the scene file and the JSON path (one case per error class;
# tests/solver/test_scene_errors.c checks every class in the library).
# Relative paths resolve against the scene's folder wherever candela runs.
set -u
: "${CANDELA:?}" "${CANDELA_BINARY_DIR:?}" "${CANDELA_SOURCE_DIR:?}"
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }

work="$CANDELA_BINARY_DIR/tests/tmp/test_scene_cli"
rm -rf "$work"
mkdir -p "$work/scenes/meshes" "$work/elsewhere"
grid='"grids": [{"name": "g", "type": "points", "points": [{"p": [0,0,0], "n": [0,0,1]}]}]'

# expect_error NAME JSON FRAGMENT: the scene is refused with NAME.json FRAGMENT in the message.
expect_error() {
  local name=$1 json=$2 fragment=$3
  printf '%s\n' "$json" > "$work/scenes/$name.json"
  err=$("$CANDELA" solve "$work/scenes/$name.json" -o "$work/out_$name" 2>&1 >/dev/null); st=$?
  check "$name: exit status 1" '[ $st -eq 1 ]'
  check "$name: message names file and path ($fragment)" '[[ "$err" == *"$name.json$fragment"* ]]'
  check "$name: no output folder" '[ ! -e "$work/out_$name/g.csv" ]'
}

expect_error unknown_key "{\"version\": 1, \"luminaire\": [], $grid}" \
  ': luminaire: expected a key of a scene'
expect_error wrong_type "{\"version\": 1, \"luminaires\": [{\"type\": \"point\", \"position\": \"up\", \"intensity_cd\": 1}], $grid}" \
  ': luminaires[0].position: expected an array of 3 numbers, found the string "up"'
expect_error missing "{\"version\": 1, \"luminaires\": [{\"type\": \"spot\", \"position\": [0,0,3], \"direction\": [0,0,-1], \"intensity_cd\": 1}], $grid}" \
  ': luminaires[0].half_angle: expected a half angle in (0, 180] degrees'
expect_error non_finite "{\"version\": 1, \"luminaires\": [{\"type\": \"point\", \"position\": [0,0,1e999], \"intensity_cd\": 1}], $grid}" \
  ': luminaires[0].position[2]: expected a finite number'
expect_error zero_normal "{\"version\": 1, \"surfaces\": [{\"type\": \"disk\", \"center\": [0,0,0], \"normal\": [0,0,0], \"radius\": 1, \"reflectance\": 0}], $grid}" \
  ': surfaces[0].normal: expected a non-zero vector'
expect_error non_planar "{\"version\": 1, \"surfaces\": [{\"type\": \"polygon\", \"vertices\": [[0,0,0],[4,0,0],[4,4,0],[2,5,1],[0,4,0]], \"reflectance\": 0}], $grid}" \
  ': surfaces[0].vertices[3]: expected a point in the plane'
expect_error body "{\"version\": 1, \"luminaires\": [{\"type\": \"goniometric\", \"file\": \"a.ies\", \"position\": [0,0,3], \"body\": {\"reflectance\": -0.1}}], $grid}" \
  ': luminaires[0].body.reflectance: expected a number in [0, 1], found the number -0.1'
expect_error reflectance "{\"version\": 1, \"surfaces\": [{\"type\": \"box\", \"min\": [0,0,0], \"max\": [4,4,3], \"reflectance\": {\"floor\": 0.2, \"walls\": 1.5, \"ceiling\": 0.7}}], $grid}" \
  ': surfaces[0].reflectance.walls: expected a number in [0, 1], found the number 1.5'
expect_error negative "{\"version\": 1, \"luminaires\": [{\"type\": \"area\", \"shape\": {\"type\": \"rect\", \"origin\": [0,0,3], \"u\": [1,0,0], \"v\": [0,-1,0]}, \"luminance_cd_m2\": -5}], $grid}" \
  ': luminaires[0].luminance_cd_m2: expected a number >= 0'
expect_error syntax "{\"version\": 1,
  \"grids\": [1 2]}" \
  ':2:15: invalid JSON'

# A mesh file next to the scene is found with the scene run from another
# folder under a relative path; its own errors name its file and line.
printf 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 9\n' > "$work/scenes/meshes/bad.obj"
printf '{"version": 1, "surfaces": [{"type": "mesh", "file": "meshes/bad.obj", "reflectance": 0.5}], %s}\n' "$grid" \
  > "$work/scenes/relative.json"
err=$(cd "$work/elsewhere" && "$CANDELA" solve ../scenes/relative.json -o out 2>&1 >/dev/null); st=$?
check "relative mesh: exit status 1" '[ $st -eq 1 ]'
check "relative mesh: resolved against the scene folder, with the file's line" \
  '[[ "$err" == *"../scenes/relative.json: surfaces[0].file: ../scenes/meshes/bad.obj:4: expected vertex indices up to the number of vertices"* ]]'

rm -rf "$work"
exit $fail
