#!/usr/bin/env bash
# Mixing units must not compile: handing an illuminance where a luminous
# intensity is expected is a type error. A positive control (the correct call)
# must compile with the same command, so the test cannot pass because of a
# broken include path or compiler.
set -u
: "${CC:?CC not set}" "${CFLAGS_INCLUDE:?}"
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cat > "$dir/mixed.c" <<'SRC'
#include "radiometry/conversions.h"
double f(void)
{
#ifdef WRONG
    cdl_illuminance e = cdl_lux(500.0);
    return cdl_isotropic_flux_from_intensity(e).lm;   /* lux where candela is expected */
#else
    cdl_luminous_intensity i = cdl_candelas(500.0);
    return cdl_isotropic_flux_from_intensity(i).lm;
#endif
}
SRC
cat > "$dir/assign.c" <<'SRC'
#include "radiometry/units.h"
double g(void)
{
    cdl_luminous_intensity i;
#ifdef WRONG
    i = cdl_lux(500.0);        /* assigning lux to candela */
#else
    i = cdl_candelas(500.0);
#endif
    return i.cd;
}
SRC
status=0
for f in mixed assign; do
  if ! "$CC" -std=c11 -fsyntax-only $CFLAGS_INCLUDE "$dir/$f.c" 2>"$dir/ok.log"; then
    echo "FAIL: positive control $f.c does not compile:"; cat "$dir/ok.log"; status=1
  fi
  if "$CC" -std=c11 -fsyntax-only $CFLAGS_INCLUDE -DWRONG "$dir/$f.c" 2>"$dir/wrong.log"; then
    echo "FAIL: $f.c with mixed units compiled"; status=1
  elif ! grep -q "incompatible type" "$dir/wrong.log"; then
    echo "FAIL: $f.c failed for another reason than the unit type:"; cat "$dir/wrong.log"; status=1
  else
    echo "ok: $f.c mixed units rejected: $(grep -m1 'incompatible type' "$dir/wrong.log")"
  fi
done
exit $status
