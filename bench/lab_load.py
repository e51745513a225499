#!/usr/bin/env python3
"""A teaching lab against a running tlmhub-server: N students log in and each submits one job
of the same model at once over REST; prints the wall time from the first submission until
every job is done, and jobs per second.

usage: lab_load.py BASE_URL ADMIN_PASSWORD MODEL.hmf [--students N]
"""
import argparse, json, threading, time, urllib.request


def call(base, method, path, token=None, body=None, content_type="application/json"):
    data = None
    if body is not None:
        data = body if isinstance(body, bytes) else json.dumps(body).encode()
    req = urllib.request.Request(base + path, data=data, method=method)
    if data is not None:
        req.add_header("Content-Type", content_type)
    if token:
        req.add_header("Authorization", "Bearer " + token)
    with urllib.request.urlopen(req) as r:
        text = r.read()
        return json.loads(text) if text else None


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("base"); ap.add_argument("admin_password"); ap.add_argument("model")
    ap.add_argument("--students", type=int, default=40)
    ap.add_argument("--pause", type=float, default=0.0)
    ap.add_argument("--log-samples", type=int, default=0, help="override the model's log samples")
    a = ap.parse_args()
    admin = call(a.base, "POST", "/api/v1/auth/login", body={"username": "admin", "password": a.admin_password})["token"]
    hmf = open(a.model, "rb").read()
    tokens = []
    for i in range(a.students):
        name, pw = f"student{i:02d}-{int(time.time())}", "lab-password"
        call(a.base, "POST", "/api/v1/users", admin, {"username": name, "password": pw, "role": "user"})
        tokens.append(call(a.base, "POST", "/api/v1/auth/login", body={"username": name, "password": pw})["token"])
    models = [call(a.base, "POST", "/api/v1/models?name=lab", t, hmf, "application/xml")["id"] for t in tokens]
    jobs = [None] * a.students
    if a.pause:
        print("ready", flush=True)
        time.sleep(a.pause)   # lets a profiler attach for the job phase only
    start = time.perf_counter()

    def submit(i):
        request = {"model_id": models[i]}
        if a.log_samples:
            request["log_samples"] = a.log_samples
        jobs[i] = call(a.base, "POST", "/api/v1/jobs", tokens[i], request)["id"]

    threads = [threading.Thread(target=submit, args=(i,)) for i in range(a.students)]
    for t in threads: t.start()
    for t in threads: t.join()
    pending = set(range(a.students))
    while pending:
        for i in list(pending):
            if call(a.base, "GET", f"/api/v1/jobs/{jobs[i]}", tokens[i])["state"] not in ("queued", "running"):
                pending.discard(i)
        time.sleep(0.1)
    wall = time.perf_counter() - start
    print(f"{a.students} jobs done in {wall:.3f} s: {a.students / wall:.1f} jobs/s")


if __name__ == "__main__":
    main()
