"""API tokens (docs/studies.md, "API tokens"): create, use, list, revoke.

These wait for the server's /tokens (being built on branch `tokens`); until it is merged
they fail with 404 `no API route`."""
import time
import unittest

import tlmhub
from harness import ADMIN_PASSWORD, Server, expectation, shared_model

server: Server
HAVE_WEBSOCKET = expectation("TLMHUB_EXPECT_WEBSOCKET", "websocket")
TOKEN_CHARACTERS = set("ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789-_")


def setUpModule() -> None:
    global server
    server = Server()


def tearDownModule() -> None:
    server.stop()


class Tokens(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.admin = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)

    def test_a_new_token_is_shown_once_and_works(self):
        created = self.admin.tokens.create("test script")
        token = created["token"]
        self.assertTrue(token.startswith("tlmh_"), token)
        self.assertEqual(len(token), len("tlmh_") + 43)
        self.assertLessEqual(set(token[5:]), TOKEN_CHARACTERS)
        self.assertEqual(created["name"], "test script")
        self.assertIsNone(created["expires_at"])
        client = tlmhub.Client(server.url, token)
        self.assertEqual(client.me()["username"], "admin")
        listed = {t["id"]: t for t in self.admin.tokens.list()}
        self.assertIn(created["id"], listed)
        self.assertNotIn("token", listed[created["id"]])

    def test_list_is_newest_first(self):
        first = self.admin.tokens.create("older")
        time.sleep(1.1)   # created_at is in seconds: make the order not depend on a tie
        second = self.admin.tokens.create("newer")
        ids = [t["id"] for t in self.admin.tokens.list()]
        self.assertLess(ids.index(second["id"]), ids.index(first["id"]))

    def test_expiry_in_days(self):
        created = self.admin.tokens.create("a month", expires_in_days=30)
        self.assertAlmostEqual(created["expires_at"] - created["created_at"], 30 * 86400, delta=5)
        self.assertAlmostEqual(created["created_at"], time.time(), delta=60)

    def test_a_deleted_token_is_401_at_once(self):
        created = self.admin.tokens.create("revoked")
        client = tlmhub.Client(server.url, created["token"])
        client.models.list()
        self.admin.tokens.delete(created["id"])
        with self.assertRaises(tlmhub.ApiError) as caught:
            client.models.list()
        self.assertEqual((caught.exception.status, caught.exception.code), (401, "unauthorized"))
        self.assertNotIn(created["id"], [t["id"] for t in self.admin.tokens.list()])

    def test_another_users_token_is_404(self):
        self.admin._transport.json("POST", "/users", json_body={
            "username": "bob", "password": "bob-password", "role": "user"})
        bob = tlmhub.Client.login(server.url, "bob", "bob-password")
        created = self.admin.tokens.create("admin's")
        with self.assertRaises(tlmhub.ApiError) as caught:
            bob.tokens.delete(created["id"])
        self.assertEqual((caught.exception.status, caught.exception.code), (404, "not_found"))
        self.assertNotIn(created["id"], [t["id"] for t in bob.tokens.list()])

    def test_a_name_too_long_is_refused(self):
        with self.assertRaises(tlmhub.ApiError) as caught:
            self.admin.tokens.create("x" * 101)
        self.assertEqual(caught.exception.status, 400)

    @unittest.skipUnless(HAVE_WEBSOCKET, "streaming: the venv with websocket-client")
    def test_stream_with_a_token(self):
        client = tlmhub.Client(server.url, self.admin.tokens.create("streamer")["token"])
        job = client.run(shared_model(), stop=1, wait=False)
        frames = list(client.stream(job.id, ["Mass#P2#Position"]))
        self.assertEqual([v for f in frames for v in f["Mass#P2#Position"]],
                         list(client.jobs.results(job.id)["Mass#P2#Position"]))


if __name__ == "__main__":
    unittest.main()
