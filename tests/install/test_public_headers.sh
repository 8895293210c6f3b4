#!/usr/bin/env bash
# Each installed public header compiles on its own from the install tree
# (C11, warnings as errors), so none includes a header that is not
# installed; the umbrella also compiles as C++; every public function has a
# comment and every header says what is thread-safe (cdl_apidoc check);
# the API reference lists every public function. Negative controls: an
# internal header does not compile against the install tree, and the
# documentation check fails on an undocumented function.
# ctest-timeout: 120
set -u
: "${CANDELA_TEST_PREFIX:?}" "${CC:?}" "${CXX:?}" "${CANDELA_APIDOC:?}" "${CANDELA_SOURCE_DIR:?}"
fail=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi; }
inc=$CANDELA_TEST_PREFIX/include
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

# compiles NAME: a translation unit with only #include NAME, from the install tree.
compiles() {
  printf '#include "%s"\nint candela_header_check(void);\nint candela_header_check(void) { return 0; }\n' "$1" > "$tmp/alone.c"
  "$CC" -std=c11 -Wall -Wextra -Wpedantic -Werror -fsyntax-only -I"$inc/candela" "$tmp/alone.c" 2> "$tmp/alone.err"
}
# compiles_cxx NAME: the same as C++17, in an extern "C" block as candela.h puts it.
compiles_cxx() {
  printf '#include <cmath>\n#include <cstddef>\n#include <cstdint>\nextern "C" {\n#include "%s"\n}\nint candela_header_check();\nint candela_header_check() { return 0; }\n' "$1" > "$tmp/alone.cpp"
  "$CXX" -std=c++17 -Wall -Wextra -Wpedantic -Werror -fsyntax-only -I"$inc/candela" "$tmp/alone.cpp" 2> "$tmp/alone.err"
}
count=0
while IFS= read -r h; do
  count=$((count + 1))
  compiles "$h"; st=$?
  [ $st -eq 0 ] || cat "$tmp/alone.err"
  check "$h compiles alone from the install tree" '[ $st -eq 0 ]'
  compiles_cxx "$h"; st=$?
  [ $st -eq 0 ] || cat "$tmp/alone.err"
  check "$h compiles alone as C++17 (-Wpedantic)" '[ $st -eq 0 ]'
done < <(cd "$inc/candela" && find . -name '*.h' | sed 's|^\./||' | sort)
check "headers found ($count)" '[ $count -ge 10 ]'

printf '#include <candela/candela.h>\nint main(void) { return cdl_abi_version() > 0 ? 0 : 1; }\n' > "$tmp/umbrella.c"
"$CC" -std=c11 -Wall -Wextra -Wpedantic -Werror -fsyntax-only -I"$inc" -I"$inc/candela" "$tmp/umbrella.c"; st=$?
check "<candela/candela.h> compiles with the pkg-config include flags" '[ $st -eq 0 ]'
cp "$tmp/umbrella.c" "$tmp/umbrella.cpp"
"$CXX" -std=c++17 -Wall -Wextra -Werror -fsyntax-only -I"$inc" -I"$inc/candela" "$tmp/umbrella.cpp"; st=$?
check "<candela/candela.h> compiles as C++17" '[ $st -eq 0 ]'
# The options' INIT macros are designated initializers in declaration
# order: valid C++20.
cat > "$tmp/init.cpp" <<'CPP'
#include <candela/candela.h>
int main()
{
    cdl_solve_options solve = CDL_SOLVE_OPTIONS_INIT;
    cdl_solution_write_options write = CDL_SOLUTION_WRITE_OPTIONS_INIT;
    cdl_grid_summary summary = CDL_GRID_SUMMARY_INIT;
    cdl_solution_info info = CDL_SOLUTION_INFO_INIT;
    return solve.size == sizeof solve && write.size == sizeof write && summary.size == sizeof summary &&
                   info.size == sizeof info
               ? 0
               : 1;
}
CPP
"$CXX" -std=c++20 -Wall -Wextra -Wpedantic -Werror -fsyntax-only -I"$inc" -I"$inc/candela" "$tmp/init.cpp"; st=$?
check "the options' INIT macros compile as C++20 (-Wpedantic)" '[ $st -eq 0 ]'

# Negative control: a header that is not installed cannot be reached.
printf '#include "lights/photometry/photometry_internal.h"\n' > "$tmp/internal.c"
"$CC" -std=c11 -fsyntax-only -I"$inc/candela" "$tmp/internal.c" 2>/dev/null; st=$?
check "an internal header does not compile against the install tree" '[ $st -ne 0 ]'

"$CANDELA_APIDOC" check --root "$inc/candela" "$inc/candela/candela.h"; st=$?
check "every public function documented, every header says what is thread-safe" '[ $st -eq 0 ]'
# The API reference (the doc target's program) has an entry for every public function.
"$CANDELA_APIDOC" html --root "$inc/candela" --out "$tmp/api" "$inc/candela/candela.h"; st=$?
check "the API reference is made" '[ $st -eq 0 ] && [ -s "$tmp/api/index.html" ]'
unlisted=""
for f in $("$CANDELA_APIDOC" symbols --root "$inc/candela" "$inc/candela/candela.h"); do
  grep -q "id=\"$f\"" "$tmp"/api/*.html || unlisted="$unlisted $f"
done
check "every public function has its entry in the API reference" '[ -z "$unlisted" ]'
[ -z "$unlisted" ] || echo "missing:$unlisted"

# Negative control: the same check on a copy with one comment removed.
cp -r "$inc" "$tmp/copy"
sed -i 's|^/\* Free a photometry (NULL is fine); nothing may use it afterwards. \*/$|int cdl_undocumented_probe(void);|' "$tmp/copy/candela/lights/photometry/photometry.h"
out=$("$CANDELA_APIDOC" check --root "$tmp/copy/candela" "$tmp/copy/candela/candela.h" 2>&1); st=$?
check "the documentation check names an undocumented function" '[ $st -ne 0 ] && [[ "$out" == *cdl_undocumented_probe* ]]'
exit $fail
