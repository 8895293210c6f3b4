# Sourced by the Python tests' scripts: the interpreter, checked for NumPy
# and pytest; run_pytest ARGS... runs pytest from a scratch folder without
# writing bytecode or a cache into the source tree, with the sanitizers'
# runtimes loaded first when the library is built with them.
: "${CANDELA_PYTHON:?}" "${CANDELA_SOURCE_DIR:?}" "${CC:?}"
py=$CANDELA_PYTHON
if ! "$py" -c "import numpy, pytest" 2>/dev/null; then
  echo "FAIL: $py cannot import numpy and pytest (scripts/setup.sh installs python3-numpy and python3-pytest)"
  exit 1
fi
export PYTHONDONTWRITEBYTECODE=1
unset CANDELA_LIBRARY
if [ "${CANDELA_SANITIZE:-0}" = 1 ]; then
  # An instrumented libcandela needs the ASan and UBSan runtimes loaded
  # before it; Python's own allocations are not ours to leak-check.
  LD_PRELOAD="$("$CC" -print-file-name=libasan.so) $("$CC" -print-file-name=libubsan.so)"
  export LD_PRELOAD
  export ASAN_OPTIONS=detect_leaks=0
  # pytest captures each test's file descriptor 2, and a sanitizer's report
  # there would die with the process unseen: capture Python's sys.stderr
  # only, so that the report reaches the test's log.
  capture=--capture=sys
fi
run_pytest() {
  local scratch
  scratch=$(mktemp -d)
  (cd "$scratch" && "$py" -m pytest -p no:cacheprovider -q -rs --tb=short ${capture:-} "$@")
  local st=$?
  rm -rf "$scratch"
  return $st
}
