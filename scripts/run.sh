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
# Every job allocates and frees a few MiB (logs, result columns, the stored blob). glibc's
# defaults map and unmap each such block, so every job pays page faults for memory the last
# one returned; keeping blocks up to 32 MiB in a heap that is not trimmed halves a class's
# wait (bench/lab_load.py, 40 Position Servo jobs on 2 workers: 1.5-2.0 s -> 0.7-0.9 s).
# (The same settings made with mallopt() at start-up did not help; the tunables do.)
export GLIBC_TUNABLES="${GLIBC_TUNABLES:-glibc.malloc.mmap_threshold=33554432:glibc.malloc.trim_threshold=1073741824}"
exec build/bin/tlmhub-server "${examples[@]}" "$@"
