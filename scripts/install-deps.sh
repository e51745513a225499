#!/usr/bin/env bash
# Install the Debian 12 packages tlmhub builds against (skips what is already there).
# `--with-browser` adds Chromium, which the browser tests drive.
set -euo pipefail
packages=(build-essential cmake pkg-config libmuparser-dev libpugixml-dev nlohmann-json3-dev
          libgtest-dev libbenchmark-dev libboost-dev libboost-system-dev libsqlite3-dev
          libsqlitecpp-dev libsodium-dev)
# The web app needs Node.js and npm; a machine that already has them (any install) keeps them.
command -v npm >/dev/null 2>&1 || packages+=(nodejs npm)
[ "${1:-}" = "--with-browser" ] && packages+=(chromium)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}"
fi
