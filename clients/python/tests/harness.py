"""A real tlmhub-server for the tests, started the way tests/server/ServerHarness.cpp starts
one: any free loopback port, a fresh data directory, a known admin password, no examples.

The environment names what to test against, and a missing piece fails the tests, never
skips them:
  TLMHUB_SERVER_BIN   the tlmhub-server binary
  TLMHUB_SHARED_DIR   ../shared (the Hopsan models)
  TLMHUB_EXPECT_NUMPY, TLMHUB_EXPECT_WEBSOCKET, TLMHUB_EXPECT_PANDAS   "1" or "0": whether
                      this environment must have NumPy / websocket-client / pandas (ctest
                      sets them per venv; when unset the tests follow what is installed)
  TLMHUB_HANG_REPORT_SECONDS   optional: after this long, print every thread's stack and the
                      servers' recent output (ctest sets it a little under its timeout, which
                      would otherwise cut off unittest's report and leave a hang unexplained)"""
from __future__ import annotations

import faulthandler
import importlib.util
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import threading
import time
from pathlib import Path

ADMIN_PASSWORD = os.environ.get("TLMHUB_ADMIN_PASSWORD", "admin-secret-pw")
REPO = Path(__file__).resolve().parents[3]


def required_env(name: str) -> str:
    value = os.environ.get(name)
    if not value:
        raise RuntimeError(f"set {name} (see clients/python/tests/harness.py)")
    return value


def shared_model(name: str = "Position Servo") -> Path:
    """A model of ../shared/hopsan-models/Example Models."""
    path = Path(required_env("TLMHUB_SHARED_DIR")) / "hopsan-models" / "Example Models" / f"{name}.hmf"
    if not path.is_file():
        raise RuntimeError(f"missing shared model {path}")
    return path


def expectation(name: str, module: str) -> bool:
    """Whether the environment must have `module` (env `name`), else whether it has it."""
    value = os.environ.get(name)
    if value in ("0", "1"):
        return value == "1"
    return importlib.util.find_spec(module) is not None


class _Process:
    """A child process whose stdout is read until a line starting with `marker`; the rest of
    its output is drained in a thread (so a full pipe never blocks it) and kept for errors."""

    def __init__(self, args: list[str], marker: str, env: dict[str, str] | None = None):
        self.output: list[str] = []
        self.process = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                        text=True, env=env)
        deadline = time.monotonic() + 30
        found = threading.Event()
        self.line = ""

        def read() -> None:
            for line in self.process.stdout:
                self.output.append(line)
                if not found.is_set() and line.startswith(marker):
                    self.line = line.strip()
                    found.set()

        self._reader = threading.Thread(target=read, daemon=True)
        self._reader.start()
        while not found.wait(0.05):
            if self.process.poll() is not None or time.monotonic() > deadline:
                self.stop()
                raise RuntimeError(f"{args[0]} did not start:\n" + "".join(self.output))

    def stop(self) -> None:
        if self.process.poll() is None:
            self.process.send_signal(signal.SIGTERM)
            try:
                self.process.wait(15)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait()
        # The reader ends at the pipe's end; then the pipe is closed, not left to the collector
        # (whose ResourceWarning would land inside unittest's "... ok" line).
        self._reader.join(5)
        if not self._reader.is_alive():
            self.process.stdout.close()


_servers: list["Server"] = []
_hang_report: threading.Timer | None = None


def _report_hang() -> None:
    print("\n--- still running: each thread's stack, then each server's last output ---",
          file=sys.__stderr__, flush=True)
    faulthandler.dump_traceback(file=sys.__stderr__, all_threads=True)
    for server in list(_servers):
        print(f"--- {server.url}:\n{server.output()[-8000:]}", file=sys.__stderr__, flush=True)


def _arm_hang_report() -> None:
    global _hang_report
    seconds = os.environ.get("TLMHUB_HANG_REPORT_SECONDS")
    if seconds and _hang_report is None:
        _hang_report = threading.Timer(float(seconds), _report_hang)
        _hang_report.daemon = True
        _hang_report.start()


class Server:
    """`Server.start()` ... `server.stop()`; `server.url` is `http://127.0.0.1:PORT`."""

    def __init__(self, workers: int = 2, extra_args: tuple = ()) -> None:
        _arm_hang_report()
        self._binary = required_env("TLMHUB_SERVER_BIN")
        if not os.access(self._binary, os.X_OK):
            raise RuntimeError(f"TLMHUB_SERVER_BIN={self._binary} is not an executable")
        self._workers = workers
        self._extra_args = list(extra_args)
        self.directory = Path(tempfile.mkdtemp(prefix="tlmhub-python-"))
        (self.directory / "examples").mkdir()
        self._process = self._start("127.0.0.1:0")
        self.url = self._process.line.rsplit(" ", 1)[1]
        self._proxies: list[_Process] = []
        _servers.append(self)

    def _start(self, listen: str) -> "_Process":
        env = {**os.environ, "TLMHUB_ADMIN_PASSWORD": ADMIN_PASSWORD}
        return _Process(
            [self._binary, "--listen", listen, "--data-dir", str(self.directory / "data"),
             "--workers", str(self._workers), "--examples-dir", str(self.directory / "examples"),
             "--web-root", str(self.directory / "no-web"),
             # Cheap hashes: the tests log in often (a test server, as ServerHarness.cpp's).
             "--password-hash-cost", "minimal", *self._extra_args],
            "tlmhub-server listening on ", env)

    def restart(self) -> None:
        """Stops the server (SIGTERM) and starts it again on the same address and data."""
        self._process.stop()
        self._process = self._start(self.url.removeprefix("http://"))

    def tls_proxy(self) -> tuple[str, str]:
        """An https:// URL in front of this server (tests/tools/tls_proxy.py) and the
        certificate file to trust."""
        cert_dir = self.directory / f"tls-{len(self._proxies)}"
        cert_dir.mkdir()
        backend = self.url.removeprefix("http://")
        proxy = _Process([sys.executable, str(REPO / "tests" / "tools" / "tls_proxy.py"),
                          "--backend", backend, "--cert-dir", str(cert_dir)], "listening ")
        self._proxies.append(proxy)
        return f"https://127.0.0.1:{proxy.line.split()[1]}", str(cert_dir / "cert.pem")

    def stop(self) -> None:
        for proxy in self._proxies:
            proxy.stop()
        self._process.stop()
        shutil.rmtree(self.directory, ignore_errors=True)
        if self in _servers:
            _servers.remove(self)

    def output(self) -> str:
        return "".join(self._process.output)
