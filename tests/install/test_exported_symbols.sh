#!/usr/bin/env bash
# libcandela.so exports exactly the functions the installed public headers
# declare: `nm -D --defined-only` against the declarations the compiler
# itself lists (gcc -aux-info) for the installed umbrella, both ways: a
# symbol exported but declared in no public header fails, and so does a
# public function the library does not export. Negative control: the same
# comparison on libcandela.a, which holds the internal functions too, must
# find undeclared symbols.
# ctest-timeout: 60
set -u
: "${CANDELA_TEST_PREFIX:?}" "${CANDELA_INSTALL_LIBDIR:?}" "${CC:?}"
fail=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi; }
inc=$CANDELA_TEST_PREFIX/include
lib=$CANDELA_TEST_PREFIX/$CANDELA_INSTALL_LIBDIR
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

printf '#include <candela/candela.h>\n' > "$tmp/api.c"
if ! "$CC" -std=c11 -I"$inc" -I"$inc/candela" -aux-info "$tmp/aux.txt" -fsyntax-only "$tmp/api.c" 2>/dev/null; then
  echo "skipped: $CC cannot list declarations (-aux-info is GCC's)"
  exit 77
fi
# Lines read "/* FILE:LINE:XX */ extern TYPE NAME (ARGS);"; keep the
# installed headers' non-static functions.
grep -F "/* $inc/" "$tmp/aux.txt" | grep -v ' static ' |
  sed -E 's/^[^*]*\*\/ *//; s/ *\(.*$//; s/.*[ *]([A-Za-z_][A-Za-z0-9_]*)$/\1/' | sort -u > "$tmp/declared"
exported_from() { nm "$@" 2>/dev/null | awk 'NF >= 3 && $2 ~ /^[A-Z]$/ && $2 != "U" && $2 != "w" {print $3}' | sed 's/@.*//' | sort -u; }
exported_from -D --defined-only "$lib/libcandela.so" > "$tmp/exported"

declared=$(wc -l < "$tmp/declared")
check "public headers declare functions ($declared)" '[ "$declared" -ge 50 ]'
leaked=$(comm -23 "$tmp/exported" "$tmp/declared")
check "nothing exported that no public header declares" '[ -z "$leaked" ]'
[ -z "$leaked" ] || echo "exported but not public:" $leaked
missing=$(comm -13 "$tmp/exported" "$tmp/declared")
check "every public function exported" '[ -z "$missing" ]'
[ -z "$missing" ] || echo "public but not exported:" $missing
check "an internal function (cdl_pool_run) is not exported" '! grep -qx cdl_pool_run "$tmp/exported"'
check "cdl_version is exported" 'grep -qx cdl_version "$tmp/exported"'

# Negative control: the static archive's global functions include internal ones.
exported_from --defined-only "$lib/libcandela.a" > "$tmp/archive"
undeclared=$(comm -23 "$tmp/archive" "$tmp/declared" | wc -l)
check "the comparison finds undeclared symbols where they are ($undeclared in libcandela.a)" '[ "$undeclared" -gt 0 ]'
exit $fail
