#!/usr/bin/env bash
# candela info as a photometric-file checker: many files and folders (a
# line each, a summary, exit 1 naming the files that failed, --json an
# array); files in radiometric units reported in W and refused by a scene;
# the physics warnings (efficacy above 683 lm/W or above the lamp type's,
# a candela multiplier that explains a flux mismatch); --plot's polar
# diagram against the closed form of an isotropic source.
# ctest-timeout: 120
source "$(dirname "$0")/harness.sh"
data="$CANDELA_SOURCE_DIR/tests/data/photometric"
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }

# An IES file of constant intensity CD (19 gamma angles, one plane): LAMPS
# LUMENS MULT on record A, WATTS on record B, extra keywords first.
ies() { # file cd lumens mult watts keywords...
  local f=$1 cd=$2 lumens=$3 mult=$4 watts=$5; shift 5
  { echo "IESNA:LM-63-2002"; echo "[TEST] candela test"; for k in "$@"; do echo "$k"; done
    echo "TILT=NONE"; echo "1 $lumens $mult 19 1 1 2 0 0 0"; echo "1 1 $watts"
    echo "0 10 20 30 40 50 60 70 80 90 100 110 120 130 140 150 160 170 180"; echo "0"
    for i in $(seq 19); do printf '%s ' "$cd"; done; echo; } > "$f"
}

# 1. A maker's folder: good files, a warning, broken files, a subfolder.
mkdir -p "$tmp/maker/sub"
cp "$data/iso_1000cd.ies" "$data/warn_seam.ies" "$data/bad_truncated.ies" "$tmp/maker/"
cp "$data/ldt_comma_blank_crlf.ldt" "$data/bad_isym.ldt" "$tmp/maker/sub/"
echo "not photometry" > "$tmp/maker/README.txt"
"$CANDELA" info "$tmp/maker" > "$tmp/batch.out" 2> "$tmp/batch.err"; st=$?
check "folder: exit 1 when a file fails" '[ $st -eq 1 ]'
check "folder: one line per photometric file (5), README skipped" '[ $(grep -c "^ok \|^FAIL " "$tmp/batch.out") -eq 5 ] && ! grep -q README "$tmp/batch.out"'
check "folder: subfolders read, in name order" '[ "$(grep -o "maker/[a-z_/]*\.[a-z]*" "$tmp/batch.out" | head -1)" = "maker/bad_truncated.ies" ] && grep -q "^ok    $tmp/maker/sub/ldt_comma_blank_crlf.ldt: EULUMDAT" "$tmp/batch.out"'
check "folder: a good file's line (flux, beam, warnings)" 'grep -q "^ok    $tmp/maker/iso_1000cd.ies: LM-63-2002, 12566 lm, beam -/- deg, 0 warnings" "$tmp/batch.out"'
check "folder: a failed file's line names file, line and what was expected" 'grep -q "^FAIL  $tmp/maker/bad_truncated.ies:[0-9]*: expected" "$tmp/batch.out"'
check "folder: the summary" 'grep -qx "5 files: 3 read (1 with warnings, 1 warning in all), 2 failed" "$tmp/batch.out"'
check "folder: stderr lists which failed" 'grep -q "2 of 5 files failed" "$tmp/batch.err" && grep -qx "  $tmp/maker/bad_truncated.ies" "$tmp/batch.err" && grep -qx "  $tmp/maker/sub/bad_isym.ldt" "$tmp/batch.err"'
"$CANDELA" info "$data/iso_1000cd.ies" "$data/warn_seam.ies" > "$tmp/two.out"; st=$?
check "two good files: exit 0, two lines and a summary" '[ $st -eq 0 ] && [ $(wc -l < "$tmp/two.out") -eq 3 ]'
"$CANDELA" info --json "$data/iso_1000cd.ies" "$data/bad_nan.ies" > "$tmp/arr.json" 2>/dev/null; st=$?
check "--json: an array, the failed file with its error; exit 1" '[ $st -eq 1 ] && [ "$(json "$tmp/arr.json" "[type(d).__name__, len(d), d[0][\"flux_lm\"] > 0, \"error\" in d[1]]")" = "['"'"'list'"'"', 2, True, True]" ]'
"$CANDELA" info --strict "$tmp/maker/iso_1000cd.ies" "$tmp/maker/warn_seam.ies" > /dev/null 2>&1; st=$?
check "--strict: a warning fails its file" '[ $st -eq 1 ]'

# 2. Radiometric units: [_INTENSITYUNITS] mW/sr. 1000 mW/sr everywhere is
# 4 pi W of radiant flux; no lumens anywhere.
ies "$tmp/uv.ies" 1000 -1 1 0 "[_INTENSITYUNITS] mW/sr" "[LAMP] excimer 222 nm"
"$CANDELA" info "$tmp/uv.ies" > "$tmp/uv.txt"; st=$?
check "radiometric: reported in W (4 pi x 1 W/sr)" '[ $st -eq 0 ] && grep -q "^flux            12.5664 W radiant" "$tmp/uv.txt" && grep -q "^max intensity   1 W/sr" "$tmp/uv.txt" && ! grep -q " lm" "$tmp/uv.txt"'
"$CANDELA" info --json "$tmp/uv.ies" > "$tmp/uv.json"
check "radiometric JSON: W, no lumens" '[ "$(json "$tmp/uv.json" "[d[\"radiometric\"], abs(d[\"radiant_flux_w\"] - 4e-3 * 3.141592653589793 * 1000) < 1e-9, d[\"flux_lm\"], d[\"max_intensity_cd\"], d[\"max_radiant_intensity_w_sr\"] == 1]")" = "[True, True, None, None, True]" ]'
printf '{"version": 1, "luminaires": [{"type": "goniometric", "file": "uv.ies", "position": [0,0,2]}], "grids": [{"name": "g", "type": "points", "points": [{"p": [0,0,0], "n": [0,0,1]}]}]}\n' > "$tmp/uv_scene.json"
"$CANDELA" solve "$tmp/uv_scene.json" -o "$tmp/uv_out" --quiet > /dev/null 2> "$tmp/uv_scene.err"; st=$?
check "radiometric file in a scene: refused, exit 1, saying why" '[ $st -eq 1 ] && grep -q "luminaires\[0\].file: .*uv.ies: expected photometric data (candela), found radiant intensity in mW/sr (\[_INTENSITYUNITS\])" "$tmp/uv_scene.err"'

# 3. Efficacy: 4000 pi lm from 10 W is 1257 lm/W, beyond 683 lm/W; from an
# LED at 40 W 314 lm/W is beyond LEDs, at 50 W 251 lm/W is not.
ies "$tmp/eff.ies" 1000 -1 1 10
check "efficacy above 683 lm/W: warned" '"$CANDELA" info "$tmp/eff.ies" | grep -q "efficacy 1257 lm/W (12566.4 lm from 10 W) is above 683 lm/W"'
ies "$tmp/led40.ies" 1000 -1 1 40 "[LAMP] LED module 4000 K"
ies "$tmp/led50.ies" 1000 -1 1 50 "[LAMP] LED module 4000 K"
check "efficacy above the lamp type's: warned" '"$CANDELA" info "$tmp/led40.ies" | grep -q "efficacy 314.2 lm/W is above what LED lamps reach (at most about 310 lm/W"'
check "a plausible LED efficacy: no warning" '"$CANDELA" info "$tmp/led50.ies" | grep -q "^warnings        none"'

# 4. A multiplier that explains a flux mismatch: 1000 lm of lamps, a table
# of 73.052119 cd x 1.32 integrates to 1212 lm (121 %); without the
# multiplier 4 pi x 73.052119 = 918 lm.
ies "$tmp/mult.ies" 73.052119 1000 1.32 20
check "multiplier explains the mismatch: said with the flux without it" '"$CANDELA" info "$tmp/mult.ies" | grep -q "output ratio above 1: the table integrates to 1211.76 lm, 121.2 % of the rated lamp flux 1000 lm (expected at most 100 %); the table integrates to 918 lm without the 1.32 multiplier"'

# 5. The polar diagram: valid SVG; the isotropic source's curves are circles
# of I x 1000 / flux = 1000 x 1000 / (4000 pi) = 79.58 cd/klm on rings
# fitted to it (4 of 20, up to 80): radius 220 x 79.58 / 80 = 218.84 units
# around (280, 300)
# (cairo writes coordinates to 1/256 of a unit).
"$CANDELA" info --plot "$tmp/iso.svg" "$data/iso_1000cd.ies" > /dev/null; st=$?
check "--plot: exit 0, valid SVG" '[ $st -eq 0 ] && xmllint --noout "$tmp/iso.svg"'
python3 - "$tmp/iso.svg" > "$tmp/radii.txt" <<'PY'
import re, sys, math
svg = open(sys.argv[1]).read()
# cairo writes each curve as a path: C0-C180 solid red, C90-C270 dashed blue.
for plane, colour in (("c0-c180", "rgb(80%,0%,0%)"), ("c90-c270", "rgb(0%,0%,80%)")):
    d = re.search(r'<path style="[^"]*stroke-width:2;[^"]*stroke:%s;[^"]*" d="([^"]*)"' % re.escape(colour), svg).group(1)
    nums = [float(v) for v in re.findall(r"-?[0-9.]+", d)]
    r = [math.hypot(x - 280, y - 300) for x, y in zip(nums[0::2], nums[1::2])]
    print(plane, len(r), min(r), max(r))
PY
check "--plot: both planes, 361 points each, a circle of radius 218.84 (to 0.01)" 'python3 -c "
import sys
want = 220 * 1000 * 1000 / (4000 * 3.141592653589793) / 80
rows = [l.split() for l in open(sys.argv[1])]
assert [r[0] for r in rows] == [\"c0-c180\", \"c90-c270\"] and all(r[1] == \"361\" for r in rows)
assert all(abs(float(r[2]) - want) < 0.01 and abs(float(r[3]) - want) < 0.01 for r in rows), (rows, want)" "$tmp/radii.txt"'
check "--plot: titled (<title>; cairo draws the labels as glyphs) in cd/klm with the luminaire's name" 'grep -q "<title>Polar intensity diagram: isotropic point source.*(cd/klm, nadir down)</title>" "$tmp/iso.svg"'
check "--plot: the labels are drawn (glyphs used)" '[ $(grep -c "<use xlink:href=\"#glyph" "$tmp/iso.svg") -gt 40 ]'
"$CANDELA" info --plot "$tmp/x.svg" "$data/iso_1000cd.ies" "$data/warn_seam.ies" > /dev/null 2>&1; st=$?
check "--plot with two files: usage error" '[ $st -eq 2 ]'
exit $fail
