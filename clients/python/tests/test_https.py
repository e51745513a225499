"""https:// through a TLS-terminating proxy (tests/tools/tls_proxy.py): the certificate is
trusted through SSL_CERT_FILE, as the system trust store would trust a real one."""
import os
import ssl
import unittest
from unittest import mock

import tlmhub
from harness import ADMIN_PASSWORD, Server, expectation, shared_model

server: Server
HAVE_WEBSOCKET = expectation("TLMHUB_EXPECT_WEBSOCKET", "websocket")


def setUpModule() -> None:
    global server, https_url, certificate
    server = Server()
    https_url, certificate = server.tls_proxy()


def tearDownModule() -> None:
    server.stop()


class Https(unittest.TestCase):
    def test_run_over_https_with_ssl_cert_file(self):
        with mock.patch.dict(os.environ, {"SSL_CERT_FILE": certificate}):
            client = tlmhub.Client.login(https_url, "admin", ADMIN_PASSWORD)
            result = client.run(shared_model(), stop=0.2)
        plain = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD).run(shared_model(), stop=0.2)
        self.assertEqual(result.to_csv(), plain.to_csv())

    def test_an_untrusted_certificate_is_refused(self):
        with mock.patch.dict(os.environ, {"SSL_CERT_FILE": os.devnull}):
            with self.assertRaises(tlmhub.ConnectionFailed) as caught:
                tlmhub.Client.login(https_url, "admin", ADMIN_PASSWORD)
        self.assertIsInstance(caught.exception.reason, ssl.SSLCertVerificationError)

    def test_errors_come_through_the_proxy(self):
        with mock.patch.dict(os.environ, {"SSL_CERT_FILE": certificate}):
            client = tlmhub.Client.login(https_url, "admin", ADMIN_PASSWORD)
            with self.assertRaises(tlmhub.ApiError) as caught:
                client.jobs.get(999999)
        self.assertEqual((caught.exception.status, caught.exception.code), (404, "not_found"))

    @unittest.skipUnless(HAVE_WEBSOCKET, "wss://: the venv with websocket-client")
    def test_stream_over_wss(self):
        with mock.patch.dict(os.environ, {"SSL_CERT_FILE": certificate}):
            client = tlmhub.Client.login(https_url, "admin", ADMIN_PASSWORD)
            job = client.run(shared_model(), stop=2, wait=False)
            frames = list(client.stream(job.id, ["Mass#P2#Position"]))
            stored = client.jobs.results(job.id, ["Mass#P2#Position"])
        self.assertEqual([v for f in frames for v in f["Mass#P2#Position"]],
                         list(stored["Mass#P2#Position"]))


if __name__ == "__main__":
    unittest.main()
