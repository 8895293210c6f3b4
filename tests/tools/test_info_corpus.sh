#!/usr/bin/env bash
# ctest-labels: corpus
# ctest-timeout: 600
# `candela info` and `candela convert` on every real file of the corpus
# folder: the MALFORMED ones exit 1 with FILE:LINE: expected ..., found ...;
# every other file is summarised (text and JSON with a finite flux) and
# converts to the other format and back; a radiometric one (W/sr) is
# refused by EULUMDAT and kept radiometric in IES.
set -u
: "${CANDELA:?}" "${CANDELA_PHOTOMETRIC_DIR:?}"
dir=$CANDELA_PHOTOMETRIC_DIR
if [ ! -d "$dir" ]; then
  echo "SKIPPED: the photometric corpus folder $dir is absent (this test needs ../shared/photometric)"
  exit 77
fi
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
fail=0
check() { if eval "$2"; then :; else echo "FAIL: $1"; fail=1; fi; }
count=0
for path in "$dir"/*; do
  f=$(basename "$path")
  case "$f" in *.md|*.csv|tilt.dat) continue ;; esac
  count=$((count + 1))
  out=$("$CANDELA" info "$path" 2>"$tmp/err"); st=$?
  err=$(cat "$tmp/err")
  if [[ "$f" == *MALFORMED* ]]; then
    check "$f is rejected with exit 1" '[ $st -eq 1 ] && [ -z "$out" ]'
    check "$f: a clear message" '[[ "$err" =~ $f:[0-9]+:\ expected.*found ]]'
    continue
  fi
  check "$f: info exits 0 ($err)" '[ $st -eq 0 ]'
  json=$("$CANDELA" info --json "$path" | tr -d '\n\t ')
  check "$f: JSON flux (radiant in W for files in W/sr)" '( [[ "$json" =~ \"flux_lm\":[0-9] ]] || [[ "$json" =~ \"radiant_flux_w\":[0-9] ]] ) && [[ "$json" != *:nan* ]] && [[ "$json" != *:inf* ]] && [[ "$json" != *:-inf* ]]'
  case "$f" in *.ldt|*.LDT) other=ies; back=ldt ;; *) other=ldt; back=ies ;; esac
  if [[ "$json" == *'"radiometric":true'* ]]; then
    # EULUMDAT holds cd/klm only: a file in W/sr is refused there, and kept radiometric in IES
    rm -f "$tmp/a.ldt"
    "$CANDELA" convert -q "$path" "$tmp/a.ldt" 2>/dev/null; st1=$?
    "$CANDELA" convert -q "$path" "$tmp/a.ies"; st2=$?
    again=$("$CANDELA" info --json "$tmp/a.ies" | tr -d '\n\t ')
    check "$f: radiometric: refused by EULUMDAT, kept in IES" '[ $st1 -eq 1 ] && [ ! -e "$tmp/a.ldt" ] && [ $st2 -eq 0 ] && [[ "$again" == *\"radiometric\":true* ]]'
    continue
  fi
  "$CANDELA" convert -q "$path" "$tmp/a.$other"; st1=$?
  "$CANDELA" convert -q "$tmp/a.$other" "$tmp/b.$back"; st2=$?
  check "$f: converts to $other and back" '[ $st1 -eq 0 ] && [ $st2 -eq 0 ]'
done
check "the corpus has files ($count)" '[ $count -gt 10 ]'

# EULUMDAT -> IES -> EULUMDAT: the alternative lamp sets travel as
# [_EULUMDAT_LAMPSET] keywords and come back as lamp sets, unremarked
for m in "ldt_gldf_two_lamp_sets_CRLF.ldt:2" "ldt_dlip_three_lamp_sets.ldt:3"; do
  f=${m%%:*}; want=${m#*:}
  err=$("$CANDELA" convert "$dir/$f" "$tmp/sets.ies" 2>&1 >/dev/null); st=$?
  check "$f: nothing said of the lamp sets ($err)" '[ $st -eq 0 ] && [[ "$err" != *"lamp set"* ]]'
  check "$f: lamp sets 2..$want as [_EULUMDAT_LAMPSET]" '[ "$(grep -c "^\[_EULUMDAT_LAMPSET\] " "$tmp/sets.ies")" -eq $((want - 1)) ]'
  "$CANDELA" convert -q "$tmp/sets.ies" "$tmp/sets.ldt"
  check "$f: $want lamp sets back in EULUMDAT" '[ "$(sed -n 26p "$tmp/sets.ldt" | tr -d "\r")" = "$want" ]'
done
# The luminous opening, one real file per shape code of the corpus: read
# (shape and size in metres in the JSON), shown (the text's opening line;
# the near-field distance for the openings the solver spreads, luminance where the opening
# has area), and carried by convert: kept IES -> IES, EULUMDAT -> IES ->
# EULUMDAT, and where EULUMDAT has no such shape, said on stderr.
for m in "ies_lithonia_AF10_bf088.ies:rectangle:0.329184:1.2192:0" \
         "ies_dlip_1995_relative_mult.ies:circle" \
         "ies_gldf_H90-270_circle2002.ies:vertical cylinder:0.56:0.56:0.065" \
         "ldt_road_Isym3_Mc52.ldt:vertical cylinder:0.472:0.472:0.14" \
         "ies_dlip_1995_sphere.ies:sphere:0.12:0.12:0.12" \
         "ies_dlip_1995_ellipsoid.ies:ellipsoid:0.12:0.34:0.56" \
         "ies_lithonia_RV8_oddshape.ies:unknown" \
         "ies_maxwell_1995_full.IES:point:0:0:0"; do
  IFS=: read -r f shape w l h <<<"$m"
  json=$("$CANDELA" info --json "$dir/$f" | tr -d '\n\t ')
  check "$f: opening shape $shape in the JSON" '[[ "$json" == *"\"opening\":{\"shape\":\"${shape// /}\""* ]]'
  if [ -n "${w:-}" ]; then
    check "$f: opening $w x $l x $h m in the JSON" '[[ "$json" == *"\"width_m\":$w,\"length_m\":$l,\"height_m\":$h,"* ]]'
  fi
  check "$f: luminance table in the JSON" '[[ "$json" == *"\"luminance\":[{\"c_deg\":0,\"gamma_deg\":0,\"average_cd_m2\":"* ]]'
  text=$("$CANDELA" info "$dir/$f")
  check "$f: the opening shown" '[[ "$text" == *"opening         $shape"* ]]'
  case "$shape" in
    rectangle|circle|box|"vertical cylinder"|"vertical elliptic cylinder"|sphere|ellipsoid|"horizontal cylinder"*) check "$f: the near-field distance shown" '[[ "$text" == *"near field      spread over its opening within"* ]]' ;;
    *) check "$f: no near field for a $shape" '[[ "$text" != *"near field      "* ]]' ;;
  esac
  "$CANDELA" convert -q "$dir/$f" "$tmp/o.ies" && back=$("$CANDELA" info "$tmp/o.ies")
  check "$f: the opening kept in IES" '[[ "$back" == *"opening         $shape"* ]]'
  err=$("$CANDELA" convert "$dir/$f" "$tmp/o.ldt" 2>&1 >/dev/null)
  case "$shape" in
    point|rectangle|circle|"vertical cylinder")
      back=$("$CANDELA" info "$tmp/o.ldt")
      check "$f: the opening kept in EULUMDAT" '[[ "$back" == *"opening         $shape"* ]] && [[ "$err" != *"luminous opening"* ]]' ;;
    *) check "$f: EULUMDAT cannot hold a $shape, said on stderr ($err)" '[[ "$err" == *"luminous opening '"'"'$shape'"'"' written as its bounding rectangle or circle"* ]]' ;;
  esac
done

echo "$count files checked"
exit $fail
