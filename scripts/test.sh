#!/usr/bin/env bash
# Install dependencies, build, and run the whole test suite: unit tests, server tests on a
# real server process, validation against Hopsan's reference results in ../shared, and the
# web app's unit and browser tests (Debian's Chromium).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh --with-browser
scripts/build.sh
cd build && ctest --output-on-failure -j"$(nproc)"
