#!/usr/bin/env bash
# Install dependencies, build, and start tlmhub-server with its defaults on
# http://127.0.0.1:8080 (data in ./data, the example models seeded on first start).
# First start: the administrator is 'admin' with the password in TLMHUB_ADMIN_PASSWORD,
# or a generated one printed below.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
scripts/build.sh
examples=(--examples-dir examples)
# Hopsan's example models, read in place when the shared directory is next to the repo.
shared="../shared/hopsan-models/Example Models"
[ -d "$shared" ] && examples+=(--examples-dir "$shared")
exec build/bin/tlmhub-server "${examples[@]}" "$@"
