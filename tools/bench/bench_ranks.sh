#!/usr/bin/env bash
# bench_ranks.sh - a solve shared by MPI ranks against one process.
#
#   tools/bench/bench_ranks.sh [SCENE.json] [REPEATS]
#
# Solves SCENE (default: data/bench/cube_dense.json, the irradiance cache's
# dense cube, at its quality "normal") REPEATS times (default 3) alone with
# one thread and under mpirun with 2 ranks of one thread each, alternating,
# and once with "method": "direct" (the direct light alone); checks that
# every output but summary.json has the same bytes on 1 and 2 ranks. Prints, from
# each run's summary.json: the solve's seconds (wall, the process's start
# and MPI's set-up excluded) with the best and the median of the repeats and
# their ratio (the wall-clock speed-up), each rank's CPU seconds computing
# its share of the points (its worker threads' CPU time: the split,
# whatever else the machine runs) and in all, and its bytes received; the
# speed-up an idle machine would give, projected from CPU times (the serial
# CPU every rank repeats plus the larger share); and the constants
# docs/mpi-scaling.md's model takes (tools/bench/mpi_scaling_model.py): per
# point and per record CPU seconds, the serial CPU seconds, records, passes,
# points, the bytes a rank received. The candela command is build/candela
# unless CANDELA says otherwise. Ratios, not limits: on a machine other
# jobs load, the wall-clock speed-up says little.
set -eu
source "$(dirname "$0")/ranks_pairs.sh"
scene=${1:-$root/data/bench/cube_dense.json}
repeats=${2:-3}

ranks_pairs "$repeats" solve "$scene"
ranks_same_bytes bench_ranks
python3 - "$scene" "$tmp/direct.json" <<'PY'
import json, sys
scene = json.load(open(sys.argv[1]))
scene["solver"]["method"] = "direct"
json.dump(scene, open(sys.argv[2], "w"))
PY
(cd "$(dirname "$scene")" && "$candela" solve "$tmp/direct.json" -o "$tmp/direct" --threads 1 --quiet > /dev/null)

python3 - "$tmp" "$repeats" "$scene" "$(uptime)" <<'PY'
import json, statistics, sys
tmp, n, scene, load = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
def summary(name):
    return json.load(open(f"{tmp}/{name}/summary.json"))
alone = [summary(f"alone{k}") for k in range(1, n + 1)]
two = [summary(f"two{k}") for k in range(1, n + 1)]
direct = summary("direct")
med = statistics.median
wa = [s["seconds"] for s in alone]
wt = [s["seconds"] for s in two]
print(f"scene {scene}, {n} repeats; machine: {load.strip()}")
ca = [s["ranks"]["cpu_seconds"][0] for s in alone]
wca = [s["ranks"]["work_cpu_seconds"][0] for s in alone]
print(f"alone, 1 thread:    seconds best {min(wa):.3f} median {med(wa):.3f}; CPU s {med(ca):.3f}, of which "
      f"computing the points {med(wca):.3f}")
print(f"2 ranks x 1 thread: seconds best {min(wt):.3f} median {med(wt):.3f}")
print(f"wall-clock speed-up (alone / 2 ranks): best {min(wa) / min(wt):.2f}  median {med(wa) / med(wt):.2f}")
for k, s in enumerate(two, 1):
    r = s["ranks"]
    print(f"  run {k}: per rank: work CPU s {[round(x, 3) for x in r['work_cpu_seconds']]}  CPU s "
          f"{[round(x, 3) for x in r['cpu_seconds']]}  bytes received {r['bytes_received']}")
# What an idle machine would take: the serial CPU every rank repeats (the
# alone run's CPU outside the worker tasks) plus the larger rank's share.
serial_cpu = med(c - w for c, w in zip(ca, wca))
share = med(max(s["ranks"]["work_cpu_seconds"]) for s in two)
split = med(max(s["ranks"]["work_cpu_seconds"]) / sum(s["ranks"]["work_cpu_seconds"]) for s in two)
print(f"work split: the larger rank did {100 * split:.1f} % of the points' CPU; projected speed-up on an idle "
      f"machine (alone CPU / (serial CPU + larger share)): {med(ca) / (serial_cpu + share):.2f}")
a = alone[0]
points = sum(g["count"] for g in a["grids"].values())
inter = a["plan"]["interreflection"]
records = inter.get("records", 0)
passes = max((g.get("placement_passes", 0) for g in inter.get("grids", {}).values()), default=0)
direct_work = direct["ranks"]["work_cpu_seconds"][0]
per_point = direct_work / points
per_record = (med(wca) - direct_work) / records if records else 0.0
print("model constants (tools/bench/mpi_scaling_model.py):")
print(f"  --points {points} --records {records} --passes {passes} --point-cpu {per_point:.3e} "
      f"--record-cpu {per_record:.3e} --serial-cpu {serial_cpu:.3f} "
      f"--bytes-two {max(max(s['ranks']['bytes_received'][1:]) for s in two)}")
PY
