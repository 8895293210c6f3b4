#!/usr/bin/env python3
"""annual_check.py - what the tests of `candela annual` compute on their own.

  annual_check.py epw FILE [--leap] [--constant-dew]
      a synthetic weather year (no third-party data): latitude 48 N,
      11.6 E, UTC+1; a simple sun (Cooper's declination, the hour angle of
      mean solar time) decides which hours are light; clear, broken and
      overcast days in turn; illuminances from the irradiances by fixed
      efficacies (the file's own numbers, whatever model made them).
  annual_check.py occupancy FILE
      a schedule: weekdays (the year starting on a Tuesday) 9-17, with a
      header line.
  annual_check.py overcast OUTDIR GRID EPW OCCUPANCY
      checks an annual run under --sky cie_overcast against the daylight
      factor it wrote and the weather file: every hour of the hourly file
      equals DF / 100 x the hour's diffuse horizontal illuminance (field 19)
      rounded to float32; DA300, UDI (and its two others) and the EN 17037
      share per point recomputed from those hours and the schedule ("A-B"
      or a file) equal the CSV's; sDA300, the UDI means and the EN 17037
      hours per level equal summary.json's.
  annual_check.py hour OUTDIR GRID HOUR
      prints the hour's illuminance at every point of the hourly file.
Exit status 0 when every check holds; each failure is printed.
"""
import csv
import json
import math
import struct
import sys

DA, LOW, HIGH = 300.0, 100.0, 3000.0
LEVELS = [("minimum", 300.0, 100.0), ("medium", 500.0, 300.0), ("high", 750.0, 500.0)]


def write_epw(path, leap=False, constant_dew=False):
    lat, lon, tz = 48.1, 11.6, 1.0
    days = [31, 29 if leap else 28, 31, 30, 31, 30, 31, 31, 30, 31, 30, 31]
    with open(path, "w") as f:
        f.write("LOCATION,Testburg,TB,Testland,synthetic,000000,%.1f,%.1f,%.1f,520.0\n" % (lat, lon, tz))
        for line in ["DESIGN CONDITIONS,0", "TYPICAL/EXTREME PERIODS,0", "GROUND TEMPERATURES,0",
                     "HOLIDAYS/DAYLIGHT SAVINGS,No,0,0,0", "COMMENTS 1,synthetic weather of Candela's tests",
                     "COMMENTS 2,", "DATA PERIODS,1,1,Data,Tuesday, 1/ 1,12/31"]:
            f.write(line + "\n")
        doy = 0
        for m in range(12):
            for d in range(days[m]):
                doy += 1
                decl = math.radians(23.45 * math.sin(math.radians(360.0 * (284 + doy) / 365.0)))
                kind = doy % 3  # 0 clear, 1 overcast, 2 broken
                for h in range(1, 25):
                    solar = h - 0.5 - tz + lon / 15.0
                    ha = math.radians(15.0 * (solar - 12.0))
                    s = (math.sin(math.radians(lat)) * math.sin(decl) +
                         math.cos(math.radians(lat)) * math.cos(decl) * math.cos(ha))
                    dni = dhi = 0.0
                    if s > 0.02:
                        if kind == 0:
                            dni, dhi = 820.0 * math.exp(-0.17 / s), 50.0 + 90.0 * s
                        elif kind == 1:
                            dni, dhi = 0.0, 30.0 + 260.0 * s
                        else:
                            dni, dhi = 380.0 * s, 80.0 + 200.0 * s
                    ghi = dhi + dni * max(s, 0.0)
                    dew = 8.0 if constant_dew else 2.0 + 10.0 * math.sin(doy / 58.0)
                    f.write("2019,%d,%d,%d,60,x,14,%.1f,60,95000,0,0,350,%.1f,%.1f,%.1f,%.0f,%.0f,%.0f,0,180,2,5,5,"
                            "20,77777,9,999999999,15,0.1,0,88,0.2,0,1\n"
                            % (m + 1, d + 1, h, dew, ghi, dni, dhi, 110 * ghi, 95 * dni, 122 * dhi))


def write_occupancy(path):
    with open(path, "w") as f:
        f.write("hour,occupied\n")
        for k in range(8760):
            day, hour = divmod(k, 24)
            weekday = (day + 1) % 7  # 1 January a Tuesday: 0 Monday
            f.write("%d,%d\n" % (k, 1 if weekday < 5 and 9 <= hour < 17 else 0))


def read_epw(path):
    rows = []
    with open(path) as f:
        lines = f.read().splitlines()
    start = next(i for i, l in enumerate(lines) if l.startswith("DATA PERIODS")) + 1
    for l in lines[start:]:
        if l.strip():
            x = l.split(",")
            rows.append({"hour": int(x[3]), "Edh": float(x[18])})
    return rows


def read_hourly(path):
    with open(path, "rb") as f:
        data = f.read()
    assert data[:8] == b"CDLHOUR1", "magic"
    hours, points, quantity, zero = struct.unpack("<4I", data[8:24])
    assert len(data) == 24 + 4 * hours * points, "size"
    values = struct.unpack("<%df" % (hours * points), data[24:])
    return hours, points, quantity, [values[h * points:(h + 1) * points] for h in range(hours)]


def f32(x):
    return struct.unpack("<f", struct.pack("<f", x))[0]


def schedule(spec, epw):
    if "-" in spec and spec.replace("-", "").isdigit():
        a, b = (int(v) for v in spec.split("-"))
        return [1 if r["hour"] - 1 >= a and r["hour"] <= b else 0 for r in epw]
    occ = []
    with open(spec) as f:
        for i, l in enumerate(f):
            v = l.strip().split(",")[-1]
            if i == 0 and not v.replace(".", "").isdigit():
                continue
            if v:
                occ.append(int(float(v)))
    return occ


def daylight_hours(epw):
    order = sorted(range(len(epw)), key=lambda h: (-epw[h]["Edh"], h))
    day = [0] * len(epw)
    for h in order[:len(epw) // 2]:
        day[h] = 1
    return day


def check_overcast(out, grid, epw_path, occ_spec):
    bad = []
    epw = read_epw(epw_path)
    hours, points, quantity, E = read_hourly("%s/%s.hourly.bin" % (out, grid))
    rows = list(csv.DictReader(open("%s/%s.csv" % (out, grid))))
    summary = json.load(open("%s/summary.json" % out))["grids"][grid]
    if hours != len(epw) or points != len(rows) or quantity != 1:
        return ["header: %d hours, %d points, quantity %d" % (hours, points, quantity)]
    DF = [float(r["DF_percent"]) for r in rows]
    worst = 0
    for h in range(hours):
        for i in range(points):
            want = f32(DF[i] / 100.0 * epw[h]["Edh"]) if epw[h]["Edh"] > 0 else 0.0
            if E[h][i] != want:
                worst += 1
                if worst < 4:
                    bad.append("hour %d point %d: %r, DF x E_dh gives %r" % (h, i, E[h][i], want))
    if worst:
        bad.append("%d values differ from DF x E_dh" % worst)
    occ, day = schedule(occ_spec, epw), daylight_hours(epw)
    n_occ, n_day = sum(occ), sum(day)
    sda = udi_s = udi = udi_x = 0.0
    hours_t = [0] * 3
    hours_m = [0] * 3
    for h in range(hours):
        if day[h]:
            for l, (name, t, m) in enumerate(LEVELS):
                hours_t[l] += sum(1 for i in range(points) if E[h][i] >= t) >= 0.5 * points
                hours_m[l] += sum(1 for i in range(points) if E[h][i] >= m) >= 0.95 * points
    for i in range(points):
        da = sum(1 for h in range(hours) if occ[h] and E[h][i] >= DA)
        short = sum(1 for h in range(hours) if occ[h] and E[h][i] < LOW)
        over = sum(1 for h in range(hours) if occ[h] and E[h][i] > HIGH)
        en = sum(1 for h in range(hours) if day[h] and E[h][i] >= 300.0)
        mine = {"DA300_percent": 100.0 * da / n_occ, "UDI_fell_short_percent": 100.0 * short / n_occ,
                "UDI_percent": 100.0 * (n_occ - short - over) / n_occ, "UDI_exceeded_percent": 100.0 * over / n_occ,
                "EN17037_target_percent": 100.0 * en / n_day, "ASE_hours": 0.0}
        for k, v in mine.items():
            if abs(float(rows[i][k]) - v) > 1e-9:
                bad.append("point %d %s: CSV %s, recomputed %r" % (i, k, rows[i][k], v))
        sda += 100.0 / points if mine["DA300_percent"] >= 50.0 else 0.0
        udi_s += mine["UDI_fell_short_percent"] / points
        udi += mine["UDI_percent"] / points
        udi_x += mine["UDI_exceeded_percent"] / points
    for k, v in [("sDA300_percent", sda), ("UDI_fell_short_percent", udi_s), ("UDI_percent", udi),
                 ("UDI_exceeded_percent", udi_x), ("ASE1000_percent", 0.0)]:
        if abs(summary[k] - v) > 1e-9:
            bad.append("summary %s: %r, recomputed %r" % (k, summary[k], v))
    for l, (name, t, m) in enumerate(LEVELS):
        got = summary["EN17037"][name]
        if abs(got["target_hours_percent"] - 100.0 * hours_t[l] / n_day) > 1e-9 or \
           abs(got["minimum_hours_percent"] - 100.0 * hours_m[l] / n_day) > 1e-9:
            bad.append("EN 17037 %s: %r, recomputed %r %r" % (name, got, hours_t[l], hours_m[l]))
    print("overcast: %d hours x %d points, %d occupied, %d daylight hours, sDA %.4g %%" %
          (hours, points, n_occ, n_day, sda))
    return bad


def main(argv):
    if argv[1] == "epw":
        write_epw(argv[2], "--leap" in argv, "--constant-dew" in argv)
        return 0
    if argv[1] == "occupancy":
        write_occupancy(argv[2])
        return 0
    if argv[1] == "hour":
        hours, points, quantity, E = read_hourly("%s/%s.hourly.bin" % (argv[2], argv[3]))
        print(" ".join("%.9g" % v for v in E[int(argv[4])]))
        return 0
    bad = check_overcast(*argv[2:6])
    for b in bad:
        print("FAIL: " + b)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
