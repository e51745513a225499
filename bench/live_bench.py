#!/usr/bin/env python3
"""Live sessions (docs/live-sessions.md, issue 42) against a tlmhub-server this script starts.

Two phases, each on a fresh server (the lab benchmark's Server class: a free loopback port, a
fresh data directory in a temporary directory, SIGTERM at the end):

1. A class: N users at once (default 40), each with one live session of Position Servo at 1x,
   streaming 4 variables (the step's output and the first three other logged ones) at 30 frames
   a second for S seconds (default 30; the model's stop time is set to S + 10 s so no session
   reaches its end). Every session starts paused; all resume together. Once a second after the
   step (model time > 1.5 s), at a random moment within the second (as a hand on a slider, not
   in step with the frames), each sends live.set of Step.y_A with a new value.
   Printed:
   - pacing: for every whole 1-s window of wall time after the first second, the model time a
     session advanced in it, from the frames' own stamps (model_time, wall_time: the server's
     clock) and from the client's receive times; the worst ratio to 1 over all windows and
     sessions, and how many windows were off by more than 2 %;
   - p50 / p99 (nearest rank) from sending live.set to receiving the first frame whose step
     output shows the new value (y_0 + y_A);
   - frames received, frames with `dropped` > 0, `seq` gaps (frames lost), sessions lost;
   - the server's CPU (utime + stime from /proc/PID/stat) over the class, as a share of one core.
2. One session of Load Sensing System at speed max (its stop time x10, so 300 s of model time),
   from live.start's reply to event.live.state stopped (finished), against `tlmhub-cli run` of
   the same file with --threads 1 (its wall time, process start included): simulated seconds
   per wall second of each and their ratio. Each is run --repeat times; the medians count.

Needs Python 3 with websocket-client (Debian: python3-websocket).

example: bench/live_bench.py                      # both phases, the issue's figures
         bench/live_bench.py --sessions 10 --seconds 10 --skip-max
"""
import argparse
import json
import os
import random
import re
import signal
import statistics
import subprocess
import sys
import tempfile
import threading
import time
import urllib.parse

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from lab_bench import (ADMIN_PASSWORD, ROOT, Server, percentile, rest, start_profiler,  # noqa: E402
                       variable_names, websocket)

MODELS = os.path.join(ROOT, "..", "shared", "hopsan-models", "Example Models")
STEP_OUT = "Step#out#Value"
STEP_Y0 = 0.2   # Position Servo's Step: y_0 (its output after t_step is y_0 + y_A)


def with_stop_time(hmf_text, stop):
    """The model file with another stop time (the first <simulationtime>, the root system's)."""
    return re.sub(r'(<simulationtime[^>]*\bstop=")[^"]*(")', rf"\g<1>{stop:g}\g<2>", hmf_text, count=1)


def make_users(port, count, prefix):
    admin = rest(port, "POST", "/api/v1/auth/login", body={"username": "admin", "password": ADMIN_PASSWORD})["token"]
    tokens = []
    for i in range(count):
        name, pw = f"{prefix}{i:03d}", f"{prefix}{i:03d}-password"
        rest(port, "POST", "/api/v1/users", admin, {"username": name, "password": pw, "role": "user"})
        tokens.append(rest(port, "POST", "/api/v1/auth/login", body={"username": name, "password": pw})["token"])
    return tokens


def upload(port, token, name, hmf_text):
    path = "/api/v1/models?name=" + urllib.parse.quote(name)
    return rest(port, "POST", path, token, hmf_text.encode(), "application/xml")["id"]


def connect(port, token, timeout):
    ws = websocket.create_connection(f"ws://127.0.0.1:{port}/api/v1/ws?token={token}", timeout=timeout,
                                     skip_utf8_validation=True, enable_multithread=True)
    json.loads(ws.recv())  # hello
    return ws


def call(ws, request_id, message):
    """Sends a request and returns its reply; events received meanwhile are returned too."""
    ws.send(json.dumps(dict(message, id=request_id)))
    events = []
    while True:
        m = json.loads(ws.recv())
        if m.get("id") == request_id:
            if m.get("type") != "reply":
                raise RuntimeError(f"{message['type']}: {json.dumps(m)[:300]}")
            return m.get("data"), events
        events.append(m)


# ---------------------------------------------------------------------------------------------
# Phase 1: a class of sessions at 1x

class Session:
    def __init__(self, index):
        self.index = index
        self.error = ""
        self.frames = []     # (receive time, text), parsed after the class
        self.sets = []       # (send time, step output expected)
        self.stopped = None  # the stopped event's reason, if one came


def session_main(s, port, token, model_id, variables, rate, seconds, ready, go, t_end):
    try:
        ws = connect(port, token, timeout=60)
        data, _ = call(ws, 1, {"type": "live.start", "model_id": model_id, "speed": 1, "rate": rate,
                               "variables": variables, "paused": True})
        s.session_id = data["session_id"]
    except Exception as e:  # noqa: BLE001 - reported as a lost session
        s.error = f"start: {e}"
        ready.abort()
        return
    try:
        ready.wait()
        go.wait()
    except threading.BrokenBarrierError:
        s.error = s.error or "the class did not start"
        return
    model_time = [0.0]
    setter = threading.Thread(target=set_main, args=(s, ws, model_time, t_end), daemon=True)
    try:
        ws.send(json.dumps({"id": 2, "type": "live.resume", "session_id": s.session_id}))
        setter.start()
        ws.settimeout(0.2)
        while time.perf_counter() < t_end[0]:
            try:
                text = ws.recv()
            except websocket.WebSocketTimeoutException:
                continue
            now = time.perf_counter()
            if '"event.live.frame"' in text[:64]:
                s.frames.append((now, text))
                # model_time sits near the start of the frame's JSON: found without parsing all of it.
                at = text.find('"model_time":')
                if at >= 0:
                    model_time[0] = float(re.match(r"[-+0-9.eE]+", text[at + 13:]).group(0))
            elif '"event.live.state"' in text[:64] and '"stopped"' in text:
                s.stopped = json.loads(text).get("reason")
                break
        setter.join()
        ws.settimeout(10)
        ws.send(json.dumps({"id": 3, "type": "live.stop", "session_id": s.session_id}))
        ws.close()
    except Exception as e:  # noqa: BLE001
        s.error = f"running: {e}"


def set_main(s, ws, model_time, t_end):
    """Once a second, at a random moment in it, a new Step.y_A (after the step, and none in the
    last second, so that each one shows in a frame)."""
    rng = random.Random(s.index)
    second, request_id = time.perf_counter(), 100
    while True:
        at = second + rng.random()
        second += 1.0
        if at >= t_end[0] - 1.0:
            return
        time.sleep(max(0.0, at - time.perf_counter()))
        if model_time[0] <= 1.5:
            continue
        request_id += 1
        y_a = 0.5 + 0.001 * request_id
        sent = time.perf_counter()
        ws.send(json.dumps({"id": request_id, "type": "live.set", "session_id": s.session_id,
                            "name": "Step.y_A", "value": y_a}))
        s.sets.append((sent, STEP_Y0 + y_a))


def window_ratios(points):
    """points: (wall, model) in order. The model time advanced in each whole second of wall time
    after the first, by linear interpolation between frames."""
    def model_at(t):
        for (w0, m0), (w1, m1) in zip(points, points[1:]):
            if w0 <= t <= w1:
                return m0 if w1 == w0 else m0 + (m1 - m0) * (t - w0) / (w1 - w0)
        return None
    if len(points) < 2:
        return []
    start, end = points[0][0], points[-1][0]
    ratios, k = [], 1
    while start + k + 1 <= end:
        a, b = model_at(start + k), model_at(start + k + 1)
        if a is not None and b is not None:
            ratios.append(b - a)
        k += 1
    return ratios


def analyse_session(s):
    server_points, client_points = [], []
    lost = dropped = 0
    last_seq = -1
    step_values = []   # (receive time, step output)
    for received, text in s.frames:
        m = json.loads(text)
        if m["seq"] != last_seq + 1:
            lost += 1
        last_seq = m["seq"]
        dropped += 1 if m.get("dropped") else 0
        server_points.append((m["wall_time"], m["model_time"]))
        client_points.append((received, m["model_time"]))
        values = m["variables"].get(STEP_OUT)
        if values:
            step_values.append((received, values[-1]))
    latencies = []
    for sent, expected in s.sets:
        for received, value in step_values:
            if received > sent and abs(value - expected) < 1e-9:
                latencies.append(received - sent)
                break
    return {"frames": len(s.frames), "seq_gaps": lost, "dropped": dropped, "latencies": latencies,
            "sets": len(s.sets), "server_windows": window_ratios(server_points),
            "client_windows": window_ratios(client_points)}


def class_phase(a, clis):
    server = Server(a.server, 0, a.server_arg)
    try:
        with open(os.path.join(MODELS, "Position Servo.hmf")) as f:
            hmf = with_stop_time(f.read(), a.seconds + 10)
        others = [v for v in variable_names(clis[0], os.path.join(MODELS, "Position Servo.hmf"), 8, server.tmp)
                  if v != STEP_OUT]
        variables = [STEP_OUT] + others[:a.variables - 1]
        tokens = make_users(server.port, a.sessions, "live")
        models = [upload(server.port, t, f"Position Servo live {i}", hmf) for i, t in enumerate(tokens)]
        sessions = [Session(i) for i in range(a.sessions)]
        ready = threading.Barrier(a.sessions + 1, timeout=120)
        go = threading.Barrier(a.sessions + 1, timeout=120)
        t_end = [float("inf")]
        threads = [threading.Thread(target=session_main, daemon=True,
                                    args=(s, server.port, tokens[i], models[i], variables, a.rate, a.seconds,
                                          ready, go, t_end)) for i, s in enumerate(sessions)]
        for t in threads:
            t.start()
        try:
            ready.wait()
        except threading.BrokenBarrierError:
            raise RuntimeError("sessions did not start: " + "; ".join(sorted({s.error for s in sessions if s.error})))
        profiler = start_profiler(a.perf, server.proc.pid) if a.perf else None
        cpu0, wall0 = server.cpu_seconds(), time.perf_counter()
        t_end[0] = wall0 + a.seconds
        go.wait()
        for t in threads:
            t.join(a.seconds + 60)
        wall = time.perf_counter() - wall0
        cpu = server.cpu_seconds() - cpu0
        if profiler:
            profiler.send_signal(signal.SIGINT)
            profiler.wait()
    finally:
        server.stop()
        server.cleanup()

    results = [analyse_session(s) for s in sessions]
    server_windows = [r for x in results for r in x["server_windows"]]
    client_windows = [r for x in results for r in x["client_windows"]]
    latencies = [v for x in results for v in x["latencies"]]
    sets = sum(x["sets"] for x in results)
    figures = {
        "sessions": a.sessions, "seconds": a.seconds, "variables": variables, "rate": a.rate,
        "sessions_lost": sum(1 for s in sessions if s.error),
        "errors": sorted({s.error for s in sessions if s.error})[:5],
        "stopped_early": sum(1 for s in sessions if s.stopped),
        "frames": sum(x["frames"] for x in results),
        "frames_dropped": sum(x["dropped"] for x in results),
        "seq_gaps": sum(x["seq_gaps"] for x in results),
        "windows": len(server_windows),
        "server_windows_off_2pc": sum(1 for r in server_windows if abs(r - 1) > 0.02),
        "server_worst_ratio": max(server_windows, key=lambda r: abs(r - 1)) if server_windows else None,
        "client_windows_off_2pc": sum(1 for r in client_windows if abs(r - 1) > 0.02),
        "client_worst_ratio": max(client_windows, key=lambda r: abs(r - 1)) if client_windows else None,
        "sets": sets, "sets_seen": len(latencies),
        "set_to_frame_p50_ms": percentile(latencies, 50) * 1000,
        "set_to_frame_p99_ms": percentile(latencies, 99) * 1000,
        "server_cpu_s": cpu, "wall_s": wall, "server_cpu_share_of_one_core": cpu / wall,
    }
    print(f"class: {a.sessions} sessions of Position Servo at 1x, {len(variables)} variables at {a.rate:g}/s "
          f"for {a.seconds:g} s")
    print(f"  sessions lost {figures['sessions_lost']} {figures['errors'] or ''}, stopped early "
          f"{figures['stopped_early']}")
    print(f"  frames {figures['frames']}, with dropped > 0: {figures['frames_dropped']}, seq gaps (lost): "
          f"{figures['seq_gaps']}")
    print(f"  pacing, 1-s windows after the first: {figures['windows']}; off by > 2 %: server clock "
          f"{figures['server_windows_off_2pc']} (worst {figures['server_worst_ratio']:.4f}), client clock "
          f"{figures['client_windows_off_2pc']} (worst {figures['client_worst_ratio']:.4f})")
    print(f"  live.set to the first frame showing it: {figures['sets_seen']}/{sets} seen, p50 "
          f"{figures['set_to_frame_p50_ms']:.1f} ms, p99 {figures['set_to_frame_p99_ms']:.1f} ms")
    print(f"  server CPU {cpu:.2f} s over {wall:.1f} s: {100 * cpu / wall:.1f} % of one core")
    return figures


# ---------------------------------------------------------------------------------------------
# Phase 2: one session at max against the CLI

def cli_run_seconds(cli, path):
    t = time.perf_counter()
    subprocess.run([cli, "run", path, "--threads", "1"], check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - t


def max_phase(a, clis):
    source = os.path.join(MODELS, "Load Sensing System.hmf")
    with open(source) as f:
        text = f.read()
    stop = 10 * float(re.search(r'<simulationtime[^>]*\bstop="([^"]*)"', text).group(1))
    hmf = with_stop_time(text, stop)
    tmp = tempfile.mkdtemp(prefix="tlmhub-live-bench-")
    path = os.path.join(tmp, "Load Sensing System.hmf")
    with open(path, "w") as f:
        f.write(hmf)
    server = Server(a.server, 0, a.server_arg)
    try:
        variables = variable_names(clis[0], path, 4, tmp)
        token = make_users(server.port, 1, "max")[0]
        model_id = upload(server.port, token, "Load Sensing System x10", hmf)
        ws = connect(server.port, token, timeout=600)
        live_walls, request_id = [], 1
        for _ in range(a.repeat):
            t = time.perf_counter()
            call(ws, request_id, {"type": "live.start", "model_id": model_id, "speed": "max",
                                  "variables": variables})
            request_id += 1
            while True:
                m = json.loads(ws.recv())
                if m.get("type") == "event.live.state" and m.get("state") == "stopped":
                    break
            live_walls.append(time.perf_counter() - t)
            if m.get("reason") != "finished" or abs(m.get("model_time", 0) - stop) > 1e-6:
                raise RuntimeError("the session did not finish: " + json.dumps(m))
        ws.close()
    finally:
        server.stop()
        server.cleanup()
    cli_walls = [cli_run_seconds(clis[0], path) for _ in range(a.repeat)]
    os.unlink(path)
    os.rmdir(tmp)
    live, cli = statistics.median(live_walls), statistics.median(cli_walls)
    figures = {"model": "Load Sensing System", "stop": stop, "live_wall_s": live, "cli_wall_s": cli,
               "live_sim_s_per_s": stop / live, "cli_sim_s_per_s": stop / cli, "ratio": cli / live}
    print(f"max: Load Sensing System, {stop:g} s of model time, median of {a.repeat}: live session "
          f"{live:.3f} s ({stop / live:.0f} simulated s per s), tlmhub-cli run --threads 1 {cli:.3f} s "
          f"({stop / cli:.0f} per s): the session reaches {100 * cli / live:.0f} % of the CLI")
    return figures


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--server", default=os.path.join(ROOT, "build/bin/tlmhub-server"))
    ap.add_argument("--cli", default=os.path.join(ROOT, "build/bin/tlmhub-cli"))
    ap.add_argument("--sessions", type=int, default=40)
    ap.add_argument("--seconds", type=float, default=30.0, help="wall seconds the class runs")
    ap.add_argument("--variables", type=int, default=4, help="variables each session streams")
    ap.add_argument("--rate", type=float, default=30.0, help="frames per second")
    ap.add_argument("--repeat", type=int, default=5, help="runs of the max phase (the median counts)")
    ap.add_argument("--skip-class", action="store_true")
    ap.add_argument("--skip-max", action="store_true")
    ap.add_argument("--server-arg", action="append", default=[], help="one more server argument (repeatable)")
    ap.add_argument("--json", help="append the figures as one JSON line to this file")
    ap.add_argument("--perf", help="record the server during the class with perf (call graphs) into this file")
    a = ap.parse_args()
    clis = [a.cli]
    figures = {}
    if not a.skip_class:
        figures["class"] = class_phase(a, clis)
    if not a.skip_max:
        figures["max"] = max_phase(a, clis)
    if a.json:
        with open(a.json, "a") as f:
            f.write(json.dumps(figures) + "\n")
    c = figures.get("class")
    return 0 if not c or (c["sessions_lost"] == 0 and c["seq_gaps"] == 0) else 1


if __name__ == "__main__":
    sys.exit(main())
