#!/usr/bin/env python3
"""A teaching lab over WebSocket against a tlmhub-server this script starts itself.

N students, all at once, each runs R simulations of the same model one after the other
(simulate.start, read frames until event.done, then the next run) with live streaming of K
variables. The server runs on a free loopback port with a fresh data directory in a temporary
directory, which is removed at the end; the server is stopped with SIGTERM.

Printed:
- jobs done / lost (no reply, an error reply, a state other than done, the timeout, a closed
  socket);
- per job, whether its frames concatenated in order (time and every variable) equal the stored
  result (GET /api/v1/jobs/{id}/results?format=json&variables=...) exactly, float for float as
  parsed from JSON; samples missing from the stream; runs that got event.resync (the client
  then reads the stored result during the lab, as the web app does);
- p50 / p99 (nearest rank) of the time from sending simulate.start to the job's first
  event.frame and to its event.done;
- the server's CPU seconds (utime + stime from /proc/PID/stat; with --postgres plus that of
  PostgreSQL's processes) from just before the first
  simulate.start to just after the last event.done (creating users, logins, uploads, connecting
  and model.open are excluded), beside the CPU of `tlmhub-cli batch MODEL --copies N*R
  --threads 1` (the bare engine for the same runs, measured with getrusage(RUSAGE_CHILDREN)
  after the server has stopped) and their ratio.

The client shares the machine with the server: its own CPU during the lab is printed too. It
keeps frames as text while the lab runs and parses them afterwards, so its JSON work does not
delay other students' timestamps.

Needs Python 3 with websocket-client (Debian: apt-get install python3-websocket) and the
standard library. Works against servers before and after the lossless-streaming change (issue
15): frames are matched by job_id, `dropped` is only reported, an error reply to simulate.start
and event.resync are handled.

With --assignment, a teaching lab instead (docs/labs.md, bench/README.md): a teacher (server role
teacher) uploads the model and makes a class and an assignment of it (edit_mode parameters,
GainP.k within [0, 0.1]; a pretest curve check and a hand-in scalar check of
Position_Sensor#out#Value); then all students at once, each one step after the other: join by
code, open the assignment (a copy), connect and model.open the copy, and --runs times:
parameter.set GainP.k, model.save, simulate.start streaming the position until event.done,
POST pretest, POST handin. Afterwards the teacher's hand-in list and dashboard are checked.
Printed: hand-ins stored / lost, runs done / lost, p50 / p99 of first frame, run done, pretest
and hand-in, the server's peak RSS (VmHWM) and CPU, the wall time.

With --interleaved, the students connect before the start and open the model after it, each
then running at once: opens (model work, a whole model's reply) and other students' runs and
frames meet, as in a crowded lab's first minute. The open's p50 / p99 are printed too.

example: nice -n 0 bench/lab_bench.py --students 40 --runs 3 --variables 16
         bench/lab_bench.py --interleaved --students 40 --runs 3
         bench/lab_bench.py --assignment --students 40 --runs 3
"""
import argparse
import array
import http.client
import json
import math
import os
import resource
import shutil
import signal
import struct
import subprocess
import sys
import tempfile
import threading
import time
import urllib.parse
from socket import timeout as socket_timeout

try:
    import websocket  # websocket-client
except ImportError:  # Debian's package, when another python3 comes first on PATH
    sys.path.append("/usr/lib/python3/dist-packages")
    import websocket

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_MODEL = os.path.join(ROOT, "..", "shared", "hopsan-models", "Example Models", "Position Servo.hmf")
ADMIN_PASSWORD = "lab-bench-admin-password"
CLK_TCK = os.sysconf("SC_CLK_TCK")


# ---------------------------------------------------------------------------------------------
# The server process and REST

class Server:
    def __init__(self, binary, workers, extra):
        self.tmp = tempfile.mkdtemp(prefix="tlmhub-lab-bench-")
        os.makedirs(os.path.join(self.tmp, "data"))
        os.makedirs(os.path.join(self.tmp, "examples"))  # empty: no examples seeded
        self.log_path = os.path.join(self.tmp, "server.log")
        args = [binary, "--listen", "127.0.0.1:0", "--data-dir", os.path.join(self.tmp, "data"),
                "--examples-dir", os.path.join(self.tmp, "examples"),
                "--web-root", os.path.join(self.tmp, "no-web")]
        if workers:
            args += ["--workers", str(workers)]
        args += extra
        env = dict(os.environ, TLMHUB_ADMIN_PASSWORD=ADMIN_PASSWORD)
        self.log = open(self.log_path, "wb")
        self.proc = subprocess.Popen(args, stdout=self.log, stderr=subprocess.STDOUT, env=env)
        self.port = None
        marker = "listening on http://127.0.0.1:"
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline and self.proc.poll() is None:
            with open(self.log_path, errors="replace") as f:
                text = f.read()
            at = text.find(marker)
            if at >= 0 and "\n" in text[at:]:
                self.port = int(text[at + len(marker):].split("\n")[0].strip().rstrip("/"))
                return
            time.sleep(0.05)
        with open(self.log_path, errors="replace") as f:
            output = f.read()
        self.stop()
        self.cleanup()
        raise RuntimeError("tlmhub-server did not start; output:\n" + output)

    def cpu_seconds(self):
        with open(f"/proc/{self.proc.pid}/stat") as f:
            fields = f.read().rsplit(")", 1)[1].split()
        return (int(fields[11]) + int(fields[12])) / CLK_TCK  # utime, stime (stat fields 14, 15)

    def stop(self):
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
            try:
                self.proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        self.log.close()

    def cleanup(self):
        shutil.rmtree(self.tmp, ignore_errors=True)


class Postgres:
    """A PostgreSQL 15 (Debian's postgresql-15) with its durable defaults (fsync and synchronous
    commit on) in its own temporary directory on a free loopback port, run as nobody when this
    script runs as root (initdb refuses root)."""
    BIN = "/usr/lib/postgresql/15/bin"

    def __init__(self):
        import pwd, socket
        self.dir = tempfile.mkdtemp(prefix="tlmhub-lab-pg-")
        os.makedirs(os.path.join(self.dir, "socket"))
        demote = None
        if os.geteuid() == 0:
            nobody = pwd.getpwnam("nobody")
            for d in (self.dir, os.path.join(self.dir, "socket")):
                os.chown(d, nobody.pw_uid, nobody.pw_gid)

            def demote():
                os.setgroups([])
                os.setgid(nobody.pw_gid)
                os.setuid(nobody.pw_uid)
        data = os.path.join(self.dir, "data")
        subprocess.run([self.BIN + "/initdb", "-D", data, "-U", "tlmhub", "--auth=trust", "--encoding=UTF8",
                        "--locale=C.UTF-8", "--no-instructions"], check=True, stdout=subprocess.DEVNULL,
                       preexec_fn=demote, cwd=self.dir)
        with socket.socket() as s:
            s.bind(("127.0.0.1", 0))
            self.port = s.getsockname()[1]
        self.log = open(os.path.join(self.dir, "postgres.log"), "wb")
        self.proc = subprocess.Popen([self.BIN + "/postgres", "-D", data, "-h", "127.0.0.1", "-p", str(self.port),
                                      "-k", os.path.join(self.dir, "socket")],
                                     stdout=self.log, stderr=subprocess.STDOUT, preexec_fn=demote, cwd=self.dir)
        deadline = time.monotonic() + 30
        while subprocess.run(["/usr/bin/createdb", "-h", "127.0.0.1", "-p", str(self.port), "-U", "tlmhub", "tlmhub"],
                             stderr=subprocess.DEVNULL).returncode != 0:
            if time.monotonic() > deadline or self.proc.poll() is not None:
                self.stop()
                raise RuntimeError("PostgreSQL did not start; see " + self.log.name)
            time.sleep(0.2)
        self.uri = f"postgresql://tlmhub@127.0.0.1:{self.port}/tlmhub"

    def cpu_seconds(self):
        """The postmaster's CPU with that of its ended children, plus its live children's."""
        def stat(pid):
            with open(f"/proc/{pid}/stat") as f:
                return f.read().rsplit(")", 1)[1].split()
        fields = stat(self.proc.pid)
        total = sum(int(fields[i]) for i in (11, 12, 13, 14))  # utime, stime, cutime, cstime
        for pid in os.listdir("/proc"):
            if pid.isdigit() and pid != str(self.proc.pid):
                try:
                    child = stat(pid)
                except OSError:
                    continue
                if child[1] == str(self.proc.pid):
                    total += int(child[11]) + int(child[12])
        return total / CLK_TCK

    def stop(self):
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGINT)  # fast shutdown
            self.proc.wait(timeout=60)
        self.log.close()
        shutil.rmtree(self.dir, ignore_errors=True)


def rest(port, method, path, token=None, body=None, content_type="application/json", timeout=60):
    conn = http.client.HTTPConnection("127.0.0.1", port, timeout=timeout)
    try:
        headers = {}
        data = None
        if body is not None:
            data = body if isinstance(body, bytes) else json.dumps(body).encode()
            headers["Content-Type"] = content_type
        if token:
            headers["Authorization"] = "Bearer " + token
        for _ in range(50):  # 503 busy (the password-hashing queue) asks to try again
            conn.request(method, path, body=data, headers=headers)
            r = conn.getresponse()
            text = r.read()
            if r.status != 503:
                break
            time.sleep(0.2)
        if r.status >= 300:
            raise RuntimeError(f"{method} {path}: HTTP {r.status}: {text[:300]!r}")
        return json.loads(text) if text else None
    finally:
        conn.close()


# ---------------------------------------------------------------------------------------------
# One student

class Run:
    __slots__ = ("student", "index", "job_id", "state", "error", "t_first", "t_done", "frames",
                 "dropped_sum", "dropped_max", "seq_gaps", "resync", "time", "vars", "raw", "stored")

    def __init__(self, student, index):
        self.student, self.index = student, index
        self.job_id = None
        self.state = None        # done, failed, cancelled, ... or error / timeout / closed
        self.error = ""
        self.t_first = None      # seconds from sending simulate.start to the first event.frame
        self.t_done = None       # ... to event.done
        self.frames = 0
        self.dropped_sum = 0
        self.dropped_max = 0
        self.seq_gaps = 0
        self.resync = False
        self.time = array.array("d")
        self.vars = {}
        self.raw = []            # (seconds since simulate.start, text) of each frame received
        self.stored = None       # (time, {name: data}) of the stored result, read after the lab


def open_model(ws, model_id):
    ws.send(json.dumps({"id": 1, "type": "model.open", "model_id": model_id}))
    while True:
        m = json.loads(ws.recv())
        if m.get("id") == 1:
            if m.get("type") != "reply":
                raise RuntimeError("model.open: " + json.dumps(m)[:200])
            return


def student_main(i, port, token, model_id, runs, variables, rate, frames, ready, go, deadline, out, connect_times,
                 interleaved=False):
    """`interleaved`: model.open after the start too, so that some students' opens meet
    others' runs (connect_times then holds the open's time alone)."""
    my_runs = [Run(i, r) for r in range(runs)]
    out[i] = my_runs
    ws = None
    try:
        t0 = time.perf_counter()
        ws = websocket.create_connection(f"ws://127.0.0.1:{port}/api/v1/ws?token={token}",
                                         timeout=max(1.0, deadline - time.monotonic()),
                                         skip_utf8_validation=True, enable_multithread=False)
        json.loads(ws.recv())  # hello
        if not interleaved:
            open_model(ws, model_id)
            connect_times[i] = time.perf_counter() - t0
    except Exception as e:  # noqa: BLE001 - reported as lost runs
        for run in my_runs:
            run.state, run.error = "error", f"connect/open: {e}"
        ws = None
    try:
        ready.wait()
        go.wait()
    except threading.BrokenBarrierError:
        ws = None
        for run in my_runs:
            if run.state is None:
                run.state, run.error = "timeout", "the lab did not start"
    if ws is None:
        return
    if interleaved:
        try:
            t0 = time.perf_counter()
            open_model(ws, model_id)
            connect_times[i] = time.perf_counter() - t0
        except Exception as e:  # noqa: BLE001 - reported as lost runs
            for run in my_runs:
                run.state, run.error = "error", f"model.open: {e}"
            return
    next_id = 2
    try:
        for run in my_runs:
            request = {"id": next_id, "type": "simulate.start", "rate": rate}
            if variables:
                request["variables"] = variables
            if frames != "json":
                request["frames"] = frames
            reply_id = next_id
            next_id += 1
            sent = time.perf_counter()
            ws.send(json.dumps(request))
            while True:
                remaining = deadline - time.monotonic()
                if remaining <= 0:
                    raise TimeoutError("lab timeout")
                ws.settimeout(remaining)
                text = ws.recv()
                now = time.perf_counter()
                if isinstance(text, bytes) or '"event.frame"' in text:
                    # Parsed after the lab (matched by job_id there).
                    run.raw.append((now - sent, text))
                    continue
                m = json.loads(text)
                kind = m.get("type")
                if run.job_id is None:
                    if m.get("id") == reply_id:
                        if kind != "reply" or not m.get("ok", False):
                            run.state = "error"
                            run.error = json.dumps(m.get("error", m))[:200]
                            break
                        run.job_id = m["data"]["job_id"]
                    continue  # the subscription starts after the reply: no events of it before
                if m.get("job_id") != run.job_id:
                    continue
                if kind == "event.resync":
                    run.resync = True
                elif kind == "event.done":
                    run.t_done = now - sent
                    run.state = m.get("state")
                    run.error = m.get("error", "")
                    break
            if run.resync and run.state == "done":
                # What the web app does: read the stored result in place of the stream.
                rest(port, "GET", f"/api/v1/jobs/{run.job_id}/results?format=json", token)
    except Exception as e:  # noqa: BLE001 - timeout or a closed socket: this and later runs are lost
        timeout = isinstance(e, (TimeoutError, websocket.WebSocketTimeoutException))
        for run in my_runs:
            if run.state is None:
                run.state = "timeout" if timeout else "closed"
                run.error = str(e)[:200]
    finally:
        try:
            ws.close()
        except Exception:  # noqa: BLE001
            pass


def decode_binary_frame(data):
    """A binary event.frame (protocol/README.md) as the JSON frame it stands for."""
    (header_bytes,) = struct.unpack_from("<I", data, 0)
    header = json.loads(data[4:4 + header_bytes])
    at = (4 + header_bytes + 7) // 8 * 8

    def take(n):
        nonlocal at
        values = array.array("d", data[at:at + 8 * n])  # little-endian, as this machine
        at += 8 * n
        return values
    frame = dict(header)
    frame["time"] = take(header["time_samples"])
    frame["variables"] = {v["name"]: take(v["samples"]) for v in header["variables"]}
    return frame


def take_frames(run):
    """Parses the run's frames of its job, in the order received."""
    for elapsed, text in run.raw:
        m = decode_binary_frame(text) if isinstance(text, bytes) else json.loads(text)
        if m.get("job_id") != run.job_id:
            continue
        if run.t_first is None:
            run.t_first = elapsed
        if m.get("seq", run.frames) != run.frames:
            run.seq_gaps += 1
        run.frames += 1
        d = m.get("dropped", 0) or 0
        run.dropped_sum += d
        run.dropped_max = max(run.dropped_max, d)
        run.time.extend(m.get("time", []))
        for name, values in m.get("variables", {}).items():
            col = run.vars.get(name)
            if col is None:
                col = run.vars[name] = array.array("d")
            col.extend(values)
    run.raw = []


# ---------------------------------------------------------------------------------------------

def percentile(values, p):
    """Nearest rank: the smallest value with at least p% of the values at or below it."""
    if not values:
        return float("nan")
    s = sorted(values)
    return s[max(0, math.ceil(p / 100.0 * len(s)) - 1)]


def engine_cpu(cli, model, copies):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = time.perf_counter()
    p = subprocess.run([cli, "batch", model, "--copies", str(copies), "--threads", "1"],
                       stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    wall = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    if p.returncode != 0:
        raise RuntimeError(f"{cli} batch failed: {p.stdout}")
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return cpu, wall, p.stdout.strip()


def variable_names(cli, model, count, tmp):
    """The first `count` logged variables, in the order of `tlmhub-cli run --csv`'s header (the
    server's stored results have the same names and order)."""
    csv = os.path.join(tmp, "names.csv")
    subprocess.run([cli, "run", model, "--csv", csv], check=True, stdout=subprocess.DEVNULL)
    with open(csv) as f:
        header = f.readline().strip().split(",")
    os.unlink(csv)
    return header[1:1 + count]


def read_stored(port, runs, tokens, requested):
    """Reads the stored result of every done job that streamed (after the lab)."""
    for run in runs:
        if run.state != "done" or run.resync:
            continue
        names = list(requested) if requested else list(run.vars.keys())
        query = "format=json"
        if names:
            query += "&variables=" + urllib.parse.quote(",".join(names), safe="")
        stored = rest(port, "GET", f"/api/v1/jobs/{run.job_id}/results?{query}", tokens[run.student])
        run.stored = (array.array("d", stored["time"]),
                      {v["name"]: array.array("d", v["data"]) for v in stored["variables"]})


def start_profiler(output, pid):
    """perf record attached to the server; it needs a moment to attach before the lab starts."""
    profiler = subprocess.Popen(["perf", "record", "-q", "-F", "1000", "--call-graph", "dwarf,16384",
                                 "-o", output, "-p", str(pid)], stdout=subprocess.DEVNULL)
    time.sleep(0.5)
    return profiler


# ---------------------------------------------------------------------------------------------
# The assignment mode (--assignment): students work on a teacher's assignment (docs/labs.md)

POSITION = "Position_Sensor#out#Value"


def http_call(port, method, path, token=None, body=None, timeout=60.0):
    """One REST call: (status, parsed body or None, 503 replies retried). A 503 `busy` is
    retried after 0.2 s while the timeout allows; any other status is returned as it is."""
    deadline = time.monotonic() + timeout
    retries = 0
    while True:
        conn = http.client.HTTPConnection("127.0.0.1", port, timeout=max(0.5, deadline - time.monotonic()))
        try:
            headers = {}
            data = None
            if body is not None:
                data = json.dumps(body).encode()
                headers["Content-Type"] = "application/json"
            if token:
                headers["Authorization"] = "Bearer " + token
            conn.request(method, path, body=data, headers=headers)
            r = conn.getresponse()
            text = r.read()
        finally:
            conn.close()
        if r.status == 503 and time.monotonic() + 0.2 < deadline:
            retries += 1
            time.sleep(0.2)
            continue
        try:
            parsed = json.loads(text) if text else None
        except ValueError:
            parsed = {"text": text[:200].decode(errors="replace")}
        return r.status, parsed, retries


class Step:
    """A timed call: seconds, status (HTTP status or 'ok' / 'error' / 'timeout') and detail."""
    __slots__ = ("start", "seconds", "status", "detail", "retries")

    def __init__(self):
        self.start = self.seconds = None  # start: time.perf_counter() when sent
        self.status, self.detail, self.retries = None, "", 0


class Round:
    __slots__ = ("index", "value", "set", "save", "job_id", "state", "error", "sent", "t_reply", "t_first", "t_done", "frames",
                 "samples", "pretest", "pretest_score", "handin", "handin_id", "attempt", "score", "max_score")

    def __init__(self, index, value):
        self.index, self.value = index, value
        self.set, self.save, self.pretest, self.handin = Step(), Step(), Step(), Step()
        self.job_id = self.state = None
        self.error = ""
        self.sent = self.t_reply = self.t_first = self.t_done = None
        self.frames = self.samples = 0
        self.pretest_score = self.handin_id = self.attempt = self.score = self.max_score = None


class Student:
    def __init__(self, index, name, token, rounds):
        self.index, self.name, self.token = index, name, token
        self.user_id = None
        self.join, self.open, self.connect = Step(), Step(), Step()
        self.copy_id = None
        # A different value per round within the bounds [0, 0.1], and per student.
        self.rounds = [Round(k, round(0.015 + 0.01 * k + 0.0001 * (index % 50), 6)) for k in range(rounds)]
        self.failure = ""        # where the student's work stopped, if it did


def student_assignment(s, port, code, assignment_id, rate, frames, go, deadline):
    """One student, every step after the other: join, open (a copy), connect and open it, then
    per round parameter.set, model.save, simulate.start until event.done, pretest, hand-in."""
    def remaining():
        left = deadline - time.monotonic()
        if left <= 0:
            raise TimeoutError("the lab's timeout passed")
        return left

    def timed_rest(step, method, path, body=None, expect=(200,)):
        step.start = t = time.perf_counter()
        status, data, retries = http_call(port, method, path, s.token, body, timeout=remaining())
        step.seconds, step.status, step.retries = time.perf_counter() - t, status, retries
        if status not in expect:
            step.detail = json.dumps(data)[:200]
            raise RuntimeError(f"{method} {path}: HTTP {status}: {step.detail}")
        return data

    ws = None
    next_id = [1]

    def ws_request(step, request):
        """Sends a request and waits for its reply (skipping events); the reply's data."""
        request = dict(request, id=next_id[0])
        next_id[0] += 1
        t = time.perf_counter()
        ws.send(json.dumps(request))
        while True:
            ws.settimeout(remaining())
            text = ws.recv()
            if isinstance(text, bytes) or '"event.' in text:
                continue
            m = json.loads(text)
            if m.get("id") != request["id"]:
                continue
            step.seconds = time.perf_counter() - t
            if m.get("type") != "reply" or not m.get("ok", False):
                step.status, step.detail = "error", json.dumps(m.get("error", m))[:200]
                raise RuntimeError(f"{request['type']}: {step.detail}")
            step.status = "ok"
            return m.get("data", {})

    try:
        go.wait()
    except threading.BrokenBarrierError:
        s.failure = "the lab did not start"
        return
    step_name = "join"
    try:
        timed_rest(s.join, "POST", "/api/v1/classes/join", {"code": code})
        step_name = "open"
        data = timed_rest(s.open, "POST", f"/api/v1/assignments/{assignment_id}/open", {}, expect=(200, 201))
        s.copy_id = data["copy"]["model_id"]
        step_name = "connect"
        t = time.perf_counter()
        ws = websocket.create_connection(f"ws://127.0.0.1:{port}/api/v1/ws?token={s.token}", timeout=remaining(),
                                         skip_utf8_validation=True, enable_multithread=False)
        json.loads(ws.recv())  # hello
        opened = ws_request(Step(), {"type": "model.open", "model_id": s.copy_id})
        s.connect.seconds, s.connect.status = time.perf_counter() - t, "ok"
        if not opened.get("writable", False):
            raise RuntimeError(f"model.open of the copy {s.copy_id}: not writable")
        for rd in s.rounds:
            step_name = f"round {rd.index + 1} parameter.set"
            ws_request(rd.set, {"type": "parameter.set", "component": "GainP", "parameter": "k#Value",
                                "value": rd.value})
            step_name = f"round {rd.index + 1} model.save"
            saved = ws_request(rd.save, {"type": "model.save"})
            if saved.get("copied") or saved.get("model_id") != s.copy_id:
                rd.save.status = "error"
                raise RuntimeError(f"model.save made another model: {json.dumps(saved)[:200]}")
            step_name = f"round {rd.index + 1} simulate.start"
            request = {"id": next_id[0], "type": "simulate.start", "rate": rate, "variables": [POSITION]}
            if frames != "json":
                request["frames"] = frames
            next_id[0] += 1
            rd.sent = sent = time.perf_counter()
            ws.send(json.dumps(request))
            while True:
                ws.settimeout(remaining())
                text = ws.recv()
                now = time.perf_counter()
                if isinstance(text, bytes):
                    (header_bytes,) = struct.unpack_from("<I", text, 0)
                    m = json.loads(text[4:4 + header_bytes])
                else:
                    m = json.loads(text)
                kind = m.get("type")
                if rd.job_id is None:
                    if m.get("id") == request["id"]:
                        if kind != "reply" or not m.get("ok", False):
                            rd.state, rd.error = "error", json.dumps(m.get("error", m))[:200]
                            raise RuntimeError(f"simulate.start: {rd.error}")
                        rd.job_id, rd.t_reply = m["data"]["job_id"], now - sent
                    continue
                if m.get("job_id") != rd.job_id:
                    continue
                if kind == "event.frame":
                    if rd.t_first is None:
                        rd.t_first = now - sent
                    rd.frames += 1
                    rd.samples += m["time_samples"] if isinstance(text, bytes) else len(m.get("time", []))
                elif kind == "event.done":
                    rd.t_done = now - sent
                    rd.state, rd.error = m.get("state"), m.get("error", "")
                    break
            if rd.state != "done":
                raise RuntimeError(f"job {rd.job_id}: {rd.state} {rd.error}")
            step_name = f"round {rd.index + 1} pretest"
            data = timed_rest(rd.pretest, "POST", f"/api/v1/assignments/{assignment_id}/pretest", {})
            rd.pretest_score = data.get("score")
            step_name = f"round {rd.index + 1} hand-in"
            data = timed_rest(rd.handin, "POST", f"/api/v1/assignments/{assignment_id}/handin", {}, expect=(201,))
            rd.handin_id, rd.attempt = data.get("id"), data.get("attempt")
            rd.score, rd.max_score = data.get("score"), data.get("max_score")
    except Exception as e:  # noqa: BLE001 - the student's later steps are lost; reported
        timeout = isinstance(e, (TimeoutError, websocket.WebSocketTimeoutException, socket_timeout))
        s.failure = f"{step_name}: " + ("timeout" if timeout else f"{type(e).__name__}: {e}")[:300]
        for rd in s.rounds:
            if rd.job_id is not None and rd.state is None:
                rd.state, rd.error = ("timeout" if timeout else "closed"), str(e)[:200]
    finally:
        if ws is not None:
            try:
                ws.close()
            except Exception:  # noqa: BLE001
                pass


def vm_hwm_kib(pid):
    with open(f"/proc/{pid}/status") as f:
        for line in f:
            if line.startswith("VmHWM:"):
                return int(line.split()[1])
    return None


def machine_busy_seconds():
    """CPU seconds all cores of the machine have been busy (not idle, not waiting for I/O)."""
    with open("/proc/stat") as f:
        fields = [int(x) for x in f.readline().split()[1:]]
    return (sum(fields[:8]) - fields[3] - fields[4]) / CLK_TCK  # up to steal; less idle, iowait


def assignment_main(a):
    n, r = a.students, a.runs
    postgres = Postgres() if a.postgres else None
    try:
        server = Server(a.server, a.workers, list(a.server_arg) + (["--database", postgres.uri] if postgres else []))
    except Exception:
        if postgres:
            postgres.stop()
        raise
    missing = []             # what the verification found wrong or missing
    try:
        port = server.port
        with open(a.model, "rb") as f:
            hmf = f.read()
        t_setup = time.perf_counter()
        admin = rest(port, "POST", "/api/v1/auth/login", body={"username": "admin", "password": ADMIN_PASSWORD})["token"]
        rest(port, "POST", "/api/v1/users", admin,
             {"username": "teacher", "password": "teacher-password", "role": "teacher"})
        teacher = rest(port, "POST", "/api/v1/auth/login",
                       body={"username": "teacher", "password": "teacher-password"})["token"]
        model_id = rest(port, "POST", "/api/v1/models?name=" + urllib.parse.quote("Position Servo"),
                        teacher, hmf, "application/xml")["id"]
        klass = rest(port, "POST", "/api/v1/classes", teacher, {"name": "Lab bench"})
        assignment = rest(port, "POST", f"/api/v1/classes/{klass['id']}/assignments", teacher, {
            "title": "Tune the servo", "instructions": "Set **GainP.k** so that the position follows.",
            "template_model_id": model_id, "solution_model_id": model_id, "edit_mode": "parameters",
            "parameters": [{"name": a.lock_parameter, "min": 0, "max": 0.1}]})
        assignment_id = assignment["id"]
        rest(port, "PUT", f"/api/v1/assignments/{assignment_id}/checks", teacher, {"checks": [
            {"name": "Position follows the reference", "points": 2, "pretest": True,
             "definition": {"kind": "curve", "variable": POSITION, "tolerance": 0.05}},
            {"name": "Overshoot", "points": 1, "pretest": False,
             "definition": {"kind": "scalar", "variable": POSITION, "measure": "overshoot", "max": 50}}]})
        students = []
        for i in range(n):
            name, pw = f"student{i:03d}", f"student{i:03d}-password"
            rest(port, "POST", "/api/v1/users", admin, {"username": name, "password": pw, "role": "user"})
            token = rest(port, "POST", "/api/v1/auth/login", body={"username": name, "password": pw})["token"]
            students.append(Student(i, name, token, r))
        setup = time.perf_counter() - t_setup

        go = threading.Barrier(n + 1, timeout=a.timeout)
        deadline = time.monotonic() + a.timeout
        threads = [threading.Thread(target=student_assignment, daemon=True,
                                    args=(s, port, klass["join_code"], assignment_id, a.rate, a.frames, go, deadline))
                   for s in students]
        for t in threads:
            t.start()
        profiler = start_profiler(a.perf, server.proc.pid) if a.perf else None
        load0 = os.getloadavg()[0]
        cpu0, client0, wall0, busy0 = server.cpu_seconds(), os.times(), time.perf_counter(), machine_busy_seconds()
        pg0 = postgres.cpu_seconds() if postgres else 0.0
        go.wait()
        for t in threads:
            t.join(max(0.0, deadline - time.monotonic()) + 5)
        wall = time.perf_counter() - wall0
        cpu1, client1, busy1 = server.cpu_seconds(), os.times(), machine_busy_seconds()
        database_cpu = postgres.cpu_seconds() - pg0 if postgres else 0.0
        load1 = os.getloadavg()[0]
        if profiler:
            profiler.send_signal(signal.SIGINT)
            profiler.wait()
        timed_out = time.monotonic() >= deadline or any(t.is_alive() for t in threads)
        lab_cpu = cpu1 - cpu0
        client_cpu = (client1.user - client0.user) + (client1.system - client0.system)

        # Verification, as the teacher: the hand-ins stored and the dashboard.
        posted = {}          # hand-in id -> (student index, round index), the 201 replies
        for s in students:
            for rd in s.rounds:
                if rd.handin.status == 201 and rd.handin_id is not None:
                    posted[rd.handin_id] = (s.index, rd.index)
        listed = {}
        status, data, _ = http_call(port, "GET", f"/api/v1/assignments/{assignment_id}/handins", teacher, timeout=60)
        if status != 200:
            missing.append(f"GET handins: HTTP {status}: {json.dumps(data)[:200]}")
        else:
            for h in data.get("handins", []):
                listed[h.get("id")] = h
        by_name = {s.name: s for s in students}
        attempts = {s.name: [] for s in students}
        for h in listed.values():
            who = (h.get("student") or {}).get("username")
            if who in attempts:
                attempts[who].append(h.get("attempt"))
            else:
                missing.append(f"hand-in {h.get('id')} of an unknown student {who!r}")
        stored = sum(1 for hid in posted if hid in listed)
        for hid, (si, ri) in posted.items():
            if hid not in listed:
                missing.append(f"hand-in {hid} (student{si:03d} round {ri + 1}) answered 201 but is not listed")
            elif listed[hid].get("job_id") != students[si].rounds[ri].job_id:
                # A hand-in keeps the id of the copy's latest run: the run of the same round.
                missing.append(f"hand-in {hid} (student{si:03d} round {ri + 1}): job_id {listed[hid].get('job_id')}, "
                               f"the round ran job {students[si].rounds[ri].job_id}")
        for name, got in attempts.items():
            if sorted(x for x in got if x is not None) != list(range(1, r + 1)):
                missing.append(f"{name}: attempts listed {sorted(got, key=lambda x: (x is None, x))}, "
                               f"expected 1..{r}")
        for s in students:
            got = [rd.attempt for rd in s.rounds if rd.handin.status == 201]
            if got != list(range(1, len(got) + 1)):
                missing.append(f"{s.name}: attempts in the 201 replies {got}")
        dashboard_ok = 0
        status, data, _ = http_call(port, "GET", f"/api/v1/assignments/{assignment_id}/dashboard", teacher, timeout=60)
        if status != 200:
            missing.append(f"GET dashboard: HTTP {status}: {json.dumps(data)[:200]}")
        else:
            rows = {(row.get("student") or {}).get("username"): row for row in data.get("students", [])}
            for s in students:
                row = rows.get(s.name)
                if row is None:
                    missing.append(f"dashboard: no row for {s.name}")
                elif row.get("status") != "handed_in" or row.get("handins") != r:
                    missing.append(f"dashboard: {s.name} status {row.get('status')!r}, handins {row.get('handins')!r}")
                elif row.get("copy_model_id") != s.copy_id:
                    missing.append(f"dashboard: {s.name} copy {row.get('copy_model_id')!r}, opened {s.copy_id}")
                else:
                    dashboard_ok += 1
            extra = set(rows) - set(by_name)
            if extra:
                missing.append(f"dashboard: rows of others {sorted(extra)[:5]}")
        peak_rss = vm_hwm_kib(server.proc.pid)
        total_cpu = server.cpu_seconds()
    finally:
        server.stop()
        server.cleanup()
        if postgres:
            postgres.stop()

    rounds = [rd for s in students for rd in s.rounds]
    runs_done = [rd for rd in rounds if rd.state == "done"]
    runs_lost = len(rounds) - len(runs_done)
    handins_lost = n * r - stored
    stopped = {}             # where students stopped: "step: reason" -> students
    for s in students:
        if s.failure:
            stopped.setdefault(s.failure.split(":")[0] + ": " + ("timeout" if s.failure.endswith("timeout") else "error"),
                               []).append(s)

    def stat(values):
        values = [v for v in values if v is not None]
        if not values:
            return "-"
        return (f"{percentile(values, 50) * 1000:.0f} / {percentile(values, 99) * 1000:.0f} / "
                f"{max(values) * 1000:.0f} ms  (n={len(values)})")

    first = [rd.t_first for rd in runs_done]
    dones = [rd.t_done for rd in runs_done]
    pretests = [rd.pretest.seconds for rd in rounds if rd.pretest.status == 200]
    handins = [rd.handin.seconds for rd in rounds if rd.handin.status == 201]
    retries = sum(st.retries for s in students for st in [s.join, s.open] + [x for rd in s.rounds
                                                                          for x in (rd.pretest, rd.handin)])
    scores = [rd.score for rd in rounds if rd.score is not None]
    max_score = next((rd.max_score for rd in rounds if rd.max_score is not None), None)
    pre_scores = [rd.pretest_score for rd in rounds if rd.pretest_score is not None]

    # Where the time goes: the first frames by how many check calls (pretests and hand-ins, run
    # on the server's checks pool) and other runs were in flight when simulate.start was sent.
    checks_busy = [(st.start, st.start + st.seconds) for rd in rounds for st in (rd.pretest, rd.handin)
                   if st.start is not None and st.seconds is not None]
    runs_busy = [(rd.sent, rd.sent + rd.t_done) for rd in runs_done]

    def in_flight(intervals, at):
        return sum(1 for b, e in intervals if b <= at < e)

    def by_load(intervals, bounds, itself=0):
        groups = {}
        for rd in runs_done:
            if rd.t_first is None:
                continue
            k = in_flight(intervals, rd.sent) - itself
            key = next(f"{lo}+" if hi is None else f"{lo}-{hi}" if hi != lo else f"{lo}"
                       for lo, hi in bounds if lo <= k and (hi is None or k <= hi))
            groups.setdefault(key, []).append(rd.t_first)
        return "; ".join(f"{key}: {percentile(v, 50) * 1000:.0f} / {percentile(v, 99) * 1000:.0f} ms (n={len(v)})"
                         for key, v in sorted(groups.items(), key=lambda kv: int(kv[0].rstrip("+").split("-")[0])))
    wide = [(0, 0), (1, 2), (3, 5), (6, 10), (11, 20), (21, None)]

    label = f" [{a.label}]" if a.label else ""
    print(f"lab bench, assignment{label}: {n} students x {r} rounds (parameter.set, model.save, run streaming "
          f"{POSITION} at {a.rate:g}/s {a.frames} frames, pretest, hand-in), server {a.server}")
    rows = [
        ("students / rounds", f"{n} / {r}"),
        ("hand-ins stored / lost", f"{stored} / {handins_lost}  (of {n * r}; dashboard handed_in: {dashboard_ok} of {n})"),
        ("runs done / lost", f"{len(runs_done)} / {runs_lost}  (of {n * r})"),
        ("first frame p50 / p99 / max", stat(first)),
        ("run done p50 / p99 / max", stat(dones)),
        ("pretest p50 / p99 / max", stat(pretests)),
        ("hand-in p50 / p99 / max", stat(handins)),
        ("join; open p50 / p99 / max", f"{stat([s.join.seconds for s in students])};  {stat([s.open.seconds for s in students])}"),
        ("parameter.set; model.save", f"{stat([rd.set.seconds for rd in rounds])};  "
                                          f"{stat([rd.save.seconds for rd in rounds])}"),
        ("simulate.start reply", stat([rd.t_reply for rd in runs_done])),
        ("first frame after the reply", stat([rd.t_first - rd.t_reply for rd in runs_done
                                              if rd.t_first is not None and rd.t_reply is not None])),
        ("reply by round", "; ".join(
            f"{k + 1}: {stat([rd.t_reply for rd in runs_done if rd.index == k])}" for k in range(r))),
        ("first frame by round", "; ".join(
            f"{k + 1}: {stat([rd.t_first for rd in runs_done if rd.index == k])}" for k in range(r))),
        ("first frame by checks in flight", by_load(checks_busy, wide)),
        ("first frame by other runs in flight", by_load(runs_busy, wide, itself=1)),
        ("503 retries", f"{retries}"),
        ("scores", f"pretest mean {sum(pre_scores) / max(1, len(pre_scores)):.2f}, hand-in mean "
                   f"{sum(scores) / max(1, len(scores)):.2f} of {max_score}"),
        ("server peak RSS (VmHWM)", f"{peak_rss / 1024:.1f} MiB" if peak_rss else "-"),
        ("server CPU", f"{lab_cpu:.2f} s in the lab ({total_cpu:.2f} s since start)"
                       + (f"; PostgreSQL's processes {database_cpu:.2f} s in the lab" if postgres else "")),
        ("client CPU (this script)", f"{client_cpu:.2f} s"),
        ("machine CPU busy in the lab", f"{busy1 - busy0:.2f} s of {wall * (os.cpu_count() or 1):.2f} s "
                                        f"({os.cpu_count()} cores; others: {max(0.0, busy1 - busy0 - lab_cpu - database_cpu - client_cpu):.2f} s); "
                                        f"load average {load0:.2f} -> {load1:.2f}"),
        ("lab wall time", f"{wall:.2f} s  (setup before it, not timed in the lab: {setup:.2f} s)"),
    ]
    width = max(len(k) for k, _ in rows)
    for k, v in rows:
        print(f"  {k:<{width}}  {v}")
    if timed_out:
        print(f"  TIMEOUT: the lab did not finish within {a.timeout:g} s")
    for where, who in sorted(stopped.items(), key=lambda kv: -len(kv[1])):
        print(f"  stopped: {len(who)} students at {where}; e.g. {who[0].name}: {who[0].failure}")
    for line in missing[:12]:
        print("  missing: " + line)
    if len(missing) > 12:
        print(f"  missing: ... and {len(missing) - 12} more")
    ok = not timed_out and runs_lost == 0 and handins_lost == 0 and not missing and not stopped
    goals = [("0 lost hand-ins and runs", handins_lost == 0 and runs_lost == 0),
             ("p99 first frame < 250 ms", bool(first) and percentile(first, 99) < 0.25),
             ("p99 hand-in < 1 s", bool(handins) and percentile(handins, 99) < 1.0)]
    print("  goals: " + "; ".join(f"{g}: {'met' if m else 'MISSED'}" for g, m in goals))

    if a.json:
        def p(values, q):
            return percentile(values, q) if values else None
        figures = {
            "mode": "assignment", "label": a.label, "server": a.server, "students": n, "rounds": r,
            "handins_stored": stored, "handins_lost": handins_lost, "runs_done": len(runs_done), "runs_lost": runs_lost,
            "first_p50": p(first, 50), "first_p99": p(first, 99), "done_p50": p(dones, 50), "done_p99": p(dones, 99),
            "pretest_p50": p(pretests, 50), "pretest_p99": p(pretests, 99),
            "handin_p50": p(handins, 50), "handin_p99": p(handins, 99), "retries_503": retries,
            "peak_rss_kib": peak_rss, "server_cpu": lab_cpu, "database_cpu": database_cpu, "server_cpu_total": total_cpu,
            "client_cpu": client_cpu, "machine_busy": busy1 - busy0, "load": [load0, load1], "wall": wall,
            "timed_out": timed_out, "missing": missing,
            "stopped": {where: len(who) for where, who in stopped.items()},
        }
        with open(a.json, "a") as f:
            f.write(json.dumps(figures) + "\n")
    return 0 if ok else 1


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--server", default=os.path.join(ROOT, "build/bin/tlmhub-server"))
    ap.add_argument("--cli", action="append", help="tlmhub-cli for the engine CPU (repeatable; the "
                    "first also names the variables and gives the ratio; default build/bin/tlmhub-cli)")
    ap.add_argument("--model", default=DEFAULT_MODEL)
    ap.add_argument("--students", type=int, default=40)
    ap.add_argument("--runs", type=int, default=3, help="runs per student, one after the other "
                    "(--assignment: rounds of set, save, run, pretest, hand-in)")
    ap.add_argument("--variables", type=int, default=16,
                    help="variables streamed: the first K logged ones (0: none asked, the server's default)")
    ap.add_argument("--rate", type=float, default=30.0, help="frame rate asked for (default 30/s)")
    ap.add_argument("--frames", choices=["json", "binary"], default="json",
                    help="how frames come (binary: what the web app asks for)")
    ap.add_argument("--workers", type=int, default=0, help="server --workers (default: the server's own)")
    ap.add_argument("--timeout", type=float, default=300.0, help="bound on the lab phase in seconds")
    ap.add_argument("--port-file", help="write the server's port here once it listens")
    ap.add_argument("--server-arg", action="append", default=[], help="one more server argument (repeatable)")
    ap.add_argument("--label", default="", help="a name for this run in the output")
    ap.add_argument("--postgres", action="store_true",
                    help="store in a PostgreSQL 15 this script starts (fsync on) instead of SQLite; "
                         "its CPU counts as the server's")
    ap.add_argument("--perf", help="record the server's lab phase with perf (call graphs) into this file")
    ap.add_argument("--json", help="append the figures as one JSON line to this file")
    ap.add_argument("--interleaved", action="store_true",
                    help="every student opens the model after the start, then runs: opens and runs "
                         "interleave (a crowded lab's first minute) instead of all opens first")
    ap.add_argument("--assignment", action="store_true",
                    help="the assignment mode: a teacher's assignment; each student joins, opens a copy, and "
                         "--runs times sets GainP.k, saves, runs with streaming, pretests and hands in")
    ap.add_argument("--lock-parameter", default="GainP.k",
                    help="--assignment: the parameter the assignment's lock lists (default GainP.k)")
    a = ap.parse_args()
    if a.assignment:
        return assignment_main(a)
    clis = a.cli or [os.path.join(ROOT, "build/bin/tlmhub-cli")]
    n, r = a.students, a.runs

    postgres = Postgres() if a.postgres else None
    server_args = a.server_arg + (["--database", postgres.uri] if postgres else [])
    server = Server(a.server, a.workers, server_args)
    try:
        try:
            if a.port_file:
                with open(a.port_file, "w") as f:
                    f.write(f"{server.port}\n")
            requested = variable_names(clis[0], a.model, a.variables, server.tmp) if a.variables > 0 else []
            port = server.port
            with open(a.model, "rb") as f:
                hmf = f.read()
            admin = rest(port, "POST", "/api/v1/auth/login",
                         body={"username": "admin", "password": ADMIN_PASSWORD})["token"]
            tokens, models = [], []
            for i in range(n):
                name, pw = f"student{i:03d}", f"student{i:03d}-password"
                rest(port, "POST", "/api/v1/users", admin, {"username": name, "password": pw, "role": "user"})
                token = rest(port, "POST", "/api/v1/auth/login", body={"username": name, "password": pw})["token"]
                tokens.append(token)
                models.append(rest(port, "POST", "/api/v1/models?name=" + urllib.parse.quote(f"Position Servo {i}"),
                                   token, hmf, "application/xml")["id"])

            out = [None] * n
            connect_times = [None] * n
            ready = threading.Barrier(n + 1, timeout=a.timeout)
            go = threading.Barrier(n + 1, timeout=a.timeout)
            deadline = time.monotonic() + a.timeout
            threads = [threading.Thread(target=student_main, daemon=True,
                                        args=(i, port, tokens[i], models[i], r, requested, a.rate, a.frames, ready, go,
                                              deadline, out, connect_times, a.interleaved)) for i in range(n)]
            for t in threads:
                t.start()
            ready.wait()  # every student is connected (and has the model open unless interleaved)
            profiler = start_profiler(a.perf, server.proc.pid) if a.perf else None
            cpu0, client0, wall0 = server.cpu_seconds(), os.times(), time.perf_counter()
            pg0 = postgres.cpu_seconds() if postgres else 0.0
            go.wait()
            for t in threads:
                t.join(max(0.0, deadline - time.monotonic()) + 5)
            wall = time.perf_counter() - wall0
            cpu1, client1 = server.cpu_seconds(), os.times()
            database_cpu = postgres.cpu_seconds() - pg0 if postgres else 0.0
            if profiler:
                profiler.send_signal(signal.SIGINT)
                profiler.wait()
            # With PostgreSQL, its processes' CPU is the server's too.
            server_cpu = cpu1 - cpu0 + database_cpu
            client_cpu = (client1.user - client0.user) + (client1.system - client0.system)

            runs = [run for rs in out for run in rs]
            for run in runs:
                take_frames(run)
            read_stored(port, runs, tokens, requested)
        finally:
            server.stop()
        engines = [(cli,) + engine_cpu(cli, a.model, n * r) for cli in clis]
    finally:
        server.cleanup()
        if postgres:
            postgres.stop()

    # Verdicts
    done = [x for x in runs if x.state == "done"]
    lost = [x for x in runs if x.state != "done"]
    equal = differ = 0
    samples_stored = samples_streamed = samples_missing = 0
    odd = []
    for x in done:
        if x.stored is None:
            continue
        st_time, st_vars = x.stored
        ok = (x.time == st_time and set(x.vars) == set(st_vars) and all(x.vars[k] == st_vars[k] for k in st_vars)
              and (not requested or set(st_vars) == set(requested)))
        samples_stored += len(st_time) * (1 + len(st_vars))
        samples_streamed += len(x.time) + sum(len(v) for v in x.vars.values())
        samples_missing += max(0, len(st_time) - len(x.time)) * (1 + len(st_vars))
        if ok:
            equal += 1
        else:
            differ += 1
            if len(odd) < 5:
                odd.append(f"job {x.job_id}: streamed {len(x.time)} of {len(st_time)} time samples in "
                           f"{x.frames} frames, dropped max {x.dropped_max}, variables {len(x.vars)}/{len(st_vars)}")
    resyncs = sum(1 for x in runs if x.resync)
    first = [x.t_first for x in done if x.t_first is not None]
    dones = [x.t_done for x in done]
    frames = sum(x.frames for x in runs)
    jobs_dropped = sum(1 for x in runs if x.dropped_max > 0)
    seq_gaps = sum(x.seq_gaps for x in runs)
    no_frame = sum(1 for x in done if x.t_first is None and not x.resync)
    eng_cpu = engines[0][1]
    ratio = server_cpu / eng_cpu if eng_cpu > 0 else float("nan")
    conn = [c for c in connect_times if c is not None]

    def ms(v):
        return f"{v * 1000:.0f} ms"

    label = f" [{a.label}]" if a.label else ""
    print(f"lab bench{label}: {n} students x {r} runs, {len(requested) or 'default'} variables at "
          f"{a.rate:g}/s, {a.frames} frames, server {a.server}")
    rows = [
        ("jobs done / lost", f"{len(done)} / {len(lost)}  (of {len(runs)})"),
        ("frames equal stored result", f"{equal} jobs; {differ} differ; {resyncs} resync"),
        ("samples streamed / stored", f"{samples_streamed} / {samples_stored}  (missing {samples_missing})"),
        ("frames; jobs with dropped > 0", f"{frames}; {jobs_dropped}  (seq gaps {seq_gaps}, "
                                          f"done jobs without a frame {no_frame})"),
        ("first frame p50 / p99 / max", f"{ms(percentile(first, 50))} / {ms(percentile(first, 99))} / "
                                        f"{ms(max(first) if first else float('nan'))}"),
        ("done p50 / p99 / max", f"{ms(percentile(dones, 50))} / {ms(percentile(dones, 99))} / "
                                 f"{ms(max(dones) if dones else float('nan'))}"),
        ("lab wall time", f"{wall:.2f} s  (model.open within it: p50 {ms(percentile(conn, 50))}, p99 "
                          f"{ms(percentile(conn, 99))})" if a.interleaved else
                          f"{wall:.2f} s  (connect + model.open before it: p99 {ms(percentile(conn, 99))})"),
        ("server CPU", f"{server_cpu:.2f} s" + (f" (PostgreSQL's processes: {database_cpu:.2f} s)" if a.postgres else "")),
    ]
    for cli, cpu, ewall, _ in engines:
        name = "engine CPU" + (f" ({cli})" if len(engines) > 1 else " (tlmhub-cli batch)")
        rows.append((name, f"{cpu:.2f} s  ({n * r} copies, 1 thread, {ewall:.2f} s wall)"))
    rows.append(("server / engine CPU", f"{ratio:.2f}x"))
    rows.append(("client CPU (this script)", f"{client_cpu:.2f} s"))
    width = max(len(k) for k, _ in rows)
    for k, v in rows:
        print(f"  {k:<{width}}  {v}")
    for x in lost[:5]:
        print(f"  lost: student {x.student} run {x.index} job {x.job_id}: {x.state} {x.error}")
    for line in odd:
        print("  differs: " + line)

    if a.json:
        figures = {
            "label": a.label, "server": a.server, "students": n, "runs": r, "variables": len(requested),
            "rate": a.rate, "jobs": len(runs), "done": len(done), "lost": len(lost), "equal": equal,
            "differ": differ, "resync": resyncs, "samples_stored": samples_stored,
            "samples_streamed": samples_streamed, "samples_missing": samples_missing, "frames": frames,
            "jobs_dropped": jobs_dropped, "seq_gaps": seq_gaps,
            "first_p50": percentile(first, 50), "first_p99": percentile(first, 99),
            "done_p50": percentile(dones, 50), "done_p99": percentile(dones, 99), "wall": wall,
            "server_cpu": server_cpu, "engine_cpu": {cli: cpu for cli, cpu, _, _ in engines},
            "ratio": ratio, "client_cpu": client_cpu, "interleaved": a.interleaved,
            "open_p50": percentile(conn, 50), "open_p99": percentile(conn, 99),
        }
        with open(a.json, "a") as f:
            f.write(json.dumps(figures) + "\n")
    return 0 if not lost and differ == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
