#!/usr/bin/env bash
# The README's "Using the library" programs, taken from README.md as they
# are printed there, built outside the source tree against the installed
# prefix: with pkg-config (shared library, then candela-static.pc) and with
# find_package(Candela). Their numbers against closed forms:
#  - flux of an IES table I(gamma) = 1000 cd (1 - gamma / 90 deg) for gamma
#    in [0, 90], 0 beyond, interpolated linearly as LM-63 tables are:
#    Phi = 2 pi I0 int_0^{pi/2} (1 - 2 g / pi) sin g dg = 2 pi I0 (1 - 2 / pi)
#    = 2000 pi - 4000 lm; and of a uniform 100 cd table, 4 pi 100 lm;
#  - illuminance under a 1000 cd point light 2 m up, E = I cos(theta) / d^2:
#    250 lx below it, 128 lx 1.5 m aside, exact (stated error 0).
# ctest-timeout: 180
set -u
: "${CANDELA_TEST_PREFIX:?}" "${CANDELA_INSTALL_LIBDIR:?}" "${CANDELA_SOURCE_DIR:?}" "${CC:?}" "${CMAKE_COMMAND:?}"
: "${CANDELA_ABI_VERSION:?}"
san=${CANDELA_SANITIZE_FLAGS:-}
fail=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi; }
P=$CANDELA_TEST_PREFIX
L=$P/$CANDELA_INSTALL_LIBDIR
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
src=$tmp/src
mkdir -p "$src"

# readme_block FIRST-LINE-START: the README code block whose first line starts so.
readme_block() {
  awk -v head="$1" '
    /^```/ { if (inside) { inside = 0; if (found) exit } else { inside = 1; first = 1 } ; next }
    inside && first { first = 0; if (index($0, head) == 1) found = 1 }
    inside && found { print }' "$CANDELA_SOURCE_DIR/README.md"
}
readme_block "/* flux.c " > "$src/flux.c"
readme_block "/* illuminance.c " > "$src/illuminance.c"
readme_block "# CMakeLists.txt" > "$src/CMakeLists.txt"
for f in flux.c illuminance.c CMakeLists.txt; do
  check "README holds $f" '[ -s "$src/$f" ]'
done

# ies_file NAME COMMENT CANDELA: an LM-63-2002 table of one plane (rotational
# symmetry), absolute photometry, at gamma 0, 90 and 180 degrees.
ies_file() {
  printf '%s\r\n' "IESNA:LM-63-2002" "[TEST] $2" "TILT=NONE" "1 -1 1 3 1 1 2 0 0 0" "1 1 0" "0 90 180" "0" "$3" \
    > "$tmp/$1.ies"
}
ies_file cone "I = 1000 cd (1 - gamma / 90) below the horizontal, nothing above" "1000 0 0"
ies_file uniform "100 cd in every direction" "100 100 100"
ies_file uv "100 mW/sr in every direction" "100 100 100"
sed -i 's/^\[TEST\].*/&\r\n[_INTENSITYUNITS] mW\/sr/' "$tmp/uv.ies"
cone=$(awk 'BEGIN { printf "%.12f", 2000 * atan2(0, -1) - 4000 }')
uniform=$(awk 'BEGIN { printf "%.12f", 400 * atan2(0, -1) }')

# close A B: |A - B| <= 1e-9 |B| (A may carry a unit after it).
close() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-9 * (b < 0 ? -b : b)) }'; }

# check_programs LABEL DIR: run DIR/flux and DIR/illuminance and check their numbers.
check_programs() {
  local label=$1 dir=$2 out st
  out=$(LD_LIBRARY_PATH="$L" "$dir/flux" "$tmp/cone.ies" 2>&1); st=$?
  check "$label: flux runs" '[ $st -eq 0 ]'
  check "$label: flux of the cone table = 2000 pi - 4000 = $cone lm (got '$out')" 'close "${out% lm}" "$cone"'
  out=$(LD_LIBRARY_PATH="$L" "$dir/flux" "$tmp/uniform.ies" 2>&1); st=$?
  check "$label: flux of the uniform table = 400 pi = $uniform lm (got '$out')" '[ $st -eq 0 ] && close "${out% lm}" "$uniform"'
  out=$(LD_LIBRARY_PATH="$L" "$dir/flux" "$tmp/uv.ies" 2>&1); st=$?
  check "$label: flux of the table in mW/sr = 400 pi mW, in W (got '$out')" '[ $st -eq 0 ] && [[ "$out" == *" W" ]] && close "${out% W}" "$(awk "BEGIN { printf \"%.12f\", $uniform / 1000 }")"'
  out=$(LD_LIBRARY_PATH="$L" "$dir/flux" "$tmp/missing.ies" 2>&1); st=$?
  check "$label: flux of a missing file fails with a message naming it" '[ $st -eq 1 ] && [[ "$out" == *missing.ies* ]]'
  out=$(LD_LIBRARY_PATH="$L" "$dir/illuminance" 2>&1); st=$?
  check "$label: illuminance runs" '[ $st -eq 0 ]'
  local below aside
  below=$(echo "$out" | awk '$2 == "(0," && $3 == "0," {print $5, $8}')
  aside=$(echo "$out" | awk '$2 == "(1.5," {print $5, $8}')
  check "$label: E below the light = 1000 / 2^2 = 250 lx, error 0 (got '$below')" \
    'close "${below% *}" 250 && [ "${below#* }" = 0 ]'
  check "$label: E 1.5 m aside = 1000 x 0.8 / 2.5^2 = 128 lx, error 0 (got '$aside')" \
    'close "${aside% *}" 128 && [ "${aside#* }" = 0 ]'
}

# pkg-config, shared: the README's commands.
export PKG_CONFIG_PATH="$L/pkgconfig"
libs=$(pkg-config --libs candela); st=$?
check "pkg-config --libs candela is -L... -lcandela alone (got '$libs')" '[ $st -eq 0 ] && [[ "$libs" =~ ^-L[^\ ]+\ -lcandela\ *$ ]]'
mkdir -p "$tmp/pc"
for prog in flux illuminance; do
  # shellcheck disable=SC2046
  (cd "$src" && "$CC" $san $prog.c $(pkg-config --cflags --libs candela) -o "$tmp/pc/$prog"); st=$?
  check "pkg-config: $prog builds" '[ $st -eq 0 ]'
  needed=$(objdump -p "$tmp/pc/$prog" 2>/dev/null | awk '$1 == "NEEDED" {print $2}' | tr '\n' ' ')
  check "pkg-config: $prog links libcandela.so.$CANDELA_ABI_VERSION (needs: $needed)" \
    '[[ " $needed" == *" libcandela.so.$CANDELA_ABI_VERSION "* ]]'
  check "pkg-config: $prog needs none of the library's dependencies" \
    '! [[ "$needed" =~ embree|OpenColorIO|OpenEXR|cjson|gmp|png ]]'
done
check_programs "pkg-config" "$tmp/pc"

# pkg-config, static archive.
mkdir -p "$tmp/static"
for prog in flux illuminance; do
  (cd "$src" && "$CC" $san $prog.c $(pkg-config --cflags --libs candela-static) -o "$tmp/static/$prog"); st=$?
  check "candela-static.pc: $prog builds" '[ $st -eq 0 ]'
  check "candela-static.pc: $prog does not need libcandela.so" \
    '! objdump -p "$tmp/static/$prog" | grep -q "NEEDED.*libcandela"'
done
check_programs "static" "$tmp/static"

# find_package(Candela): the README's CMakeLists.txt.
"$CMAKE_COMMAND" -S "$src" -B "$tmp/cmake" -DCMAKE_PREFIX_PATH="$P" -DCMAKE_C_COMPILER="$CC" \
  -DCMAKE_C_FLAGS="$san" -DCMAKE_EXE_LINKER_FLAGS="$san" > "$tmp/cmake.log" 2>&1; st=$?
[ $st -eq 0 ] || cat "$tmp/cmake.log"
check "find_package(Candela): configures" '[ $st -eq 0 ]'
"$CMAKE_COMMAND" --build "$tmp/cmake" > "$tmp/build.log" 2>&1; st=$?
[ $st -eq 0 ] || cat "$tmp/build.log"
check "find_package(Candela): builds" '[ $st -eq 0 ]'
check "find_package(Candela): links libcandela.so.$CANDELA_ABI_VERSION" \
  'objdump -p "$tmp/cmake/illuminance" | grep -q "NEEDED.*libcandela.so.$CANDELA_ABI_VERSION"'
check_programs "find_package" "$tmp/cmake"

# The compile-time version macros, the run-time query and the build's
# version are one: the program prints both, the build says which it made.
cat > "$tmp/version.c" <<'C'
#include <stdio.h>
#include <candela/candela.h>
int main(void)
{
    printf("%d.%d.%d %s\n", CDL_VERSION_MAJOR, CDL_VERSION_MINOR, CDL_VERSION_PATCH, cdl_version());
    return 0;
}
C
(cd "$tmp" && "$CC" $san version.c $(pkg-config --cflags --libs candela) -o version); st=$?
out=$(LD_LIBRARY_PATH="$L" "$tmp/version" 2>&1)
check "CDL_VERSION_MAJOR.MINOR.PATCH = cdl_version() = the build's $CANDELA_PROJECT_VERSION (got '$out')" \
  '[ $st -eq 0 ] && [ "$out" = "$CANDELA_PROJECT_VERSION $CANDELA_PROJECT_VERSION" ]'
exit $fail
