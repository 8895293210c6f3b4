#!/usr/bin/env bash
# cmake --install into a prefix of our own (the fixture the other install
# tests read): the shared library with its SONAME, the static archive, the
# public headers and nothing else under include/candela, the command, the
# OCIO config, candela.pc and the CMake package.
# ctest-timeout: 120
set -u
: "${CANDELA_TEST_PREFIX:?}" "${CANDELA_BINARY_DIR:?}" "${CANDELA_SOURCE_DIR:?}" "${CMAKE_COMMAND:?}"
: "${CANDELA_INSTALL_LIBDIR:?}" "${CANDELA_ABI_VERSION:?}" "${CANDELA_PROJECT_VERSION:?}"
fail=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi; }
P=$CANDELA_TEST_PREFIX
L=$P/$CANDELA_INSTALL_LIBDIR
abi=$CANDELA_ABI_VERSION
log=$(mktemp)
trap 'rm -f "$log"' EXIT

rm -rf "$P"
"$CMAKE_COMMAND" --install "$CANDELA_BINARY_DIR" --prefix "$P" >"$log" 2>&1; st=$?
[ $st -eq 0 ] || cat "$log"
check "cmake --install --prefix exits 0" '[ $st -eq 0 ]'

check "shared library libcandela.so.$abi.$CANDELA_PROJECT_VERSION" '[ -f "$L/libcandela.so.$abi.$CANDELA_PROJECT_VERSION" ]'
check "libcandela.so.$abi links to it" '[ "$(readlink "$L/libcandela.so.$abi")" = "libcandela.so.$abi.$CANDELA_PROJECT_VERSION" ]'
check "libcandela.so links to libcandela.so.$abi" '[ "$(readlink "$L/libcandela.so")" = "libcandela.so.$abi" ]'
soname=$(objdump -p "$L/libcandela.so" 2>/dev/null | awk '$1 == "SONAME" {print $2}')
check "SONAME carries the ABI version (libcandela.so.$abi, found '$soname')" '[ "$soname" = "libcandela.so.$abi" ]'
check "static archive" '[ -f "$L/libcandela.a" ]'
check "the candela command" '[ -x "$P/bin/candela" ]'
check "the OCIO config and its LUT" '[ -f "$P/share/candela/ocio/config.ocio" ] && [ -f "$P/share/candela/ocio/falsecolor.spi1d" ]'
check "candela.pc" '[ -f "$L/pkgconfig/candela.pc" ]'
check "candela-static.pc" '[ -f "$L/pkgconfig/candela-static.pc" ]'
for f in CandelaConfig.cmake CandelaConfigVersion.cmake CandelaTargets.cmake; do
  check "CMake package: $f" '[ -f "$L/cmake/Candela/$f" ]'
done

# The headers installed are the umbrella and exactly those it includes,
# and beside it the MPI glue (candela_mpi.h: header-only, it needs mpi.h,
# which the umbrella must not).
inc=$P/include/candela
check "umbrella candela/candela.h" '[ -f "$inc/candela.h" ]'
check "candela/candela_mpi.h" '[ -f "$inc/candela_mpi.h" ]'
installed=$(cd "$inc" && find . -type f | sed 's|^\./||' | grep -vx -e candela.h -e candela_mpi.h | sort)
declared=$(sed -n 's/^#include "\([^"]*\)".*/\1/p' "$CANDELA_SOURCE_DIR/include/candela/candela.h" | sort)
check "installed headers = the umbrella's includes" '[ "$installed" = "$declared" ]'
[ "$installed" = "$declared" ] || diff <(echo "$declared") <(echo "$installed")
check "no *_internal.h installed" '[ -z "$(find "$P/include" -name "*_internal.h")" ]'
check "only headers under include/" '[ -z "$(find "$P/include" -type f ! -name "*.h")" ]'

out=$("$P/bin/candela" --version 2>&1); st=$?
check "installed candela --version prints candela $CANDELA_PROJECT_VERSION (got '$out')" \
  '[ $st -eq 0 ] && [ "$out" = "candela $CANDELA_PROJECT_VERSION" ]'
exit $fail
