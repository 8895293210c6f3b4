"""The files of a reported solve, read once, and the ok/FAIL lines the
report checks print (report_check.py, report_client_check.py)."""
import json


class Report:
    """OUTDIR's summary.json and report.html, the PDF's text, and a tally
    of the checks: say() prints "ok WHAT" or "FAIL WHAT"."""

    def __init__(self, out, pdf_text_path):
        self.summary = json.load(open(out + "/summary.json"))
        self.page = open(out + "/report.html", encoding="utf-8").read()
        self.pdf = open(pdf_text_path, encoding="utf-8").read()
        self.failed = False

    def say(self, ok, what):
        print(("ok " if ok else "FAIL ") + what)
        self.failed |= not ok
