#!/usr/bin/env bash
# Candela from Python: `cmake --install` into a temporary prefix, then the
# pytest files of tests/python/ (but the corpus's, test_python_corpus.sh)
# with that prefix's site folder on PYTHONPATH and nothing else pointing at
# the library: the installed package must find libcandela.so.N beside it.
# ctest-labels: slow
# ctest-timeout: 600
set -u
: "${CANDELA_BINARY_DIR:?}" "${CMAKE_COMMAND:?}" "${CANDELA_PYTHON_DIR:?}"
here=$(cd "$(dirname "$0")" && pwd)
source "$here/python_env.sh"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
if ! "$CMAKE_COMMAND" --install "$CANDELA_BINARY_DIR" --prefix "$tmp/prefix" >"$tmp/install.log" 2>&1; then
  cat "$tmp/install.log"
  echo "FAIL: cmake --install --prefix $tmp/prefix"
  exit 1
fi
export CANDELA_TEST_PREFIX=$tmp/prefix
export PYTHONPATH=$tmp/prefix/$CANDELA_PYTHON_DIR
unset LD_LIBRARY_PATH
run_pytest "$here" --ignore="$here/test_corpus.py"
