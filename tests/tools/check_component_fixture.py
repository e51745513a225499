#!/usr/bin/env python3
"""Checks that the web app's component-type fixture (web/src/model/componentTypes.fixture.json,
which Vitest's port-placement proof and type-replacement tests read instead of a server) is
what the engine's catalogue says today: every type with its ports (name, node type, port type)
and parameter names, as `tlmhub-cli components --json` lists them.

    check_component_fixture.py TLMHUB_CLI FIXTURE            exits 1 naming the types that differ
    check_component_fixture.py TLMHUB_CLI FIXTURE --write    writes the fixture anew
"""
import json
import subprocess
import sys


def fixture_entry(component):
    return {
        "type": component["type"],
        "ports": [{"name": p["name"], "nodetype": p["nodetype"], "porttype": p["porttype"]} for p in component["ports"]],
        "parameters": [p["name"] for p in component["parameters"]],
    }


def main():
    cli, fixture_path = sys.argv[1], sys.argv[2]
    listed = json.loads(subprocess.run([cli, "components", "--json"], check=True, capture_output=True, text=True).stdout)
    expected = [fixture_entry(c) for c in listed]
    if "--write" in sys.argv[3:]:
        with open(fixture_path, "w") as out:
            out.write("[\n" + ",\n".join(json.dumps(e, separators=(",", ":")) for e in expected) + "\n]\n")
        return 0
    with open(fixture_path) as f:
        fixture = json.load(f)
    have = {e["type"]: e for e in fixture}
    want = {e["type"]: e for e in expected}
    problems = [f"missing from the fixture: {t}" for t in sorted(want.keys() - have.keys())]
    problems += [f"no longer a component type: {t}" for t in sorted(have.keys() - want.keys())]
    problems += [f"differs from the catalogue: {t}" for t in sorted(want.keys() & have.keys()) if want[t] != have[t]]
    for p in problems:
        print(p)
    if problems:
        print(f"{len(problems)} difference(s); write the fixture anew with: {sys.argv[0]} {cli} {fixture_path} --write")
        return 1
    print(f"the fixture matches the catalogue: {len(want)} types")
    return 0


if __name__ == "__main__":
    sys.exit(main())
