#!/usr/bin/env bash
# Install the Debian 12 packages tlmhub builds against (skips what is already there).
# `--with-browser` adds Chromium, which the browser tests drive; `--with-clang` adds clang 14
# with libFuzzer and the sanitizer runtimes (the sanitizer and fuzz builds of scripts/test.sh).
set -euo pipefail
packages=(build-essential cmake ninja-build lld pkg-config libmuparser-dev libpugixml-dev nlohmann-json3-dev
          libgtest-dev libbenchmark-dev libboost-dev libboost-system-dev libsqlite3-dev
          libsqlitecpp-dev libsodium-dev libzstd-dev libzip-dev postgresql-15 libpqxx-dev libssl-dev nginx-light libldap-dev
          python3-venv python3-websocket python3-numpy)
# Without their Recommends: pandas would bring scipy, matplotlib and numba (89 packages),
# which nothing here uses. slapd: the LDAP directory the sign-in tests start on loopback.
lean_packages=(python3-pandas slapd)
# The web app needs Node.js and npm; a machine that already has them (any install) keeps them.
command -v npm >/dev/null 2>&1 || packages+=(nodejs npm)
for flag in "$@"; do
  case $flag in
    --with-browser) packages+=(chromium) ;;
    --with-clang) packages+=(clang-14 libfuzzer-14-dev libclang-rt-14-dev) ;;
    *) echo "install-deps.sh: unknown flag $flag" >&2; exit 1 ;;
  esac
done
installed() { dpkg-query -W -f='${Status}' "$1" 2>/dev/null | grep -q "install ok installed"; }
missing=() missing_lean=()
for p in "${packages[@]}"; do installed "$p" || missing+=("$p"); done
for p in "${lean_packages[@]}"; do installed "$p" || missing_lean+=("$p"); done
if [ $((${#missing[@]} + ${#missing_lean[@]})) -gt 0 ]; then
  SUDO=""; [ "$(id -u)" -ne 0 ] && SUDO="sudo"
  $SUDO apt-get update -qq
  [ ${#missing[@]} -eq 0 ] || DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq "${missing[@]}"
  [ ${#missing_lean[@]} -eq 0 ] ||
    DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing_lean[@]}"
fi
