#!/usr/bin/env bash
# candela solve -o OUTDIR when OUTDIR cannot hold the results: an existing
# file, a file among its parents, an empty name, a folder without write
# permission. Each is refused with a message naming the path and what was
# found, exit 1 (2 for the empty name, a usage error), before any solving,
# and nothing is written. A missing chain of folders is created.
# ctest-timeout: 120
set -u
: "${CANDELA:?}"
fail=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi; }
tmp=$(mktemp -d)
trap 'chmod -R u+w "$tmp" 2>/dev/null; rm -rf "$tmp"' EXIT
chmod 755 "$tmp"

cat > "$tmp/scene.json" <<'EOF'
{"version": 1,
 "luminaires": [{"type": "point", "position": [0, 0, 2], "intensity_cd": 400}],
 "grids": [{"name": "g", "type": "points", "points": [{"p": [0, 0, 0], "n": [0, 0, 1]}]}]}
EOF
# Loads, but cannot be solved (its photometric file is missing): shows that
# the output folder is checked before the solve.
cat > "$tmp/unsolvable.json" <<'EOF'
{"version": 1,
 "luminaires": [{"type": "goniometric", "file": "missing.ies", "position": [0, 0, 2]}],
 "grids": [{"name": "g", "type": "points", "points": [{"p": [0, 0, 0], "n": [0, 0, 1]}]}]}
EOF
chmod 644 "$tmp"/*.json
echo "not a folder" > "$tmp/afile"

"$CANDELA" solve "$tmp/scene.json" -o "$tmp/afile" --quiet >/dev/null 2>"$tmp/err"; st=$?
check "OUTDIR that is a file: exit 1" '[ $st -eq 1 ]'
check "OUTDIR that is a file: message" 'grep -q "afile: expected a folder for the results, found a file$" "$tmp/err"'
check "OUTDIR that is a file: file untouched" '[ "$(cat "$tmp/afile")" = "not a folder" ]'
check "OUTDIR that is a file: no temporary files" '[ -z "$(ls "$tmp" | grep -F .tmp.)" ]'

"$CANDELA" solve "$tmp/scene.json" -o "$tmp/afile/sub" --quiet >/dev/null 2>"$tmp/err"; st=$?
check "a file among OUTDIR's parents: exit 1" '[ $st -eq 1 ]'
check "a file among OUTDIR's parents: message names it" \
  'grep -q "afile/sub: expected a folder for the results, found a file at $tmp/afile$" "$tmp/err"'

"$CANDELA" solve "$tmp/unsolvable.json" -o "$tmp/afile" --quiet >/dev/null 2>"$tmp/err"; st=$?
check "OUTDIR checked before the solve" '[ $st -eq 1 ] && grep -q "expected a folder for the results" "$tmp/err" && ! grep -q missing.ies "$tmp/err"'

"$CANDELA" solve "$tmp/scene.json" -o "" --quiet >/dev/null 2>"$tmp/err"; st=$?
check "empty OUTDIR: usage error (exit 2)" '[ $st -eq 2 ] && grep -q "expected a folder name, found an empty string" "$tmp/err"'

"$CANDELA" solve "$tmp/scene.json" -o "$tmp/new/chain/of/folders" --quiet >/dev/null 2>"$tmp/err"; st=$?
check "missing folders are created" '[ $st -eq 0 ] && [ -s "$tmp/new/chain/of/folders/g.csv" ]'

# Permissions: as an unprivileged user (root may write anywhere).
mkdir -p "$tmp/readonly"
chmod 555 "$tmp/readonly"
as_user=()
if [ "$(id -u)" -eq 0 ]; then
  command -v setpriv >/dev/null || { echo "FAIL: running as root without setpriv: cannot test permissions"; exit 1; }
  as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups)
fi
"${as_user[@]}" "$CANDELA" solve "$tmp/scene.json" -o "$tmp/readonly" --quiet >/dev/null 2>"$tmp/err"; st=$?
check "read-only OUTDIR: exit 1" '[ $st -eq 1 ]'
check "read-only OUTDIR: message" \
  'grep -q "readonly: cannot write into the folder for the results: Permission denied" "$tmp/err"'
check "read-only OUTDIR: nothing written" '[ -z "$(ls -A "$tmp/readonly")" ]'
"${as_user[@]}" "$CANDELA" solve "$tmp/scene.json" -o "$tmp/readonly/sub" --quiet >/dev/null 2>"$tmp/err"; st=$?
check "OUTDIR inside a read-only folder: exit 1" '[ $st -eq 1 ]'
check "OUTDIR inside a read-only folder: message" \
  'grep -q "readonly/sub: cannot create the folder for the results: Permission denied" "$tmp/err"'
# A solve that fails after the folder was made for it leaves no empty folder
# behind; a folder that was there before stays.
"$CANDELA" solve "$tmp/unsolvable.json" -o "$tmp/fresh_out" --quiet >/dev/null 2>"$tmp/err"; st=$?
check "failed solve: exit 1, the new folder removed" '[ $st -eq 1 ] && [ ! -e "$tmp/fresh_out" ]'
mkdir "$tmp/kept_out"
"$CANDELA" solve "$tmp/unsolvable.json" -o "$tmp/kept_out" --quiet >/dev/null 2>"$tmp/err"; st=$?
check "failed solve: an existing folder stays" '[ $st -eq 1 ] && [ -d "$tmp/kept_out" ]'
exit $fail
