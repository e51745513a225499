#!/usr/bin/env bash
# Install dependencies, build, and run tlmhub on its example model (CSV to build/example.csv).
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
build/bin/tlmhub-cli run examples/pressure-build-up.hmf --csv build/example.csv
echo "Results written to build/example.csv"
