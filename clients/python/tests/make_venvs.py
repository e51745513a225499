#!/usr/bin/env python3
"""Builds the two virtual environments the client's tests run in, offline, from the source
tree, and checks each is what its tests expect (tests/python.cmake runs this as a ctest):

  DIR/system    `--system-site-packages`: Debian's python3-numpy, python3-websocket and
                python3-pandas are visible.
  DIR/isolated  a plain venv: no system packages, so neither NumPy nor websocket-client nor
                pandas, and no `wheel` package either.
Both install the package as docs/scripting.md says,
`pip install --no-index --no-build-isolation clients/python`: the package's own build
backend (_build/tlmhub_build.py) needs nothing beyond the standard library.

    make_venvs.py [--python /usr/bin/python3] DIR

Both are made anew each time. The package is built from a copy in DIR/src, so nothing a
build writes lands in the source tree."""
import argparse
import shutil
import subprocess
import sys
from pathlib import Path

SOURCE = Path(__file__).resolve().parents[1]


def run(*args: object) -> None:
    print("+", " ".join(str(a) for a in args), flush=True)
    subprocess.run([str(a) for a in args], check=True)


def importable(python: Path, module: str) -> bool:
    return subprocess.run([str(python), "-c", f"import {module}"],
                          capture_output=True).returncode == 0


def check(python: Path, *, numpy: bool, websocket: bool, pandas: bool) -> None:
    """Fails unless the venv has exactly the optional modules its tests are told to expect,
    and has tlmhub installed in it."""
    problems = []
    for module, wanted, package in (("numpy", numpy, "python3-numpy"),
                                     ("websocket", websocket, "python3-websocket"),
                                     ("pandas", pandas, "python3-pandas")):
        if importable(python, module) != wanted:
            problems.append(f"{module} {'missing (apt-get install ' + package + ')' if wanted else 'present'}")
    where = subprocess.run([str(python), "-c", "import tlmhub, sys; print(tlmhub.__file__.startswith(sys.prefix))"],
                           capture_output=True, text=True, cwd="/")
    if where.stdout.strip() != "True":
        problems.append("tlmhub is not installed in the venv: " + where.stdout + where.stderr)
    if problems:
        sys.exit(f"{python}: " + "; ".join(problems))


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--python", default="/usr/bin/python3", help="Debian's Python 3.11")
    parser.add_argument("dir", type=Path)
    args = parser.parse_args()
    root = args.dir.resolve()
    src = root / "src"
    shutil.rmtree(src, ignore_errors=True)
    shutil.copytree(SOURCE, src, ignore=shutil.ignore_patterns(
        "tests", "build", "*.egg-info", "__pycache__"))

    # Making a venv (ensurepip) takes most of the time: make the isolated one meanwhile.
    isolated = root / "isolated"
    print("+", args.python, "-m venv --clear", isolated, "(in the background)", flush=True)
    making_isolated = subprocess.Popen([args.python, "-m", "venv", "--clear", str(isolated)])
    system = root / "system"
    run(args.python, "-m", "venv", "--clear", "--system-site-packages", system)
    run(system / "bin" / "pip", "install", "--no-index", "--no-build-isolation", src)
    check(system / "bin" / "python", numpy=True, websocket=True, pandas=True)

    if making_isolated.wait() != 0:
        sys.exit(f"{args.python} -m venv {isolated} failed")
    run(isolated / "bin" / "pip", "install", "--no-index", "--no-build-isolation", src)
    check(isolated / "bin" / "python", numpy=False, websocket=False, pandas=False)


if __name__ == "__main__":
    main()
