#!/usr/bin/env python3
"""mpi_scaling_model.py - a solve shared by 8 to 256 MPI ranks, modelled from measured costs (docs/mpi-scaling.md).

    tools/bench/mpi_scaling_model.py [--points 1e7] [constants measured by tools/bench/bench_ranks.sh ...]

A grid of N points solved with the irradiance cache by P ranks of one
thread each. Per rank, in seconds:

  compute   (N c_point + R c_record) / P, times the imbalance of the blocks;
            R = N r, the records per point measured;
  serial    what every rank repeats whatever P: s_fixed + s_point N (the
            scene's set-up, the grid's points and edge points, each pass's
            picking of the points that ask for records in index order, each
            record's radius and its entry in the octree);
  exchange  each collective a latency alpha per stage of a tree (log2 P
            stages), and the bytes a rank receives over a link of
            bandwidth beta: every point's direct light (16 B), every record
            and its tally (160 B), the asks (a per point, measured), the
            other ranks' share of each, (P - 1) / P; rank 0 also the
            results of the points it did not compute (16 B a point);
  write     rank 0 writes the outputs alone: w_point N.

Memory per rank: m_base + m_point N + m_record R, and rank 0 m_write N more
while it writes. Every number is the model's, from the constants given;
the defaults are this machine's measurements (docs/mpi-scaling.md gives the
commands), so the table is reproducible.
"""
import argparse
import math


def parse():
    p = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    # measured on the dense cube at normal (tools/bench/bench_ranks.sh)
    p.add_argument("--points", type=float, default=1e7, help="points of the site modelled")
    p.add_argument("--measured-points", type=float, default=12500, help="points of the measured scene")
    p.add_argument("--records", type=float, default=1652, help="records of the measured scene")
    p.add_argument("--passes", type=int, default=11, help="placement passes of the measured scene")
    p.add_argument("--point-cpu", type=float, default=4.752e-07, help="s of direct light per point")
    p.add_argument("--record-cpu", type=float, default=2.302e-03,
                   help="s per record: its gather and its share of the interpolation passes")
    p.add_argument("--bytes-two", type=float, default=363656,
                   help="bytes rank 1 received in the measured scene on 2 ranks")
    # measured on the 10^6-point site (docs/mpi-scaling.md)
    p.add_argument("--serial-fixed", type=float, default=0.05, help="s every rank repeats, whatever N")
    p.add_argument("--serial-point", type=float, default=0.6e-6, help="s every rank repeats per point")
    p.add_argument("--write-point", type=float, default=3.3e-6, help="s rank 0 takes to write a point's outputs")
    p.add_argument("--mem-base", type=float, default=23e6, help="bytes of a rank before any point")
    p.add_argument("--mem-point", type=float, default=125, help="bytes a rank holds per point (cache grid)")
    p.add_argument("--mem-record", type=float, default=190, help="bytes a rank holds per record")
    p.add_argument("--mem-write", type=float, default=47, help="bytes rank 0 adds per point while writing")
    p.add_argument("--imbalance", type=float, default=1.05, help="the largest block's work over the mean")
    return p.parse_args()


# Links: latency per collective stage (s), bandwidth (bytes/s).
NETWORKS = {
    "10 GbE (TCP)": (30e-6, 1.1e9),
    "100 Gb/s InfiniBand": (2e-6, 11e9),
}

RECORD_BYTES = 136 + 24  # a record (17 doubles) and its paths' tally (3 doubles)
DIRECT_BYTES = 16        # E_direct and its variance, every point to every rank
RESULT_BYTES = 16        # E_indirect and its variance, every point to rank 0


def model(a, n, ranks, alpha, beta):
    r = a.records / a.measured_points
    records = n * r
    # the asks a rank received on 2 ranks, beyond the direct light and the records
    asks = max(0.0, 2 * a.bytes_two - DIRECT_BYTES * a.measured_points - RECORD_BYTES * a.records)
    ask_per_point = asks / a.measured_points
    other = (ranks - 1) / ranks
    received = (DIRECT_BYTES * n + RECORD_BYTES * records + ask_per_point * n) * other
    received_root = received + RESULT_BYTES * n * other
    # collectives: per pass about eight (agreement, the asks' counts and list,
    # the records and their tallies, the counts of rays), thirty more per grid,
    # and one more per 8 MiB window of each exchange
    windows = received_root / (8 << 20)
    collectives = 8 * a.passes + 30 + windows
    exchange = collectives * alpha * math.ceil(math.log2(ranks)) + received_root / beta
    compute = (n * a.point_cpu + records * a.record_cpu) / ranks * a.imbalance
    serial = a.serial_fixed + a.serial_point * n
    write = a.write_point * n
    memory = a.mem_base + a.mem_point * n + a.mem_record * records
    return {
        "compute": compute, "serial": serial, "exchange": exchange, "write": write,
        "total": compute + serial + exchange + write,
        "received": received, "received_root": received_root,
        "memory": memory, "memory_root": memory + a.mem_write * n,
        "one": n * a.point_cpu + records * a.record_cpu + serial + write,
    }


def table(a, title, rows):
    print(f"\n{title}")
    for net, (alpha, beta) in NETWORKS.items():
        print(f"\n  {net} (latency {alpha * 1e6:g} us a stage, {beta / 1e9:g} GB/s)")
        print("  ranks   points  compute s  serial s  exchange s  write s  total s  speed-up  efficiency"
              "  MB received (rank 0)  GB per rank (rank 0)")
        for ranks, n in rows:
            m = model(a, n, ranks, alpha, beta)
            speed = m["one"] / m["total"]
            print(f"  {ranks:5d} {n:8.3g} {m['compute']:10.1f} {m['serial']:9.2f} {m['exchange']:11.3f}"
                  f" {m['write']:8.1f} {m['total']:8.1f} {speed:9.1f} {speed / ranks:10.2f}"
                  f" {m['received'] / 1e6:9.0f} ({m['received_root'] / 1e6:.0f})"
                  f" {m['memory'] / 1e9:12.2f} ({m['memory_root'] / 1e9:.2f})")


def main():
    a = parse()
    ranks = [8, 16, 32, 64, 128, 256]
    one = model(a, a.points, 1, 0.0, 1e30)
    print(f"site of {a.points:.3g} points, {a.records / a.measured_points:.3f} records a point "
          f"({a.points * a.records / a.measured_points:.3g} records), {a.passes} passes; one rank: "
          f"{one['one']:.0f} s ({one['one'] / 3600:.1f} h), {one['memory_root'] / 1e9:.2f} GB")
    table(a, f"strong scaling: {a.points:.3g} points on 8 to 256 ranks", [(p, a.points) for p in ranks])
    per = a.points / ranks[-1]
    table(a, f"weak scaling: {per:.3g} points a rank", [(p, per * p) for p in ranks])


if __name__ == "__main__":
    main()
