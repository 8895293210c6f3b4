#!/usr/bin/env bash
# The README's MPI program (illuminance_mpi.c, taken from README.md as it is
# printed there) built outside the source tree against the installed
# prefix with mpicc and pkg-config, then run by mpiexec on 2 and 3 ranks:
# rank 0 alone prints, and its numbers are the closed forms of the
# README's other illuminance program, E = I cos(theta) / d^2 under a
# 1000 cd point light 2 m up: 250 lx below it, 128 lx 1.5 m aside, with
# the count of ranks the solution says shared it. The program needs no MPI
# in libcandela: the library's dependencies do not include libmpi.
# ctest-labels: mpi
# ctest-timeout: 180
set -u
: "${CANDELA_TEST_PREFIX:?}" "${CANDELA_INSTALL_LIBDIR:?}" "${CANDELA_SOURCE_DIR:?}" "${CC:?}"
source "$CANDELA_SOURCE_DIR/tests/tools/mpi_env.sh"
command -v mpicc > /dev/null || { echo "no mpicc: skipped"; exit 77; }
san=${CANDELA_SANITIZE_FLAGS:-}
fail=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi; }
L=$CANDELA_TEST_PREFIX/$CANDELA_INSTALL_LIBDIR
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

awk -v head="/* illuminance_mpi.c " '
  /^```/ { if (inside) { inside = 0; if (found) exit } else { inside = 1; first = 1 } ; next }
  inside && first { first = 0; if (index($0, head) == 1) found = 1 }
  inside && found { print }' "$CANDELA_SOURCE_DIR/README.md" > "$tmp/illuminance_mpi.c"
check "README holds illuminance_mpi.c" '[ -s "$tmp/illuminance_mpi.c" ]'

export PKG_CONFIG_PATH="$L/pkgconfig"
# shellcheck disable=SC2046
OMPI_CC="$CC" mpicc $san "$tmp/illuminance_mpi.c" $(pkg-config --cflags --libs candela) -o "$tmp/illuminance_mpi" \
  2> "$tmp/build.err"; st=$?
[ $st -eq 0 ] || cat "$tmp/build.err"
check "mpicc and pkg-config build it" '[ $st -eq 0 ]'
check "libcandela itself needs no MPI" '! objdump -p "$L/libcandela.so" | grep -q "NEEDED.*libmpi"'

# close A B: |A - B| <= 1e-9 |B|.
close() { awk -v a="$1" -v b="$2" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d <= 1e-9 * (b < 0 ? -b : b)) }'; }
for n in 2 3; do
  out=$(LD_LIBRARY_PATH="$L" "$CANDELA_MPIEXEC" -np $n "$tmp/illuminance_mpi" 2>&1); st=$?
  check "$n ranks: exit 0" '[ $st -eq 0 ]'
  below=$(echo "$out" | awk '$1 == "point" && $2 == "0:" {print $3}')
  aside=$(echo "$out" | awk '$1 == "point" && $2 == "1:" {print $3}')
  check "$n ranks: E below the light = 250 lx (got '$below')" 'close "$below" 250'
  check "$n ranks: E 1.5 m aside = 128 lx (got '$aside')" 'close "$aside" 128'
  check "$n ranks: printed by rank 0 alone, which says $n ranks shared it" \
    '[ "$(echo "$out" | grep -c "^point")" = 2 ] && [ "$(echo "$out" | grep -c "($n ranks)")" = 2 ]'
done
exit $fail
