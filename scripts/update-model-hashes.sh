#!/usr/bin/env bash
# Rewrite tests/models/hashes.txt: the SHA-256 of `tlmhub-cli run --csv` output of every .hmf
# under ../shared/hopsan-models and ../shared/bench-models that runs to its stop time or to the
# end a component of the model designs (SignalStopSimulation; its message is checked through
# tests/models/outcomes.txt too). The ones ending with an error are checked against
# tests/models/outcomes.txt alone.
# Run it only for an intended change of results, and say in the commit why they changed.
# JOBS=N runs N models at a time (default 2).
set -euo pipefail
cd "$(dirname "$0")/.."
export CLI=${CLI:-build/bin/tlmhub-cli}
shared=../shared
out=tests/models/hashes.txt
hashOne() {
  local hmf=$1 line
  if line=$("$CLI" run "$hmf" --sha256 2>/dev/null); then
    echo "${line##*csv sha256 }  ${hmf#../shared/}"
  fi
}
export -f hashOne
tmp=$(mktemp)
{
  echo "# SHA-256 of 'tlmhub-cli run MODEL --csv' output, path relative to ../shared (scripts/update-model-hashes.sh)."
  find "$shared/hopsan-models" "$shared/bench-models" -name '*.hmf' -print0 |
    xargs -0 -n1 -P"${JOBS:-2}" bash -c 'hashOne "$0"' | LC_ALL=C sort -k2
} > "$tmp"
mv "$tmp" "$out"
echo "wrote $out ($(grep -c '^[0-9a-f]' "$out") models)"
