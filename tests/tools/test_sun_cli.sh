#!/usr/bin/env bash
# `candela sun` through the command line: the SPA report's worked example
# (NREL/TP-560-34302, Table A5.1: zenith 50.11162, azimuth 194.34024
# degrees, declination -9.31434) in text and JSON to 1e-4 degrees, the same
# instant written in UTC, and bad input: a time without a UTC offset and a
# latitude out of range exit 1 naming the option; a missing option or a
# value that is no number exit 2.
source "$(dirname "$0")/harness.sh"

golden=(--lat 39.742476 --lon -105.1786 --elevation 1830.14 --pressure 820 --temperature 11 --delta-t 67)
"$CANDELA" sun "${golden[@]}" --time 2003-10-17T12:30:30-07:00 > "$tmp/text.txt" 2>&1
check "text: exit 0" '[ $? -eq 0 ]'
check "text: zenith 50.11162" 'grep -q "zenith  *50.11162 deg" "$tmp/text.txt"'
check "text: azimuth 194.34024" 'grep -q "azimuth  *194.34024 deg" "$tmp/text.txt"'
check "text: declination -9.31434" 'grep -q "declination  *-9.31434 deg" "$tmp/text.txt"'

# field NAME FILE: a number from the one-line JSON object
field() { sed -E "s/.*\"$1\": ([-0-9.eE+]+).*/\1/" "$2"; }
near() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a != "" && d <= t) }'; }
"$CANDELA" sun "${golden[@]}" --time 2003-10-17T19:30:30Z --json > "$tmp/sun.json"
check "json: exit 0" '[ $? -eq 0 ]'
check "json: one object, every key" 'python3 -c "import json,sys; d=json.load(open(sys.argv[1])); sys.exit(not all(k in d for k in (\"zenith_deg\",\"azimuth_deg\",\"declination_deg\",\"equation_of_time_min\")))" "$tmp/sun.json"'
check "json (UTC): zenith 50.11162 to 1e-4" 'near "$(field zenith_deg "$tmp/sun.json")" 50.11162 1e-4'
check "json (UTC): azimuth 194.34024 to 1e-4" 'near "$(field azimuth_deg "$tmp/sun.json")" 194.34024 1e-4'

"$CANDELA" sun --lat 39.7 --lon -105.2 --time 2003-10-17T12:30:30 > "$tmp/o.txt" 2> "$tmp/e.txt"
st=$?
check "no UTC offset: exit 1 (got $st)" '[ $st -eq 1 ]'
check "no UTC offset: names --time and the offset" 'grep -q -- "--time: .*UTC offset" "$tmp/e.txt"'
check "no UTC offset: nothing on stdout" '[ ! -s "$tmp/o.txt" ]'
"$CANDELA" sun --lat 95 --lon 0 --time 2003-10-17T12:30:30Z > /dev/null 2> "$tmp/e.txt"
st=$?
check "latitude 95: exit 1 (got $st)" '[ $st -eq 1 ]'
check "latitude 95: names --lat and the range" 'grep -q -- "--lat: .*\[-90, 90\]" "$tmp/e.txt"'
"$CANDELA" sun --lat 40 --time 2003-10-17T12:30:30Z > /dev/null 2> "$tmp/e.txt"
st=$?
check "missing --lon: exit 2 (got $st)" '[ $st -eq 2 ] && grep -q -- "--lon is required" "$tmp/e.txt"'
"$CANDELA" sun --lat north --lon 0 --time 2003-10-17T12:30:30Z > /dev/null 2> "$tmp/e.txt"
st=$?
check "--lat north: exit 2 (got $st)" '[ $st -eq 2 ] && grep -q -- "--lat: expected a number" "$tmp/e.txt"'
"$CANDELA" sun --help | grep -q "eastward from north"
check "--help describes the azimuth" '[ $? -eq 0 ]'
exit $fail
