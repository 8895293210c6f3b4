#!/usr/bin/env bash
# The ABI version moves when a public type changes: the fingerprint of the
# installed public types (every struct, enum and typedef, macros expanded,
# spacing normalised: `cdl_apidoc types`) must be the one recorded in
# cmake/candela_abi.txt for the library's ABI version (its SONAME's N), and
# each version is recorded once. Controls: a comment changed keeps the
# fingerprint, a field added to a public struct changes it.
# ctest-timeout: 60
set -u
: "${CANDELA_TEST_PREFIX:?}" "${CANDELA_SOURCE_DIR:?}" "${CC:?}" "${CANDELA_APIDOC:?}" "${CANDELA_ABI_VERSION:?}"
fail=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi; }
history=$CANDELA_SOURCE_DIR/cmake/candela_abi.txt
abi=$CANDELA_ABI_VERSION
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# fingerprint INCLUDE-DIR: the SHA-256 of the public types under it.
fingerprint() {
  "$CC" -E -I"$1/candela" "$1/candela/candela.h" | "$CANDELA_APIDOC" types --root "$1/candela" "$1/candela/candela.h" \
    > "$tmp/types.txt" || return 1
  sha256sum < "$tmp/types.txt" | cut -d' ' -f1
}
current=$(fingerprint "$CANDELA_TEST_PREFIX/include"); st=$?
check "the public types are read ($(wc -l < "$tmp/types.txt") definitions)" '[ $st -eq 0 ] && [ "$(wc -l < "$tmp/types.txt")" -ge 40 ]'

versions=$(grep -E '^[0-9]+ ' "$history" | cut -d' ' -f1)
check "each ABI version is recorded once, in increasing order" \
  '[ "$versions" = "$(echo "$versions" | sort -n -u)" ]'
recorded=$(awk -v n="$abi" '$1 == n {print $2}' "$history")
if [ -z "$recorded" ]; then
  echo "ABI $abi is not recorded in cmake/candela_abi.txt: cmake --build BUILD --target abi_record"
elif [ "$recorded" != "$current" ]; then
  echo "The public types changed since ABI $abi was recorded. Raise CANDELA_ABI_VERSION in CMakeLists.txt"
  echo "to $((abi + 1)) and run: cmake --build BUILD --target abi_record"
fi
check "the public types are those recorded for ABI $abi" '[ -n "$recorded" ] && [ "$recorded" = "$current" ]'
latest=$(echo "$versions" | tail -n 1)
check "ABI $abi is the latest recorded ($latest)" '[ "$latest" = "$abi" ]'

# Controls on a copy of the headers.
cp -r "$CANDELA_TEST_PREFIX/include" "$tmp/copy"
sed -i 's|/\* 1: warnings become errors \*/|/* 1: warnings are errors (reworded) */|' "$tmp/copy/candela/lights/photometry/photometry.h"
check "control: the copy's comment was changed" '! cmp -s "$tmp/copy/candela/lights/photometry/photometry.h" "$CANDELA_TEST_PREFIX/include/candela/lights/photometry/photometry.h"'
check "control: a comment changed keeps the fingerprint" '[ "$(fingerprint "$tmp/copy")" = "$current" ]'
sed -i 's|    int no_external_files;|    int no_external_files;\n    int added_field;|' "$tmp/copy/candela/lights/photometry/photometry.h"
check "control: a field added to a public struct changes it" '[ "$(fingerprint "$tmp/copy")" != "$current" ]'
exit $fail
