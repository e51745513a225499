"""The REST API through the client against a real server: login, models, jobs, results and
the errors a script sees."""
import json
import math
import unittest
import urllib.request

import tlmhub
from harness import ADMIN_PASSWORD, Server, shared_model

server: Server


def setUpModule() -> None:
    global server
    server = Server()


def tearDownModule() -> None:
    server.stop()


def raw_get(client: tlmhub.Client, path: str) -> bytes:
    """A GET outside the client, so its answers can be compared with the server's own."""
    request = urllib.request.Request(client.url + path,
                                     headers={"Authorization": "Bearer " + client._transport.token})
    with urllib.request.urlopen(request) as response:
        return response.read()


class Login(unittest.TestCase):
    def test_login_gives_a_session_that_works(self):
        client = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)
        self.assertEqual(client.me()["username"], "admin")

    def test_url_may_name_the_api_root(self):
        client = tlmhub.Client.login(server.url + "/api/v1/", "admin", ADMIN_PASSWORD)
        self.assertEqual(client.me()["role"], "admin")

    def test_wrong_password_is_401_unauthorized(self):
        with self.assertRaises(tlmhub.ApiError) as caught:
            tlmhub.Client.login(server.url, "admin", "not-the-password")
        self.assertEqual((caught.exception.status, caught.exception.code), (401, "unauthorized"))

    def test_unknown_token_is_401_unauthorized(self):
        with self.assertRaises(tlmhub.ApiError) as caught:
            tlmhub.Client(server.url, "tlmh_not-a-token").models.list()
        self.assertEqual((caught.exception.status, caught.exception.code), (401, "unauthorized"))
        self.assertTrue(caught.exception.message)

    def test_logout_ends_the_session(self):
        client = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)
        client.logout()
        with self.assertRaises(tlmhub.ApiError) as caught:
            client.me()
        self.assertEqual(caught.exception.status, 401)


class Models(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.client = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)

    def test_upload_a_file_names_the_model_after_it(self):
        model = self.client.models.upload(shared_model())
        self.assertEqual(model.name, "Position Servo")
        self.assertIn(model.id, [m.id for m in self.client.models.list()])
        self.assertEqual(self.client.models.hmf(model.id), shared_model().read_text())

    def test_upload_text_with_a_name(self):
        model = self.client.models.upload(shared_model().read_text(), name="servo from text")
        detail = self.client.models.get(model.id)
        self.assertEqual(detail.name, "servo from text")
        self.assertIn("model", detail.info)

    def test_delete_then_get_is_404_not_found(self):
        model = self.client.models.upload(shared_model())
        self.client.models.delete(model.id)
        with self.assertRaises(tlmhub.ApiError) as caught:
            self.client.models.get(model.id)
        self.assertEqual((caught.exception.status, caught.exception.code), (404, "not_found"))

    def test_text_that_is_no_model_is_400_invalid_model(self):
        with self.assertRaises(tlmhub.ApiError) as caught:
            self.client.models.upload("<hopsanmodelfile>", name="broken")
        self.assertEqual((caught.exception.status, caught.exception.code), (400, "invalid_model"))


class Jobs(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.client = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)
        cls.model = cls.client.models.upload(shared_model())

    def test_run_gives_the_servers_csv_byte_for_byte(self):
        job = self.client.run(self.model, stop=0.5, wait=False)
        result = job.wait().results()
        self.assertIn(job.id, [j.id for j in self.client.jobs.list()])
        self.assertEqual(result.to_csv(), raw_get(self.client, f"/jobs/{job.id}/results?format=csv"))

    def test_columns_equal_the_servers_json_exactly(self):
        job = self.client.run(self.model, stop=0.5, log_samples=300, wait=False).wait()
        result = job.results()
        stored = json.loads(raw_get(self.client, f"/jobs/{job.id}/results?format=json"))
        self.assertEqual(list(result.time), stored["time"])
        self.assertEqual(result.names, [v["name"] for v in stored["variables"]])
        for variable in stored["variables"]:
            column = [math.nan if v is None else v for v in variable["data"]]
            self.assertEqual(list(result[variable["name"]]), column, variable["name"])
        self.assertEqual(len(result), 300)

    def test_a_path_runs_without_storing_a_model(self):
        before = len(self.client.models.list())
        result = self.client.run(str(shared_model()), stop=0.2)
        self.assertIn("Mass#P2#Position", result)
        self.assertEqual(len(self.client.models.list()), before)

    def test_parameters_change_the_run(self):
        slow = self.client.run(self.model.id, parameters={"GainP.k": 0.001}, stop=0.5)
        fast = self.client.run(self.model.id, parameters={"GainP.k": 0.05}, stop=0.5)
        self.assertNotEqual(list(slow["Mass#P2#Position"]), list(fast["Mass#P2#Position"]))

    def test_results_of_chosen_variables(self):
        job = self.client.run(self.model, stop=0.2, wait=False).wait()
        result = self.client.jobs.results(job.id, variables=["Mass#P2#Position"])
        self.assertEqual(result.names, ["Mass#P2#Position"])
        self.assertEqual(result.to_csv().splitlines()[0], b"time,Mass#P2#Position")
        result.to_csv(server.directory / "chosen.csv")
        self.assertEqual((server.directory / "chosen.csv").read_bytes(), result.to_csv())

    def test_cancel_a_running_job(self):
        job = self.client.run(self.model, stop=500, wait=False)
        cancelled = self.client.jobs.cancel(job.id)
        self.assertIn(cancelled.state, ("cancelled", "running"))
        with self.assertRaises(tlmhub.SimulationFailed) as caught:
            job.wait(timeout=30)
        self.assertEqual(caught.exception.state, "cancelled")
        self.assertEqual(self.client.jobs.cancel(job.id).state, "cancelled")

    def test_an_unkept_runs_results_are_given_once(self):
        job = self.client.run(self.model, stop=0.2, wait=False, keep=False)
        result = job.wait().results()
        self.assertGreater(len(result), 1)
        self.assertIn("Mass#P2#Position", result)
        with self.assertRaises(tlmhub.Refused) as caught:
            self.client.jobs.results(job.id)
        self.assertEqual((caught.exception.status, caught.exception.code), (410, "gone"))
        self.assertIn("keep: false", caught.exception.message)
        listed = self.client.jobs.get(job.id)
        self.assertEqual(listed.state, "done")
        self.assertTrue(listed.info["results_dropped"])

    def test_a_result_knows_its_variables_units(self):
        result = self.client.run(self.model, stop=0.2, keep=False)
        self.assertEqual(result.units["4_3_Servo_Valve#PA#Pressure"], "Pa")
        self.assertEqual(set(result.units), set(result.names))

    def test_a_run_is_kept_by_default(self):
        job = self.client.run(self.model, stop=0.2, wait=False)
        job.wait()
        self.assertEqual(self.client.jobs.results(job.id).to_csv(), self.client.jobs.results(job.id).to_csv())

    def test_unknown_job_is_404_not_found(self):
        with self.assertRaises(tlmhub.ApiError) as caught:
            self.client.jobs.results(999999)
        self.assertEqual((caught.exception.status, caught.exception.code), (404, "not_found"))


if __name__ == "__main__":
    unittest.main()
