# mpi_env.sh - sourced by the tests labelled mpi: skipped (exit 77) in a
# build without MPI; Open MPI allowed to run as root (containers) and more
# ranks than cores (--oversubscribe); under AddressSanitizer, allocations
# unwound the slow way, so that what Open MPI leaks is traced through its
# own libraries (tests/lsan.supp) rather than stopping in the components it
# dlopens and unloads, which LeakSanitizer cannot name.
[ -n "${CANDELA_MPIEXEC:-}" ] || { echo "built without MPI (CANDELA_MPI off): skipped"; exit 77; }
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1
export ASAN_OPTIONS="${ASAN_OPTIONS:-}:fast_unwind_on_malloc=0"
