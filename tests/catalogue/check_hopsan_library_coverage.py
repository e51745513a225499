#!/usr/bin/env python3
"""Every component type name of Hopsan's default library (../shared/reference/appearance.json)
must be in the catalogue that `tlmhub-cli components --json` prints, so any Hopsan model
opens. Run as: check_hopsan_library_coverage.py TLMHUB_CLI APPEARANCE_JSON"""
import json
import subprocess
import sys


def main() -> int:
    cli, appearance_path = sys.argv[1], sys.argv[2]
    with open(appearance_path, encoding="utf-8") as f:
        appearance = json.load(f)
    # Keys are "typename" or "typename|subtypename"; a subtype is the same component type.
    hopsan_types = {key.split("|")[0] for key in appearance["types"]}
    if len(hopsan_types) < 300:
        print(f"{appearance_path}: only {len(hopsan_types)} type names; is it the full reference?")
        return 1

    out = subprocess.run([cli, "components", "--json"], check=True, capture_output=True, text=True).stdout
    catalogue = {entry["type"] for entry in json.loads(out)}

    missing = sorted(hopsan_types - catalogue)
    print(f"{len(hopsan_types)} Hopsan type names, {len(catalogue)} catalogue types, {len(missing)} missing")
    for name in missing:
        print(f"missing: {name}")
    return 1 if missing else 0


if __name__ == "__main__":
    sys.exit(main())
