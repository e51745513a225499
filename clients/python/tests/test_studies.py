"""Studies (docs/studies.md): sweeps, sensitivity, optimisation, the table, a run's result,
bands, cancelling and waiting with and without the WebSocket.

These wait for the server's /studies (being built on branch `optim`); until it is merged
they fail with 404 `no API route`."""
import contextlib
import io
import json
import unittest
import urllib.request
from unittest import mock

import tlmhub
from harness import ADMIN_PASSWORD, Server, shared_model

server: Server
POSITION = "Mass#P2#Position"
SHORT = {"stop": 0.5, "log_samples": 200}


def setUpModule() -> None:
    global server
    server = Server()


def tearDownModule() -> None:
    server.stop()


def raw_get(client: tlmhub.Client, path: str) -> bytes:
    request = urllib.request.Request(client.url + path,
                                     headers={"Authorization": "Bearer " + client._transport.token})
    with urllib.request.urlopen(request) as response:
        return response.read()


class Sweep(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.client = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)
        cls.model = cls.client.models.upload(shared_model())
        cls.study = cls.client.sweep(
            cls.model, parameters={"GainP.k": [0.01, 0.03], "GainI.k": {"from": 0, "to": 0.001, "steps": 2}},
            outputs=[POSITION], values=["final", "max"], full=True, **SHORT)

    def test_a_grid_runs_every_combination_first_parameter_slowest(self):
        # The server takes parameters in the order of their names: GainI.k comes first.
        self.assertEqual(self.study.state, "done")
        self.assertEqual(self.study.info["runs_total"], 4)
        table = self.study.table()
        self.assertEqual(table.columns, ["run", "ok", "GainI.k", "GainP.k",
                                         f"{POSITION}:final", f"{POSITION}:max"])
        self.assertEqual([row[2:4] for row in table.rows],
                         [[0, 0.01], [0, 0.03], [0.001, 0.01], [0.001, 0.03]])
        self.assertTrue(all(row[1] for row in table.rows))
        self.assertEqual(len(table[f"{POSITION}:final"]), 4)

    def test_table_csv_is_the_servers(self):
        csv = self.study.table().to_csv()
        self.assertEqual(csv, raw_get(self.client, f"/studies/{self.study.id}/results?format=csv"))
        self.assertTrue(csv.startswith(b"run,ok,GainI.k,GainP.k,"))

    def test_a_runs_result_equals_a_job_with_its_parameters(self):
        table = self.study.table()
        row = table.rows[2]
        run = self.study.run_result(row[0])
        job = self.client.run(self.model, parameters={"GainI.k": row[2], "GainP.k": row[3]}, **SHORT)
        self.assertEqual(run.to_csv(), job.to_csv())
        self.assertEqual(run[POSITION][-1], row[table.columns.index(f"{POSITION}:final")])
        chosen = self.study.run_result(row[0], variables=[POSITION])
        self.assertEqual(chosen.names, [POSITION])

    def test_list_mode_pairs_the_values(self):
        study = self.client.sweep(self.model, parameters={"GainP.k": [0.01, 0.02, 0.03],
                                                          "GainI.k": [0.0, 0.0005, 0.001]},
                                  mode="list", outputs=[POSITION], **SHORT)
        self.assertEqual([row[2:4] for row in study.table().rows],
                         [[0.0, 0.01], [0.0005, 0.02], [0.001, 0.03]])

    def test_random_mode_takes_samples(self):
        study = self.client.sweep(self.model, parameters={"GainP.k": {"from": 0.01, "to": 0.03, "steps": 2}},
                                  mode="random", samples=5, seed=3, outputs=[POSITION],
                                  fixed={"GainI.k": 0.0005}, **SHORT)
        values = study.table()["GainP.k"]
        self.assertEqual(len(values), 5)
        self.assertTrue(all(0.01 <= v <= 0.03 for v in values))

    def test_studies_are_listed_and_deleted(self):
        study = self.client.sweep(self.model, parameters={"GainP.k": [0.01]}, outputs=[POSITION], **SHORT)
        self.assertIn(study.id, [s.id for s in self.client.studies.list()])
        self.assertEqual(self.client.studies.get(study.id).state, "done")
        study.delete()
        with self.assertRaises(tlmhub.ApiError) as caught:
            study.refresh()
        self.assertEqual((caught.exception.status, caught.exception.code), (404, "not_found"))


class Waiting(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.client = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)
        cls.model = cls.client.models.upload(shared_model())

    def sweep(self, runs: int, stop: float = 0.5):
        return self.client.sweep(self.model, parameters={"GainP.k": {"from": 0.01, "to": 0.03, "steps": runs}},
                                 outputs=[POSITION], stop=stop, log_samples=100, wait=False)

    def test_progress_draws_one_line_on_stderr(self):
        study = self.sweep(10)
        stderr = io.StringIO()
        with contextlib.redirect_stderr(stderr):
            study.wait(progress=True, timeout=60)
        text = stderr.getvalue()
        self.assertTrue(text.endswith("\n"))
        self.assertEqual(text.count("\n"), 1)
        self.assertIn("10/10 runs", text.rsplit("\r", 1)[-1])

    def test_waiting_by_polling_gives_the_same_study(self):
        study = self.sweep(6)
        with mock.patch("tlmhub._websocket.available", return_value=False):
            study.wait(timeout=60)
        self.assertEqual((study.state, study.info["runs_done"]), ("done", 6))
        self.assertEqual(len(study.table().rows), 6)

    def test_cancel_a_running_study(self):
        study = self.sweep(400, stop=3)
        study.cancel()
        self.assertIn(study.state, ("cancelling", "cancelled"))
        with self.assertRaises(tlmhub.SimulationFailed) as caught:
            study.wait(timeout=60)
        self.assertEqual(caught.exception.state, "cancelled")
        self.assertLess(len(study.table().rows), 400)

    def test_a_cancelled_study_resumes_and_runs_only_what_it_lacks(self):
        study = self.sweep(400, stop=3)
        study.cancel()
        with self.assertRaises(tlmhub.SimulationFailed):
            study.wait(timeout=60)
        kept = study.info["runs_done"]
        self.assertLess(kept, 400)
        study.resume()
        self.assertIn(study.state, ("queued", "running"))
        study.wait(timeout=120)
        self.assertEqual((study.state, study.info["runs_done"]), ("done", 400))
        self.assertEqual(study.summary.get("runs_reused", 0), kept)
        self.assertEqual(sorted(row[0] for row in study.table().rows), list(range(400)))
        with self.assertRaises(tlmhub.ApiError) as caught:   # a finished study does not resume
            study.resume()
        self.assertEqual(caught.exception.status, 409)

    def test_ctrl_c_while_waiting_cancels_the_study_unless_detached(self):
        study = self.sweep(400, stop=3)
        with mock.patch("tlmhub._websocket.available", return_value=False), \
                mock.patch("tlmhub.studies.time.sleep", side_effect=KeyboardInterrupt):
            with self.assertRaises(KeyboardInterrupt):
                study.wait(timeout=60)
        with self.assertRaises(tlmhub.SimulationFailed) as ended:   # its runs in flight stop first
            study.wait(timeout=60)
        self.assertEqual(ended.exception.state, "cancelled")

        detached = self.sweep(400, stop=3)
        with mock.patch("tlmhub._websocket.available", return_value=False), \
                mock.patch("tlmhub.studies.time.sleep", side_effect=KeyboardInterrupt):
            with self.assertRaises(KeyboardInterrupt):
                detached.wait(timeout=60, on_interrupt="detach")
        self.assertIn(detached.refresh().state, ("queued", "running"))
        detached.cancel()

    def test_ctrl_c_while_waiting_for_a_job_cancels_it(self):
        job = self.client.run(self.model, stop=500, wait=False)   # 0.8 s: outlasts the cancel request
        with mock.patch("tlmhub.client.time.sleep", side_effect=KeyboardInterrupt):
            with self.assertRaises(KeyboardInterrupt):
                job.wait(timeout=60)
        with self.assertRaises(tlmhub.SimulationFailed) as ended:
            job.wait(timeout=60)
        self.assertEqual(ended.exception.state, "cancelled")

    def test_a_bad_request_is_an_api_error(self):
        with self.assertRaises(tlmhub.ApiError) as caught:   # list mode needs equal lengths
            self.client.sweep(self.model, parameters={"GainP.k": [0.01, 0.02], "GainI.k": [0.0]},
                              mode="list", outputs=[POSITION], **SHORT)
        self.assertEqual(caught.exception.status, 400)


class Sensitivity(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.client = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)
        cls.study = cls.client.sensitivity(
            shared_model(), parameters={"GainP.k": ("normal", 0.0264, 0.002),
                                        "GainI.k": ("uniform", 0.0005, 0.0008)},
            runs=8, seed=7, outputs=[POSITION], stop=1.5, log_samples=150)

    def test_runs_and_correlations(self):
        self.assertEqual((self.study.state, self.study.info["runs_done"]), ("done", 8))
        self.assertIn("correlations", self.study.summary)
        self.assertIn("GainP.k", json.dumps(self.study.summary["correlations"]))
        table = self.study.table()
        self.assertEqual(len(table.rows), 8)
        self.assertTrue(all(0.0005 <= v <= 0.0008 for v in table["GainI.k"]))

    def test_bands_per_variable(self):
        bands = self.study.bands()
        self.assertIn(POSITION, json.dumps(bands))

    def test_same_seed_same_table(self):
        again = self.client.sensitivity(
            shared_model(), parameters={"GainP.k": ("normal", 0.0264, 0.002),
                                        "GainI.k": ("uniform", 0.0005, 0.0008)},
            runs=8, seed=7, outputs=[POSITION], stop=1.5, log_samples=150)
        self.assertEqual(again.table().rows, self.study.table().rows)

    def test_an_unknown_distribution_is_refused_before_sending(self):
        with self.assertRaises(ValueError):
            self.client.sensitivity(shared_model(), parameters={"GainP.k": ("poisson", 1, 2)},
                                    runs=2, outputs=[POSITION])


class Optimise(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.client = tlmhub.Client.login(server.url, "admin", ADMIN_PASSWORD)
        cls.study = cls.client.optimise(
            shared_model(), parameters={"GainP.k": (0.001, 0.05), "GainI.k": (0, 0.002, 0.0005)},
            objective=[{"function": "ise", "variable": POSITION, "reference_variable": "Step#out#Value"},
                       {"function": "overshoot", "variable": POSITION, "weight": 0.01}],
            max_evaluations=20, seed=1, stop=1.5, log_samples=150)

    def test_best_is_the_lowest_objective_of_the_table(self):
        self.assertEqual(self.study.state, "done")
        best = self.study.best
        self.assertEqual(set(best), {"run", "parameters", "objective"})
        table = self.study.table()
        self.assertEqual(table.columns[-1], "objective")
        self.assertLessEqual(len(table.rows), 20)
        self.assertEqual(best["objective"], min(row[-1] for row in table.rows if row[1]))
        self.assertTrue(0.001 <= best["parameters"]["GainP.k"] <= 0.05)

    def test_maximise_with_another_algorithm(self):
        study = self.client.optimise(
            shared_model(), parameters={"GainP.k": (0.001, 0.05)},
            objective=[{"function": "max", "variable": POSITION}], goal="maximise",
            algorithm="nelder-mead", max_evaluations=10, stop=1.5, log_samples=150)
        table = study.table()
        self.assertEqual(study.best["objective"], max(row[-1] for row in table.rows if row[1]))


if __name__ == "__main__":
    unittest.main()
