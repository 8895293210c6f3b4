#!/usr/bin/env bash
# Install the Debian 12 packages Candela needs to build and test.
# Idempotent: when everything is present it prints nothing and changes nothing.
set -euo pipefail

packages=(
  build-essential cmake pkg-config
  libopenexr-dev libopencolorio-dev libcgal-dev libembree-dev libtbb-dev
  libgmp-dev libmpfr-dev libboost-dev
  libcjson-dev libpng-dev zlib1g-dev
  clang libclang-rt-14-dev
  libxml2-utils
  python3-jsonschema
  libcairo2-dev libpango1.0-dev
  libopenblas-dev
  fonts-dejavu-core chromium poppler-utils
)

missing=()
for p in "${packages[@]}"; do
  status=$(dpkg-query -W -f='${Status}' "$p" 2>/dev/null || true)
  [[ "$status" == "install ok installed" ]] || missing+=("$p")
done
[[ ${#missing[@]} -eq 0 ]] && exit 0

echo "setup: installing ${missing[*]}" >&2
sudo_cmd=()
if [[ $(id -u) -ne 0 ]]; then
  command -v sudo >/dev/null || { echo "setup: need root or sudo to install packages" >&2; exit 3; }
  sudo_cmd=(sudo)
fi
export DEBIAN_FRONTEND=noninteractive
"${sudo_cmd[@]}" apt-get update -qq >/dev/null
"${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
