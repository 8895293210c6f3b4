#!/usr/bin/env bash
# The command line: --version, --help everywhere, exit statuses for usage errors.
set -u
: "${CANDELA:?}" "${CANDELA_SOURCE_DIR:?}" "${CANDELA_BINARY_DIR:?}"
fail=0
check() { if ! eval "$2"; then echo "FAIL: $1"; fail=1; else echo "ok: $1"; fi; }

out=$("$CANDELA" --version); st=$?
check "--version exits 0" '[ $st -eq 0 ]'
check "--version prints the version" '[[ "$out" =~ ^candela\ [0-9]+\.[0-9]+\.[0-9]+$ ]]'

out=$("$CANDELA" --help); st=$?
check "--help exits 0" '[ $st -eq 0 ]'
for c in info convert solve report bench; do
  check "--help lists $c" '[[ "$out" == *"  $c "* ]]'
  sub=$("$CANDELA" "$c" --help); st=$?
  check "$c --help exits 0" '[ $st -eq 0 ]'
  check "$c --help shows usage" '[[ "$sub" == "usage: candela $c"* ]]'
  err=$("$CANDELA" "$c" 2>&1 >/dev/null); st=$?
  check "$c without arguments is a usage error (2)" '[ $st -eq 2 ]'
  check "$c without arguments says why" '[ -n "$err" ]'
done

# Every subcommand is built: none claims otherwise.
for c in info convert solve bench report; do
  err=$("$CANDELA" "$c" 2>&1 >/dev/null)
  check "$c is built" '[[ "$err" != *"not built yet"* ]]'
done

out=$("$CANDELA" help solve); st=$?
check "help solve exits 0 with the solve usage" '[ $st -eq 0 ] && [[ "$out" == "usage: candela solve"* ]]'
err=$("$CANDELA" help frobnicate 2>&1 >/dev/null); st=$?
check "help for an unknown command is a usage error naming it" '[ $st -eq 2 ] && [[ "$err" == *frobnicate* ]]'

"$CANDELA" >/dev/null 2>&1; st=$?
check "no command is a usage error" '[ $st -eq 2 ]'
err=$("$CANDELA" frobnicate 2>&1); st=$?
check "unknown command is a usage error" '[ $st -eq 2 ]'
check "unknown command is named" '[[ "$err" == *frobnicate* ]]'
exit $fail
