#!/usr/bin/env bash
# `candela annual --sky perez` against direct solves of single hours: for five
# hours of the synthetic weather year (clear, overcast, broken, a summer
# evening, a winter noon) `candela solve` of the same black room under the
# Perez sky of that hour's irradiances and dew point, the sun placed by the
# SPA at the hour's middle from the same site (its disk's penumbra the only
# thing the annual run leaves out); the annual run's hourly file at every
# point within 4 combined sigmas: its stated error (the coefficients'
# sampling and the patches' discretisation, coefficient_rel_stderr) and the
# solve's. With MF 1 and MF 2 (the discretisation stated apart for each).
# The room is black: what the coefficients add to direct light by
# interreflection is held to the path tracer in
# tests/solver/daylight/test_daylight_coefficients.c.
# ctest-timeout: 600
source "$(dirname "$0")/harness.sh"
py="$CANDELA_SOURCE_DIR/tests/tools/annual_check.py"
python3 "$py" epw "$tmp/w.epw"

room='"surfaces": [{"type": "box", "min": [0,0,0], "max": [3,4,2.8], "inward": true, "reflectance": 0, "open": ["-y"]},
  {"type": "polygon", "vertices": [[0,0,0],[3,0,0],[3,0,2.8],[0,0,2.8]],
   "holes": [[[0.7,0,0.9],[2.3,0,0.9],[2.3,0,2.1],[0.7,0,2.1]]], "reflectance": 0}],
 "grids": [{"name": "desk", "type": "rect", "origin": [0.2,0.3,0.8], "u": [2.6,0,0], "v": [0,3.4,0], "nu": 3, "nv": 4},
           {"name": "wall", "type": "points", "points": [{"p": [2.99,2,1.5], "n": [-1,0,0]}, {"p": [1.5,3.99,1.5], "n": [0,-1,0]}]}],
 "solver": {"quality": "high", "seed": 2}'
printf '{"version": 1, %s}\n' "$room" > "$tmp/room.json"
for mf in 1 2; do
  "$CANDELA" annual "$tmp/room.json" --weather "$tmp/w.epw" --mf $mf -o "$tmp/a$mf" --quiet > /dev/null 2> "$tmp/a$mf.err"; st=$?
  check "annual MF $mf: exit 0 (got $st)" '[ $st -eq 0 ]' || cat "$tmp/a$mf.err"
done

check "five hours against direct solves" 'python3 - "$tmp" "$CANDELA" <<EOF
import csv, json, math, struct, subprocess, sys
tmp, candela = sys.argv[1], sys.argv[2]
def hourly(path):
    d = open(path, "rb").read()
    H, N, q, z = struct.unpack("<4I", d[8:24])
    v = struct.unpack("<%df" % (H * N), d[24:])
    return [v[h * N:(h + 1) * N] for h in range(H)]
epw = [l.split(",") for l in open(tmp + "/w.epw").read().splitlines()[8:]]
scene = json.load(open(tmp + "/room.json"))
ok = True
for doy, hour in [(81, 13), (82, 10), (83, 15), (171, 17), (351, 12)]:
    h = (doy - 1) * 24 + hour - 1
    r = epw[h]
    month, day = int(r[1]), int(r[2])
    sky = {"type": "environment", "sky": "perez", "direct_normal_irradiance_w_m2": float(r[14]),
           "diffuse_horizontal_irradiance_w_m2": float(r[15]), "dew_point_c": float(r[7]),
           "site": {"latitude_deg": 48.1, "longitude_deg": 11.6, "elevation_m": 520.0},
           "time": "2019-%02d-%02dT%02d:30:00+01:00" % (month, day, hour - 1)}
    scene["luminaires"] = [sky]
    json.dump(scene, open(tmp + "/hour.json", "w"))
    subprocess.run([candela, "solve", tmp + "/hour.json", "-o", tmp + "/hour", "--quiet"], check=True)
    for grid in ["desk", "wall"]:
        solved = list(csv.DictReader(open(tmp + "/hour/" + grid + ".csv")))
        for mf in (1, 2):
            E = hourly("%s/a%d/%s.hourly.bin" % (tmp, mf, grid))[h]
            stated = [float(x["coefficient_rel_stderr"]) for x in csv.DictReader(open("%s/a%d/%s.csv" % (tmp, mf, grid)))]
            worst = 0.0
            for i, x in enumerate(solved):
                want, sw = float(x["E_lx"]), float(x["E_stderr_lx"])
                sd = math.hypot(stated[i] * E[i], sw)
                z = abs(E[i] - want) / sd if sd > 0 else (0.0 if E[i] == want else 99.0)
                worst = max(worst, z)
                ok &= z <= 4.0
            print("day %d hour %d %s MF %d: worst %.2f combined sigmas" % (doy, hour, grid, mf, worst))
sys.exit(0 if ok else 1)
EOF'
exit $fail
