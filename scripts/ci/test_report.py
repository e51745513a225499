#!/usr/bin/env python3
"""What one stage of scripts/test.sh ran, how long it took, and whether anything went missing.

    test_report.py --stage NAME --junit CTEST.xml [--reports DIR] [--expected FILE] [--update]

Reads ctest's JUnit file (`ctest --output-junit`) and the JUnit files that the test runners
inside single ctests wrote to DIR (Vitest, Playwright). Test names are
  * the ctest name (for gtest_discover_tests that is `Suite.Case`);
  * `CTEST :: Suite.Case` for the gtest cases of a ctest that runs a whole executable
    (read from its output, `[       OK ] Suite.Case`);
  * `CTEST :: module.Class.test` for Python's unittest (read from its `-v` output);
  * `vitest :: FILE > NAME` and `playwright :: FILE > NAME` from DIR.
A test that was skipped or not run does not count as run.

Prints the stage's 15 slowest ctests. With --expected, fails (exit 1) when a listed test did
not run, or a test ran that the list does not have (new tests are added to the list in the
commit that adds them). --update writes the names that ran to the list instead.
"""
import argparse
import pathlib
import re
import sys
import xml.etree.ElementTree as ElementTree

GTEST_CASE = re.compile(r"^\[\s+(?:OK|FAILED)\s+\] (\S+\.\S+) \(\d+ ms\)$", re.MULTILINE)
# A unittest case's line: "name (module.Class.name) ... " (a docstring may come first on a
# line of its own), then its outcome at once, or on a line of its own when something the test
# wrote (a warning) came in between.
UNITTEST_START = re.compile(r"^(\w+) \(([\w.]+)\)(?:\n.*)? \.\.\. ", re.MULTILINE)
UNITTEST_OUTCOME = re.compile(r"^(?:ok|FAIL|ERROR|expected failure|unexpected success)$", re.MULTILINE)


def ctest_results(path):
    """[(name, seconds, ran, output)] from ctest's JUnit file."""
    results = []
    for case in ElementTree.parse(path).getroot().iter("testcase"):
        status = case.get("status", "")
        output = case.findtext("system-out") or ""
        skipped = case.find("skipped") is not None
        ran = status in ("run", "fail") and not skipped
        results.append((case.get("name"), float(case.get("time") or 0), ran, output))
    return results


def inner_names(ctest_name, output):
    """Names of the tests a single ctest ran inside it (several gtest cases, unittest)."""
    names = []
    gtest_cases = GTEST_CASE.findall(output)
    # One case in a ctest of its own (gtest_discover_tests) is that ctest; a whole suite
    # (`Suite.*`) or executable lists its cases.
    if len(gtest_cases) > 1 or (gtest_cases and ctest_name.endswith(".*")):
        names += [f"{ctest_name} :: {case}" for case in gtest_cases]
    starts = list(UNITTEST_START.finditer(output))
    for at, start in enumerate(starts):
        end = starts[at + 1].start() if at + 1 < len(starts) else len(output)
        rest_of_line = output[start.end():end].split("\n", 1)[0]
        if UNITTEST_OUTCOME.fullmatch(rest_of_line) or UNITTEST_OUTCOME.search(output, start.end(), end):
            names.append(f"{ctest_name} :: {start.group(2)}")
    return names


def runner_names(reports, ctest_junit):
    """Names from the JUnit files that Vitest and Playwright wrote (see web/)."""
    names = []
    for path in sorted(reports.glob("*.xml")):
        if path.resolve() == ctest_junit.resolve():
            continue
        runner = path.stem.split("-")[0]
        for case in ElementTree.parse(path).getroot().iter("testcase"):
            if case.find("skipped") is not None:
                continue
            names.append(f"{runner} :: {case.get('classname')} > {case.get('name')}")
    return names


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--stage", required=True)
    parser.add_argument("--junit", required=True, type=pathlib.Path)
    parser.add_argument("--reports", type=pathlib.Path)
    parser.add_argument("--expected", type=pathlib.Path)
    parser.add_argument("--update", action="store_true", help="write the names that ran to --expected")
    args = parser.parse_args()

    results = ctest_results(args.junit)
    ran = set()
    for name, _, did_run, output in results:
        if did_run:
            ran.add(name)
            ran.update(inner_names(name, output))
    if args.reports and args.reports.is_dir():
        ran.update(runner_names(args.reports, args.junit))

    slowest = sorted(results, key=lambda result: result[1], reverse=True)[:15]
    total = sum(result[1] for result in results)
    print(f"stage {args.stage}: {len(ran)} tests ran ({sum(r[2] for r in results)} ctests, "
          f"{total:.0f} s of test time); the 15 slowest ctests:")
    for name, seconds, _, _ in slowest:
        print(f"  {seconds:8.2f} s  {name}")

    if not args.expected:
        return 0
    if args.update:
        args.expected.write_text("".join(f"{name}\n" for name in sorted(ran)))
        print(f"stage {args.stage}: wrote {len(ran)} names to {args.expected}")
        return 0
    expected = {line for line in args.expected.read_text().splitlines() if line and not line.startswith("#")}
    missing = sorted(expected - ran)
    unlisted = sorted(ran - expected)
    for name in missing:
        print(f"stage {args.stage}: MISSING (listed in {args.expected.name}, did not run): {name}")
    for name in unlisted:
        print(f"stage {args.stage}: UNLISTED (ran, not in {args.expected.name}): {name}")
    if missing or unlisted:
        print(f"stage {args.stage}: {len(missing)} listed tests did not run, {len(unlisted)} ran unlisted; "
              f"a test removed or added on purpose is removed from or added to {args.expected} in the same "
              f"commit (scripts/ci/test_report.py --update writes the list)")
        return 1
    print(f"stage {args.stage}: all {len(expected)} listed tests ran")
    return 0


if __name__ == "__main__":
    sys.exit(main())
