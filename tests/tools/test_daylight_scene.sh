#!/usr/bin/env bash
# Daylight skies in a scene, bad input through `candela solve`: each refused
# with exit status 1 and a message naming the file, the JSON path and what
# was expected (a time without its UTC offset, a latitude out of range, a
# CIE type out of range, the sun given twice or not at all where the sky
# needs it, a Perez sky with the sun below the horizon or without its day
# of the year, a Perez input outside the model, keys of one sky on
# another, glass clearer than clear glass or with a reflectance); and a
# good scene solves, its plan naming the model.
source "$(dirname "$0")/harness.sh"

grid='"grids": [{"name": "g", "type": "points", "points": [{"p": [0,0,0], "n": [0,0,1]}]}], "solver": {"method": "direct"}'
# refused NAME LUMINAIRE FRAGMENT: exit 1, stderr holds FRAGMENT (grep -F)
refused() {
  name=$1 frag=$3
  printf '{"version": 1, "luminaires": [%s], %s}\n' "$2" "$grid" > "$tmp/$name.json"
  "$CANDELA" solve "$tmp/$name.json" -o "$tmp/out_$name" --quiet > /dev/null 2> "$tmp/$name.err"; st=$?
  check "$name: exit 1 (got $st)" '[ $st -eq 1 ]'
  check "$name: names the file and '$frag'" 'grep -qF "$name.json: " "$tmp/$name.err" && grep -qF -- "$frag" "$tmp/$name.err"' ||
    cat "$tmp/$name.err"
}
site='"site": {"latitude_deg": 52.5, "longitude_deg": 13.4}'
refused no_offset '{"type": "environment", "sky": "cie", "cie_type": 12, "zenith_luminance_cd_m2": 5000, '"$site"', "time": "2024-06-21T12:00:00"}' \
  'luminaires[0].time: '"'"'2024-06-21T12:00:00'"'"': expected a UTC offset'
refused latitude '{"type": "environment", "sky": "cie", "cie_type": 12, "zenith_luminance_cd_m2": 5000, "site": {"latitude_deg": 95, "longitude_deg": 0}, "time": "2024-06-21T12:00:00Z"}' \
  'luminaires[0].site.latitude_deg: expected a number in [-90, 90] degrees, found the number 95'
refused cie_type '{"type": "environment", "sky": "cie", "cie_type": 16, "zenith_luminance_cd_m2": 5000}' \
  'luminaires[0].cie_type: expected an integer in [1, 15]'
refused no_sun '{"type": "environment", "sky": "cie", "cie_type": 12, "zenith_luminance_cd_m2": 5000}' \
  "luminaires[0]: expected the sun's place"
refused both_suns '{"type": "environment", "sky": "cie", "cie_type": 12, "zenith_luminance_cd_m2": 5000, "sun": {"azimuth_deg": 180, "altitude_deg": 40}, '"$site"', "time": "2024-06-21T12:00:00Z"}' \
  'luminaires[0].sun: expected either "sun" or "site" and "time"'
refused time_without_site '{"type": "environment", "sky": "cie", "cie_type": 1, "zenith_luminance_cd_m2": 5000, "time": "2024-06-21T12:00:00Z"}' \
  'expected "time" only with "site"'
refused two_scales '{"type": "environment", "sky": "cie", "cie_type": 1, "zenith_luminance_cd_m2": 5000, "diffuse_horizontal_illuminance_lx": 9000}' \
  'expected exactly one of "zenith_luminance_cd_m2" and "diffuse_horizontal_illuminance_lx"'
refused sun_below '{"type": "environment", "sky": "cie", "cie_type": 12, "zenith_luminance_cd_m2": 5000, "sun": {"azimuth_deg": 0, "altitude_deg": -5}}' \
  'expected the sun above the horizon'
refused perez_night '{"type": "environment", "sky": "perez", "direct_normal_irradiance_w_m2": 0, "diffuse_horizontal_irradiance_w_m2": 10, '"$site"', "time": "2024-01-10T00:30:00+01:00"}' \
  'expected the sun above the horizon for a Perez sky'
refused perez_day '{"type": "environment", "sky": "perez", "direct_normal_irradiance_w_m2": 500, "diffuse_horizontal_irradiance_w_m2": 100, "sun": {"azimuth_deg": 180, "altitude_deg": 40}}' \
  'luminaires[0].day_of_year: expected an integer in [1, 366]'
refused perez_range '{"type": "environment", "sky": "perez", "direct_normal_irradiance_w_m2": 10, "diffuse_horizontal_irradiance_w_m2": 500, "sun": {"azimuth_deg": 180, "altitude_deg": 10}, "day_of_year": 100}' \
  "luminaires[0]: expected a sky within the Perez model's range"
refused perez_mixed '{"type": "environment", "sky": "perez", "direct_normal_irradiance_w_m2": 500, "diffuse_horizontal_illuminance_lx": 10000, "sun": {"azimuth_deg": 180, "altitude_deg": 40}, "day_of_year": 100}' \
  'expected the direct normal and diffuse horizontal illuminances (lx) or irradiances (W/m2), found both'
refused uniform_with_site '{"type": "environment", "luminance_cd_m2": 100, '"$site"'}' \
  'luminaires[0].site: expected this key only with "sky": "cie" or "perez"'
refused north_up '{"type": "environment", "sky": "cie", "cie_type": 1, "zenith_luminance_cd_m2": 5000, "north": [0, 0, 2]}' \
  'luminaires[0].north: expected a direction of north not along "up"'
refused diameter '{"type": "directional", "direction": [0,0,-1], "illuminance_lx": 1000, "angular_diameter_deg": 30}' \
  'luminaires[0].angular_diameter_deg: expected an angular diameter in [0, 10] degrees'

# Glass: a transmittance beyond clear glass, or with a reflectance.
# refused_surface NAME SURFACE FRAGMENT: the same with a surface, under a uniform sky
refused_surface() {
  local plain=$grid
  grid='"surfaces": ['"$2"'], '"$plain"
  refused "$1" '{"type": "environment", "luminance_cd_m2": 100}' "$3"
  grid=$plain
}
pane='"type": "rect", "origin": [0,0,2], "u": [1,0,0], "v": [0,1,0]'
refused_surface glass_clearer '{'"$pane"', "transmittance": 0.95}' \
  'surfaces[0].transmittance: expected a normal transmittance in (0, 0.9183]'
refused_surface glass_reflects '{'"$pane"', "transmittance": 0.8, "reflectance": 0.1}' \
  'surfaces[0].reflectance: expected no "reflectance" or "luminance_cd_m2" on glass'

# A good one: Perez from irradiances with the sun by the SPA.
printf '{"version": 1, "luminaires": [{"type": "environment", "sky": "perez", "direct_normal_irradiance_w_m2": "600 W/m2", "diffuse_horizontal_irradiance_w_m2": 120, %s, "time": "2024-06-21T14:00:00+02:00"}], %s}\n' "$site" "$grid" > "$tmp/good.json"
"$CANDELA" solve "$tmp/good.json" -o "$tmp/good" --quiet > /dev/null 2> "$tmp/good.err"; st=$?
check "perez by the SPA: exit 0 (got $st)" '[ $st -eq 0 ]' || cat "$tmp/good.err"
check "perez: the plan names the model and the sun" 'grep -q "Perez all-weather sky" "$tmp/good/summary.json" && grep -q "NREL SPA" "$tmp/good/summary.json" && grep -q "(sun)" "$tmp/good/summary.json"'
exit $fail
