#!/usr/bin/env bash
# A solve shared by MPI ranks that cannot go on ends every rank cleanly:
#  - a luminaire file missing for every rank: exit 1, the message (the file
#    and the JSON path) once, no output folder;
#  - missing for one rank only (mpiexec's MPMD form gives rank 1 a copy of
#    the scene whose folder lacks the file, as a node that cannot see it):
#    exit 1, the message naming rank 1, no output folder;
#  - ranks holding different scenes (rank 1's panel brighter): exit 1;
#  - a cache file one rank reads and another cannot see: exit 1;
#  - a rank killed part-way (SIGKILL): the job ends with a failure and
#    leaves no file in the output folder;
# and --cache under ranks: written once, by rank 0, then read by every
# rank with the same bytes out.
# ctest-labels: mpi
# ctest-timeout: 240
source "$(dirname "$0")/harness.sh"
source "$(dirname "$0")/mpi_env.sh"
mpi() { "$CANDELA_MPIEXEC" "$@"; }
cd "$tmp" || exit 1

# The path-traced room of test_solve_ranks.sh, its luminaire file beside it.
mkdir seen unseen
cp "$CANDELA_SOURCE_DIR/data/office/downlight.ies" seen/
sed 's|../../../data/office/downlight.ies|downlight.ies|' "$CANDELA_SOURCE_DIR/tests/data/scene/ranks_paths.json" \
  > seen/scene.json
cp seen/scene.json unseen/scene.json

mpi -np 2 "$CANDELA" solve unseen/scene.json -o out.all --threads 1 > all.txt 2>&1; st=$?
check "missing everywhere: exit 1" '[ $st -eq 1 ]'
check "missing everywhere: the message names the file and the JSON path, once" \
  '[ "$(grep -c "candela solve: unseen/scene.json: luminaires\[0\].file: unseen/downlight.ies: cannot open" all.txt)" = 1 ]'
check "missing everywhere: no rank named (every rank failed)" '! grep -q "candela solve: rank" all.txt'
check "missing everywhere: no output folder" '[ ! -e out.all ]'

mpi -np 1 "$CANDELA" solve seen/scene.json -o out.one --threads 1 : \
    -np 1 "$CANDELA" solve unseen/scene.json -o out.one --threads 1 > one.txt 2>&1; st=$?
check "missing on rank 1: exit 1" '[ $st -eq 1 ]'
check "missing on rank 1: the message names the rank and the file" \
  'grep -q "candela solve: rank 1 of 2: unseen/scene.json: luminaires\[0\].file: unseen/downlight.ies" one.txt'
check "missing on rank 1: no output folder" '[ ! -e out.one ]'

cp seen/downlight.ies unseen/
sed -i 's/"luminance_cd_m2": 2000/"luminance_cd_m2": 2500/' unseen/scene.json
mpi -np 1 "$CANDELA" solve seen/scene.json -o out.differ --threads 1 : \
    -np 1 "$CANDELA" solve unseen/scene.json -o out.differ --threads 1 > differ.txt 2>&1; st=$?
check "different scenes: exit 1" '[ $st -eq 1 ]'
check "different scenes: said so" 'grep -q "the 2 ranks do not hold the same scene" differ.txt'
check "different scenes: no output folder" '[ ! -e out.differ ]'

# --cache: rank 0 writes it once; a second run reads it on every rank.
cube="$CANDELA_SOURCE_DIR/tests/data/scene/ranks_cube.json"
"$CANDELA" solve "$cube" -o cube.alone --threads 1 --quiet > /dev/null 2>&1
mpi -np 2 "$CANDELA" solve "$cube" -o cube.write --threads 1 --cache c.bin > write.txt 2>&1; st=$?
check "cache: first run on 2 ranks: exit 0, the file written" '[ $st -eq 0 ] && [ -s c.bin ]'
check "cache: no temporary file left" '[ -z "$(find . -name "*.tmp.*")" ]'
mpi -np 3 "$CANDELA" solve "$cube" -o cube.read --threads 1 --cache c.bin > read.txt 2>&1; st=$?
check "cache: second run on 3 ranks: exit 0, records read" \
  '[ $st -eq 0 ] && grep -q "records read from it, none gathered" read.txt'
check "cache: the same CSV bytes as one process without it" \
  'cmp -s cube.alone/floor.csv cube.read/floor.csv && cmp -s cube.alone/wall.csv cube.read/wall.csv'
mpi -np 1 "$CANDELA" solve "$cube" -o cube.half --threads 1 --cache c.bin : \
    -np 1 "$CANDELA" solve "$cube" -o cube.half --threads 1 --cache elsewhere.bin > half.txt 2>&1; st=$?
check "cache seen by rank 0 only: exit 1, said so" \
  '[ $st -eq 1 ] && grep -q "read by some ranks and missing on others" half.txt'
check "cache seen by rank 0 only: no output folder, no file made" '[ ! -e cube.half ] && [ ! -e elsewhere.bin ]'

# A rank that dies: rank 1 killed two seconds into a solve of about ten.
dense="$CANDELA_SOURCE_DIR/data/bench/cube_dense.json"
mpi -np 1 "$CANDELA" solve "$dense" -o out.killed --threads 1 --quiet : \
    -np 1 timeout -s KILL 2 "$CANDELA" solve "$dense" -o out.killed --threads 1 --quiet > killed.txt 2>&1; st=$?
check "a rank killed: the job fails" '[ $st -ne 0 ]'
check "a rank killed: no file in the output folder" '[ -z "$(find out.killed -type f 2> /dev/null)" ]'
exit $fail
