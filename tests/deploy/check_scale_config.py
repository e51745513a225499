#!/usr/bin/env python3
"""Checks docker/compose.scale.yaml and docker/nginx/tlmhub-scale.conf without Docker.

  python3 tests/deploy/check_scale_config.py

Needs python3-yaml and Debian's nginx (apt-get install python3-yaml nginx). It checks that
the compose file parses and that its nodes agree with each other and with nginx's upstream,
that nginx accepts the configuration (`nginx -t`, the upstream names pointed at loopback,
since they resolve only inside compose), and runs the node-secrets step's script on
temporary files. Exit status 0 when all hold, 1 with the failures listed.
"""
import os
import re
import shutil
import subprocess
import sys
import tempfile

import yaml

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
COMPOSE = os.path.join(ROOT, "docker", "compose.scale.yaml")
NGINX_CONF = os.path.join(ROOT, "docker", "nginx", "tlmhub-scale.conf")

failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def flag(command, name):
    return command[command.index(name) + 1] if name in command else None


def check_compose(compose):
    services = compose["services"]
    for name in ("postgres", "node-secrets", "api1", "api2", "worker1", "worker2", "worker3", "nginx"):
        check(name in services, f"service {name} exists")
    nodes = {n: s for n, s in services.items() if re.fullmatch(r"(api|worker)\d+", n)}
    databases, secrets, addresses = set(), set(), set()
    for name, service in nodes.items():
        command = service["command"]
        role = "api" if name.startswith("api") else "worker"
        check(flag(command, "--role") == role, f"{name}: --role {role}")
        address = flag(command, "--node-address")
        check(address == f"http://{name}:8080", f"{name}: --node-address http://{name}:8080")
        addresses.add(address)
        databases.add(flag(command, "--database"))
        secrets.add(flag(command, "--node-secret-file"))
        check(service.get("build", {}).get("dockerfile") == "docker/Dockerfile", f"{name}: built from docker/Dockerfile")
        check("PGPASSFILE" in service.get("environment", {}), f"{name}: PGPASSFILE set")
        check(service.get("stop_signal") == "SIGTERM", f"{name}: stopped with SIGTERM")
        check(name == "api1" or "api1" in service.get("depends_on", {}), f"{name}: is api1 or starts after it")
    check(len(addresses) == len(nodes), "node addresses are distinct")
    check(len(databases) == 1 and next(iter(databases), "").startswith("postgresql://"), "one postgresql:// database for all nodes")
    check(len(secrets) == 1 and None not in secrets, "one node secret file for all nodes")
    check("TLMHUB_ADMIN_PASSWORD" in services["api1"]["environment"], "api1 sets the first admin password")
    # The failed-login limits count each client's address only if the API nodes trust nginx's
    # X-Forwarded-For, and nothing else's.
    nginx_networks = services["nginx"].get("networks", {})
    nginx_address = nginx_networks.get("nodes", {}).get("ipv4_address") if isinstance(nginx_networks, dict) else None
    check(nginx_address is not None, "nginx has a fixed address on the nodes network")
    for name, service in nodes.items():
        if name.startswith("api"):
            check(flag(service["command"], "--trusted-proxy") == nginx_address,
                  f"{name}: --trusted-proxy is nginx's address ({nginx_address})")
    check("X-Forwarded-For $proxy_add_x_forwarded_for" in open(NGINX_CONF).read(),
          "nginx appends the client's address to X-Forwarded-For")
    ports = services["nginx"].get("ports", [])
    check(ports == ["127.0.0.1:8080:8080"], "only nginx publishes a port, on loopback")
    check(all("ports" not in s for n, s in services.items() if n != "nginx"), "no other service publishes a port")
    for dockerfile in {s["build"]["dockerfile"] for s in services.values() if "build" in s}:
        check(os.path.isfile(os.path.join(ROOT, dockerfile)), f"{dockerfile} exists")
    return nodes


def check_nginx(nodes):
    text = open(NGINX_CONF).read()
    upstream = set(re.findall(r"server (\w+):8080", text))
    check(upstream == {n for n in nodes if n.startswith("api")}, "nginx's upstream lists exactly the API nodes")
    if shutil.which("nginx") is None and not os.path.exists("/usr/sbin/nginx"):
        check(False, "nginx is installed (apt-get install nginx)")
        return
    nginx = shutil.which("nginx") or "/usr/sbin/nginx"
    with tempfile.TemporaryDirectory() as tmp:
        site = text
        for i, name in enumerate(sorted(upstream)):
            site = site.replace(f"{name}:8080", f"127.0.0.1:{18081 + i}")
        open(os.path.join(tmp, "site.conf"), "w").write(site)
        open(os.path.join(tmp, "test.conf"), "w").write(
            f"pid {tmp}/nginx.pid;\nerror_log {tmp}/error.log;\nevents {{}}\n"
            f"http {{\n access_log off;\n client_body_temp_path {tmp};\n proxy_temp_path {tmp};\n"
            f" include {tmp}/site.conf;\n}}\n")
        r = subprocess.run([nginx, "-t", "-q", "-c", os.path.join(tmp, "test.conf")], capture_output=True, text=True)
        check(r.returncode == 0, "nginx -t accepts tlmhub-scale.conf" + ("" if r.returncode == 0 else ": " + r.stderr.strip()))


def run_secret_step(script, tmp, node_secret, db_password):
    secrets, out = os.path.join(tmp, "secrets"), os.path.join(tmp, "out")
    os.makedirs(secrets, exist_ok=True)
    shutil.rmtree(out, ignore_errors=True)
    os.makedirs(out)
    open(os.path.join(secrets, "node_secret"), "w").write(node_secret)
    open(os.path.join(secrets, "db_password"), "w").write(db_password)
    # Compose turns $$ into $; the server's user does not exist here.
    script = (script.replace("$$", "$").replace("/run/secrets", secrets).replace("/run/tlmhub-node", out)
              .replace("install -o tlmhub ", "install ").replace("chown tlmhub ", "true "))
    r = subprocess.run(["bash", "-c", script], capture_output=True, text=True)
    return r.returncode, out


def check_secret_step(compose):
    script = compose["services"]["node-secrets"]["command"][0]
    with tempfile.TemporaryDirectory() as tmp:
        rc, out = run_secret_step(script, tmp, "x" * 64 + "\n", "pa:ss\\word\n")
        check(rc == 0, "node-secrets step succeeds")
        if rc == 0:
            pgpass = open(os.path.join(out, "pgpass")).read()
            check(pgpass == "postgres:5432:tlmhub:tlmhub:pa\\:ss\\\\word\n", "pgpass escapes ':' and '\\'")
            for name in ("node.secret", "pgpass"):
                mode = os.stat(os.path.join(out, name)).st_mode & 0o777
                check(mode == 0o600, f"{name} has mode 0600")
        rc, _ = run_secret_step(script, tmp, "short\n", "pw\n")
        check(rc != 0, "node-secrets step refuses a secret under 32 bytes")


def main():
    compose = yaml.safe_load(open(COMPOSE))
    nodes = check_compose(compose)
    check_nginx(nodes)
    check_secret_step(compose)
    print(f"{len(failures)} failed")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
