#!/usr/bin/env bash
# Install the Debian 12 packages Candela needs to build and test, and the
# Khronos glTF validator (from the npm registry, for the test of scene.glb).
# Idempotent: when everything is present it prints nothing and changes nothing.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)

packages=(
  build-essential cmake pkg-config
  libopenexr-dev libopencolorio-dev libcgal-dev libembree-dev libtbb-dev
  libgmp-dev libmpfr-dev libboost-dev
  libcjson-dev libpng-dev zlib1g-dev
  clang libclang-rt-14-dev
  libxml2-utils
  python3-jsonschema
  python3-numpy python3-pytest python3-pip python3-setuptools python3-wheel python3-venv python3-matplotlib
  libcairo2-dev libpango1.0-dev
  fonts-dejavu-core chromium poppler-utils
)

# Node.js and npm run the glTF validator; a machine that has them from
# elsewhere (NodeSource) keeps its own.
if ! command -v node >/dev/null || ! command -v npm >/dev/null; then
  packages+=(nodejs npm)
fi

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done

if [[ ${#missing[@]} -gt 0 ]]; then
  echo "setup: installing ${missing[*]}" >&2
  sudo_cmd=()
  if [[ $(id -u) -ne 0 ]]; then
    command -v sudo >/dev/null || { echo "setup: need root or sudo to install packages" >&2; exit 3; }
    sudo_cmd=(sudo)
  fi
  export DEBIAN_FRONTEND=noninteractive
  "${sudo_cmd[@]}" apt-get update -qq >/dev/null
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# The Khronos glTF validator, the version tools/gltf_validator/package.json
# pins (its package-lock.json holds the checksum), installed into that
# folder's node_modules by npm ci unless that version is already there.
validator_dir=${CANDELA_GLTF_VALIDATOR_DIR:-$root/tools/gltf_validator}
want=$(sed -n 's/.*"gltf-validator": *"\([^"]*\)".*/\1/p' "$validator_dir/package.json")
if ! grep -qs "\"version\": *\"$want\"" "$validator_dir/node_modules/gltf-validator/package.json"; then
  echo "setup: installing the glTF validator $want (npm) into $validator_dir" >&2
  npm ci --prefix "$validator_dir" --no-audit --no-fund --loglevel=error >/dev/null
fi
