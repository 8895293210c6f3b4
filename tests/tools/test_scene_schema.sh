#!/usr/bin/env bash
# data/scene.schema.json (JSON Schema draft 2020-12) is a valid schema; every
# example scene (data/ and tests/data/scene/) validates against it, and the
# loader reads each; scenes the loader refuses for a wrong key or value are
# refused by the schema too; `candela help scene` names every key of the
# schema with its unit, and `--schema` prints the file itself. Needs
# python3-jsonschema (scripts/setup.sh installs it).
# ctest-timeout: 120
source "$(dirname "$0")/harness.sh"
schema="$CANDELA_SOURCE_DIR/data/scene.schema.json"
python3 -c 'import jsonschema' 2>/dev/null || { echo "python3-jsonschema missing: run scripts/setup.sh"; exit 1; }

# Validate FILE...: prints "FILE: ok" or "FILE: <first error>".
validate() {
  python3 - "$schema" "$@" <<'PY'
import json, sys
from jsonschema import Draft202012Validator
schema = json.load(open(sys.argv[1]))
Draft202012Validator.check_schema(schema)
v = Draft202012Validator(schema)
for path in sys.argv[2:]:
    errors = sorted(v.iter_errors(json.load(open(path))), key=lambda e: list(e.absolute_path))
    print("%s: %s" % (path, "ok" if not errors else "/".join(map(str, errors[0].absolute_path)) + ": " + errors[0].message[:160]))
PY
}

check "the schema is a valid draft 2020-12 schema" 'python3 -c "
import json, sys; from jsonschema import Draft202012Validator
s = json.load(open(sys.argv[1])); Draft202012Validator.check_schema(s)
assert s[\"\$schema\"] == \"https://json-schema.org/draft/2020-12/schema\"" "$schema"'

mapfile -t scenes < <(find "$CANDELA_SOURCE_DIR/data" "$CANDELA_SOURCE_DIR/tests/data/scene" -name '*.json' ! -name 'scene.schema.json' | sort)
check "example scenes found" '[ ${#scenes[@]} -ge 5 ]'
validate "${scenes[@]}" > "$tmp/examples.txt"
while read -r line; do
  check "schema: ${line#"$CANDELA_SOURCE_DIR/"}" '[[ "$line" == *": ok" ]]'
done < "$tmp/examples.txt"
check "every example checked" '[ $(wc -l < "$tmp/examples.txt") -eq ${#scenes[@]} ]'

# Scenes the loader refuses (a typo, two placements, a bad output, a range;
# an observer's unknown key, missing view, eye and positions both, a limit
# of 0, an empty observer grid, no grid and no observer) are refused by
# the schema as well.
base='"version": 1, "grids": [{"name": "g", "type": "points", "points": [{"p": [0,0,0], "n": [0,0,1]}]}]'
bad=(
  '{'"$base"', "luminaires": [{"type": "point", "positon": [0,0,3], "intensity_cd": 1}]}'
  '{'"$base"', "luminaires": [{"type": "goniometric", "file": "a.ies", "position": [0,0,3], "aim": [0,0,0], "rotation": [0,0,0]}]}'
  '{'"$base"', "luminaires": [{"type": "point", "position": [0,0,3], "positions": [[0,0,3]], "intensity_cd": 1}]}'
  '{'"$base"', "luminaires": [{"type": "point", "position": [0,0,3], "intensity_cd": 1, "array": {"counts": [0, 2], "spacing": [1, 1]}}]}'
  '{"version": 1, "grids": [{"name": "g", "type": "points", "outputs": ["lux"], "points": [{"p": [0,0,0], "n": [0,0,1]}]}]}'
  '{'"$base"', "surfaces": [{"type": "rect", "origin": [0,0,0], "u": [1,0,0], "v": [0,1,0], "reflectance": 1.5}]}'
  '{'"$base"', "solver": {"quality": "best"}}'
  '{"version": 2, "grids": [{"name": "g", "type": "points", "points": [{"p": [0,0,0], "n": [0,0,1]}]}]}'
  '{"version": 1, "observers": [{"name": "o", "eye": [0,0,1.2], "view": [0,1,0], "look": 1}]}'
  '{"version": 1, "observers": [{"name": "o", "eye": [0,0,1.2]}]}'
  '{"version": 1, "observers": [{"name": "o", "eye": [0,0,1.2], "positions": [[0,0,1.2]], "view": [0,1,0]}]}'
  '{"version": 1, "observers": [{"name": "o", "eye": [0,0,1.2], "view": [0,1,0], "requirements": {"UGR_L": 0}}]}'
  '{"version": 1, "grids": [{"name": "m", "type": "observers", "origin": [0,0,1.2], "u": [1,0,0], "v": [0,1,0], "nu": 0, "nv": 1, "view": [0,1,0]}]}'
  '{"version": 1, "observers": []}'
)
for i in "${!bad[@]}"; do
  printf '%s\n' "${bad[$i]}" > "$tmp/bad$i.json"
  "$CANDELA" solve "$tmp/bad$i.json" -o "$tmp/out$i" --quiet > /dev/null 2> "$tmp/bad$i.err"; st=$?
  check "bad scene $i: the loader refuses it (exit 1)" '[ $st -eq 1 ]'
  check "bad scene $i: the schema refuses it" '! validate "$tmp/bad$i.json" | grep -q ": ok$"'
done
# A scene naming the schema in "$schema" loads and solves.
printf '%s\n' '{"$schema": "../data/scene.schema.json", "version": 1, "luminaires": [{"type": "point", "position": [0,0,2], "intensity_cd": 100}], "grids": [{"name": "g", "type": "points", "points": [{"p": [0,0,0], "n": [0,0,1]}]}]}' > "$tmp/named.json"
check "\$schema accepted by the loader" '"$CANDELA" solve "$tmp/named.json" -o "$tmp/named" --quiet > /dev/null'
check "\$schema accepted by the schema" 'validate "$tmp/named.json" | grep -q ": ok$"'

# The human reference: every key of every object, its unit where it has one.
"$CANDELA" help scene > "$tmp/help.txt"; st=$?
check "help scene: exit 0" '[ $st -eq 0 ]'
python3 - "$schema" "$tmp/help.txt" > "$tmp/missing.txt" <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); text = open(sys.argv[2]).read()
objs = [("scene", s)] + [(k, v) for k, v in s["$defs"].items() if "properties" in v]
for name, o in objs:
    title = o.get("title")
    if title and title not in text: print("section", title)
    for key, p in o["properties"].items():
        if key != "type" and ("\n  %s " % key) not in text: print(name, key)
        if "x-unit" in p and p["x-unit"] and ("in " + p["x-unit"]) not in text: print(name, key, "unit", p["x-unit"])
PY
check "help scene: every section and key, with units" '[ ! -s "$tmp/missing.txt" ]' || cat "$tmp/missing.txt"
check "help scene --schema: the file itself" '"$CANDELA" help scene --schema | cmp -s - "$schema"'
check "help scene with a stray argument: usage error" '"$CANDELA" help scene --bogus 2>/dev/null; [ $? -eq 2 ]'
exit $fail
