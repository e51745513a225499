"""Submits whose answer is lost on the way back: the client sends the POST again with the same
Idempotency-Key, and the real server gives it the job or study the first attempt made, so a
script's retry never runs anything twice. A refusal (4xx) is never sent again. A small proxy
in front of the server drops chosen answers."""
import http.client
import threading
import unittest
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer

import tlmhub
from harness import ADMIN_PASSWORD, Server, shared_model

server: Server


def setUpModule() -> None:
    global server
    server = Server()


def tearDownModule() -> None:
    server.stop()


class LosingProxy(BaseHTTPRequestHandler):
    """Forwards every request to the server; the first answer to each path in `lose` is read
    from the server and then dropped (the connection closed without it). Records each
    forwarded request's method, path and Idempotency-Key."""
    backend = ""
    lose: set = set()
    lost: set = set()
    seen: list = []

    def _forward(self):
        length = int(self.headers.get("Content-Length") or 0)
        body = self.rfile.read(length) if length else None
        headers = {k: v for k, v in self.headers.items() if k.lower() not in ("host", "connection")}
        LosingProxy.seen.append((self.command, self.path, self.headers.get("Idempotency-Key")))
        upstream = http.client.HTTPConnection(LosingProxy.backend, timeout=60)
        upstream.request(self.command, self.path, body=body, headers=headers)
        answer = upstream.getresponse()
        data = answer.read()
        upstream.close()
        key = (self.command, self.path)
        if key in LosingProxy.lose and key not in LosingProxy.lost:
            LosingProxy.lost.add(key)
            self.close_connection = True
            return
        self.send_response(answer.status)
        for name, value in answer.getheaders():
            if name.lower() not in ("connection", "transfer-encoding", "content-length"):
                self.send_header(name, value)
        self.send_header("Content-Length", str(len(data)))
        self.end_headers()
        self.wfile.write(data)

    do_GET = do_POST = do_DELETE = _forward

    def log_message(self, *args):
        pass


class LostAnswers(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        LosingProxy.backend = server.url.removeprefix("http://")
        cls.proxy = ThreadingHTTPServer(("127.0.0.1", 0), LosingProxy)
        threading.Thread(target=cls.proxy.serve_forever, daemon=True).start()
        admin = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)
        cls.direct = admin
        cls.client = tlmhub.Client(f"http://127.0.0.1:{cls.proxy.server_port}", admin._transport.token)
        cls.client._transport.backoff = 0.05

    @classmethod
    def tearDownClass(cls):
        cls.proxy.shutdown()

    def setUp(self):
        LosingProxy.lose, LosingProxy.lost, LosingProxy.seen = set(), set(), []

    def posts(self, path):
        return [key for method, p, key in LosingProxy.seen if method == "POST" and p == "/api/v1" + path]

    def test_a_job_submit_whose_answer_was_lost_makes_one_job(self):
        LosingProxy.lose = {("POST", "/api/v1/jobs")}
        before = {job.id for job in self.direct.jobs.list()}
        job = self.client.run(shared_model(), stop=0.2, wait=False)
        keys = self.posts("/jobs")
        self.assertEqual(len(keys), 2, "sent again after the lost answer")
        self.assertTrue(keys[0])
        self.assertEqual(keys[0], keys[1], "with the same Idempotency-Key")
        made = {j.id for j in self.direct.jobs.list()} - before
        self.assertEqual(made, {job.id}, "one job, the one the client was given")
        self.assertEqual(job.wait(timeout=60).state, "done")

    def test_a_study_submit_whose_answer_was_lost_makes_one_study(self):
        LosingProxy.lose = {("POST", "/api/v1/studies")}
        before = {study.id for study in self.direct.studies.list()}
        study = self.client.sweep(shared_model(), {"GainP.k": [0.01, 0.02]}, stop=0.2, wait=False)
        keys = self.posts("/studies")
        self.assertEqual(len(keys), 2)
        self.assertEqual(keys[0], keys[1])
        made = {s.id for s in self.direct.studies.list()} - before
        self.assertEqual(made, {study.id})
        self.assertEqual(study.wait(timeout=120).state, "done")

    def test_each_submit_has_a_key_of_its_own(self):
        first = self.client.run(shared_model(), stop=0.1, wait=False)
        second = self.client.run(shared_model(), stop=0.1, wait=False)
        self.assertNotEqual(first.id, second.id)
        keys = self.posts("/jobs")
        self.assertEqual(len(keys), 2)
        self.assertNotEqual(keys[0], keys[1])

    def test_a_refusal_is_not_sent_again(self):
        with self.assertRaises(tlmhub.LimitExceeded) as caught:
            self.client.run(shared_model(), stop=1e12, wait=False)
        self.assertEqual(caught.exception.status, 422)
        self.assertEqual(len(self.posts("/jobs")), 1)


if __name__ == "__main__":
    unittest.main()
