# harness.sh - sourced by tests/tools/test_*.sh: strict variables, the
# check NAME CONDITION helper (prints ok/FAIL and sets fail=1), and a
# temporary folder $tmp removed on exit. Needs CANDELA and
# CANDELA_SOURCE_DIR in the environment (tests/CMakeLists.txt sets them).
set -u
: "${CANDELA:?}" "${CANDELA_SOURCE_DIR:?}"
fail=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
