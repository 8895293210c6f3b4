#!/usr/bin/env bash
# bench_annual_ranks.sh - candela annual shared by 2 MPI ranks against one process.
#
#   tools/bench/bench_annual_ranks.sh [SCENE.json] [REPEATS]
#
# Runs `candela annual` of SCENE (default: data/bench/annual_office.json, a
# 6 x 4 m office glazed to the south, 384 points at draft) under the
# synthetic weather year of tests/tools/annual_check.py (Perez skies, MF 1),
# REPEATS times (default 3) alone with one thread and under mpirun with 2
# ranks of one thread each, alternating. Checks that every file but
# summary.json has the same bytes, then prints from each run's summary.json:
# the study's seconds (wall, the process's start and MPI's set-up
# excluded), best and median, and their ratio (the wall-clock speed-up);
# each rank's CPU seconds computing its share (its worker threads' CPU
# time: the split of the skies, points and direct sun, whatever else the
# machine runs) and in all, its bytes received and peak memory; and the
# speed-up an idle machine would give, projected from CPU times (what rank
# 0 does alone, the hours, metrics and files, plus the larger share). The
# candela command is build/candela unless CANDELA says otherwise. Ratios,
# not limits: on a machine other jobs load, the wall-clock speed-up says
# little.
set -eu
source "$(dirname "$0")/ranks_pairs.sh"
scene=${1:-$root/data/bench/annual_office.json}
repeats=${2:-3}
python3 "$root/tests/tools/annual_check.py" epw "$tmp/year.epw"
load_before=$(uptime)

ranks_pairs "$repeats" annual "$scene" --weather "$tmp/year.epw"
ranks_same_bytes bench_annual_ranks

python3 - "$tmp" "$repeats" "$scene" "$load_before" "$(uptime)" <<'PY'
import json, statistics, sys
tmp, n, scene, before, after = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4], sys.argv[5]
def summary(name):
    return json.load(open(f"{tmp}/{name}/summary.json"))
alone = [summary(f"alone{k}") for k in range(1, n + 1)]
two = [summary(f"two{k}") for k in range(1, n + 1)]
med = statistics.median
wall = lambda s: s["ranks"]["seconds"][0]
wa, wt = [wall(s) for s in alone], [wall(s) for s in two]
points = sum(g["count"] for g in alone[0]["grids"].values())
print(f"scene {scene}: {points} points, {n} repeats; every file but summary.json the same bytes on 1 and 2 ranks")
print(f"machine before: {before.strip()}\nmachine after:  {after.strip()}")
ca = [s["ranks"]["cpu_seconds"][0] for s in alone]
wca = [s["ranks"]["work_cpu_seconds"][0] for s in alone]
print(f"alone, 1 thread:    seconds best {min(wa):.2f} median {med(wa):.2f}; CPU s {med(ca):.2f}, of which "
      f"the shared steps {med(wca):.2f}; steps {alone[0]['annual']['seconds']}")
print(f"2 ranks x 1 thread: seconds best {min(wt):.2f} median {med(wt):.2f}")
print(f"wall-clock speed-up (alone / 2 ranks): best {min(wa) / min(wt):.2f}  median {med(wa) / med(wt):.2f}")
for k, s in enumerate(two, 1):
    r = s["ranks"]
    print(f"  run {k}: per rank: work CPU s {[round(x, 2) for x in r['work_cpu_seconds']]}  CPU s "
          f"{[round(x, 2) for x in r['cpu_seconds']]}  bytes received {r['bytes_received']}  peak RSS MB "
          f"{[round(x / 1e6, 1) for x in r['peak_rss_bytes']]}")
# An idle machine: what rank 0 does alone (the alone run's CPU outside the
# shared steps) plus the larger rank's share of them.
serial = med(c - w for c, w in zip(ca, wca))
share = med(max(s["ranks"]["work_cpu_seconds"]) for s in two)
split = med(max(s["ranks"]["work_cpu_seconds"]) / sum(s["ranks"]["work_cpu_seconds"]) for s in two)
print(f"work split: the larger rank did {100 * split:.1f} % of the shared CPU; projected speed-up on an idle machine "
      f"(alone CPU / (rank 0's own CPU + larger share)): {med(ca) / (serial + share):.2f}")
PY
