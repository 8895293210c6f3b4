#!/usr/bin/env bash
# `candela info --plot`: the polar diagram's SVG read back with xmllint.
#  1. the scale fits the peak: a 247 cd/klm peak on rings whose outer one
#     is 250 (the curve reaches 247/250 of the outer ring, at least 0.8;
#     a 1-2-5 scale put it on 500, at 0.49), 3 to 6 rings;
#  2. the ring labels (their own grey) keep clear of every curve;
#  3. a plane through a peak at C 233.8 is drawn (dotted green) and reaches
#     the peak; none for a symmetric file;
#  4. a title too long for a line stays inside the page: every glyph of the
#     figure lies within it;
#  5. the corpus file with a 247 cd/klm peak and the type B flood peaking
#     at C 233.8, when ../shared/photometric is there.
# Cairo draws text as glyphs: what the legend says is checked in
# tests/lights/photometry/test_photometry_plot.c from a PDF.
source "$(dirname "$0")/harness.sh"
command -v xmllint > /dev/null || { echo "SKIPPED: xmllint not installed"; exit 77; }
cx=280; cy=300
# the path data of every path stroked in a colour, one point "x y" per line
points() { xmllint --xpath "//*[local-name()=\"path\"][contains(@style,\"stroke:rgb($2)\")]/@d" "$1" 2>/dev/null | grep -oE '[-0-9.]+ [-0-9.]+' ; }
# the outer ring's radius: each ring starts at angle 0, "M cx+r cy" (its other points are Bezier handles)
ring() { xmllint --xpath "//*[local-name()=\"path\"][contains(@style,\"stroke:rgb(73%,73%,73%)\")]/@d" "$1" | grep -oE 'd="M [-0-9.]+' | awk -v cx=$cx '{ r = $2 - cx; if (r > m) m = r } END { printf "%.6f", m }'; }
# the largest distance of those points from the centre
reach() { points "$1" "$2" | awk -v cx=$cx -v cy=$cy '{ d = sqrt(($1-cx)^2 + ($2-cy)^2); if (d > m) m = d } END { printf "%.6f", m + 0 }'; }
curves() { { points "$1" "80%,0%,0%"; points "$1" "0%,0%,80%"; points "$1" "0%,50%,0%"; }; }
ies() { # file title peak_cd c_list cd_rows...
  local f=$1 title=$2; shift 2
  { echo "IESNA:LM-63-2002"; echo "[TEST] t"; echo "[TESTLAB] l"; echo "[ISSUEDATE] d"; echo "[MANUFAC] m"; echo "[LUMINAIRE] $title"
    echo "TILT=NONE"; printf '1 1000 1 7 %s 1 2 0 0 0\n1 1 10\n0 15 30 45 60 75 90\n' "$1"; shift; echo "$1"; shift
    for row in "$@"; do echo "$row"; done; } > "$f"
}

# 1, 2: a downlight of 247 cd/klm at nadir (lamp 1000 lm), rotational
ies "$tmp/down.ies" "Downlight" 1 "0" "247 230 180 110 40 5 0"
"$CANDELA" info --plot "$tmp/down.svg" "$tmp/down.ies" > /dev/null; st=$?
outer=$(ring "$tmp/down.svg"); peak=$(reach "$tmp/down.svg" "80%,0%,0%")
rings=$(xmllint --xpath 'count(//*[local-name()="path"][contains(@style,"stroke:rgb(73%,73%,73%)")])' "$tmp/down.svg")
check "scale: the curve reaches $peak of the outer ring's $outer (247/250), $rings rings" '[ $st -eq 0 ] && awk -v p="$peak" -v o="$outer" "BEGIN { exit !(o > 0 && p / o >= 0.8 && p / o <= 1.0 && (p / o - 0.988) ^ 2 < 1e-4) }" && [ "$rings" -ge 3 ] && [ "$rings" -le 6 ]'
labels() { xmllint --xpath '//*[local-name()="g"][contains(@style,"fill:rgb(30%,30%,30%)")]/*[local-name()="use"]' "$1" 2>/dev/null | grep -oE 'x="[-0-9.]+" y="[-0-9.]+"' | tr -d 'xy="' | tr '=' ' '; }
clear_of_curves() { # every ring-label glyph (box x..x+8, y-10..y+1) at least 1 pt from every curve point
  awk 'NR == FNR { px[++n] = $1; py[n] = $2; next }
       { for (i = 1; i <= n; ++i) { dx = (px[i] < $1) ? $1 - px[i] : (px[i] > $1 + 8 ? px[i] - $1 - 8 : 0);
                                      dy = (py[i] < $2 - 10) ? $2 - 10 - py[i] : (py[i] > $2 + 1 ? py[i] - $2 - 1 : 0);
                                      if (dx * dx + dy * dy < 1) bad++ } ++glyphs }
       END { exit !(glyphs > 0 && bad == 0) }' <(curves "$1") <(labels "$1")
}
check "ring labels: $(labels "$tmp/down.svg" | wc -l) glyphs, each clear of the curves" 'clear_of_curves "$tmp/down.svg"'

# 3: an asymmetric table whose peak lies at C 233.8 (IES H = 360 - C = 126.2)
ies "$tmp/asym.ies" "Asymmetric" 5 "0 90 126.2 180 270" \
  "100 100 100 100 100 100 0" "100 120 140 160 150 100 0" "100 200 400 700 500 100 0" "100 120 140 160 150 100 0" "100 100 100 100 100 100 0"
"$CANDELA" info --plot "$tmp/asym.svg" "$tmp/asym.ies" > /dev/null; st=$?
green=$(reach "$tmp/asym.svg" "0%,50%,0%"); all=$(curves "$tmp/asym.svg" | awk -v cx=$cx -v cy=$cy '{ d = sqrt(($1-cx)^2 + ($2-cy)^2); if (d > m) m = d } END { printf "%.6f", m }')
check "the plane through the peak at C 233.8: drawn, reaching the peak ($green of $all)" '[ $st -eq 0 ] && awk -v g="$green" -v a="$all" "BEGIN { exit !(g > 0 && g >= 0.999 * a) }"'
check "no such plane for a rotational downlight" '[ -z "$(points "$tmp/down.svg" "0%,50%,0%")" ]'

# 4: a title of 240 characters
long=$(printf 'Recessed linear luminaire with opal diffuser %.0s' 1 2 3 4 5 6)
ies "$tmp/long.ies" "$long" 1 "0" "247 230 180 110 40 5 0"
"$CANDELA" info --plot "$tmp/long.svg" "$tmp/long.ies" > /dev/null; st=$?
inside() { xmllint --xpath '//*[local-name()="use"]' "$1" | grep -oE 'x="[-0-9.]+" y="[-0-9.]+"' | tr -d 'xy="' | tr '=' ' ' | awk '{ if ($1 < 0 || $1 > 550 || $2 < 8 || $2 > 650) bad++; ++n } END { exit !(n > 0 && bad == 0) }'; }
check "a long title stays inside the page (every glyph within it)" '[ $st -eq 0 ] && inside "$tmp/long.svg"'
check "its <title> keeps the whole name" 'xmllint --xpath "string(//*[local-name()=\"title\"])" "$tmp/long.svg" | grep -q "opal diffuser Recessed linear luminaire with opal diffuser (cd/klm"'

# 5: the corpus files of the issues
dir=${CANDELA_PHOTOMETRIC_DIR:-}
if [ -f "$dir/ies_lithonia_AF10_bf088.ies" ]; then
  "$CANDELA" info --plot "$tmp/af.svg" "$dir/ies_lithonia_AF10_bf088.ies" > /dev/null
  o=$(ring "$tmp/af.svg"); p=$(curves "$tmp/af.svg" | awk -v cx=$cx -v cy=$cy '{ d = sqrt(($1-cx)^2 + ($2-cy)^2); if (d > m) m = d } END { printf "%.6f", m }')
  check "AF10: its 247 cd/klm peak reaches $p of the outer ring's $o" 'awk -v p="$p" -v o="$o" "BEGIN { exit !(p / o >= 0.8) }" && clear_of_curves "$tmp/af.svg" && inside "$tmp/af.svg"'
  "$CANDELA" info --plot "$tmp/flood.svg" "$dir/ies_rab_flood_typeB_half.IES" > /dev/null
  check "the type B flood peaking at C 233.8: the plane through its peak drawn" '[ -n "$(points "$tmp/flood.svg" "0%,50%,0%")" ] && inside "$tmp/flood.svg"'
else
  echo "skip: corpus not found"
fi
exit $fail
