#!/usr/bin/env bash
# Runs the libFuzzer targets of a -DTLMHUB_FUZZ=ON build (fuzz/README.md), each with a fixed
# seed for a bounded time: first the inputs of past findings in fuzz/regressions/<target>/
# (each must pass), then fuzzing from the seeds (shared models and README examples, read in
# place) into a fresh corpus directory. Exits non-zero on the first crash, leak or timeout.
#   scripts/fuzz.sh [--build DIR] [--seconds N] [--corpus DIR] [TARGET...] [-- LIBFUZZER_ARGS]
# Defaults: build-asan, 30 s per target, a temporary corpus, every target. With --corpus,
# DIR/<target> keeps the corpus between runs (longer runs, see fuzz/README.md).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
shared=$root/../shared/hopsan-models
build=$root/build-asan seconds=30 corpus="" targets=() extra=()
while [ $# -gt 0 ]; do
  case $1 in
    --build) build=$2; shift 2 ;;
    --seconds) seconds=$2; shift 2 ;;
    --corpus) corpus=$2; shift 2 ;;
    --) shift; extra=("$@"); break ;;
    *) targets+=("$1"); shift ;;
  esac
done
[ ${#targets[@]} -gt 0 ] || targets=(hmf parameter-expression parameter-graph csv plo websocket rest static-files study-request lab-definitions binary-frame model-description)
[ -d "$shared" ] || { echo "fuzz.sh: no shared models at $shared" >&2; exit 1; }

# Seed directories per target, one a line (read only: libFuzzer writes only to the first
# corpus directory).
seeds_for() {
  local own=$root/fuzz/corpus/$1 readme=$build/fuzz/readme-seeds
  case $1 in
    hmf) printf '%s\n' "$shared/Example Models" "$shared/Component Test" ;;
    csv) printf '%s\n' "$own" "$shared/Example Models Validations" ;;
    websocket) printf '%s\n' "$readme/ws" ;;
    rest) printf '%s\n' "$own" "$readme/rest" ;;
    *) printf '%s\n' "$own" ;;
  esac
}

for t in "${targets[@]}"; do
  bin=$build/bin/tlmhub-fuzz-$t
  [ -x "$bin" ] || { echo "fuzz.sh: no $bin (configure with -DTLMHUB_FUZZ=ON)" >&2; exit 1; }
  flags=()
  [ -f "$root/fuzz/$t.dict" ] && flags=(-dict="$root/fuzz/$t.dict")
  # The shared CSVs are over 100 KB and the csv target converts every row and column of an
  # input (37 runs/s at full size); their first 4 KB cover the same code.
  [ "$t" = csv ] && flags+=(-max_len=4096)
  regressions=$root/fuzz/regressions/$t
  if [ -d "$regressions" ] && [ -n "$(ls -A "$regressions")" ]; then
    echo "== $t: replaying $regressions"
    "$bin" -runs=1 "$regressions"/*
  fi
  if [ -n "$corpus" ]; then work=$corpus/$t; mkdir -p "$work"; else work=$(mktemp -d); fi
  mapfile -t seeds < <(seeds_for "$t")
  echo "== $t: fuzzing ${seconds}s"
  status=0
  "$bin" -seed=1 -max_total_time="$seconds" -timeout=30 -rss_limit_mb=2048 -print_final_stats=1 \
         -artifact_prefix="${TMPDIR:-/tmp}/fuzz-$t-" "${flags[@]}" "${extra[@]}" "$work" "${seeds[@]}" || status=$?
  [ -n "$corpus" ] || rm -rf "$work"
  [ $status -eq 0 ] || { echo "fuzz.sh: $t failed (input saved as ${TMPDIR:-/tmp}/fuzz-$t-*)" >&2; exit $status; }
done
