#!/usr/bin/env python3
"""Checks of a client's report (used by test_report_client.sh) against what
it was made from, each computed here from the scene, summary.json and the
CSVs, never from the report itself:

  - the title is the scene's name, the project block carries every field;
  - every quantity each grid asked for (Ez, Esz, L, AO next to E) has its
    summary row, whose mean, min and max are summary.json's (or for AO the
    CSV's) rounded to the printed decimals, and its map;
  - the luminaire list has a row per luminaire placed, at the position the
    scene's array puts it (origin + i dx, j dy, computed here), with the
    file's product name and catalogue number, the height above the floor
    and the aim point; the schedule counts them;
  - the room's dimensions, floor area and reflectances; the open face;
  - installed power and power density per grid as summary.json states them;
  - the method table names every light and grid;
  - with --values, every rect grid's E at every point, as the CSV gives it,
    rounded to the printed decimals, laid out as the map (top row = the
    grid's last row of points).

usage: report_client_check.py SCENE OUTDIR PDF_TEXT -> "ok ..." / "FAIL ..." lines
"""
import csv, html, json, re, sys

from report_files import Report

scene_path, out = sys.argv[1:3]
scene = json.load(open(scene_path))
report = Report(out, sys.argv[3])
summary, page, pdf, say = report.summary, report.page, report.pdf, report.say


def tables():
    """Every HTML table as a list of rows of unescaped cell texts."""
    found = []
    for t in re.findall(r"<table>(.*?)</table>", page, re.S):
        rows = []
        for tr in re.findall(r"<tr>(.*?)</tr>", t, re.S):
            rows.append([html.unescape(c) for c in re.findall(r"<t[dh][^>]*>(.*?)</t[dh]>", tr, re.S)])
        found.append(rows)
    return found


def table_with(heading):
    return [t for t in tables() if t and t[0] and t[0][0] == heading]


def rounds_to(printed, value):
    """The printed text is value rounded to the printed decimals."""
    d = len(printed.split(".")[1]) if "." in printed else 0
    return abs(float(printed) - value) <= 0.5 * 10 ** -d * (1 + 1e-9) + 1e-12


def flat(text):
    return " ".join(text.split())


# 1. Title and project block.
name, project = scene["name"], scene["project"]
say(re.search(r"<title>%s</title>" % re.escape(html.escape(name, quote=False)), page) is not None,
    "the HTML's title is the scene's name")
say(pdf.lstrip().startswith(name), "the PDF opens with the scene's name")
for key, label in [("project", "Project"), ("client", "Client"), ("designer", "Designer"), ("date", "Date")]:
    say(re.search(r"^%s +%s$" % (label, re.escape(project[key])), pdf, re.M) is not None,
        "the cover's project block: %s %s" % (label, project[key]))
say("Notes: " + project["notes"] in flat(pdf), "the cover's notes")

# 2. Every quantity asked, in the summary and as a map.
columns = {"cylindrical": ("Ez_lx", "Ez (lx)", "Ez"), "semicylindrical": ("Esz_lx", "Esz (lx)", "Esz"),
           "luminance": ("L_cd_m2", "L (cd/m2)", "L"), "ao": ("AO", "AO", None)}
outputs = table_with("grid")
outputs = [t for t in outputs if t[0][1] == "quantity"]
say(len(outputs) == 1, "one table of the other quantities")
rows = {(r[0], r[1]): r for r in (outputs[0][1:] if outputs else [])}
for g in scene["grids"]:
    rows_csv = list(csv.DictReader(open("%s/%s.csv" % (out, g["name"]))))
    for output in g.get("outputs", []):
        column, label, key = columns[output]
        row = rows.get((g["name"], label))
        say(row is not None, "summary row for %s %s" % (g["name"], label))
        if not row:
            continue
        if key:
            unit = "cd_m2" if key == "L" else "lx"
            stats = [summary["grids"][g["name"]]["%s_%s_%s" % (key, q, unit)] for q in ("avg", "min", "max")]
        else:  # AO: the CSV's mean (area weights equal on a rect grid), min, max
            values = [float(r[column]) for r in rows_csv]
            stats = [sum(values) / len(values), min(values), max(values)]
        for printed, value, what in zip(row[2:5], stats, ("mean", "min", "max")):
            say(rounds_to(printed, value), "%s %s %s: printed %s is %.10g rounded" % (g["name"], label, what, printed,
                                                                                         value))
        what = {"Ez": "cylindrical illuminance Ez in lx", "Esz": "semicylindrical illuminance Esz in lx",
                "L": "luminance L in cd/m2", None: "ambient occlusion"}[key]
        say(re.search(r'alt="%s: %s' % (re.escape(g["name"]), re.escape(what)), page) is not None,
            "a map of %s %s" % (g["name"], label))
        say("%s: %s" % (g["name"], what) in pdf, "the PDF's map of %s %s" % (g["name"], label))

# 3. The luminaire list: every placement where the scene's array puts it.
listed = table_with("luminaire")
listed = [t for t in listed if t[0][1] == "product"]
say(len(listed) == 1, "one luminaire list")
rows = listed[0][1:] if listed else []
expected = []
for entry in scene["luminaires"]:
    p, a = entry["position"], entry.get("array")
    nx, ny = a["counts"] if a else (1, 1)
    dx, dy = a["spacing"] if a else (0, 0)
    for j in range(ny):
        for i in range(nx):
            expected.append((entry, [p[0] + i * dx, p[1] + j * dy, p[2]], i + j * nx, nx * ny))
say(len(rows) == len(expected), "a row per luminaire placed (%d, expected %d)" % (len(rows), len(expected)))
products = {"linear.ies": ("Suspended linear LED luminaire, 1200 mm, opal diffuser", "CX-LN-1200"),
            "downlight.ies": ("Recessed LED downlight, 60 deg reflector", "CX-DL-20")}
for row, (entry, xyz, k, n) in zip(rows, expected):
    label = entry["name"] + (", %d of %d" % (k + 1, n) if n > 1 else "")
    say(row[0] == label, "list row %s (%s)" % (label, row[0]))
    say((row[1], row[2]) == products[entry["file"]], "%s: product and catalogue number from the file" % label)
    position = ["%.3f" % c for c in xyz]
    say(row[3:6] == position, "%s at %s (%s)" % (label, xyz, row[3:6]))
    say(row[6] == "%.3f" % xyz[2], "%s: %.3f m above the floor (%s)" % (label, xyz[2], row[6]))
    if "aim" in entry:
        say(row[7].startswith("aim (%g, %g, %g)" % tuple(entry["aim"])), "%s: aim point (%s)" % (label, row[7]))
    say(row[8] == "%g" % entry.get("maintenance_factor", 1), "%s: maintenance factor" % label)
    # the PDF's row: the label, then (past the product's first line) x, y, z and the height on its line
    line = r"^%s .* %s +%s +%s +%s " % (re.escape(label), position[0], position[1], position[2], "%.3f" % xyz[2])
    say(re.search(line, pdf, re.M) is not None, "%s: position and height in the PDF's list" % label)

# 4. Room and surfaces.
room = scene["surfaces"][0]
size = [room["max"][k] - room["min"][k] for k in range(3)]
say("The room (surfaces[0] %s): %g m x %g m, %g m high; floor area %g m2, volume %g m3." %
    (room["name"], size[0], size[1], size[2], size[0] * size[1], size[0] * size[1] * size[2]) in flat(pdf),
    "the room's dimensions, floor area and volume")
surf = [t for t in table_with("surface")]
row = surf[0][1] if surf else []
r = room["reflectance"]
say(len(row) == 5 and row[3] == "floor %g, walls %g, ceiling %g" % (r["floor"], r["walls"], r["ceiling"]),
    "the room's reflectances (%s)" % (row[3] if len(row) > 3 else None))
say(len(row) == 5 and "-y open" in row[4], "the room's open face")
say(len(row) == 5 and row[1] == "box %g x %g x %g m (x, y, z)" % tuple(size), "the room's box dimensions")

# 5. Power per grid, as summary.json states it.
power = table_with("grid")
power = [t for t in power if len(t[0]) > 1 and t[0][1] == "area (m2)"]
say(len(power) == 1, "one table of power")
for row in (power[0][1:] if power else []):
    g = summary["grids"][row[0]]
    if "power_density_w_m2" in g:
        say(rounds_to(row[3], g["power_w"]) and abs(float(row[4]) / g["power_density_w_m2"] - 1) < 5e-3,
            "%s: %s W, %s W/m2 as summary.json (%g, %g)" % (row[0], row[3], row[4], g["power_w"],
                                                           g["power_density_w_m2"]))
    else:
        say(row[3] == "-", "%s: no power density where the files do not give it" % row[0])

# 6. The method table names each light and grid.
routes = table_with("light")
say(len(routes) == 1, "one table of direct light")
rows = routes[0][1:] if routes else []
for k, entry in enumerate(scene["luminaires"]):
    say(any(r[0].startswith("luminaires[%d]" % k) and entry["name"] in r[0] for r in rows),
        "the direct-light table names luminaires[%d] %s" % (k, entry["name"]))
for g in scene["grids"]:
    say(any(g["name"] in r[1].split(", ") for r in rows), "the direct-light table names grid %s" % g["name"])

# 7. --values: every rect grid's E, laid out as its map.
for g in scene["grids"]:
    if g["type"] != "rect":
        continue
    nu, nv = g["nu"], g["nv"]
    E = [float(r["E_lx"]) for r in csv.DictReader(open("%s/%s.csv" % (out, g["name"])))]
    heading = "%s: illuminance E (lx)" % g["name"]
    start = page.find(">%s</h3>" % html.escape(heading))
    say(start >= 0, "values of %s" % g["name"])
    blocks, col0, bad = re.findall(r"<table>(.*?)</table>", page[start:], re.S), 0, 0
    for t in blocks:
        trs = re.findall(r"<tr>(.*?)</tr>", t, re.S)
        cells = [[html.unescape(c) for c in re.findall(r"<t[dh][^>]*>(.*?)</t[dh]>", tr, re.S)] for tr in trs]
        if col0 == nu or not cells or not re.match(r"^\w+ \\ \w+ \(m\)$", cells[0][0]):
            break
        width = len(cells[0]) - 1
        for r in range(nv):  # the map's top row is the grid's last row of points
            for c in range(width):
                bad += not rounds_to(cells[r + 1][c + 1], E[(nv - 1 - r) * nu + col0 + c])
        col0 += width
    say(col0 == nu and bad == 0, "%s: %d x %d values as the CSV's, laid out as the map (%d differ)" % (g["name"], nu,
                                                                                                 nv, bad))

sys.exit(1 if report.failed else 0)
