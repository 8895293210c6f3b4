#!/usr/bin/env bash
# `candela report` on the folder of `candela annual`: a daylight report.
# The HTML and the PDF exist; the title names the scene; the daylight table
# carries summary.json's sDA300/50%, ASE1000,250h and UDI as rounded there
# (the numbers read back from summary.json here); each grid's EN 17037 table
# with its levels; the four maps of a rect grid as pictures; the PDF holds
# the same words (pdftotext).
source "$(dirname "$0")/harness.sh"
py="$CANDELA_SOURCE_DIR/tests/tools/annual_check.py"
python3 "$py" epw "$tmp/w.epw"
cat > "$tmp/room.json" <<'JSON'
{"version": 1, "surfaces": [{"type": "box", "min": [0,0,0], "max": [3,4,2.8], "inward": true,
  "reflectance": {"floor": 0.25, "walls": 0.55, "ceiling": 0.75}, "open": ["-y"]},
  {"type": "polygon", "vertices": [[0,0,0],[3,0,0],[3,0,2.8],[0,0,2.8]],
   "holes": [[[0.7,0,0.9],[2.3,0,0.9],[2.3,0,2.1],[0.7,0,2.1]]], "reflectance": 0.4}],
 "grids": [{"name": "desk", "type": "rect", "origin": [0.2,0.3,0.8], "u": [2.6,0,0], "v": [0,3.4,0], "nu": 3, "nv": 4},
           {"name": "probe", "type": "points", "points": [{"p": [1.5,2,0.8], "n": [0,0,1]}]}],
 "solver": {"quality": "draft", "seed": 2}}
JSON
"$CANDELA" annual "$tmp/room.json" --weather "$tmp/w.epw" --sky cie_overcast -o "$tmp/a" --quiet > /dev/null 2> "$tmp/a.err"; st=$?
check "annual: exit 0 (got $st)" '[ $st -eq 0 ]' || cat "$tmp/a.err"
"$CANDELA" report "$tmp/a" > "$tmp/r.out" 2> "$tmp/r.err"; st=$?
check "report: exit 0 (got $st)" '[ $st -eq 0 ]' || cat "$tmp/r.err"
check "report: html and pdf" '[ -s "$tmp/a/report.html" ] && [ -s "$tmp/a/report.pdf" ]'
check "report: titled with the scene" 'grep -q "<title>Daylight report: .*room.json</title>" "$tmp/a/report.html"'
for grid in desk probe; do
  for key in sDA300_percent ASE1000_percent UDI_percent; do
    want=$(python3 -c "import json,sys; print('%.1f %%' % json.load(open(sys.argv[1]))['grids'][sys.argv[2]][sys.argv[3]])" \
      "$tmp/a/summary.json" "$grid" "$key")
    check "report: $grid's $key as summary.json has it ($want)" 'grep -q "<td class=\"num\">$want</td>" "$tmp/a/report.html"'
  done
  check "report: $grid's EN 17037 table" 'grep -q "$grid: EN 17037 daylight provision" "$tmp/a/report.html"'
done
check "report: the desk's four maps, the probe's none" '[ "$(grep -c "<img" "$tmp/a/report.html")" -eq 4 ]'
check "report: the PDF says the same" 'pdftotext "$tmp/a/report.pdf" - | grep -q "sDA300/50%" && pdftotext "$tmp/a/report.pdf" - | grep -q "EN 17037 daylight provision"'
exit $fail
