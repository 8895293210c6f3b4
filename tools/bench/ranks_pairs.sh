# ranks_pairs.sh - sourced by the bench scripts that set one process
# against 2 MPI ranks (bench_ranks.sh, bench_annual_ranks.sh).
#
# Sets root, candela (build/candela unless CANDELA says otherwise), mpirun
# (MPIRUN, default mpirun, allowed to run as root and to oversubscribe) and
# tmp (a folder removed on exit), and defines:
#   ranks_pairs REPEATS SUBCOMMAND ARGS...: runs `candela SUBCOMMAND ARGS...`
#     REPEATS times alone with one thread (into $tmp/aloneK) and under
#     mpirun with 2 ranks of one thread each (into $tmp/twoK), alternating,
#     so that whatever else loads the machine falls on both alike;
#   ranks_same_bytes NAME: fails (naming the file) unless every output of
#     the first pair but summary.json has the same bytes on 1 and 2 ranks.
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
candela=${CANDELA:-$root/build/candela}
mpirun=${MPIRUN:-mpirun}
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

ranks_pairs() {
  local repeats=$1 command=$2
  shift 2
  for ((k = 1; k <= repeats; ++k)); do
    "$candela" "$command" "$@" -o "$tmp/alone$k" --threads 1 --quiet > /dev/null
    "$mpirun" -np 2 "$candela" "$command" "$@" -o "$tmp/two$k" --threads 1 --quiet > /dev/null
  done
}

ranks_same_bytes() {
  local f
  for f in "$tmp"/alone1/*; do
    [ "$(basename "$f")" = summary.json ] || cmp -s "$f" "$tmp/two1/$(basename "$f")" \
      || { echo "$1: $(basename "$f") differs between 1 and 2 ranks" >&2; exit 1; }
  done
}
