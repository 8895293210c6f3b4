#!/usr/bin/env bash
# ctest-labels: corpus
# ctest-timeout: 600
# `candela info` and `candela convert` on every real file of the corpus
# folder: the MALFORMED ones exit 1 with FILE:LINE: expected ..., found ...;
# every other file is summarised (text and JSON with a finite flux) and
# converts to the other format and back.
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
  "$CANDELA" convert -q "$path" "$tmp/a.$other"; st1=$?
  "$CANDELA" convert -q "$tmp/a.$other" "$tmp/b.$back"; st2=$?
  check "$f: converts to $other and back" '[ $st1 -eq 0 ] && [ $st2 -eq 0 ]'
done
check "the corpus has files ($count)" '[ $count -gt 10 ]'

# EULUMDAT -> IES: what IES cannot hold is said on stderr; the alternative
# lamp sets survive as [OTHER] text
for m in "ldt_gldf_two_lamp_sets_CRLF.ldt:lamp set 2 (alternative" "ldt_dlip_three_lamp_sets.ldt:lamp sets 2..3 (alternative"; do
  f=${m%%:*}; want=${m#*:}
  err=$("$CANDELA" convert "$dir/$f" "$tmp/sets.ies" 2>&1 >/dev/null); st=$?
  check "$f: IES cannot hold the other lamp sets, said on stderr ($err)" '[ $st -eq 0 ] && [[ "$err" == *"IES cannot hold: EULUMDAT $want"* ]] && [[ "$err" == *"direct ratios"* ]]'
  check "$f: lamp set 2 kept as [OTHER]" 'grep -q "^\[OTHER\] Alternative lamp set 2: " "$tmp/sets.ies"'
done
echo "$count files checked"
exit $fail
