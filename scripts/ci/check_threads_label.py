#!/usr/bin/env python3
"""Every test that touches threads has the ctest label `threads` (it always runs under TSan).

    check_threads_label.py BUILD_DIR PROBE_DIR

PROBE_DIR holds what tests/tools/thread_probe.c wrote during the Release test run: one file
per process that started a thread or a child process, holding its command line. A test
touches threads when its own process is among them. Each such test must carry the label
`threads`, unless it runs in no sanitizer stage at all (labels web, models, validation,
scaleout, python). Exit 1, naming the tests, when one does not.
"""
import collections
import json
import pathlib
import subprocess
import sys

NEVER_SANITIZED = {"web", "models", "validation", "scaleout", "python"}


def ctest_tests(build_dir):
    """{arguments: [(name, labels)]} of every test ctest knows in build_dir, keyed by its
    command without the program: an interpreter may re-execute itself under another path
    (a pyenv shim), and two tests may share their arguments (the two Python venvs)."""
    listing = subprocess.run(["ctest", "--test-dir", str(build_dir), "--show-only=json-v1"],
                             check=True, capture_output=True, text=True).stdout
    tests = collections.defaultdict(list)
    for test in json.loads(listing)["tests"]:
        labels = set()
        for prop in test.get("properties", []):
            if prop["name"] == "LABELS":
                labels = set(prop["value"])
        if "command" in test:
            tests[tuple(test["command"][1:])].append((test["name"], labels))
    return tests


def main():
    build_dir, probe_dir = map(pathlib.Path, sys.argv[1:3])
    tests = ctest_tests(build_dir)
    touching = {}
    for note in probe_dir.iterdir():
        argv = note.read_bytes().decode(errors="replace").split("\0")[:-1]
        for name, labels in tests.get(tuple(argv[1:]), []):
            touching[name] = labels
    unlabelled = sorted(name for name, labels in touching.items()
                        if "threads" not in labels and not labels & NEVER_SANITIZED)
    print(f"threads label: {len(touching)} tests started threads or child processes; "
          f"{sum('threads' in labels for labels in touching.values())} of them are labelled threads")
    for name in unlabelled:
        print(f"threads label: MISSING on {name}: it starts threads or child processes, so it must run under TSan")
    if unlabelled:
        print("threads label: add their suites to TLMHUB_THREADS_SUITES in tests/CMakeLists.txt (a ctest of its own: the label threads)")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
