"""Live frames of a running job over the WebSocket (websocket-client), authenticated by the
Authorization header of the upgrade, and the clear error where websocket-client is missing."""
import importlib.util
import unittest
from unittest import mock

import tlmhub
from harness import ADMIN_PASSWORD, Server, expectation, shared_model

server: Server
HAVE_WEBSOCKET = expectation("TLMHUB_EXPECT_WEBSOCKET", "websocket")
VARIABLES = ["Mass#P2#Position", "Mass#P2#Velocity"]


def setUpModule() -> None:
    global server
    server = Server()


def tearDownModule() -> None:
    server.stop()


class Stream(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.client = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)
        cls.model = cls.client.models.upload(shared_model())

    def test_the_environment_is_the_expected_one(self):
        installed = importlib.util.find_spec("websocket") is not None
        self.assertEqual(installed, HAVE_WEBSOCKET)

    @unittest.skipUnless(HAVE_WEBSOCKET, "streaming: the venv with websocket-client")
    def test_frames_of_a_running_job_add_up_to_its_result(self):
        # 400 s of model time (4 000 000 steps) runs about a second in a Release build: frames
        # come 30 a second, so several arrive even when subscribing lags the start by a lot.
        # 20 s (56 ms) once finished before a loaded CI machine subscribed: one frame.
        job = self.client.run(self.model, stop=400, log_samples=4000, wait=False)
        frames = list(self.client.stream(job.id, VARIABLES))
        self.assertGreater(len(frames), 1)
        self.assertEqual(set(frames[0]), {"time", *VARIABLES})
        stored = self.client.jobs.results(job.id, VARIABLES)
        for name in ["time", *VARIABLES]:
            self.assertEqual([v for f in frames for v in f[name]], list(stored[name]), name)

    @unittest.skipUnless(HAVE_WEBSOCKET, "streaming: the venv with websocket-client")
    def test_the_token_travels_in_the_header_not_the_url(self):
        import websocket
        real = websocket.create_connection
        with mock.patch.object(websocket, "create_connection", side_effect=real) as spy:
            job = self.client.run(self.model, stop=0.2, wait=False)
            list(self.client.stream(job.id, VARIABLES))
        url = spy.call_args.args[0]
        token = self.client._transport.token
        self.assertTrue(url.endswith("/api/v1/ws"), url)
        self.assertNotIn(token, url)
        self.assertIn(f"Authorization: Bearer {token}", spy.call_args.kwargs["header"])

    @unittest.skipUnless(HAVE_WEBSOCKET, "streaming: the venv with websocket-client")
    def test_a_cancelled_job_ends_the_stream_with_simulation_failed(self):
        job = self.client.run(self.model, stop=500, wait=False)
        frames = self.client.stream(job.id, VARIABLES)
        next(frames)
        self.client.jobs.cancel(job.id)
        with self.assertRaises(tlmhub.SimulationFailed) as caught:
            list(frames)
        self.assertEqual(caught.exception.state, "cancelled")

    @unittest.skipUnless(HAVE_WEBSOCKET, "streaming: the venv with websocket-client")
    def test_a_bad_token_is_refused_at_the_upgrade(self):
        client = tlmhub.Client(server.url, "tlmh_not-a-token")
        with self.assertRaises(tlmhub.ApiError) as caught:
            next(client.stream(1))
        self.assertEqual(caught.exception.status, 401)

    @unittest.skipIf(HAVE_WEBSOCKET, "the missing-module error: the venv without websocket-client")
    def test_stream_says_what_to_install(self):
        with self.assertRaises(ImportError) as caught:
            self.client.stream(1)
        self.assertIn("websocket-client", str(caught.exception))
        self.assertIn("tlmhub[stream]", str(caught.exception))


if __name__ == "__main__":
    unittest.main()
