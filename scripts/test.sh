#!/usr/bin/env bash
# Install dependencies, build, and run the whole test suite (unit tests and validation
# against Hopsan's reference results in ../shared).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
cd build && ctest --output-on-failure -j"$(nproc)"
