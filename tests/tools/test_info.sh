#!/usr/bin/env bash
# `candela info`: usage errors, the text summary, broken files (exit 1 with
# FILE:LINE: expected ..., found ...), warnings and --strict.
set -u
: "${CANDELA:?}" "${CANDELA_SOURCE_DIR:?}"
fix="$CANDELA_SOURCE_DIR/tests/data/photometric"
fail=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi; }

err=$("$CANDELA" info 2>&1 >/dev/null); st=$?
check "no argument is a usage error" '[ $st -eq 2 ] && [[ "$err" == *"expected a luminaire file"* ]]'
"$CANDELA" info a.ies b.ies >/dev/null 2>&1; st=$?
check "two missing files: read as a batch, both failed (exit 1)" '[ $st -eq 1 ]'
"$CANDELA" info --frobnicate "$fix/iso_1000cd.ies" >/dev/null 2>&1; st=$?
check "an unknown option is a usage error" '[ $st -eq 2 ]'
out=$("$CANDELA" info --help); st=$?
check "--help" '[ $st -eq 0 ] && [[ "$out" == "usage: candela info"* ]] && [[ "$out" == *"--json"* ]]'

out=$("$CANDELA" info "$fix/iso_1000cd.ies"); st=$?
check "isotropic fixture reads" '[ $st -eq 0 ]'
check "4000 pi lm" '[[ "$out" == *"12566.4 lm (integrated)"* ]]'
check "symmetry and format" '[[ "$out" == *"symmetry rotational"* ]] && [[ "$out" == *"IES LM-63-2002"* ]]'
check "absolute photometry named" '[[ "$out" == *"absolute photometry"* ]]'

out=$("$CANDELA" info "$fix/ies_tilt_file.ies"); st=$?
check "tilt file summary" '[ $st -eq 0 ] && [[ "$out" == *"4 angles, geometry 3"* ]] && [[ "$out" == *"LOR             90.4 %"* ]]'

out=$("$CANDELA" info "$fix/ldt_comma_blank_crlf.ldt"); st=$?
check "EULUMDAT summary" '[ $st -eq 0 ] && [[ "$out" == *"EULUMDAT (Isym 4"* ]] && [[ "$out" == *"warnings        none"* ]]'


err=$("$CANDELA" info "$fix/no_such_file.ies" 2>&1 >/dev/null); st=$?
check "a missing file is bad input" '[ $st -eq 1 ] && [[ "$err" == *"no_such_file.ies: cannot open"* ]]'

for f in bad_truncated.ies bad_not_a_number.ies bad_count_mismatch.ies bad_angles_decreasing.ies bad_nan.ies \
         bad_infinite.ies bad_negative_candela.ies bad_type_4.ies bad_no_tilt.ies bad_vertical_range.ies \
         bad_truncated.ldt bad_isym.ldt bad_negative.ldt bad_shifted.ldt; do
  out=$("$CANDELA" info "$fix/$f" 2>/tmp/candela_info_err.$$); st=$?
  err=$(cat /tmp/candela_info_err.$$)
  check "$f: exit 1" '[ $st -eq 1 ]'
  check "$f: nothing on stdout" '[ -z "$out" ]'
  check "$f: FILE:LINE: expected ..., found ..." '[[ "$err" =~ $f:[0-9]+:\ expected.*found ]]'
done
rm -f /tmp/candela_info_err.$$

# Content that fits neither format: the extension decides, so the error names
# the wrong line (here line 2, Ityp, of an EULUMDAT file) instead of line 1.
tmp=$(mktemp -d)

# EULUMDAT sides luminous to their own heights (lines 18-21) on a
# rectangular luminous area (lines 16-17: 90 x 40 mm): each shown, in text
# and JSON, the height their mean
sed -e '17s/.*/40/' -e '18s/.*/10/' -e '19s/.*/20/' -e '20s/.*/10/' -e '21s/.*/20/' "$fix/warn_lorl.ldt" > "$tmp/sides.ldt"
out=$("$CANDELA" info "$tmp/sides.ldt"); st=$?
check "sides of their own heights shown" '[ $st -eq 0 ] && [[ "$out" == *"rectangle with luminous sides, length 90 mm (along C90-C270) x width 40 mm (along C0-C180), luminous height 15 mm (EULUMDAT lines 16-21)"* ]] && [[ "$out" == *"sides luminous to 0.01 (C0), 0.02 (C90), 0.01 (C180), 0.02 (C270) m"* ]]'
out=$("$CANDELA" info --json "$tmp/sides.ldt"); st=$?
check "sides of their own heights in JSON" '[ $st -eq 0 ] && [[ "$(echo "$out" | tr -d " \t\n")" == *"\"side_heights_m\":[0.01,0.02,0.01,0.02]"* ]]'
sed '2s/.*/x/' "$fix/ldt_comma_blank_crlf.ldt" > "$tmp/ityp.ldt"
err=$("$CANDELA" info "$tmp/ityp.ldt" 2>&1 >/dev/null); st=$?
check ".ldt with a non-number on line 2: names line 2" '[ $st -eq 1 ] && [[ "$err" == *"ityp.ldt:2: expected"*"Ityp"*"found"* ]]'
printf 'hello\nworld\n' > "$tmp/words.ies"
err=$("$CANDELA" info "$tmp/words.ies" 2>&1 >/dev/null); st=$?
check ".ies without TILT=: read as IES, says TILT= is missing" '[ $st -eq 1 ] && [[ "$err" == *"words.ies:"*"expected a '"'"'TILT='"'"' line"* ]]'
cp "$tmp/words.ies" "$tmp/words.txt"
err=$("$CANDELA" info "$tmp/words.txt" 2>&1 >/dev/null); st=$?
check "unknown extension and content: says neither format" '[ $st -eq 1 ] && [[ "$err" == *"words.txt:1: expected an IES LM-63 file"*"found neither"* ]]'
sed 's/^1 1 0$/1 1 -75/' "$fix/iso_1000cd.ies" > "$tmp/watts.ies"
out=$("$CANDELA" info "$tmp/watts.ies" 2>&1); st=$?
check "negative input watts: a warning at line 9" '[ $st -eq 0 ] && [[ "$out" == *"watts.ies:9: expected input watts >= 0"*"found -75"* ]]'
"$CANDELA" info --strict "$tmp/watts.ies" >/dev/null 2>&1; st=$?
check "negative input watts: an error with --strict" '[ $st -eq 1 ]'
rm -rf "$tmp"

out=$("$CANDELA" info "$fix/warn_seam.ies" 2>&1); st=$?
check "a warning does not fail" '[ $st -eq 0 ] && [[ "$out" == *"H = 0 and H = 360 rows differ"* ]]'
err=$("$CANDELA" info --strict "$fix/warn_seam.ies" 2>&1 >/dev/null); st=$?
check "--strict makes it an error, at the H = 360 row's line" '[ $st -eq 1 ] && [[ "$err" == *"warn_seam.ies:13: "*"expected"*"found"*"an error with --strict"* ]]'
"$CANDELA" info --strict "$fix/warn_lorl.ldt" >/dev/null 2>&1; st=$?
check "--strict: stated LORL disagrees" '[ $st -eq 1 ]'
"$CANDELA" info --strict "$fix/warn_output_ratio.ies" >/dev/null 2>&1; st=$?
check "--strict: output ratio above 1" '[ $st -eq 1 ]'
"$CANDELA" info --strict "$fix/iso_1000cd.ies" >/dev/null 2>&1; st=$?
check "--strict passes a clean file" '[ $st -eq 0 ]'
out=$("$CANDELA" info --json --strict "$fix/warn_seam.ies" 2>/dev/null); st=$?
check "--json with --strict on a warning: exit 1, no JSON" '[ $st -eq 1 ] && [ -z "$out" ]'
# Warning codes: `info --help` points to the list, and the list
# (docs/photometry-warnings.md) names every code the library can give and
# no other (codes are the second argument of cdl_photometry_add_warning).
out=$("$CANDELA" info --help)
check "--help points to the list of warning codes" '[[ "$out" == *"docs/photometry-warnings.md"* ]]'
doc="$CANDELA_SOURCE_DIR/docs/photometry-warnings.md"
codes=$(grep -rhoz 'cdl_photometry_add_warning([^,]*,[[:space:]]*"[a-z0-9-]*"' "$CANDELA_SOURCE_DIR/lights" | tr '\0' '\n' | grep -o '"[a-z0-9-]*"$' | tr -d '"' | sort -u)
listed=$(grep -o '^| `[a-z0-9-]*`' "$doc" | tr -d '|` ' | sort -u)
check "the list names every code given ($(echo $codes | wc -w) codes)" '[ -n "$codes" ] && [ "$codes" = "$listed" ]' || { echo "given:  " $codes; echo "listed: " $listed; }
exit $fail
