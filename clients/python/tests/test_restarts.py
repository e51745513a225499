"""A wait that lasts through a server restart (SIGTERM, then the server again on the same
address and data): it neither raises a connection error nor hangs, and ends with what the
server says after the restart. With websocket-client (the system venv) the study's wait
listens to events, so its socket breaks and is opened again; without it, it polls."""
import threading
import time
import unittest

import tlmhub
from harness import ADMIN_PASSWORD, Server, shared_model

server: Server


def setUpModule() -> None:
    global server
    # One worker and one running job per user: a long job holds both, so the study or job
    # waited on stays queued through the restart.
    server = Server(workers=1, extra_args=("--max-running-per-user", "1"))


def tearDownModule() -> None:
    server.stop()


def wait_through_a_restart(test, waitable):
    """Waits on `waitable` in a thread, restarts the server while it waits, and returns what
    the wait returned (failing `test` if it ended before the restart, hangs or raises)."""
    outcome = {}

    def run():
        try:
            outcome["value"] = waitable.wait(timeout=120)
        except BaseException as error:  # noqa: BLE001 - the test reports it
            outcome["error"] = error

    thread = threading.Thread(target=run, daemon=True)
    thread.start()
    time.sleep(1.0)
    test.assertTrue(thread.is_alive(), f"the wait ended before the restart: {outcome}")
    server.restart()
    thread.join(150)
    test.assertFalse(thread.is_alive(), "the wait hangs after the restart")
    test.assertNotIn("error", outcome, f"the wait raised {outcome.get('error')!r}")
    return outcome["value"]


class Restarts(unittest.TestCase):
    def setUp(self):
        self.client = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)

    def running_blocker(self):
        """A long job holding the only worker, once it runs."""
        blocker = self.client.run(shared_model(), stop=5000, wait=False)
        for _ in range(500):
            if blocker.refresh().state == "running":
                return blocker
            time.sleep(0.02)
        self.fail(f"the long job never ran: {blocker.info}")

    def test_a_study_wait_goes_on_through_a_restart(self):
        blocker = self.running_blocker()
        study = self.client.sweep(shared_model(), {"GainP.k": [0.01, 0.02, 0.03]}, stop=0.2, wait=False)
        self.assertEqual(wait_through_a_restart(self, study).state, "done")
        self.assertEqual(len(study.table()), 3)
        self.assertEqual(self.client.jobs.get(blocker.id).state, "interrupted")

    def test_a_job_wait_goes_on_through_a_restart(self):
        self.running_blocker()
        job = self.client.run(shared_model(), stop=0.2, wait=False)
        self.assertEqual(wait_through_a_restart(self, job).state, "done")

    def test_a_wait_on_a_server_that_stays_away_raises_connection_failed(self):
        client = tlmhub.Client(server.url, self.client._transport.token, retries=0, reconnect_timeout=1.0)
        job = client.run(shared_model(), stop=0.2, wait=False)
        job.wait(timeout=60)
        unreachable = tlmhub.Client("http://127.0.0.1:9", "tlmh_x", retries=0, reconnect_timeout=1.0)
        job._client = unreachable
        started = time.monotonic()
        with self.assertRaises(tlmhub.ConnectionFailed):
            job.wait()
        self.assertGreaterEqual(time.monotonic() - started, 1.0, "tried for reconnect_timeout")


if __name__ == "__main__":
    unittest.main()
