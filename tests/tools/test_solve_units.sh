#!/usr/bin/env bash
# Quantities typed with their unit in a scene, through `candela solve`: the
# illuminance equals the closed form computed here from the unit's
# definition, and a unit that does not fit the field (or does not exist) is
# refused with exit status 1 and a message naming the file and JSON path.
source "$(dirname "$0")/harness.sh"

# scene NAME LUMINAIRE: one luminaire, one probe at the origin facing up.
scene() {
  printf '{"version": 1, "luminaires": [%s],\n "grids": [{"name": "p", "type": "points", "points": [{"p": [0,0,0], "n": [0,0,1]}]}],\n "solver": {"method": "direct"}}\n' \
    "$2" > "$tmp/$1.json"
}
# E_lx of the probe (column 7 of the CSV).
solve_e() {
  "$CANDELA" solve "$tmp/$1.json" -o "$tmp/out_$1" --quiet >/dev/null 2>"$tmp/err_$1.txt" || return 1
  awk -F, 'NR == 2 { print $7 }' "$tmp/out_$1/p.csv"
}
# close A B: |A - B| <= 1e-12 |B|. The solver's point and directional terms
# are a few floating-point operations (E = I cos / d^2, E = E_n cos), so the
# CSV's 17 digits carry them to ~1e-15; 1e-12 leaves margin, and the smallest
# mistake that matters (a unit off by a prefix or a factor of pi) is 1e-3 or more.
close() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a != "" && d <= 1e-12 * (b < 0 ? -b : b)) }'; }

# 1.2 kcd isotropic, 2 m above the probe: E = I / d^2 = 1200 / 4 = 300 lx.
scene kcd '{"type": "point", "position": [0,0,2], "intensity_cd": "1.2 kcd"}'
e=$(solve_e kcd)
check "1.2 kcd at 2 m gives 300 lx (got $e)" 'close "$e" 300'

# 3000 lm isotropic: I = 3000 / (4 pi) cd; at 2 m, E = 3000 / (16 pi) lx.
scene lm '{"type": "point", "position": [0,0,2], "flux_lm": "3 klm"}'
e=$(solve_e lm)
want=$(awk 'BEGIN { printf "%.17g", 3000 / (16 * atan2(0, -1)) }')
check "3 klm isotropic at 2 m gives 3000/(16 pi) lx (got $e, want $want)" 'close "$e" "$want"'

# 46.45 fc of parallel light straight down: 46.45 lm/ft^2 = 46.45 / 0.3048^2 lx.
scene fc '{"type": "directional", "direction": [0,0,-1], "illuminance_lx": "46.45 fc"}'
e=$(solve_e fc)
want=$(awk 'BEGIN { printf "%.17g", 46.45 / (0.3048 * 0.3048) }')
check "46.45 fc gives 46.45/0.3048^2 lx (got $e, want $want)" 'close "$e" "$want"'

# The same light written as a number in lx gives the same illuminance.
scene lx '{"type": "directional", "direction": [0,0,-1], "illuminance_lx": 500}'
e=$(solve_e lx)
check "500 (a number) gives 500 lx (got $e)" 'close "$e" 500'

# Refused: a unit of another dimension, an unknown unit, no unit.
expect_refused() {
  local name=$1 luminaire=$2 fragment=$3
  scene "$name" "$luminaire"
  "$CANDELA" solve "$tmp/$name.json" -o "$tmp/out_$name" --quiet >/dev/null 2>"$tmp/err_$name.txt"; st=$?
  check "$name: exit status 1" '[ $st -eq 1 ]'
  check "$name: message '$fragment'" 'grep -qF "$name.json: $fragment" "$tmp/err_$name.txt"'
  check "$name: nothing written" '[ ! -e "$tmp/out_$name/p.csv" ]'
}
expect_refused watts '{"type": "point", "position": [0,0,2], "intensity_cd": "25 W"}' \
  "luminaires[0].intensity_cd: '25 W' is a power; expected a luminous intensity"
expect_refused lumens_as_lux '{"type": "directional", "direction": [0,0,-1], "illuminance_lx": "3000 lm"}' \
  "luminaires[0].illuminance_lx: '3000 lm' is a luminous flux; expected an illuminance"
expect_refused unknown '{"type": "point", "position": [0,0,2], "flux_lm": "3000 lumen-ish"}' \
  "luminaires[0].flux_lm: '3000 lumen-ish': unknown unit 'lumen-ish'"
expect_refused no_unit '{"type": "environment", "luminance_cd_m2": "1200"}' \
  "luminaires[0].luminance_cd_m2: '1200': missing unit"
exit $fail
