#!/usr/bin/env bash
# candela annual shared by MPI ranks gives the bytes one process gives, and
# ends every rank when one cannot go on. A window room of two grids (a desk
# and a wall facing the window) under the synthetic weather year of
# annual_check.py (light on one day in five), at draft:
#  - --sky perez alone (one thread), then under mpiexec with 1, 2 and 3
#    ranks of one thread and 2 ranks of 2 threads, and 3 ranks from a
#    hostfile listing localhost with 3 slots (what a hostfile of many
#    machines does, on one): every file identical (cmp: the CSVs, hourly
#    and sun files, maps, annual.csv), summary.json but for the keys that
#    say how the run went (annual.seconds, ranks, and the threads it was
#    run with, annual.coefficients.threads);
#  - --sky cie_overcast (one coefficient a point) alone and on 2 ranks;
#  - summary.json's "ranks": count, threads, seconds, bytes (rank 0 received
#    the others' points and hours, they nothing) and memory per rank; rank 0
#    alone prints, naming the ranks;
#  - a weather file rank 1 cannot read (each rank started by a wrapper in a
#    folder of its own, by OMPI_COMM_WORLD_RANK, rank 1's without the file,
#    as a machine that does not see it): exit 1, the message naming rank 1
#    and the file, once; no output folder;
#  - rank 1 killed (SIGKILL) a second into a study: the job fails, no file
#    in the output folder.
# ctest-labels: mpi;slow
# ctest-timeout: 600
source "$(dirname "$0")/harness.sh"
source "$(dirname "$0")/mpi_env.sh"
py="$CANDELA_SOURCE_DIR/tests/tools/annual_check.py"
cd "$tmp" || exit 1
python3 "$py" epw year.epw
# Light on one day in five (the others' irradiances and illuminances,
# fields 14-19, set to 0): a fifth of the skies to make, every kind of
# hour still there.
python3 - year.epw w.epw <<'PY'
import sys
lines = open(sys.argv[1]).read().splitlines()
out = lines[:8]
for k, line in enumerate(lines[8:]):
    f = line.split(",")
    if (k // 24) % 5:
        f[13:19] = ["0"] * 6
    out.append(",".join(f))
open(sys.argv[2], "w").write("\n".join(out) + "\n")
PY

cat > room.json <<'EOF'
{"version": 1, "surfaces": [{"type": "box", "min": [0,0,0], "max": [3,4,2.8], "inward": true,
  "reflectance": {"floor": 0.25, "walls": 0.55, "ceiling": 0.75}, "open": ["-y"]},
  {"type": "polygon", "vertices": [[0,0,0],[3,0,0],[3,0,2.8],[0,0,2.8]],
   "holes": [[[0.7,0,0.9],[2.3,0,0.9],[2.3,0,2.1],[0.7,0,2.1]]], "reflectance": 0.4}],
 "grids": [{"name": "desk", "type": "rect", "origin": [0.2,0.3,0.8], "u": [2.6,0,0], "v": [0,3.4,0], "nu": 3, "nv": 5},
           {"name": "wall", "type": "rect", "origin": [0.5,3.9,0.6], "u": [2,0,0], "v": [0,0,1.6], "nu": 3, "nv": 2}],
 "solver": {"quality": "draft", "seed": 2}}
EOF

# summary.json without what says how the run went, one key a line.
strip_summary() {
  python3 -c 'import json, sys
d = json.load(open(sys.argv[1]))
d.pop("ranks", None)
d["annual"].pop("seconds", None)
d["annual"]["coefficients"].pop("threads", None)
print(json.dumps(d, indent=1, sort_keys=True))' "$1"
}
# same_outputs REF OUT: every file of REF in OUT with the same bytes (summary.json as above), and no other.
same_outputs() {
  local f rel bad=0
  [ "$(cd "$1" && find . -type f | sort)" = "$(cd "$2" && find . -type f | sort)" ] || { echo "  files differ"; return 1; }
  while IFS= read -r f; do
    rel=${f#"$1"/}
    if [ "$rel" = summary.json ]; then
      cmp -s <(strip_summary "$f") <(strip_summary "$2/$rel") || { echo "  differs: $rel"; bad=1; }
    else
      cmp -s "$f" "$2/$rel" || { echo "  differs: $rel"; bad=1; }
    fi
  done < <(find "$1" -type f | sort)
  return $bad
}
annual() { "$CANDELA" annual room.json --weather w.epw --quiet "$@"; }
mpi_annual() { local n=$1; shift; "$CANDELA_MPIEXEC" -np "$n" "$CANDELA" annual room.json --weather w.epw --quiet "$@"; }

annual -o alone --threads 1 > alone.txt 2>&1; st=$?
check "perez: alone: exit 0" '[ $st -eq 0 ]' || cat alone.txt
check "perez: alone: both grids' files written" \
  '[ -s alone/desk.hourly.bin ] && [ -s alone/wall.sun.bin ] && [ -s alone/wall_DA300.png ]'
for n in 1 2 3; do
  mpi_annual $n -o np$n --threads 1 > np$n.txt 2>&1; st=$?
  check "perez: $n rank(s): exit 0" '[ $st -eq 0 ]' || cat np$n.txt
  check "perez: $n rank(s): the same bytes as alone" 'same_outputs alone np$n'
done
mpi_annual 2 -o np2t2 --threads 2 > np2t2.txt 2>&1; st=$?
check "perez: 2 ranks x 2 threads: exit 0" '[ $st -eq 0 ]' || cat np2t2.txt
check "perez: 2 ranks x 2 threads: the same bytes as alone" 'same_outputs alone np2t2'

# A hostfile: the machines and their slots (here this one, 3 slots); no -np:
# a rank a slot.
echo "localhost slots=3" > hosts
"$CANDELA_MPIEXEC" --hostfile hosts "$CANDELA" annual room.json --weather w.epw --quiet -o hostfile --threads 1 \
  > hostfile.txt 2>&1; st=$?
check "hostfile (localhost, 3 slots): exit 0" '[ $st -eq 0 ]' || cat hostfile.txt
check "hostfile: 3 ranks ran" 'grep -q ", 3 ranks; results in hostfile" hostfile.txt'
check "hostfile: the same bytes as alone" 'same_outputs alone hostfile'

annual -o ov.alone --sky cie_overcast --threads 1 > ov.alone.txt 2>&1; st=$?
check "cie_overcast: alone: exit 0" '[ $st -eq 0 ]' || cat ov.alone.txt
mpi_annual 2 -o ov.np2 --sky cie_overcast --threads 1 > ov.np2.txt 2>&1; st=$?
check "cie_overcast: 2 ranks: exit 0, the same bytes as alone" '[ $st -eq 0 ] && same_outputs ov.alone ov.np2'

# What summary.json says of the ranks.
ranks_report() {
  python3 - "$1" "$2" <<'PY'
import json, sys
r = json.load(open(sys.argv[1]))["ranks"]
alone = json.load(open(sys.argv[2]))["ranks"]
ok = r["count"] == 3 and r["threads"] == [1, 1, 1]
ok = ok and all(len(r[k]) == 3 for k in ("seconds", "work_seconds", "work_cpu_seconds", "cpu_seconds", "bytes_received",
                                          "peak_rss_bytes"))
ok = ok and all(s > 0 for s in r["seconds"]) and all(b > 1 << 20 for b in r["peak_rss_bytes"])
# rank 0 received the others' skies, coefficients and direct sun; they received nothing
ok = ok and r["bytes_received"][0] > 0 and r["bytes_received"][1:] == [0, 0]
ok = ok and alone["count"] == 1 and alone["bytes_received"] == [0]
sys.exit(0 if ok else 1)
PY
}
check "summary.json: ranks' count, threads, seconds, bytes and memory" 'ranks_report np3/summary.json alone/summary.json'
check "stdout: rank 0 alone prints the results, naming the ranks" \
  '[ "$(grep -c "^desk " np3.txt)" = 1 ] && grep -q ", 3 ranks; results in np3" np3.txt'

# A weather file rank 1 cannot read: each rank starts in its own folder.
mkdir r0 r1
cp room.json w.epw r0/
cp room.json r1/
cat > per_rank.sh <<EOF
#!/bin/sh
cd "$tmp/r\$OMPI_COMM_WORLD_RANK" && exec "$CANDELA" annual room.json --weather w.epw -o "$tmp/out.fail" --threads 1 --quiet
EOF
chmod +x per_rank.sh
"$CANDELA_MPIEXEC" -np 2 ./per_rank.sh > fail.txt 2>&1; st=$?
check "weather file unreadable on rank 1: exit 1 (got $st)" '[ $st -eq 1 ]'
check "weather file unreadable on rank 1: the message names the rank and the file, once" \
  '[ "$(grep -c "^candela annual: rank 1 of 2: w.epw: " fail.txt)" = 1 ]' || cat fail.txt
check "weather file unreadable on rank 1: no output folder" '[ ! -e out.fail ]'

# Rank 1 killed a second into a study of tens of seconds (the whole year
# at --mf 2: 577 patches a sky).
"$CANDELA_MPIEXEC" -np 1 "$CANDELA" annual room.json --weather year.epw --mf 2 -o out.killed --threads 1 --quiet : \
  -np 1 timeout -s KILL 1 "$CANDELA" annual room.json --weather year.epw --mf 2 -o out.killed --threads 1 --quiet \
  > killed.txt 2>&1; st=$?
check "a rank killed: the job fails" '[ $st -ne 0 ]'
check "a rank killed: no file in the output folder" '[ -z "$(find out.killed -type f 2> /dev/null)" ]'
exit $fail
