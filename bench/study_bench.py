#!/usr/bin/env python3
"""Studies against the bare engine, on a tlmhub-server this script starts itself.

1. Sweep speed: paired rounds, each timing a sweep of N runs of MODEL on the server (POST
   /api/v1/studies, from submission until its last event.study.progress over a WebSocket
   subscribed before it, so that no polling takes the workers' cores) and
   `tlmhub-cli batch MODEL --copies N --threads W` (its own printed wall time: compile + run
   of N copies on W threads) in alternating order, with the server's W workers. Prints each
   round's times and ratio, and the median ratio.
2. Optimisation (--optimise): a fine grid sweep of Position Servo's two controller gains
   (GainP.k, GainI.k) with the objective "integral of the squared error between the position
   and the step reference", then Complex-RF and Nelder-Mead on the same bounds and objective;
   prints the sweep's minimum, each optimiser's best and its number of runs, and its trace
   (the best objective after each run).

The server runs on a free loopback port with a fresh data directory in a temporary
directory, removed at the end. Needs websocket-client (Debian: python3-websocket).

example: bench/study_bench.py --runs 1000 --rounds 3 --optimise
"""
import argparse
import http.client
import json
import os
import re
import shutil
import signal
import statistics
import subprocess
import sys
import tempfile
import time

try:
    import websocket  # websocket-client
except ImportError:  # Debian's package, when another python3 comes first on PATH
    sys.path.append("/usr/lib/python3/dist-packages")
    import websocket

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
SHARED = os.path.join(ROOT, "..", "shared", "hopsan-models", "Example Models")
SERVO = os.path.join(SHARED, "Position Servo.hmf")
POSITION = "Position_Sensor#out#Value"
PASSWORD = "bench-password-1"


class Api:
    def __init__(self, port):
        self.port = port
        self.token = None

    def call(self, method, path, body=None):
        connection = http.client.HTTPConnection("127.0.0.1", self.port, timeout=120)
        headers = {"Content-Type": "application/json"}
        if self.token:
            headers["Authorization"] = "Bearer " + self.token
        connection.request(method, "/api/v1" + path, json.dumps(body) if body is not None else None, headers)
        reply = connection.getresponse()
        data = reply.read()
        connection.close()
        if reply.status >= 300:
            raise RuntimeError(f"{method} {path}: {reply.status} {data[:300]!r}")
        return json.loads(data) if data and reply.getheader("Content-Type", "").startswith("application/json") else data

    def wait(self, study_id, poll=0.01):
        while True:
            info = self.call("GET", f"/studies/{study_id}")
            if info["state"] not in ("queued", "running"):
                return info
            time.sleep(poll)


def start_server(binary, data_dir, workers):
    env = dict(os.environ, TLMHUB_ADMIN_PASSWORD=PASSWORD)
    process = subprocess.Popen([binary, "--listen", "127.0.0.1:0", "--data-dir", data_dir, "--workers", str(workers),
                                "--examples-dir", data_dir], stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                               env=env, text=True)
    for line in process.stdout:
        found = re.search(r"listening on .*:(\d+)", line)
        if found:
            return process, int(found.group(1))
    raise RuntimeError("the server did not start")


def time_batch(cli, model, runs, threads):
    output = subprocess.run([cli, "batch", model, "--copies", str(runs), "--threads", str(threads)],
                            check=True, capture_output=True, text=True).stdout
    return float(re.search(r": ([0-9.]+) s,", output).group(1))


def time_sweep(api, hmf, runs):
    study = {"kind": "sweep", "hmf": hmf, "outputs": {"variables": [POSITION], "values": ["final"]},
             "sweep": {"parameters": {"GainP.k": {"from": 0.02, "to": 0.03, "steps": runs}}}}
    socket = websocket.create_connection(f"ws://127.0.0.1:{api.port}/api/v1/ws",
                                         header=["Authorization: Bearer " + api.token])
    socket.recv()  # hello
    started = time.monotonic()
    created = api.call("POST", "/studies", study)
    socket.send(json.dumps({"id": 1, "type": "study.subscribe", "study_id": created["id"]}))
    while True:
        message = json.loads(socket.recv())
        if message.get("type") == "event.study.progress" and message["state"] not in ("running", ""):
            break
    elapsed = time.monotonic() - started
    socket.close()
    info = api.call("GET", f"/studies/{created['id']}")
    if info["state"] != "done" or info["runs_done"] != runs:
        raise RuntimeError(f"sweep ended {info}")
    api.call("DELETE", f"/studies/{created['id']}")
    return elapsed


def trace(api, study_id):
    table = api.call("GET", f"/studies/{study_id}/results?format=json")
    column = table["columns"].index("objective")
    best, out = float("inf"), []
    for row in sorted(table["rows"], key=lambda r: r[0]):
        if row[column] is not None:
            best = min(best, row[column])
        out.append(best)
    return out


def optimise(api, hmf, grid, budget):
    bounds = {"GainP.k": {"min": 0.005, "max": 0.08}, "GainI.k": {"min": 0.0, "max": 0.01}}
    objective = {"terms": [{"function": "ise", "variable": POSITION, "reference_variable": "Step#out#Value"}]}
    sweep = {"kind": "sweep", "hmf": hmf, "objective": objective,
             "sweep": {"parameters": {name: {"from": b["min"], "to": b["max"], "steps": grid}
                                      for name, b in bounds.items()}}}
    created = api.call("POST", "/studies", sweep)
    info = api.wait(created["id"])
    best = info["summary"]["best"]
    print(f"fine sweep {grid}x{grid} = {grid * grid} runs: minimum {best['objective']:.6g} at {best['parameters']}")
    for algorithm in ("complex-rf", "nelder-mead"):
        study = {"kind": "optimise", "hmf": hmf,
                 "optimise": {"algorithm": algorithm, "parameters": bounds, "objective": objective,
                              "max_evaluations": budget, "seed": 1}}
        created = api.call("POST", "/studies", study)
        info = api.wait(created["id"])
        found = info["summary"]["best"]
        gap = (found["objective"] - best["objective"]) / abs(best["objective"]) * 100
        steps = trace(api, created["id"])
        print(f"{algorithm}: {info['runs_done']} runs ({info['summary'].get('finish_reason', '')}), best "
              f"{found['objective']:.6g} at {found['parameters']}, {gap:+.2f} % from the sweep's minimum")
        print("  best after run: " + " ".join(f"{i + 1}:{v:.5g}" for i, v in enumerate(steps)
                                               if i < 10 or (i + 1) % 10 == 0 or i == len(steps) - 1))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--build", default=os.path.join(ROOT, "build"), help="build directory (bin/ inside)")
    parser.add_argument("--runs", type=int, default=1000)
    parser.add_argument("--rounds", type=int, default=3)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--optimise", action="store_true", help="also the optimisation comparison")
    parser.add_argument("--grid", type=int, default=41, help="the fine sweep's points per parameter")
    parser.add_argument("--budget", type=int, default=200, help="an optimiser's evaluations at most")
    args = parser.parse_args()
    server_bin = os.path.join(args.build, "bin", "tlmhub-server")
    cli = os.path.join(args.build, "bin", "tlmhub-cli")
    hmf = open(SERVO).read()
    data_dir = tempfile.mkdtemp(prefix="study-bench-")
    process, port = start_server(server_bin, data_dir, args.workers)
    try:
        api = Api(port)
        api.token = api.call("POST", "/auth/login", {"username": "admin", "password": PASSWORD})["token"]
        ratios = []
        for round_number in range(args.rounds):
            if round_number % 2 == 0:
                batch = time_batch(cli, SERVO, args.runs, args.workers)
                sweep = time_sweep(api, hmf, args.runs)
            else:
                sweep = time_sweep(api, hmf, args.runs)
                batch = time_batch(cli, SERVO, args.runs, args.workers)
            ratios.append(sweep / batch)
            print(f"round {round_number + 1}: sweep of {args.runs} runs {sweep:.2f} s, tlmhub-cli batch "
                  f"{batch:.2f} s, ratio {sweep / batch:.3f}", flush=True)
        print(f"median ratio sweep / batch: {statistics.median(ratios):.3f}")
        if args.optimise:
            optimise(api, hmf, args.grid, args.budget)
    finally:
        process.send_signal(signal.SIGTERM)
        process.wait(timeout=60)
        shutil.rmtree(data_dir, ignore_errors=True)


if __name__ == "__main__":
    sys.exit(main())
