#!/usr/bin/env python3
"""Throughput of a scale-out deployment (issue 19): one API node and 1, 2, 4 worker nodes.

Starts a PostgreSQL 15 of its own (Debian's postgresql-15, initdb in a temporary directory,
its durable defaults: fsync and synchronous commit on) on a free loopback port. For each worker
count N it makes a fresh database, starts tlmhub-server --role api and N tlmhub-server --role
worker (each --workers 1, so a worker is one simulation thread), creates U users (admin REST
API) who upload Position Servo, and then, timed: every user submits their share of J short
jobs at once (REST, one thread per user; --users 10 keeps each user within the per-user
limits of 2 running and 20 queued, so they do not cap the throughput), until all J have
ended (polled in the database with psql every 50 ms). Printed per N: jobs done / other, the
seconds and jobs/s, how the claims spread over the workers, and each node's CPU seconds.

The machine's cores bound what more workers can give: each worker is one simulation thread,
and the API node and PostgreSQL take their share too (`nproc` is printed).

example: bench/scale_bench.py                          # 1, 2, 4 workers, 200 jobs, 10 users
         bench/scale_bench.py --workers 1,2 --jobs 400 --users 20 --json
Needs Python 3 (standard library) and /usr/bin/psql.
"""
import argparse
import json
import os
import secrets
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
import urllib.error
import urllib.request

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_SERVER = os.path.join(ROOT, "build", "bin", "tlmhub-server")
DEFAULT_MODEL = os.path.join(ROOT, "..", "shared", "hopsan-models", "Example Models", "Position Servo.hmf")
ADMIN_PASSWORD = "scale-bench-admin-password"
PG_BIN = "/usr/lib/postgresql/15/bin"
CLK_TCK = os.sysconf("SC_CLK_TCK")


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


class Postgres:
    """PostgreSQL 15 with fsync on, in a temporary directory, as nobody when run as root."""

    def __init__(self):
        import pwd
        self.dir = tempfile.mkdtemp(prefix="tlmhub-scale-pg-")
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
        subprocess.run([PG_BIN + "/initdb", "-D", data, "-U", "tlmhub", "--auth=trust", "--encoding=UTF8",
                        "--locale=C.UTF-8", "--no-instructions"], check=True, stdout=subprocess.DEVNULL,
                       preexec_fn=demote, cwd=self.dir)
        self.port = free_port()
        self.log = open(os.path.join(self.dir, "postgres.log"), "wb")
        self.proc = subprocess.Popen([PG_BIN + "/postgres", "-D", data, "-h", "127.0.0.1", "-p", str(self.port),
                                      "-k", os.path.join(self.dir, "socket"), "-c", "max_connections=100"],
                                     stdout=self.log, stderr=subprocess.STDOUT, preexec_fn=demote, cwd=self.dir)
        deadline = time.monotonic() + 30
        while self.psql("postgres", "SELECT 1", check=False) is None:
            if time.monotonic() > deadline or self.proc.poll() is not None:
                self.stop()
                raise RuntimeError("PostgreSQL did not start")
            time.sleep(0.2)

    def uri(self, db):
        return f"postgresql://tlmhub@127.0.0.1:{self.port}/{db}"

    def psql(self, db, query, check=True):
        r = subprocess.run(["/usr/bin/psql", "-X", "-q", "-t", "-A", "-F", "\t", "-h", "127.0.0.1", "-p", str(self.port),
                            "-U", "tlmhub", "-d", db, "-c", query], capture_output=True, text=True)
        if r.returncode != 0:
            if check:
                raise RuntimeError(f"psql {query!r}: {r.stderr.strip()}")
            return None
        return [line.split("\t") for line in r.stdout.splitlines() if line]

    def stop(self):
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGINT)  # fast shutdown
            self.proc.wait(timeout=60)
        self.log.close()
        shutil.rmtree(self.dir, ignore_errors=True)


def takes_node_secret(binary, cache={}):
    """Whether the server has --node-secret-file (builds before the relay between nodes do not)."""
    if binary not in cache:
        text = subprocess.run([binary, "--help"], capture_output=True, text=True).stdout
        cache[binary] = "--node-secret-file" in text
    return cache[binary]


class Node:
    """One tlmhub-server process of the deployment on a port chosen in advance."""

    def __init__(self, binary, tmp, node_id, role, database, secret_file, extra):
        self.id = node_id
        self.port = free_port()
        data = os.path.join(tmp, node_id)
        os.makedirs(os.path.join(data, "examples"), exist_ok=True)
        self.log_path = os.path.join(tmp, node_id + ".log")
        self.log = open(self.log_path, "wb")
        args = [binary, "--listen", f"127.0.0.1:{self.port}", "--data-dir", data,
                "--examples-dir", os.path.join(data, "examples"), "--web-root", os.path.join(data, "no-web"),
                "--database", database, "--role", role, "--node-id", node_id,
                "--node-address", f"http://127.0.0.1:{self.port}"]
        if takes_node_secret(binary):
            args += ["--node-secret-file", secret_file]
        args += extra
        self.proc = subprocess.Popen(args, stdout=self.log, stderr=subprocess.STDOUT,
                                     env=dict(os.environ, TLMHUB_ADMIN_PASSWORD=ADMIN_PASSWORD))
        deadline = time.monotonic() + 30
        while time.monotonic() < deadline and self.proc.poll() is None:
            with open(self.log_path, errors="replace") as f:
                if "listening on http://127.0.0.1:" in f.read():
                    return
            time.sleep(0.05)
        self.stop()
        with open(self.log_path, errors="replace") as f:
            raise RuntimeError(f"{node_id} did not start:\n{f.read()[-3000:]}")

    def cpu_seconds(self):
        try:
            with open(f"/proc/{self.proc.pid}/stat") as f:
                fields = f.read().rsplit(")", 1)[1].split()
            return (int(fields[11]) + int(fields[12])) / CLK_TCK
        except OSError:
            return float("nan")

    def stop(self):
        if self.proc.poll() is None:
            self.proc.send_signal(signal.SIGTERM)
            try:
                self.proc.wait(timeout=30)
            except subprocess.TimeoutExpired:
                self.proc.kill()
                self.proc.wait()
        self.log.close()


def rest(port, method, path, token=None, body=None, content_type="application/json"):
    data = None
    headers = {}
    if body is not None:
        data = body if isinstance(body, bytes) else json.dumps(body).encode()
        headers["Content-Type"] = content_type
    if token:
        headers["Authorization"] = "Bearer " + token
    for _ in range(50):  # 503: the password-hashing queue asks to try again
        request = urllib.request.Request(f"http://127.0.0.1:{port}{path}", data=data, headers=headers, method=method)
        try:
            with urllib.request.urlopen(request, timeout=60) as r:
                text = r.read()
                return json.loads(text) if text else None
        except urllib.error.HTTPError as e:
            if e.code != 503:
                raise RuntimeError(f"{method} {path}: HTTP {e.code}: {e.read()[:300]!r}")
        time.sleep(0.2)
    raise RuntimeError(f"{method} {path}: busy")


def run_round(a, postgres, workers, hmf, tmp):
    db = f"tlmhub_w{workers}"
    postgres.psql("postgres", f"CREATE DATABASE {db}")
    secret_file = os.path.join(tmp, "node-secret")
    with open(secret_file, "w") as f:
        f.write(secrets.token_hex(32))
    os.chmod(secret_file, 0o600)
    nodes = []
    try:
        api = Node(a.server, tmp, "api1", "api", postgres.uri(db), secret_file, list(a.server_arg))
        nodes.append(api)
        admin = rest(api.port, "POST", "/api/v1/auth/login", body={"username": "admin", "password": ADMIN_PASSWORD})["token"]
        users = []
        for u in range(a.users):
            name = f"user{u}"
            rest(api.port, "POST", "/api/v1/users", admin, {"username": name, "password": name + "-password", "role": "user"})
            token = rest(api.port, "POST", "/api/v1/auth/login", body={"username": name, "password": name + "-password"})["token"]
            model = rest(api.port, "POST", "/api/v1/models?name=servo", token, hmf.encode(), "application/xml")["id"]
            users.append((token, model))
        # Which worker claimed each job: jobs.lease_node is cleared when a job ends, so a trigger
        # (one small insert in the claim's transaction) records it.
        postgres.psql(db, "CREATE TABLE bench_claims (job_id BIGINT, node TEXT);"
                          "CREATE FUNCTION bench_claim() RETURNS trigger LANGUAGE plpgsql AS $$ BEGIN"
                          " INSERT INTO bench_claims VALUES (NEW.id, NEW.lease_node); RETURN NEW; END $$;"
                          "CREATE TRIGGER bench_claim AFTER UPDATE ON jobs FOR EACH ROW"
                          " WHEN (NEW.lease IS DISTINCT FROM OLD.lease) EXECUTE FUNCTION bench_claim();")
        for i in range(workers):
            nodes.append(Node(a.server, tmp, f"w{i + 1}", "worker", postgres.uri(db), secret_file,
                              ["--workers", "1"] + list(a.server_arg)))
        time.sleep(0.5)  # the workers register and wait for work
        cpu0 = {n.id: n.cpu_seconds() for n in nodes}

        shares = [a.jobs // a.users + (1 if u < a.jobs % a.users else 0) for u in range(a.users)]
        errors = []
        go = threading.Event()

        def submit(u):
            token, model = users[u]
            go.wait()
            for _ in range(shares[u]):
                try:
                    rest(api.port, "POST", "/api/v1/jobs", token,
                         {"model_id": model, "log_samples": a.log_samples, **({"stop": a.stop} if a.stop else {})})
                except Exception as e:  # noqa: BLE001 - reported below
                    errors.append(str(e))
        threads = [threading.Thread(target=submit, args=(u,)) for u in range(a.users)]
        for t in threads:
            t.start()
        t0 = time.monotonic()
        go.set()
        for t in threads:
            t.join()
        submitted = time.monotonic() - t0
        ended = 0
        deadline = t0 + a.timeout
        while time.monotonic() < deadline:
            ended = int(postgres.psql(db, "SELECT count(*) FROM jobs WHERE state NOT IN ('queued', 'running')")[0][0])
            if ended >= a.jobs - len(errors):
                break
            time.sleep(0.05)
        seconds = time.monotonic() - t0
        states = dict(postgres.psql(db, "SELECT state, count(*) FROM jobs GROUP BY state"))
        per_worker = dict(postgres.psql(db, "SELECT COALESCE(node, '?'), count(*) FROM bench_claims GROUP BY 1"))
        reclaimed = int(postgres.psql(db, "SELECT count(*) FROM jobs WHERE lease > 1")[0][0])
        cpu = {n.id: round(n.cpu_seconds() - cpu0[n.id], 2) for n in nodes}
        done = int(states.get("done", 0))
        return {"workers": workers, "jobs": a.jobs, "done": done, "other": sum(int(v) for k, v in states.items() if k != "done"),
                "submit_errors": len(errors), "first_error": errors[0] if errors else "",
                "seconds": round(seconds, 3), "submit_seconds": round(submitted, 3),
                "jobs_per_second": round(done / seconds, 2), "claims_per_node": per_worker, "reclaimed": reclaimed,
                "cpu_seconds": cpu, "timed_out": ended < a.jobs - len(errors)}
    finally:
        for n in reversed(nodes):
            n.stop()


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--server", default=DEFAULT_SERVER)
    ap.add_argument("--model", default=DEFAULT_MODEL)
    ap.add_argument("--workers", default="1,2,4", help="worker node counts, comma separated (default 1,2,4)")
    ap.add_argument("--jobs", type=int, default=200)
    ap.add_argument("--users", type=int, default=10, help="users sharing the jobs (default 10: 20 each)")
    ap.add_argument("--stop", type=float, default=0, help="stop time of each job (default: the model's)")
    ap.add_argument("--log-samples", type=int, default=100)
    ap.add_argument("--timeout", type=float, default=300, help="seconds per round (default 300)")
    ap.add_argument("--server-arg", action="append", default=[], help="another flag for every node (repeatable)")
    ap.add_argument("--json", action="store_true", help="print the figures as JSON too")
    a = ap.parse_args()
    with open(a.model) as f:
        hmf = f.read()
    print(f"scale_bench: {a.jobs} jobs of {os.path.basename(a.model)} (log_samples {a.log_samples}"
          f"{', stop %g' % a.stop if a.stop else ''}), {a.users} users, 1 api node; PostgreSQL 15 with fsync on;"
          f" {os.cpu_count()} cores", flush=True)
    postgres = Postgres()
    rounds = []
    try:
        for workers in [int(w) for w in a.workers.split(",")]:
            tmp = tempfile.mkdtemp(prefix="tlmhub-scale-bench-")
            try:
                r = run_round(a, postgres, workers, hmf, tmp)
            finally:
                shutil.rmtree(tmp, ignore_errors=True)
            rounds.append(r)
            claims = " ".join(f"{k}={v}" for k, v in sorted(r["claims_per_node"].items()))
            cpu = " ".join(f"{k}={v}" for k, v in r["cpu_seconds"].items())
            print(f"workers {workers}: {r['done']}/{r['jobs']} done ({r['other']} other, {r['submit_errors']} refused),"
                  f" {r['seconds']:.2f} s (submitted in {r['submit_seconds']:.2f} s): {r['jobs_per_second']:.1f} jobs/s;"
                  f" claims {claims}; claimed again {r['reclaimed']}; CPU s {cpu}"
                  + (" TIMED OUT" if r["timed_out"] else "")
                  + (f"; first refusal: {r['first_error'][:200]}" if r["first_error"] else ""), flush=True)
    finally:
        postgres.stop()
    if a.json:
        print(json.dumps(rounds, indent=1))
    return 0 if all(r["done"] == r["jobs"] for r in rounds) else 1


if __name__ == "__main__":
    sys.exit(main())
