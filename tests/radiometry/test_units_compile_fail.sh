#!/usr/bin/env bash
# Mixing units must not compile: handing an illuminance where a luminous
# intensity is expected is a type error, and so is every other pair of the
# quantity types of units.h. Positive controls (the correct calls) must
# compile with the same command, so the test cannot pass because of a broken
# include path or compiler.
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

# Every pair of quantity types declared in units.h: a value of type B handed
# to a parameter of type A, one call per line. Each such line must be a
# compile error, so a new type that is secretly another (a typedef or a
# macro alias) fails here. The types are read from units.h, so a new
# quantity is covered without editing this test.
types=()
ctors=()
while read -r type ctor; do types+=("$type"); ctors+=("$ctor"); done < <(
  sed -n 's/^CDL_DEFINE_QUANTITY(\([a-z_]*\), *[A-Za-z0-9_]*, *\([a-z0-9_]*\)).*/\1 \2/p' \
    "${CFLAGS_INCLUDE#-I}/radiometry/units.h")
n=${#types[@]}
# write_pairs FILE SAME: calls with the same type (SAME=1) or every other type.
write_pairs() {
  {
    echo '#include "radiometry/units.h"'
    for ((a = 0; a < n; a++)); do echo "static void take_$a(${types[a]} q) { (void)q; }"; done
    echo 'void every_pair(void)'
    echo '{'
    for ((a = 0; a < n; a++)); do
      for ((b = 0; b < n; b++)); do
        if { [ "$2" = 1 ] && [ $a -eq $b ]; } || { [ "$2" = 0 ] && [ $a -ne $b ]; }; then
          echo "    take_$a(${ctors[b]}(1.0));"
        fi
      done
    done
    echo '}'
  } > "$1"
}
write_pairs "$dir/pairs_same.c" 1
write_pairs "$dir/pairs_mixed.c" 0
# The quantities the foundation promises must each be a type of their own.
for t in cdl_radiant_energy cdl_radiant_flux cdl_irradiance cdl_radiant_exitance cdl_radiant_intensity \
         cdl_radiance cdl_luminous_energy cdl_luminous_flux cdl_illuminance cdl_luminous_exitance \
         cdl_luminous_intensity cdl_luminance cdl_solid_angle cdl_length; do
  [[ " ${types[*]} " == *" $t "* ]] || { echo "FAIL: $t is not declared with CDL_DEFINE_QUANTITY in units.h"; status=1; }
done
if ! "$CC" -std=c11 -Wall -Wextra -Werror -fsyntax-only $CFLAGS_INCLUDE "$dir/pairs_same.c" 2>"$dir/ok.log"; then
  echo "FAIL: positive control pairs_same.c does not compile:"; head -20 "$dir/ok.log"; status=1
fi
# Report every error, not the first 20 (clang's default limit).
no_limit=-fmax-errors=0
echo 'int x;' > "$dir/probe.c"
"$CC" -ferror-limit=0 -fsyntax-only "$dir/probe.c" 2>/dev/null && no_limit=-ferror-limit=0
"$CC" -std=c11 -fsyntax-only $no_limit $CFLAGS_INCLUDE "$dir/pairs_mixed.c" 2>"$dir/wrong.log"
calls=$(grep -n '^    take_' "$dir/pairs_mixed.c" | cut -d: -f1)
count=0
missed=0
for line in $calls; do
  count=$((count + 1))
  if ! grep -q "pairs_mixed.c:$line:[0-9]*: error: .*incompatible type" "$dir/wrong.log"; then
    missed=$((missed + 1))
    echo "compiled: $(sed -n "${line}p" "$dir/pairs_mixed.c")"
  fi
done
if [ $count -ne $((n * (n - 1))) ]; then
  echo "FAIL: generated $count mixed calls, expected $((n * (n - 1)))"; status=1
elif [ $missed -ne 0 ]; then
  echo "FAIL: $missed of $count mixed-unit calls compiled (listed above)"; status=1
else
  echo "ok: all $count ordered pairs of the $n quantity types are rejected by the compiler"
fi

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
