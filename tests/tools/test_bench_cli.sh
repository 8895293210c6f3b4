#!/usr/bin/env bash
# candela bench through the command line, on the integrating sphere (radius
# 1 m, inward, reflectance 0.5, a 1000 lm point source at its centre) whose
# answer is known at every point of the wall: direct Phi/(4 pi d^2) at the
# point's distance d from the source, interreflected rho Phi/(A (1 - rho))
# with A = 4 pi r^2 (the integrating sphere's equation; e.g. Ohno, OSA
# Handbook of Optics, "Integrating sphere"). Checks: the reference against
# that answer within its stated error; each rung's stated RMS against its
# true RMS within a factor 1.5; bench.csv's exact header and numbers;
# bench.svg valid XML with both axes labelled in units; a second run
# reuses DIR/reference (and gives the same CSV apart from seconds); a
# changed reflectance is refused; a scene without reflection benches
# direct only and says why; a budget too small for the reference is exit 1
# naming the time it needs. "<ref": absent where the reference resolves
# every rung (this sphere), on every rung of a sphere that reflects next
# to nothing (below). The furnace box (its exact answer below): a
# reference at a sample of its points, and again every rung's stated RMS
# against its true RMS within a factor 1.5.
# ctest-timeout: 300
source "$(dirname "$0")/harness.sh"
cd "$tmp" || exit 1

# 24 points spread over the wall.
source "$(dirname "$0")/sphere_scene.sh"
sphere_points 24
scene() { sphere_scene "$1"; }
scene 0.5 > sphere.json

"$CANDELA" bench sphere.json -o B --quiet > out1.txt 2> err1.txt; st=$?
check "first run: exit 0" '[ $st -eq 0 ]'
[ $st -eq 0 ] || cat err1.txt
check "first run: reference computed" 'grep -q "^reference: path traced to 0.02 %" out1.txt'
check "reference and its key written" '[ -s B/reference/wall.csv ] && [ -s B/reference/summary.json ] && [ -s B/reference/reference.key ]'
check "every rung's outputs as solve writes them" \
  'for m in icache pathtrace; do for r in draft t0.01 normal t0.0025 high; do [ -s B/runs/${m}_$r/wall.csv ] && [ -s B/runs/${m}_$r/summary.json ] || exit 1; done; done'
check "table ends with a recommendation per preset" \
  'grep -q "^recommendation" out1.txt && grep -Eq "^  draft +\(2 %\): " out1.txt && grep -Eq "^  normal +\(0.5 %\): " out1.txt && grep -Eq "^  high +\(0.1 %\): " out1.txt'
check "no temporary file left" '[ -z "$(find B -name "*.tmp.*")" ]'

# The exact answer at a point d from the centre.
exact='function exact(x, y, z) { pi = atan2(0, -1); return 1000 / (4 * pi * (x*x + y*y + z*z)) + 0.5 * 1000 / (4 * pi * 0.5) }'
# The reference: every point within 4 of its own sigma, and sigma <= 0.02 %.
check "reference within 4 sigma of the exact answer, to 0.02 %" \
  'awk -F, "$exact"'"'"' NR > 1 { e = exact($1, $2, $3); if (($7 - e) > 4 * $10 || (e - $7) > 4 * $10 || $10 / $7 > 0.0002) bad++ } END { exit bad > 0 }'"'"' B/reference/wall.csv'
# Each rung: stated RMS (of E_stderr/E) against the true RMS (against the
# exact answer) within a factor 1.5.
for d in B/runs/*/; do
  ratio=$(awk -F, "$exact"' NR > 1 { e = exact($1, $2, $3); t += (($7 - e) / e)^2; s += ($10 / $7)^2; n++ }
            END { printf "%.4f", sqrt(s / n) / sqrt(t / n) }' "$d/wall.csv")
  check "$(basename "$d"): stated RMS / true RMS = $ratio, within a factor 1.5" \
    'awk -v r="$ratio" "BEGIN { exit !(r >= 1/1.5 && r <= 1.5) }"'
done

# bench.csv: the exact header, 10 rows, numbers past the third column.
check "bench.csv header" \
  '[ "$(head -1 B/bench.csv)" = "label,method,quality,target_error,seconds,rays,records,rms_rel_error,max_rel_error,within_2_sigma" ]'
check "bench.csv: 10 rungs, each field a number past the third" \
  'awk -F, "NR > 1 { n++; if (NF != 10) bad++; for (i = 4; i <= 10; ++i) if (\$i !~ /^[0-9.e+-]+\$/) bad++ } END { exit !(n == 10 && !bad) }" B/bench.csv'
check "reference resolves every rung: no \"<ref\" in the table or bench.csv" \
  '! grep -q "<ref" out1.txt && ! grep -q "<ref" B/bench.csv'
check "bench.csv: errors are fractions, shares within [0, 1]" \
  'awk -F, "NR > 1 && (\$8 > 0.1 || \$9 > 0.1 || \$10 < 0 || \$10 > 1) { bad++ } END { exit bad > 0 }" B/bench.csv'
# bench.svg: well-formed XML, both axes labelled with their units.
check "bench.svg is valid XML" 'xmllint --noout B/bench.svg'
check "bench.svg: x axis labelled in seconds" 'grep -q "wall time of the whole solve (s)" B/bench.svg'
check "bench.svg: y axis labelled in percent" 'grep -q "RMS relative error of E against the reference (%)" B/bench.svg'
check "bench.svg: one polyline per method and the reference floor" \
  '[ "$(grep -c "<polyline" B/bench.svg)" -eq 2 ] && grep -q "reference.s own error" B/bench.svg'

check "bench.png: a 760 x 500 PNG" \
  '[ "$(head -c 8 B/bench.png | od -An -tx1 | tr -d " \n")" = 89504e470d0a1a0a ] && [ "$(od -An -tu1 -j16 -N8 B/bench.png | tr -s " ")" = " 0 0 2 248 0 0 1 244" ]'

# A second run reuses the reference and gives the same CSV but for seconds.
"$CANDELA" bench sphere.json -o B --quiet > out2.txt 2> err2.txt; st=$?
check "second run: exit 0" '[ $st -eq 0 ]'
check "second run: says the reference is reused" 'grep -q "^reference: reused B/reference (scene and settings hash" out2.txt'
cut -d, -f5 --complement B/bench.csv > second.csv
check "second run: same CSV apart from seconds" \
  '"$CANDELA" bench sphere.json -o C --quiet > /dev/null 2>&1 && cut -d, -f5 --complement C/bench.csv | cmp -s - second.csv'

# A changed reflectance: the reference is refused.
scene 0.6 > rho.json
"$CANDELA" bench rho.json -o B --quiet > /dev/null 2> err3.txt; st=$?
check "changed reflectance: exit 1" '[ $st -eq 1 ]'
check "changed reflectance: refused with a message" \
  'grep -q "B/reference: the reference there was made for another scene or other settings" err3.txt && grep -q "remove B/reference" err3.txt'

# Nothing reflects: direct only, with the reason.
scene 0 > black.json
"$CANDELA" bench black.json -o D --quiet > out4.txt 2> err4.txt; st=$?
check "no reflection: exit 0" '[ $st -eq 0 ]'
check "no reflection: says why only direct" 'grep -q "no surface reflects light" out4.txt && grep -q "only the direct method is benched" out4.txt'
check "no reflection: direct light exact, no rung flagged below the (exact) reference" \
  'awk -F, "NR > 1 && \$8 != 0 { bad++ } END { exit bad > 0 }" D/bench.csv && ! grep -q "<ref" out4.txt'
check "no reflection: only direct rungs" \
  '[ "$(awk -F, "NR > 1 { print \$2 }" D/bench.csv | sort -u)" = direct ] && [ "$(wc -l < D/bench.csv)" -eq 4 ]'

# A sphere that reflects a thousandth: the interreflected light is 0.1 %
# of E, and the solver's floor of 256 paths a point estimates it to a few
# % of itself, so every solve, the reference's too, is within about 1e-5
# of E whatever its target: the rungs are as good as the reference, their
# difference from it is the reference's own noise, and none can be
# resolved. Every rung is "<ref", in the table and in bench.csv, and no
# figure is printed in its place.
scene 0.001 > dim.json
"$CANDELA" bench dim.json -o G --quiet > out8.txt 2> err8.txt; st=$?
check "dim sphere: exit 0" '[ $st -eq 0 ]'
check "dim sphere: every rung flagged <ref in the table" \
  '[ "$(grep -Ec "^(icache|pathtrace)_[a-z0-9.]+ .* <ref " out8.txt)" -eq 10 ]'
check "dim sphere: the note says why" 'grep -q "^note: \"<ref\": the RMS error is not above 2 x the reference.s own stated RMS" out8.txt'
check "dim sphere: bench.csv says <ref in place of every RMS, the other fields numbers" \
  'awk -F, "NR > 1 { n++; if (\$8 != \"<ref\") bad++; for (i = 4; i <= 10; ++i) if (i != 8 && \$i !~ /^[0-9.e+-]+\$/) bad++ } END { exit !(n == 10 && !bad) }" G/bench.csv'
check "dim sphere: the recommendation prints no RMS figure for a rung below the reference" \
  '! grep -Eq "below the reference.s resolution.*[0-9] %" out8.txt'
# A sample of 5 of its 24 points: the same sample, reference and bench.csv
# (but for seconds) from two runs.
"$CANDELA" bench dim.json -o S1 --reference-points 5 --quiet > /dev/null 2>&1; st1=$?
"$CANDELA" bench dim.json -o S2 --reference-points 5 --quiet > /dev/null 2>&1; st2=$?
check "sampled reference: both runs exit 0, 5 points each" \
  '[ $st1 -eq 0 ] && [ $st2 -eq 0 ] && [ "$(wc -l < S1/reference/wall.csv)" -eq 6 ]'
check "sampled reference: the same points and values in both runs" 'cmp -s S1/reference/wall.csv S2/reference/wall.csv'
check "sampled reference: the same bench.csv apart from seconds" \
  'cmp -s <(cut -d, -f5 --complement S1/bench.csv) <(cut -d, -f5 --complement S2/bench.csv)'

# The furnace: a closed 4 m box whose walls emit L = 100 cd/m2 and reflect
# rho = 0.5 gives E = pi L / (1 - rho) at every point inside, whatever its
# normal. 16 points, the reference path traced at 4 of them (a sample).
fpoints=$(awk 'BEGIN { n = 16; pi = atan2(0, -1)
  for (i = 0; i < n; ++i) {
    z = 1 - 2 * (i + 0.5) / n; r = sqrt(1 - z * z); ph = i * pi * (3 - sqrt(5)); s = 1.5 * ((i % 5) + 1) / 5
    x = r * cos(ph); y = r * sin(ph)
    printf "%s{\"p\": [%.9f, %.9f, %.9f], \"n\": [%.9f, %.9f, %.9f]}", (i ? ", " : ""), 2 + s*x, 2 + s*y, 2 + s*z, y, z, x
  } }')
printf '{"version": 1, "surfaces": [{"type": "box", "min": [0, 0, 0], "max": [4, 4, 4], "inward": true, "reflectance": 0.5, "luminance_cd_m2": 100}],\n "grids": [{"name": "probes", "type": "points", "points": [%s]}]}\n' "$fpoints" > furnace.json
"$CANDELA" bench furnace.json -o H --reference-points 4 --quiet > out9.txt 2> err9.txt; st=$?
check "furnace: exit 0" '[ $st -eq 0 ]'
[ $st -eq 0 ] || cat err9.txt
check "furnace: the reference at 4 of the 16 points, said so" \
  'grep -q "^reference points: 4 of the grids. 16, a simple random sample" out9.txt && [ "$(wc -l < H/reference/probes.csv)" -eq 5 ] && grep -q "^points 4 of 16" H/reference/reference.key'
check "furnace: each RMS given +- its standard error as an estimate over all points" \
  '[ "$(grep -Ec "^(icache|pathtrace)_[a-z0-9.]+ .*[0-9]% \+-[0-9.]+%" out9.txt)" -eq 10 ]'
check "furnace: bench.svg valid XML with an error bar (a plain line in a method's colour) per rung" \
  'xmllint --noout H/bench.svg && [ "$(grep -Ec "<line [^>]*stroke=\"#(1f77b4|d62728)\"/>" H/bench.svg)" -eq 10 ]'
check "furnace: every rung solved at all 16 points" \
  'for d in H/runs/*/; do [ "$(wc -l < $d/probes.csv)" -eq 17 ] || exit 1; done'
# The reference's points are the scene's, and within 4 sigma of pi L / (1 - rho).
check "furnace: reference points are the scene's, within 4 sigma of the exact answer" \
  'awk -F, "NR > 1 { e = atan2(0, -1) * 200; if ((\$7 - e) > 4 * \$10 || (e - \$7) > 4 * \$10) bad++ } END { exit bad > 0 }" H/reference/probes.csv &&
   tail -n +2 H/reference/probes.csv | cut -d, -f1-3 | while read -r p; do grep -q "^$p," H/runs/pathtrace_draft/probes.csv || exit 1; done'
for d in H/runs/*/; do
  ratio=$(awk -F, 'NR > 1 { e = atan2(0, -1) * 200; t += (($7 - e) / e)^2; s += ($10 / $7)^2; n++ }
            END { printf "%.4f", sqrt(s / n) / sqrt(t / n) }' "$d/probes.csv")
  check "furnace $(basename "$d"): stated RMS / true RMS = $ratio, within a factor 1.5" \
    'awk -v r="$ratio" "BEGIN { exit !(r >= 1/1.5 && r <= 1.5) }"'
done

# A budget too small for the reference.
"$CANDELA" bench sphere.json -o E --budget 0.001 --quiet > /dev/null 2> err5.txt; st=$?
check "tiny budget: exit 1" '[ $st -eq 1 ]'
check "tiny budget: no folder left behind" '[ ! -e E ]'
check "tiny budget: says how long the reference needs" \
  'grep -Eq "budget 0.001 s is too small: the reference \(path tracing to 0.02 %\) needs about [0-9.e+]+ s" err5.txt'
# A budget the reused reference leaves nothing of: every rung skipped and listed.
"$CANDELA" bench sphere.json -o B --budget 0.000001 --quiet > out7.txt 2> err7.txt; st=$?
check "budget spent: exit 0" '[ $st -eq 0 ]'
check "budget spent: rungs listed as skipped" '[ "$(grep -c "skipped: would not fit the budget" out7.txt)" -eq 10 ]'
check "budget spent: bench.csv keeps only the header" '[ "$(wc -l < B/bench.csv)" -eq 1 ]'
# Usage.
"$CANDELA" bench sphere.json > /dev/null 2>&1; st=$?
check "no -o: usage error" '[ $st -eq 2 ]'
"$CANDELA" bench sphere.json -o F --reference-points -3 > /dev/null 2> err10.txt; st=$?
check "negative --reference-points: usage error naming it" '[ $st -eq 2 ] && grep -q "reference-points: expected a count" err10.txt'
"$CANDELA" bench sphere.json -o F --methods frob > /dev/null 2> err6.txt; st=$?
check "unknown method: usage error naming it" '[ $st -eq 2 ] && grep -q "frob" err6.txt'
exit $fail
