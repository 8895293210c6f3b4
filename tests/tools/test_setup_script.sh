#!/usr/bin/env bash
# scripts/setup.sh without touching the machine: dpkg-query, apt-get, sudo and
# id are replaced by stand-ins on PATH that record what the script asks for.
# It must install exactly the packages that are missing, do nothing (and say
# nothing) when all are present, and name every package the project needs.
set -u
: "${CANDELA_SOURCE_DIR:?}"
fail=0
check() { if eval "$2"; then echo "ok: $1"; else echo "FAIL: $1"; fail=1; fi; }
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
mkdir -p "$tmp/bin"

# dpkg-query -W -f=... PACKAGE: installed unless PACKAGE is in $FAKE_MISSING.
cat > "$tmp/bin/dpkg-query" <<'SH'
#!/usr/bin/env bash
p=${!#}
echo "$p" >> "$FAKE_LOG.queried"
for m in $FAKE_MISSING; do [ "$m" = "$p" ] && { echo "dpkg-query: no packages found matching $p" >&2; exit 1; }; done
printf 'install ok installed'
SH
# apt-get records its arguments; sudo runs its command; id says "not root"
# when FAKE_USER is set, so the sudo path is taken.
cat > "$tmp/bin/apt-get" <<'SH'
#!/usr/bin/env bash
echo "apt-get $*" >> "$FAKE_LOG"
SH
cat > "$tmp/bin/sudo" <<'SH'
#!/usr/bin/env bash
echo "sudo" >> "$FAKE_LOG"
exec "$@"
SH
cat > "$tmp/bin/id" <<'SH'
#!/usr/bin/env bash
[ "$1" = -u ] && { [ -n "${FAKE_USER:-}" ] && echo 1000 || echo 0; exit 0; }
exec /usr/bin/id "$@"
SH
# npm records its arguments (the glTF validator's install).
cat > "$tmp/bin/npm" <<'SH'
#!/usr/bin/env bash
echo "npm $*" >> "$FAKE_LOG"
SH
chmod +x "$tmp/bin/"*

# The validator's folder: its package.json, and node_modules holding the
# pinned version ("present") or nothing ("absent").
for v in present absent; do
  mkdir -p "$tmp/validator-$v"
  cp "$CANDELA_SOURCE_DIR/tools/gltf_validator/package.json" "$tmp/validator-$v/"
done
want=$(sed -n 's/.*"gltf-validator": *"\([^"]*\)".*/\1/p' "$CANDELA_SOURCE_DIR/tools/gltf_validator/package.json")
mkdir -p "$tmp/validator-present/node_modules/gltf-validator"
printf '{\n  "name": "gltf-validator",\n  "version": "%s"\n}\n' "$want" \
  > "$tmp/validator-present/node_modules/gltf-validator/package.json"

# run NAME MISSING [USER [VALIDATOR]]: run setup.sh; its output in
# $tmp/NAME.out. VALIDATOR: present (the default) or absent.
run() {
  local log="$tmp/$1.log"
  : > "$log"
  PATH="$tmp/bin:$PATH" FAKE_LOG="$log" FAKE_MISSING="$2" FAKE_USER="${3:-}" \
    CANDELA_GLTF_VALIDATOR_DIR="$tmp/validator-${4:-present}" \
    bash "$CANDELA_SOURCE_DIR/scripts/setup.sh" > "$tmp/$1.out" 2>&1
}

# Everything present: exit 0, no output, apt-get never called.
run present ""; st=$?
check "all present: exit 0" '[ $st -eq 0 ]'
check "all present: prints nothing" '[ ! -s "$tmp/present.out" ]'
check "all present: apt-get not called" '[ ! -s "$tmp/present.log" ]'

# Every package the issue names is among those the script checks.
for p in libopenexr-dev libopencolorio-dev libcgal-dev libembree-dev libtbb-dev pkg-config cmake \
         build-essential libcjson-dev python3-jsonschema libopenmpi-dev openmpi-bin libopenblas-dev; do
  check "checks $p" 'grep -qx "$p" "$tmp/present.log.queried"'
done

# Two missing, as root: one update, then an install of exactly those two.
run two "libembree-dev libcjson-dev"; st=$?
check "two missing: exit 0" '[ $st -eq 0 ]'
check "two missing: apt-get update then install" \
  '[ "$(cut -d" " -f2 "$tmp/two.log" | tr "\n" " ")" = "update install " ]'
install_line=$(grep "apt-get install" "$tmp/two.log")
installed=$(echo "$install_line" | tr " " "\n" | grep -v "^-" | grep -vx "apt-get\|install" | sort | tr "\n" " ")
check "two missing: installs exactly them (got: $installed)" '[ "$installed" = "libcjson-dev libembree-dev " ]'
check "two missing: non-interactive" '[[ "$install_line" == *" -y "* ]]'
check "two missing: says what it installs" 'grep -q "libembree-dev libcjson-dev" "$tmp/two.out"'
check "as root: no sudo" '! grep -qx sudo "$tmp/two.log"'

# Not root: the same through sudo.
run user "cmake" yes; st=$?
check "not root: exit 0" '[ $st -eq 0 ]'
check "not root: apt-get through sudo" '[ "$(grep -c -x sudo "$tmp/user.log")" -eq 2 ]'
check "not root: installs cmake" 'grep -q "apt-get install .*cmake" "$tmp/user.log"'

# The glTF validator missing: npm ci into its folder, said on stderr; no apt-get.
run validator "" "" absent; st=$?
check "validator missing: exit 0" '[ $st -eq 0 ]'
check "validator missing: npm ci into its folder" \
  '[ "$(cat "$tmp/validator.log")" = "npm ci --prefix $tmp/validator-absent --no-audit --no-fund --loglevel=error" ]'
check "validator missing: says so" 'grep -q "glTF validator $want" "$tmp/validator.out"'
exit $fail
