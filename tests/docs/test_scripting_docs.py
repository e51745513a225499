#!/usr/bin/env python3
"""Runs every example of docs/scripting.md against a real tlmhub-server, so the guide
cannot drift from the server, the Python client and `tlmhub-cli remote`.

    test_scripting_docs.py [docs/scripting.md]

Fenced blocks tagged ```sh and ```python (at the start of a line) run in the order they
appear, as a reader would type them into one terminal and one Python session: the sh blocks
share their shell variables and functions (each block runs under `set -e -o pipefail`, in
bash, then hands on what it defined), the Python blocks share one namespace. All run in one
fresh directory, with the environment the guide declares in its `<!-- environment: ... -->`
line; a declared name this script does not provide (or the reverse) is a failure. Every
block runs even after one fails; the script fails if any did.

Environment: TLMHUB_SERVER_BIN, TLMHUB_SHARED_DIR (as the client's tests), TLMHUB_CLI_BIN
(tlmhub-cli, put on PATH for the blocks). Run it with a Python that has the tlmhub package
(tests/python.cmake uses the client's system venv)."""
from __future__ import annotations

import os
import re
import subprocess
import sys
import tempfile
import traceback
from pathlib import Path

REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "clients" / "python" / "tests"))
from harness import ADMIN_PASSWORD, Server, required_env, shared_model  # noqa: E402

import tlmhub  # noqa: E402

FENCE = re.compile(r"^```(sh|python)\s*$")
DECLARATION = re.compile(r"<!--\s*environment:\s*([A-Z_ ]+?)\s*-->")

# Each sh block runs in bash after the variables and functions of the blocks before it, and
# writes those it defined (anything not in bash's starting set) for the next one.
SH_WRAPPER = r"""
__tlmhub_before=$(compgen -v; compgen -A function)
if [ -f "$1" ]; then source "$1"; fi
set -e -o pipefail
source "$2"
set +e
{
  for __tlmhub_name in $(compgen -v); do
    case "$__tlmhub_name" in __tlmhub_*|BASH*|FUNCNAME|PIPESTATUS|_) continue;; esac
    grep -qxF "$__tlmhub_name" <<< "$__tlmhub_before" || declare -p "$__tlmhub_name"
  done
  for __tlmhub_name in $(compgen -A function); do
    grep -qxF "$__tlmhub_name" <<< "$__tlmhub_before" || declare -f "$__tlmhub_name"
  done
} > "$1.new" && mv "$1.new" "$1"
"""


def blocks(text: str) -> list[tuple[int, str, str]]:
    """(line number, language, code) of each ```sh and ```python block."""
    found = []
    lines = text.splitlines()
    at = 0
    while at < len(lines):
        match = FENCE.match(lines[at])
        if match:
            end = next(i for i in range(at + 1, len(lines)) if lines[i].startswith("```"))
            found.append((at + 1, match.group(1), "\n".join(lines[at + 1:end]) + "\n"))
            at = end
        at += 1
    return found


def api_token(server: Server) -> tuple[str, str | None]:
    """TLMHUB_TOKEN for the blocks, made the way the guide says. While the server has no
    /tokens yet, a login session stands in so the other blocks can still be checked; the
    run fails all the same (the second value says why)."""
    admin = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)
    try:
        return admin.tokens.create("docs test")["token"], None
    except tlmhub.ApiError as error:
        if error.status != 404:
            raise
        return admin._transport.token, f"the server has no /tokens ({error}); used a login session"


def main() -> int:
    doc = Path(sys.argv[1] if len(sys.argv) > 1 else REPO / "docs" / "scripting.md")
    text = doc.read_text()
    cli = Path(required_env("TLMHUB_CLI_BIN"))
    if not os.access(cli, os.X_OK):
        raise RuntimeError(f"TLMHUB_CLI_BIN={cli} is not an executable")
    declared = DECLARATION.search(text)
    if not declared:
        raise RuntimeError(f"{doc}: no <!-- environment: ... --> line")

    server = Server()
    failures: list[str] = []
    try:
        work = Path(tempfile.mkdtemp(prefix="tlmhub-docs-", dir=server.directory))
        token, token_problem = api_token(server)
        if token_problem:
            failures.append(token_problem)
        provided = {"TLMHUB_URL": server.url, "TLMHUB_USER": "admin",
                    "TLMHUB_PASSWORD": ADMIN_PASSWORD, "TLMHUB_TOKEN": token,
                    "MODEL": str(shared_model())}
        if set(declared.group(1).split()) != set(provided):
            raise RuntimeError(f"{doc} declares {declared.group(1).split()}, "
                               f"this test provides {sorted(provided)}")
        # The blocks call `tlmhub-cli` and `python3` by name: this one and this Python.
        # HOME and XDG_CONFIG_HOME: `tlmhub-cli remote login` writes its credentials there.
        bin_dir = work / ".bin"
        bin_dir.mkdir()
        (bin_dir / "tlmhub-cli").symlink_to(cli.resolve())
        (bin_dir / "python3").symlink_to(sys.executable)
        os.environ.update(provided, HOME=str(work), XDG_CONFIG_HOME=str(work / ".config"),
                          PATH=os.pathsep.join([str(bin_dir), os.environ["PATH"]]))
        os.chdir(work)
        shell_state = work / ".shell-state"
        namespace: dict[str, object] = {"__name__": "__main__"}
        for line, language, code in blocks(text):
            print(f"--- {doc.name}:{line} ({language})", flush=True)
            if language == "sh":
                script = work / ".block.sh"
                script.write_text(code)
                ok = subprocess.run(["bash", "-c", SH_WRAPPER, "block", str(shell_state), str(script)],
                                    timeout=180).returncode == 0
            else:
                try:
                    exec(compile(code, f"{doc.name}:{line}", "exec"), namespace)
                    ok = True
                except Exception:
                    traceback.print_exc()
                    ok = False
            if not ok:
                failures.append(f"{doc.name}:{line} ({language}) failed")
    finally:
        server.stop()
    for failure in failures:
        print("FAILED:", failure)
    print(f"{len(blocks(text))} blocks, {len(failures)} failures")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
