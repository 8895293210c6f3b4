#!/usr/bin/env bash
# Radiometric files stay radiometric and the ballast factor has one
# convention, through the CLI:
#  1. a table in mW/sr: `convert` refuses EULUMDAT (which holds cd/klm
#     only: every program would read the UV lamp as light) and writes no
#     file; IES to IES (2019 and 2002) keeps [_INTENSITYUNITS], and the copy
#     reads back in W; `info` gives every figure in W, W/sr and W/m2/sr
#     (closed forms: 1000 mW/sr in every direction is 4 pi W, and over a
#     0.1 x 0.1 m opening 1 W/sr / 0.01 m2 = 100 W/m2/sr); a lumen keyword
#     is compared in the table's unit; a scene refuses the file and its copy;
#  2. a ballast factor 0.6: `info` gives the luminaire's flux, the table's
#     times 0.6, for the IES file and for its IES -> LDT -> IES round trip
#     alike (before the change: 2 pi 1000 lm for the IES file, 0.6 of it
#     after the trip), and the table's own flux beside it; `solve` lights a
#     point 2 m below each of the three files with I x BF / h^2 = 1000 x
#     0.6 / 4 = 150 lx (the solver's convention is the same);
#  3. the corpus file with a ballast factor 0.88 reads the same flux before
#     and after IES -> LDT -> IES (when ../shared/photometric is there).
source "$(dirname "$0")/harness.sh"
json() { python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print($2)" "$1"; }
close() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a != "" && d <= t * (b < 0 ? -b : b)) }'; }
ies() { # file ballast_factor opening_w opening_l keywords...
  local f=$1 bf=$2 w=$3 l=$4; shift 4
  { echo "IES:LM-63-2019"; echo "[TEST] T-1"; echo "[TESTLAB] Lab"; echo "[ISSUEDATE] 2026-01-01"; echo "[MANUFAC] Maker"
    for k in "$@"; do echo "$k"; done
    echo "TILT=NONE"; echo "1 -1 1 19 1 1 2 $w $l 0"; echo "$bf 1.00000 40"
    echo "0 10 20 30 40 50 60 70 80 90 100 110 120 130 140 150 160 170 180"; echo "0"
    echo "1000 1000 1000 1000 1000 1000 1000 1000 1000 1000 1000 1000 1000 1000 1000 1000 1000 1000 1000"; } > "$f"
}
pi=3.141592653589793

# 1. Radiometric
ies "$tmp/uv.ies" 1 0.1 0.1 "[_INTENSITYUNITS] mW/sr" "[_TOTALLUMINAIRELUMENS] 9000"
err=$("$CANDELA" convert "$tmp/uv.ies" "$tmp/uv.ldt" 2>&1); st=$?
check "uv -> EULUMDAT: refused, exit 1, saying why, no file" '[ $st -eq 1 ] && [[ "$err" == *"EULUMDAT holds cd/klm only"*"mW/sr"* ]] && [ ! -e "$tmp/uv.ldt" ]'
for v in 2019 2002; do
  "$CANDELA" convert -q --ies-version $v "$tmp/uv.ies" "$tmp/uv$v.ies"; st=$?
  "$CANDELA" info --json "$tmp/uv$v.ies" > "$tmp/uv$v.json"
  check "uv -> IES $v keeps [_INTENSITYUNITS] and reads back 4 pi W" '[ $st -eq 0 ] && tr -d "\r" < "$tmp/uv$v.ies" | grep -qx "\[_INTENSITYUNITS\] mW/sr" && close "$(json "$tmp/uv$v.json" "d[\"radiant_flux_w\"]")" "$(awk "BEGIN{printf \"%.17g\", 4 * $pi}")" 1e-9'
done
"$CANDELA" info "$tmp/uv.ies" > "$tmp/uv.txt"
check "uv text: W, W/sr, W/m2/sr, no lm or cd" 'grep -q "^zones (W)" "$tmp/uv.txt" && grep -q "^radiance        100 W/m2/sr at nadir" "$tmp/uv.txt" && grep -q "^max intensity   1 W/sr" "$tmp/uv.txt" && ! grep -Eq " (lm|cd|cd/m2)([ ,.)]|$)" <(grep -v "^warnings\|^ *\[" "$tmp/uv.txt")'
"$CANDELA" info --json "$tmp/uv.ies" > "$tmp/uv.json"
check "uv JSON: zone_flux_w and a radiance table in W/m2/sr, no lumen keys" '[ "$(json "$tmp/uv.json" "[\"zone_flux_lm\" in d, abs(sum(d[\"zone_flux_w\"]) - 4 * 3.141592653589793) < 1e-9, float(d[\"opening\"][\"radiance\"][0][\"average_w_m2_sr\"]), \"luminance\" in d[\"opening\"], d[\"flux_lm\"], d[\"bug_rating\"]]")" = "[False, True, 100.0, False, None, None]" ]'
check "uv: the lumen keyword compared in mW, with a code" '[ "$(json "$tmp/uv.json" "[w[\"code\"] for w in d[\"warnings\"]]")" = "['"'"'stated-flux-mismatch'"'"']" ] && grep -q "integrated radiant flux 12566.4 mW is far from the luminaire flux 9000 mW" "$tmp/uv.txt"'
for f in uv.ies uv2019.ies; do
  printf '{"version": 1, "luminaires": [{"type": "goniometric", "file": "%s", "position": [0,0,2]}], "grids": [{"name": "g", "type": "points", "points": [{"p": [0,0,0], "n": [0,0,1]}]}]}\n' "$f" > "$tmp/scene_$f.json"
  "$CANDELA" solve "$tmp/scene_$f.json" -o "$tmp/out_$f" --quiet > /dev/null 2> "$tmp/scene_$f.err"; st=$?
  check "$f in a scene: refused, exit 1" '[ $st -eq 1 ] && grep -q "found radiant intensity in mW/sr" "$tmp/scene_$f.err"'
done

# 2. Ballast factor 0.6: flux 0.6 x 4 pi 1000 lm before and after IES -> LDT -> IES
ies "$tmp/bf.ies" 0.6 0 0
"$CANDELA" convert -q "$tmp/bf.ies" "$tmp/bf.ldt" && "$CANDELA" convert -q "$tmp/bf.ldt" "$tmp/bf2.ies"; st=$?
check "bf: converts both ways" '[ $st -eq 0 ]'
want=$(awk "BEGIN{printf \"%.17g\", 0.6 * 4 * $pi * 1000}")
for f in bf.ies bf.ldt bf2.ies; do
  "$CANDELA" info --json "$tmp/$f" > "$tmp/$f.json"
  check "$f: flux 0.6 x 4 pi 1000 lm = $want (got $(json "$tmp/$f.json" "d[\"flux_lm\"]"))" 'close "$(json "$tmp/$f.json" "d[\"flux_lm\"]")" "$want" 1e-9 && close "$(json "$tmp/$f.json" "d[\"max_intensity_cd\"]")" 600 1e-9'
done
check "bf.ies: the table's flux beside it, 4 pi 1000 lm" 'close "$(json "$tmp/bf.ies.json" "d[\"table_flux_lm\"]")" "$(awk "BEGIN{printf \"%.17g\", 4 * $pi * 1000}")" 1e-9'
check "bf.ies text: both ways" '"$CANDELA" info "$tmp/bf.ies" | grep -q "^flux            7539.82 lm with the output factor 0.6 (integrated), 12566.4 lm as tabulated"'
for f in bf.ies bf.ldt bf2.ies; do
  printf '{"version": 1, "luminaires": [{"type": "goniometric", "file": "%s", "position": [0,0,2]}], "grids": [{"name": "g", "type": "points", "points": [{"p": [0,0,0], "n": [0,0,1]}]}]}\n' "$f" > "$tmp/s_$f.json"
  "$CANDELA" solve "$tmp/s_$f.json" -o "$tmp/o_$f" --quiet > /dev/null 2>&1; st=$?
  e=$(sed -n 2p "$tmp/o_$f/g.csv" | cut -d, -f7)
  check "$f: solve gives I x 0.6 / 2^2 = 150 lx (got $e)" '[ $st -eq 0 ] && close "$e" 150 1e-9'
done

# 3. The corpus file whose ballast factor is 0.88
af="${CANDELA_PHOTOMETRIC_DIR:-}/ies_lithonia_AF10_bf088.ies"
if [ -f "$af" ]; then
  "$CANDELA" convert -q "$af" "$tmp/af.ldt" && "$CANDELA" convert -q "$tmp/af.ldt" "$tmp/af2.ies"
  "$CANDELA" info --json "$af" > "$tmp/af.json"; "$CANDELA" info --json "$tmp/af2.ies" > "$tmp/af2.json"
  a=$(json "$tmp/af.json" "d[\"flux_lm\"]"); b=$(json "$tmp/af2.json" "d[\"flux_lm\"]"); t=$(json "$tmp/af.json" "d[\"table_flux_lm\"]")
  check "corpus BF 0.88: $a lm before and $b lm after the trip, 0.88 x $t" 'close "$a" "$b" 1e-9 && close "$a" "$(awk "BEGIN{printf \"%.17g\", 0.88 * $t}")" 1e-12'
else
  echo "skip: corpus not found (${CANDELA_PHOTOMETRIC_DIR:-unset})"
fi
exit $fail
