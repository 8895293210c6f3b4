#!/usr/bin/env bash
# `candela convert`: formats by extension, flux kept through both formats,
# LM-63 versions, the C-plane mapping and its option, what the target
# cannot hold, bad input and unwritable output.
set -u
: "${CANDELA:?}" "${CANDELA_SOURCE_DIR:?}"
fix="$CANDELA_SOURCE_DIR/tests/data/photometric"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi; }
json_number() { "$CANDELA" info --json "$1" | sed -n "s/^[[:space:]]*\"$2\":[[:space:]]*\([-0-9.eE+]*\),\{0,1\}$/\1/p"; }
max_c() { "$CANDELA" info --json "$1" | tr -d '\n\t ' | sed -n 's/.*"max_intensity_direction":{"c_deg":\([-0-9.eE+]*\).*/\1/p'; }
close() { awk -v a="$1" -v b="$2" -v t="$3" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(a != "" && d <= t * (b < 0 ? -b : b)) }'; }

err=$("$CANDELA" convert 2>&1 >/dev/null); st=$?
check "no argument is a usage error" '[ $st -eq 2 ] && [ -n "$err" ]'
out=$("$CANDELA" convert --help); st=$?
check "--help documents the mapping" '[ $st -eq 0 ] && [[ "$out" == "usage: candela convert"* ]] && [[ "$out" == *"H = (360 - C) mod 360"* ]] && [[ "$out" == *"--c-mapping"* ]]'
"$CANDELA" convert "$fix/iso_1000cd.ies" "$tmp/out.txt" 2>/dev/null; st=$?
check "an unknown output extension is a usage error" '[ $st -eq 2 ] && [ ! -e "$tmp/out.txt" ]'
"$CANDELA" convert "$fix/iso_1000cd.ies" "$tmp/out.ies" --ies-version 1995 2>/dev/null; st=$?
check "an unsupported LM-63 version is a usage error" '[ $st -eq 2 ]'
"$CANDELA" convert "$fix/iso_1000cd.ies" "$tmp/out.ldt" --c-mapping sideways 2>/dev/null; st=$?
check "an unknown mapping is a usage error" '[ $st -eq 2 ]'
err=$("$CANDELA" convert "$fix/bad_nan.ies" "$tmp/bad.ldt" 2>&1); st=$?
check "bad input: exit 1, message, no output" '[ $st -eq 1 ] && [[ "$err" == *"bad_nan.ies:9: expected"* ]] && [ ! -e "$tmp/bad.ldt" ]'
err=$("$CANDELA" convert "$fix/iso_1000cd.ies" "$tmp/no/such/dir/out.ldt" 2>&1); st=$?
check "unwritable output: exit 1 naming it" '[ $st -eq 1 ] && [[ "$err" == *"no/such/dir/out.ldt"* ]]'

# IES -> EULUMDAT -> IES keeps the light (to the ten digits the writers
# print): `info` reports the luminaire's flux, the table times its output
# factor, and a ballast factor EULUMDAT cannot hold is folded into its lamp
# flux, so the same luminaire reads the same before and after.
light() { json_number "$1" flux_lm; }
for f in iso_1000cd.ies ies_1986_one_per_line.ies ies_crlf_latin1_ctrlz.ies asym_h90_peak.ies ldt_comma_blank_crlf.ldt; do
  base=${f%.*}
  case $f in *.ldt) a=ies; b=ldt ;; *) a=ldt; b=ies ;; esac
  "$CANDELA" convert -q "$fix/$f" "$tmp/$base.1.$a"; st1=$?
  "$CANDELA" convert -q "$tmp/$base.1.$a" "$tmp/$base.2.$b"; st2=$?
  f0=$(light "$fix/$f"); f1=$(light "$tmp/$base.1.$a"); f2=$(light "$tmp/$base.2.$b")
  check "$f: converts both ways" '[ $st1 -eq 0 ] && [ $st2 -eq 0 ]'
  check "$f: flux kept ($f0 -> $f1 -> $f2)" 'close "$f1" "$f0" 1e-8 && close "$f2" "$f0" 1e-8'
done

"$CANDELA" convert "$fix/iso_1000cd.ies" "$tmp/v19.ies" 2>/dev/null
"$CANDELA" convert --ies-version 2002 "$fix/iso_1000cd.ies" "$tmp/v02.IES" 2>/dev/null
check "LM-63-2019 by default" '[ "$(head -1 "$tmp/v19.ies" | tr -d "\r")" = "IES:LM-63-2019" ]'
check "LM-63-2002 on request (and .IES)" '[ "$(head -1 "$tmp/v02.IES" | tr -d "\r")" = "IESNA:LM-63-2002" ]'

# what the target cannot hold goes to stderr
err=$("$CANDELA" convert "$fix/ies_tilt_file.ies" "$tmp/tilt.ldt" 2>&1 >/dev/null); st=$?
check "TILT reported as lost in EULUMDAT" '[ $st -eq 0 ] && [[ "$err" == *"EULUMDAT cannot hold: TILT data"* ]]'
err=$("$CANDELA" convert -q "$fix/ies_tilt_file.ies" "$tmp/tilt2.ldt" 2>&1 >/dev/null)
check "--quiet silences it" '[ -z "$err" ]'

# The C-plane mapping. The fixture's brightest plane is IES H = 90.
#   mirror (default): EULUMDAT C = 360 - H = 270; identity: C = H = 90;
#   plus90: H = C + 90, so C = 0; minus90: H = C + 270, so C = 180.
for m in default:270 identity:90 plus90:0 minus90:180; do
  name=${m%%:*}; want=${m##*:}
  opt=(); [ "$name" != default ] && opt=(--c-mapping "$name")
  "$CANDELA" convert -q "${opt[@]}" "$fix/asym_h90_peak.ies" "$tmp/map_$name.ldt"
  got=$(max_c "$tmp/map_$name.ldt")
  check "mapping $name puts IES H90 at EULUMDAT C$want (got C$got)" 'close "$got" "$want" 0 || [ "$got" = "$want" ]'
  # and back with the same mapping restores the IES angles
  "$CANDELA" convert -q "${opt[@]}" "$tmp/map_$name.ldt" "$tmp/map_$name.ies"
  back=$(max_c "$tmp/map_$name.ies")
  check "mapping $name round trip restores the frame (C$back)" '[ "$back" = "270" ]'
done
err=$("$CANDELA" convert --c-mapping identity "$fix/asym_h90_peak.ies" "$tmp/same.ies" 2>&1 >/dev/null)
check "the mapping is ignored (and said so) between two IES files" '[[ "$err" == *"ignored"* ]] && [ "$(max_c "$tmp/same.ies")" = "270" ]'

# no temporary files left behind
left=$(ls -A "$tmp" | grep -c tmp || true)
check "no temporary files left" '[ "$left" -eq 0 ]'
# The ballast factor and the test-lab fields, both ways: IES [TESTLAB],
# [TEST], [ISSUEDATE] through EULUMDAT and back; a ballast factor 0.855
# folded into EULUMDAT's lamp flux, and said so.
"$CANDELA" convert "$fix/ies_crlf_latin1_ctrlz.ies" "$tmp/bf.ldt" > /dev/null 2> "$tmp/bf.err"; st=$?
check "ballast factor folded into the lamp flux, and said" '[ $st -eq 0 ] && grep -q "ballast factor 0.855 has no EULUMDAT field: folded into the lamp flux" "$tmp/bf.err"'
# (absolute photometry: line 29 holds the table's own flux, times the factor)
light_ies=$(light "$fix/ies_crlf_latin1_ctrlz.ies"); lamp_ldt=$(sed -n 29p "$tmp/bf.ldt" | tr -d '\r')
check "EULUMDAT line 29 = the table's flux x 0.855 ($light_ies, $lamp_ldt)" 'close "$lamp_ldt" "$light_ies" 1e-9'
check "EULUMDAT has no ballast factor left (1)" '[ "$(json_number "$tmp/bf.ldt" ballast_factor)" = 1 ]'
cat > "$tmp/lab.ies" <<'IES'
IESNA:LM-63-2002
[TEST] REPORT-4711
[TESTLAB] Independent Photometry Lab GmbH
[ISSUEDATE] 2026-03-14
[MANUFAC] Maker
TILT=NONE
1 -1 1 3 1 1 2 0 0 0
1 1 10
0 45 90
0
100 80 50
IES
"$CANDELA" convert -q "$tmp/lab.ies" "$tmp/lab.ldt" && "$CANDELA" convert -q "$tmp/lab.ldt" "$tmp/lab2.ies"; st=$?
check "test lab: IES -> EULUMDAT -> IES converts" '[ $st -eq 0 ]'
check "test lab: EULUMDAT carries report number and date with the lab" 'grep -q "^REPORT-4711" "$tmp/lab.ldt" && grep -q "^2026-03-14, test lab: Independent Photometry Lab GmbH" "$tmp/lab.ldt"'
check "test lab: back in IES as [TEST], [TESTLAB], [ISSUEDATE]" 'grep -q "^\[TEST\] REPORT-4711" "$tmp/lab2.ies" && grep -q "^\[TESTLAB\] Independent Photometry Lab GmbH" "$tmp/lab2.ies" && grep -q "^\[ISSUEDATE\] 2026-03-14" "$tmp/lab2.ies"'
# IES -> EULUMDAT names every keyword EULUMDAT has no field for, each once,
# and counts them ([MORE] continues the keyword before it)
sed '5a [LAMPCAT] LC-1\n[BALLAST] electronic\n[OTHER] first note\n[MORE] its second line\n[OTHER] second note\n[_SEARCH_COLOUR] white' "$tmp/lab.ies" > "$tmp/kw.ies"
err=$("$CANDELA" convert "$tmp/kw.ies" "$tmp/kw.ldt" 2>&1 >/dev/null); st=$?
check "IES -> EULUMDAT names each lost keyword ($err)" '[ $st -eq 0 ] && [[ "$err" == *"EULUMDAT cannot hold: 5 IES keywords with no EULUMDAT field: [LAMPCAT], [BALLAST], [OTHER], [_SEARCH_COLOUR]"* ]]'
check "IES -> EULUMDAT: the direct ratios computed, not 0 (line 27, k = 0.6)" '[ "$(sed -n 27p "$tmp/kw.ldt" | tr -d "\r")" != 0 ] && [[ "$err" != *"direct ratios"* ]]'
# the input's warnings are passed on with their codes
err=$("$CANDELA" convert "$fix/warn_seam.ies" "$tmp/seam.ldt" 2>&1 >/dev/null); st=$?
check "the input's warnings on stderr with their codes" '[ $st -eq 0 ] && [[ "$err" == *"candela convert: warning: [seam-differs] "*"H = 360"* ]]'
exit $fail
