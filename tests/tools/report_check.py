#!/usr/bin/env python3
"""Checks of a report against the summary.json it was made from (used by
test_report.sh): every grid's Em and U0 as the HTML table and the PDF text
print them equal summary.json's values rounded to the printed decimals, and
those decimals are what the stated error justifies (U0's: the darkest
point's relative error plus Em's) (the last printed unit
is the decade of the uncertainty: 10^-d <= u < 10^(1-d), unless d is 0, or
the value is exact (u = 0) and carries 4 significant digits).

usage: report_check.py OUTDIR PDF_TEXT  -> prints one line per check, "ok ..." or "FAIL ..."
"""
import csv, html, math, re, sys

from report_files import Report

out = sys.argv[1]
report = Report(out, sys.argv[2])
summary, page, pdf, say = report.summary, report.page, report.pdf, report.say


def decimals(text):
    return len(text.split(".")[1]) if "." in text else 0


def justified(printed, value, u, name):
    d = decimals(printed)
    equal = abs(float(printed) - value) <= 0.5 * 10 ** -d * (1 + 1e-9) + 1e-12
    say(equal, "%s: printed %s is summary.json's %.17g to %d decimals" % (name, printed, value, d))
    if u > 0:
        fine_enough = d == 0 or 10 ** -d <= u * (1 + 1e-12)
        not_too_coarse = 10 ** (1 - d) > u or d == 0
        sig = len(printed.replace(".", "").replace("-", "").lstrip("0"))
        say((fine_enough and not_too_coarse) or sig >= 6,
            "%s: %d decimals for an uncertainty of %.3g" % (name, d, u))
    else:
        sig = len(printed.replace(".", "").replace("-", "").lstrip("0"))
        say(sig == 4 or (d == 0 and sig >= 4), "%s: exact, %s has 4 significant digits" % (name, printed))


# The summary table of the HTML: the first table whose header starts with "grid".
tables = re.findall(r"<table>(.*?)</table>", page, re.S)
summary_table = next(t for t in tables if re.search(r"<th>grid</th><th>Em \(lx\)</th>", t))
rows = {}
for tr in re.findall(r"<tr>(.*?)</tr>", summary_table, re.S)[1:]:
    cells = [html.unescape(c) for c in re.findall(r"<td[^>]*>(.*?)</td>", tr, re.S)]
    rows[cells[0]] = cells
say(sorted(rows) == sorted(summary["grids"]), "the HTML summary has a row per grid: %s" % sorted(rows))

def min_point_error(name):
    """The stated error of the grid's darkest point (the first of them), from NAME.csv."""
    points = [(float(r["E_lx"]), float(r["E_stderr_lx"])) for r in csv.DictReader(open("%s/%s.csv" % (out, name)))]
    return min(points, key=lambda p: p[0])[1]


for name, g in summary["grids"].items():
    r_mean = g["stderr_mean_rel"]
    cells = rows.get(name)
    if not cells:
        continue
    justified(cells[1], g["E_avg_lx"], g["E_avg_lx"] * r_mean, "HTML %s Em" % name)
    # U0 = Emin / Em: the relative errors of the darkest point and of Em add
    rel_min = min_point_error(name) / g["E_min_lx"] if g["E_min_lx"] > 0 else g["stderr_max_rel"]
    justified(cells[4], g["U0"], g["U0"] * (rel_min + r_mean), "HTML %s U0" % name)
    # The PDF's summary row: the grid's name at the start of a line, then the same numbers.
    m = re.search(r"^%s +(\S+) +(\S+) +(\S+) +(\S+)" % re.escape(name), pdf, re.M)
    say(m is not None, "PDF: a summary row for %s" % name)
    if m:
        say(m.group(1) == cells[1] and m.group(4) == cells[4],
            "PDF %s: Em %s and U0 %s as in the HTML (%s, %s)" % (name, m.group(1), m.group(4), cells[1], cells[4]))
sys.exit(1 if report.failed else 0)
