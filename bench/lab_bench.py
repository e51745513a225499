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

example: nice -n 0 bench/lab_bench.py --students 40 --runs 3 --variables 16
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


def student_main(i, port, token, model_id, runs, variables, rate, frames, ready, go, deadline, out, connect_times):
    my_runs = [Run(i, r) for r in range(runs)]
    out[i] = my_runs
    ws = None
    try:
        t0 = time.perf_counter()
        ws = websocket.create_connection(f"ws://127.0.0.1:{port}/api/v1/ws?token={token}",
                                         timeout=max(1.0, deadline - time.monotonic()),
                                         skip_utf8_validation=True, enable_multithread=False)
        json.loads(ws.recv())  # hello
        ws.send(json.dumps({"id": 1, "type": "model.open", "model_id": model_id}))
        while True:
            m = json.loads(ws.recv())
            if m.get("id") == 1:
                if m.get("type") != "reply":
                    raise RuntimeError("model.open: " + json.dumps(m)[:200])
                break
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


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--server", default=os.path.join(ROOT, "build/bin/tlmhub-server"))
    ap.add_argument("--cli", action="append", help="tlmhub-cli for the engine CPU (repeatable; the "
                    "first also names the variables and gives the ratio; default build/bin/tlmhub-cli)")
    ap.add_argument("--model", default=DEFAULT_MODEL)
    ap.add_argument("--students", type=int, default=40)
    ap.add_argument("--runs", type=int, default=3, help="runs per student, one after the other")
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
    a = ap.parse_args()
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
                                              deadline, out, connect_times)) for i in range(n)]
            for t in threads:
                t.start()
            ready.wait()  # every student is connected and has the model open
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
        ("lab wall time", f"{wall:.2f} s  (connect + model.open before it: p99 {ms(percentile(conn, 99))})"),
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
            "ratio": ratio, "client_cpu": client_cpu,
        }
        with open(a.json, "a") as f:
            f.write(json.dumps(figures) + "\n")
    return 0 if not lost and differ == 0 else 1


if __name__ == "__main__":
    sys.exit(main())
