#!/usr/bin/env bash
# The report in a real browser: headless Chromium (Debian's chromium,
# installed by scripts/setup.sh) loads report.html of the example office
# (draft quality) from disk, offline: every image loads (complete, with a
# size), and its screenshot is a page, not a blank: dark text, and (from
# the maps' section on) the false-colour maps' colours. Chromium is not built with the
# sanitizers, and under them its start-up is only slower: no-sanitize.
# ctest-labels: no-sanitize
# ctest-timeout: 240
source "$(dirname "$0")/harness.sh"
command -v chromium > /dev/null || { echo "FAIL: chromium missing: run scripts/setup.sh"; exit 1; }

mkdir -p "$tmp/office"
cp "$CANDELA_SOURCE_DIR"/data/office/*.ies "$tmp/office/"
python3 -c "
import json, sys
d = json.load(open(sys.argv[1])); d['solver']['quality'] = 'draft'
json.dump(d, open(sys.argv[2], 'w'), indent=1)" "$CANDELA_SOURCE_DIR/data/office/office.json" "$tmp/office/office.json"
"$CANDELA" solve "$tmp/office/office.json" -o "$tmp/out" --quiet > /dev/null 2>&1 && "$CANDELA" report "$tmp/out" > /dev/null; st=$?
check "office solved and reported" '[ $st -eq 0 ]'

# Headless, no network, a profile of its own (root needs --no-sandbox).
browse() {
  timeout 120 chromium --headless --no-sandbox --disable-gpu --no-first-run --hide-scrollbars --disable-extensions \
    --user-data-dir="$tmp/profile" --proxy-server="http://0.0.0.0:9" --virtual-time-budget=10000 "$@" 2> "$tmp/chromium.err"
}

# 1. Every image loaded: a copy of the report with a probe that writes, once
# the page has loaded, how many images there are and how many decoded.
sed 's#</body>#<script>window.addEventListener("load", function () { var all = document.images, ok = 0; for (var i = 0; i < all.length; ++i) if (all[i].complete \&\& all[i].naturalWidth > 0) ++ok; document.body.setAttribute("data-images", all.length + " " + ok); });</script></body>#' "$tmp/out/report.html" > "$tmp/probe.html"
browse --dump-dom "file://$tmp/probe.html" > "$tmp/dom.html"; st=$?
check "chromium read the page" '[ $st -eq 0 ] && grep -q ">Summary</h2>" "$tmp/dom.html"'
images=$(sed -n 's/.*data-images="\([0-9]*\) \([0-9]*\)".*/\1 \2/p' "$tmp/dom.html")
check "every image loaded: 4 maps (3 grids' E, the wall's AO) and 2 polar diagrams (found: ${images:-none})" '[ "$images" = "6 6" ]'

# 2. The screenshot of the report itself is not blank: the page from the
# maps' heading on (the cover, summary and luminaire list come first).
python3 - "$tmp/out/report.html" "$tmp/maps.html" <<'PY'
import sys
page = open(sys.argv[1], encoding="utf-8").read()
head, body = page.split("<body>", 1)
start = body.index(">Maps</h2>")
start = body.rindex("<h2", 0, start)
open(sys.argv[2], "w", encoding="utf-8").write(head + "<body>\n" + body[start:])
PY
browse --screenshot="$tmp/shot.png" --window-size=900,1800 "file://$tmp/maps.html" > /dev/null; st=$?
check "screenshot taken" '[ $st -eq 0 ] && [ -s "$tmp/shot.png" ]'
python3 - "$tmp/shot.png" > "$tmp/pixels.txt" <<'PY'
import struct, sys, zlib
data = open(sys.argv[1], "rb").read()
assert data[:8] == b"\x89PNG\r\n\x1a\n"
pos, idat, header = 8, b"", None
while pos < len(data):
    n, kind = struct.unpack(">I4s", data[pos:pos + 8])
    body = data[pos + 8:pos + 8 + n]
    if kind == b"IHDR": header = struct.unpack(">IIBBBBB", body)
    if kind == b"IDAT": idat += body
    pos += 12 + n
w, h, depth, colour, _, _, interlace = header
assert depth == 8 and colour in (2, 6) and interlace == 0, header
bpp = 3 if colour == 2 else 4
raw, stride, prev, rows = zlib.decompress(idat), w * bpp, bytearray(w * bpp), []
for y in range(h):
    f, line = raw[y * (stride + 1)], bytearray(raw[y * (stride + 1) + 1:(y + 1) * (stride + 1)])
    for i in range(stride):  # PNG filters (ISO/IEC 15948, 9.2)
        a = line[i - bpp] if i >= bpp else 0
        b, c = prev[i], prev[i - bpp] if i >= bpp else 0
        if f == 1: line[i] = (line[i] + a) & 255
        elif f == 2: line[i] = (line[i] + b) & 255
        elif f == 3: line[i] = (line[i] + (a + b) // 2) & 255
        elif f == 4:
            p = a + b - c; pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
            line[i] = (line[i] + (a if pa <= pb and pa <= pc else b if pb <= pc else c)) & 255
    rows.append(line); prev = line
dark = coloured = 0
for line in rows:
    for x in range(0, stride, bpp):
        r, g, b = line[x], line[x + 1], line[x + 2]
        dark += r < 80 and g < 80 and b < 80
        coloured += max(r, g, b) - min(r, g, b) > 60  # the palette's blues, teals, greens, yellows
print(w * h, dark, coloured)
PY
read -r total dark coloured < "$tmp/pixels.txt"
check "screenshot: text on the page (${dark:-0} dark pixels of ${total:-0})" '[ "${dark:-0}" -gt 5000 ]'
check "screenshot: the false-colour maps show (${coloured:-0} coloured pixels)" '[ "${coloured:-0}" -gt 20000 ]'
exit $fail
