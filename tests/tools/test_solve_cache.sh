#!/usr/bin/env bash
# candela solve --cache FILE through the command line: the first run writes
# the irradiance cache's records, a second run of the same scene reads them
# and writes the same CSV bytes (on another thread count); a changed scene or
# setting, a truncated or damaged file is refused (exit 1, naming the file and
# what is wrong) and the file left as it was; no temporary file remains, even
# after a run killed part-way.
# ctest-timeout: 120
source "$(dirname "$0")/harness.sh"
cd "$tmp" || exit 1

# A closed box (rho 0.5), one point light, a 20 x 20 floor grid by the cache.
cat > scene.json <<'EOF'
{"version": 1,
 "surfaces": [{"type": "box", "min": [0, 0, 0], "max": [4, 4, 3], "inward": true, "reflectance": 0.5}],
 "luminaires": [{"type": "point", "position": [2, 2, 2.5], "intensity_cd": 1000}],
 "grids": [{"name": "floor", "type": "rect", "origin": [0.1, 0.1, 0.8], "u": [3.8, 0, 0], "v": [0, 3.8, 0],
            "nu": 20, "nv": 20}],
 "solver": {"method": "icache", "quality": "draft"}}
EOF
no_temp_files() { [ -z "$(find . -name '*.tmp.*')" ]; }

"$CANDELA" solve scene.json -o out1 --cache c.bin --quiet > out1.txt 2> err1.txt; st=$?
check "first run: exit 0" '[ $st -eq 0 ]'
[ $st -eq 0 ] || cat err1.txt
check "first run: cache written" '[ -s c.bin ]'
check "first run: stdout says written" 'grep -q "irradiance cache c.bin: records gathered and written to it" out1.txt'
check "first run: summary says not reused" 'grep -q "\"reused\":[[:space:]]*false" out1/summary.json'
check "cache begins with its magic" '[ "$(head -c 8 c.bin)" = "CDLICACH" ]'
cp c.bin c.orig

"$CANDELA" solve scene.json -o out2 --cache c.bin --quiet --threads 1 > out2.txt 2> err2.txt; st=$?
check "second run: exit 0" '[ $st -eq 0 ]'
[ $st -eq 0 ] || cat err2.txt
check "second run: identical CSV bytes" 'cmp -s out1/floor.csv out2/floor.csv'
check "second run: summary says reused" 'grep -q "\"reused\":[[:space:]]*true" out2/summary.json'
check "second run: no path traced" 'grep -q "\"paths\":[[:space:]]*0," out2/summary.json'
check "second run: stdout says read" 'grep -q "records read from it, none gathered" out2.txt'
check "second run: cache untouched" 'cmp -s c.bin c.orig'
indirect_everywhere() { awk -F, 'NR > 1 && $9 <= 0 { n++ } END { exit n > 0 }' "$1"; }
check "interreflection is in the results" 'indirect_everywhere out2/floor.csv'

# A stale cache: another reflectance, another target error.
sed 's/"reflectance": 0.5/"reflectance": 0.6/' scene.json > rho.json
"$CANDELA" solve rho.json -o out3 --cache c.bin --quiet > /dev/null 2> err3.txt; st=$?
check "changed reflectance: exit 1" '[ $st -eq 1 ]'
check "changed reflectance: message names the file and the reflectances" \
  'grep -q "c.bin: the irradiance cache was made for another scene (changed since: the reflectances" err3.txt'
check "changed reflectance: no results written" '[ ! -e out3/floor.csv ]'
sed 's/"quality": "draft"/"quality": "draft", "target_error": 0.05/' scene.json > target.json
"$CANDELA" solve target.json -o out3 --cache c.bin --quiet > /dev/null 2> err4.txt; st=$?
check "changed target_error: exit 1" '[ $st -eq 1 ]'
check "changed target_error: message says both values" 'grep -q "target_error 0.02 in the cache, 0.05 now" err4.txt'
check "refused cache left as it was" 'cmp -s c.bin c.orig'

# A truncated and a damaged file.
head -c 3000 c.orig > cut.bin
"$CANDELA" solve scene.json -o out3 --cache cut.bin --quiet > /dev/null 2> err5.txt; st=$?
check "truncated cache: exit 1" '[ $st -eq 1 ]'
check "truncated cache: named and said" 'grep -q "cut.bin: not a valid irradiance cache file: truncated" err5.txt'
check "truncated cache: left as it was" '[ "$(wc -c < cut.bin)" -eq 3000 ]'
cp c.orig bad.bin
printf '\x5a' | dd of=bad.bin bs=1 seek=2000 conv=notrunc 2>/dev/null
check "the damage changed a byte" '! cmp -s bad.bin c.orig'
"$CANDELA" solve scene.json -o out3 --cache bad.bin --quiet > /dev/null 2> err6.txt; st=$?
check "damaged cache: exit 1" '[ $st -eq 1 ]'
check "damaged cache: checksum named" 'grep -q "bad.bin: not a valid irradiance cache file: damaged: its checksum" err6.txt'

# Usage and a folder that cannot take the file (refused before solving).
"$CANDELA" solve scene.json -o out3 --cache > /dev/null 2>&1; st=$?
check "--cache without a value: usage error" '[ $st -eq 2 ]'
"$CANDELA" solve scene.json -o out3 --cache "" > /dev/null 2>&1; st=$?
check "--cache '': usage error" '[ $st -eq 2 ]'
"$CANDELA" solve scene.json -o out3 --cache no/such/c.bin --quiet > /dev/null 2> err7.txt; st=$?
check "cache in a missing folder: exit 1" '[ $st -eq 1 ] && grep -q "no/such/c.bin" err7.txt'
check "help documents --cache" '"$CANDELA" solve --help | grep -q -- "--cache FILE"'

check "no temporary files after the runs" 'no_temp_files'

# A run killed part-way leaves no cache or a whole one, never part of one
# (a kill -9 inside a write may leave a temporary file: it is never taken
# for the cache).
for delay in 0.05 0.2 0.4; do
  rm -f k.bin
  "$CANDELA" solve scene.json -o outk --cache k.bin --quiet --threads 1 > /dev/null 2>&1 &
  pid=$!
  sleep $delay
  kill -9 $pid 2>/dev/null; wait $pid 2>/dev/null
  check "killed after ${delay} s: no cache or a whole one" '[ ! -e k.bin ] || cmp -s k.bin c.orig'
done
exit $fail
