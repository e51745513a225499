"""The kinds of ApiError a script catches, raised for what went wrong: a server that cannot be
reached, a URL that is not the server's, and each kind of refusal. Checked against a small
stand-in HTTP server (no tlmhub server needed); test_rest sees the same from the real one."""
import json
import socket
import threading
import unittest
from unittest import mock
from http.server import BaseHTTPRequestHandler, HTTPServer

import tlmhub


class Answers(BaseHTTPRequestHandler):
    """/api/v1/<status>: that status with the server's error body; /api/v1/flaky: 503 the
    first two times (Retry-After 0), then 200; anything else a web page."""
    calls: dict = {}

    def do_POST(self):
        self.do_GET()

    def do_GET(self):
        part = self.path.rsplit("/", 1)[-1]
        Answers.calls[(self.command, part)] = Answers.calls.get((self.command, part), 0) + 1
        if part == "flaky" and Answers.calls[(self.command, part)] > 2:
            body = b'{"ok": true}'
            self.send_response(200)
            self.send_header("Content-Type", "application/json")
        elif part == "flaky":
            body = json.dumps({"error": {"code": "busy", "message": "try again"}}).encode()
            self.send_response(503)
            self.send_header("Retry-After", "0")
        elif part.isdigit():
            body = json.dumps({"error": {"code": f"code_{part}", "message": f"status {part}"}}).encode()
            self.send_response(int(part))
            self.send_header("Content-Type", "application/json")
            if part == "429":
                self.send_header("Retry-After", "7")
        else:
            body = b"<html><body>Welcome to the intranet</body></html>"
            self.send_response(200)
            self.send_header("Content-Type", "text/html")
        self.send_header("Content-Length", str(len(body)))
        self.end_headers()
        self.wfile.write(body)

    def log_message(self, *args):
        pass


class Errors(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.http = HTTPServer(("127.0.0.1", 0), Answers)
        threading.Thread(target=cls.http.serve_forever, daemon=True).start()
        cls.client = tlmhub.Client(f"http://127.0.0.1:{cls.http.server_port}", "tlmh_test")

    @classmethod
    def tearDownClass(cls):
        cls.http.shutdown()
        cls.http.server_close()

    def test_each_refusal_has_its_kind_with_the_servers_code_and_message(self):
        self.client._transport.retries = 0   # 429, 503: one answer each
        kinds = {400: tlmhub.Refused, 401: tlmhub.Unauthorized, 403: tlmhub.Refused, 404: tlmhub.NotFound,
                 409: tlmhub.Refused, 413: tlmhub.LimitExceeded, 422: tlmhub.LimitExceeded,
                 429: tlmhub.LimitExceeded, 500: tlmhub.ApiError, 503: tlmhub.ApiError}
        for status, kind in kinds.items():
            with self.assertRaises(tlmhub.ApiError) as caught:
                self.client._transport.json("GET", f"/{status}")
            self.assertIs(type(caught.exception), kind, status)
            self.assertEqual((caught.exception.status, caught.exception.code, caught.exception.message),
                             (status, f"code_{status}", f"status {status}"))
        with self.assertRaises(tlmhub.LimitExceeded) as caught:
            self.client._transport.json("GET", "/429")
        self.assertEqual(caught.exception.retry_after, 7)
        self.client._transport.retries = 5

    def test_a_get_is_sent_again_after_a_busy_answer_a_post_is_not(self):
        self.assertEqual(self.client._transport.json("GET", "/flaky"), {"ok": True})
        self.assertEqual(Answers.calls[("GET", "flaky")], 3)
        with self.assertRaises(tlmhub.ApiError) as caught:
            self.client._transport.json("POST", "/flaky", json_body={})
        self.assertEqual(caught.exception.status, 503)
        self.assertEqual(Answers.calls[("POST", "flaky")], 1, "a POST could create twice: never sent again")

    def test_a_url_that_is_not_the_servers_says_so(self):
        with self.assertRaises(tlmhub.ApiError) as caught:
            self.client._transport.json("GET", "/models")
        self.assertEqual(caught.exception.code, "bad_reply")
        self.assertIn("is not JSON", caught.exception.message)
        self.assertIn(f"127.0.0.1:{self.http.server_port}", caught.exception.message)

    def test_a_server_that_cannot_be_reached_is_connection_failed(self):
        with socket.socket() as unused:   # a port nothing listens on
            unused.bind(("127.0.0.1", 0))
            port = unused.getsockname()[1]
        client = tlmhub.Client(f"http://127.0.0.1:{port}", "tlmh_test")
        with mock.patch("tlmhub._http.time.sleep") as sleep:
            with self.assertRaises(tlmhub.ConnectionFailed) as caught:
                client.models.list()
        pauses = [call.args[0] for call in sleep.call_args_list]
        self.assertEqual(len(pauses), 5, "tried 6 times in all")
        self.assertTrue(all(0 <= p <= 0.5 * 2 ** i for i, p in enumerate(pauses)), pauses)
        self.assertEqual((caught.exception.status, caught.exception.code), (0, "connection_failed"))
        self.assertIn(f"127.0.0.1:{port}", caught.exception.message)


if __name__ == "__main__":
    unittest.main()
