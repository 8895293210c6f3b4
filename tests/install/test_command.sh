#!/usr/bin/env bash
# The installed prefix works wherever it is put: a copy moved elsewhere
# still runs `candela solve` with its PNG maps (the OCIO config is found
# relative to the command, and relative to libcandela.so for a program
# using the library), and the library's cdl_version() is what
# `candela --version` prints, from C and from C++. Negative control: with the moved copy's
# config taken away, the PNG maps cannot be made.
# ctest-timeout: 120
set -u
: "${CANDELA_TEST_PREFIX:?}" "${CANDELA_INSTALL_LIBDIR:?}" "${CC:?}" "${CXX:?}" "${CANDELA_ABI_VERSION:?}"
: "${CANDELA_PROJECT_VERSION:?}"
san=${CANDELA_SANITIZE_FLAGS:-}
fail=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
M=$tmp/moved/prefix
mkdir -p "$tmp/moved"
cp -a "$CANDELA_TEST_PREFIX" "$M"
L=$M/$CANDELA_INSTALL_LIBDIR

cat > "$tmp/version.c" <<'SRC'
#include <stdio.h>
#include <candela/candela.h>
int main(void)
{
    printf("%s\n%d\n%s\n", cdl_version(), cdl_abi_version(), cdl_default_ocio_config());
    return 0;
}
SRC
PKG_CONFIG_PATH="$L/pkgconfig" "$CC" $san "$tmp/version.c" $(PKG_CONFIG_PATH="$L/pkgconfig" pkg-config --cflags --libs candela) \
  -o "$tmp/version"; st=$?
check "a program using the moved prefix builds" '[ $st -eq 0 ]'
mapfile -t got < <(LD_LIBRARY_PATH="$L" "$tmp/version")
cli=$("$M/bin/candela" --version)
check "cdl_version() = $CANDELA_PROJECT_VERSION (got '${got[0]:-}')" '[ "${got[0]:-}" = "$CANDELA_PROJECT_VERSION" ]'
check "candela --version prints cdl_version() (got '$cli')" '[ "$cli" = "candela ${got[0]:-}" ]'
check "cdl_abi_version() = $CANDELA_ABI_VERSION, the SONAME's (got '${got[1]:-}')" '[ "${got[1]:-}" = "$CANDELA_ABI_VERSION" ]'
check "libcandela.so finds the OCIO config in the moved prefix (got '${got[2]:-}')" \
  '[ "$(realpath -m "${got[2]:-x}")" = "$(realpath "$M/share/candela/ocio/config.ocio")" ]'

# The same program as C++: the umbrella gives the declarations C linkage.
cp "$tmp/version.c" "$tmp/version.cpp"
"$CXX" $san "$tmp/version.cpp" $(PKG_CONFIG_PATH="$L/pkgconfig" pkg-config --cflags --libs candela) -o "$tmp/version_cpp"; st=$?
check "a C++ program links against libcandela" '[ $st -eq 0 ]'
check "the C++ program reads the same version" '[ "$(LD_LIBRARY_PATH="$L" "$tmp/version_cpp" | head -n 1)" = "${got[0]:-}" ]'

# A point light 2 m above a 2 x 2 rect grid: at each of its points
# (+-0.5, +-0.5, 0), E = I cos(theta) / d^2 = 1000 x 2 / 4.5^1.5 lx.
cat > "$tmp/scene.json" <<'JSON'
{"version": 1,
 "luminaires": [{"type": "point", "position": [0, 0, 2], "intensity_cd": 1000}],
 "grids": [{"name": "floor", "type": "rect", "origin": [-1, -1, 0], "u": [2, 0, 0], "v": [0, 2, 0], "nu": 2, "nv": 2}]}
JSON
(cd "$tmp" && "$M/bin/candela" solve scene.json -o out --quiet > solve.log 2>&1); st=$?
[ $st -eq 0 ] || cat "$tmp/solve.log"
check "the moved candela solves" '[ $st -eq 0 ]'
check "the moved candela writes the false-colour map through its OCIO config" '[ -s "$tmp/out/floor.png" ]'
e=$(awk -F, 'NR == 2 {print $7}' "$tmp/out/floor.csv" 2>/dev/null)
exact=$(awk 'BEGIN { printf "%.12f", 2000 / (4.5 ^ 1.5) }')
check "E at a grid point = 2000 / 4.5^1.5 = $exact lx (got '$e')" \
  'awk -v a="$e" -v b="$exact" "BEGIN { d = a - b; exit !(d < 1e-9 * b && -d < 1e-9 * b) }"'

if [ -e "${CANDELA_CONFIGURED_DATA_DIR:-/nonexistent}/ocio/config.ocio" ]; then
  echo "skipped the negative control: the configured prefix has an installed config"
else
  mv "$M/share/candela/ocio" "$M/share/candela/ocio.away"
  (cd "$tmp" && "$M/bin/candela" solve scene.json -o out2 --quiet > solve2.log 2>&1); st=$?
  check "without the moved copy's config the maps fail (exit $st)" '[ $st -ne 0 ] && [ ! -s "$tmp/out2/floor.png" ]'
fi
exit $fail
