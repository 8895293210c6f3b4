#!/usr/bin/env bash
# Candela from Python over the corpus of real photometric files
# (../shared/photometric): tests/python/test_corpus.py, with the package of
# the source tree and the library of the build tree. Skipped (77) only when
# the corpus is absent.
# ctest-labels: corpus;slow
# ctest-timeout: 300
set -u
: "${CANDELA_PHOTOMETRIC_DIR:?}" "${CANDELA_LIBRARY_BUILT:?}"
if [ ! -d "$CANDELA_PHOTOMETRIC_DIR" ]; then
  echo "skipped: no corpus at $CANDELA_PHOTOMETRIC_DIR"
  exit 77
fi
here=$(cd "$(dirname "$0")" && pwd)
source "$here/python_env.sh"
export CANDELA_LIBRARY=$CANDELA_LIBRARY_BUILT
export PYTHONPATH=$CANDELA_SOURCE_DIR/python
run_pytest "$here/test_corpus.py"
