"""The bodies the client sends for tokens and studies, compared with docs/studies.md, and
waiting for a study by polling: checked without a server (the transport is replaced), so
they hold today, before the server has /tokens and /studies. test_tokens and test_studies
check the same against the real server."""
import contextlib
import io
import json
import math
import numbers
import unittest
from unittest import mock

import tlmhub
from harness import shared_model


class Recorder:
    """Stands in for the transport: records each call and answers from a script."""

    def __init__(self, answers=()):
        self.calls = []
        self.answers = list(answers)
        self.base = "http://127.0.0.1:1/api/v1"
        self.token = "tlmh_test"

    def json(self, method, path, **kwargs):
        self.calls.append((method, path, kwargs))
        return self.answers.pop(0) if self.answers else {"id": 12, "runs_total": 4}

    def request(self, method, path, **kwargs):
        self.calls.append((method, path, kwargs))
        return 204, b""


def client_with(recorder: Recorder) -> tlmhub.Client:
    client = tlmhub.Client("http://127.0.0.1:1", "tlmh_test")
    for holder in (client, client.tokens, client.models, client.jobs, client.studies):
        holder._transport = recorder
    return client


class Requests(unittest.TestCase):
    def test_token_create(self):
        recorder = Recorder([{"id": 1, "token": "tlmh_x"}])
        client_with(recorder).tokens.create("ci", expires_in_days=90)
        self.assertEqual(recorder.calls, [("POST", "/tokens", {"json_body": {"name": "ci", "expires_in_days": 90}})])

    def test_sweep_is_the_documented_request(self):
        recorder = Recorder()
        study = client_with(recorder).sweep(
            12, parameters={"Pump.Dp": [1e-5, 2e-5], "Valve.Kv": {"from": 1, "to": 5, "steps": 10}},
            outputs=["Mass#P1#x"], values=["final", "max"], fixed={"Valve.Kv": "2e-5"},
            name="pump size", start=0, step=0.001, stop=2, log_samples=1024, wait=False)
        self.assertEqual(study.id, 12)
        key = recorder.calls[0][2].pop("idempotency_key")
        self.assertRegex(key, r"^[0-9a-f-]{36}$", "a fresh key, so a lost answer can be retried")
        self.assertEqual(recorder.calls, [("POST", "/studies", {"json_body": {
            "kind": "sweep", "name": "pump size", "model_id": 12,
            "start": 0, "step": 0.001, "stop": 2, "log_samples": 1024,
            "parameters": {"Valve.Kv": "2e-5"},
            "outputs": {"variables": ["Mass#P1#x"], "values": ["final", "max"], "full": False},
            "sweep": {"mode": "grid", "parameters": {"Pump.Dp": [1e-5, 2e-5],
                                                     "Valve.Kv": {"from": 1, "to": 5, "steps": 10}}}}})])

    def test_a_path_is_sent_as_hmf_text(self):
        recorder = Recorder()
        client_with(recorder).sweep(shared_model(), parameters={"GainP.k": [1, 2]}, mode="random",
                                    samples=5, seed=3, wait=False)
        body = recorder.calls[0][2]["json_body"]
        self.assertEqual(body["hmf"], shared_model().read_text())
        self.assertNotIn("model_id", body)
        self.assertEqual(body["sweep"], {"mode": "random", "parameters": {"GainP.k": [1.0, 2.0]},
                                         "samples": 5, "seed": 3})

    def test_sensitivity_is_the_documented_request(self):
        recorder = Recorder()
        client_with(recorder).sensitivity(
            12, parameters={"Mass.m": ("normal", 100, 5), "Spring.k": ("uniform", 1e4, 2e4)},
            runs=200, seed=7, outputs=["Mass#P1#x"], wait=False)
        body = recorder.calls[0][2]["json_body"]
        self.assertEqual(body["kind"], "sensitivity")
        self.assertEqual(body["sensitivity"], {"runs": 200, "seed": 7, "parameters": {
            "Mass.m": {"distribution": "normal", "mean": 100, "sd": 5},
            "Spring.k": {"distribution": "uniform", "min": 1e4, "max": 2e4}}})
        self.assertEqual(body["outputs"]["variables"], ["Mass#P1#x"])

    def test_optimise_is_the_documented_request(self):
        recorder = Recorder()
        terms = [{"function": "ise", "variable": "Mass#P1#x", "reference_variable": "Ref#out#y", "weight": 1},
                 {"function": "overshoot", "variable": "Mass#P1#x", "weight": 0.1}]
        client_with(recorder).optimise(
            tlmhub.Model(12, "servo"), parameters={"Kp.k": (0, 0.01), "Ki.k": (0, 0.1, 0.05)},
            objective=terms, max_evaluations=200, seed=1, tolerance=1e-4, options={"alpha": 1.3},
            wait=False)
        body = recorder.calls[0][2]["json_body"]
        self.assertEqual(body["model_id"], 12)
        self.assertEqual(body["optimise"], {
            "algorithm": "complex-rf",
            "parameters": {"Kp.k": {"min": 0, "max": 0.01}, "Ki.k": {"min": 0, "max": 0.1, "start": 0.05}},
            "objective": {"goal": "minimise", "terms": terms},
            "max_evaluations": 200, "seed": 1, "tolerance": 1e-4, "options": {"alpha": 1.3}})

    def test_bad_shorthands_are_refused_before_sending(self):
        client = client_with(Recorder())
        with self.assertRaises(ValueError):
            client.sensitivity(12, parameters={"Mass.m": ("poisson", 1, 2)}, runs=2, outputs=["x"])
        with self.assertRaises(ValueError):
            client.optimise(12, parameters={"Kp.k": (0,)}, objective=[])


class Float32:
    """Stands in for a NumPy scalar (NumPy is optional): a real number json cannot encode."""

    def __init__(self, value):
        self.value = value

    def __float__(self):
        return float(self.value)


class Int64(Float32):
    def __int__(self):
        return int(self.value)

    def __index__(self):
        return int(self.value)

    def __lt__(self, other):
        return int(self.value) < other


numbers.Real.register(Float32)
numbers.Integral.register(Int64)


class Values(unittest.TestCase):
    """Values are checked before anything is sent, and a mistake names its parameter."""

    def refused(self, error, words, call):
        recorder = Recorder()
        with self.assertRaises(error) as caught:
            call(client_with(recorder))
        self.assertIn(words, str(caught.exception))
        self.assertEqual(recorder.calls, [], "nothing is sent")

    def test_nan_and_infinity_are_refused_naming_the_parameter(self):
        self.refused(ValueError, "GainP.k", lambda c: c.jobs.submit(12, {"GainP.k": math.nan}))
        self.refused(ValueError, "GainP.k[1]", lambda c: c.sweep(12, {"GainP.k": [0.1, math.inf]}, wait=False))
        self.refused(ValueError, "Mass.m sd", lambda c: c.sensitivity(12, {"Mass.m": ("normal", 1, math.nan)},
                                                                      runs=4, outputs=["x"], wait=False))
        self.refused(ValueError, "Kp.k max", lambda c: c.optimise(12, {"Kp.k": (0, -math.inf)}, objective=[],
                                                                  wait=False))
        self.refused(TypeError, "GainP.k", lambda c: c.jobs.submit(12, {"GainP.k": [1, 2]}))

    def test_times_and_counts_are_checked(self):
        self.refused(ValueError, "step", lambda c: c.jobs.submit(12, step=0))
        self.refused(ValueError, "stop", lambda c: c.jobs.submit(12, start=2, stop=1))
        self.refused(ValueError, "runs", lambda c: c.sensitivity(12, {"Mass.m": ("uniform", 1, 2)}, runs=1,
                                                                 outputs=["x"], wait=False))
        self.refused(TypeError, "samples", lambda c: c.sweep(12, {"GainP.k": {"from": 0, "to": 1}}, mode="random",
                                                             samples=2.5, wait=False))
        self.refused(ValueError, "min", lambda c: c.optimise(12, {"Kp.k": {"min": 2, "max": 1}}, objective=[],
                                                             wait=False))

    def test_numpy_scalars_and_bound_dicts_are_sent_as_plain_numbers(self):
        recorder = Recorder()
        client = client_with(recorder)
        client.jobs.submit(12, {"GainP.k": Float32(0.25), "Steps.n": Int64(3), "Expr.x": "2*pi"},
                           stop=Float32(2.0), log_samples=Int64(100))
        body = recorder.calls[-1][2]["json_body"]
        self.assertEqual(body["parameters"], {"GainP.k": 0.25, "Steps.n": 3.0, "Expr.x": "2*pi"})
        self.assertEqual((body["stop"], body["log_samples"]), (2.0, 100))
        json.dumps(body)   # what the transport sends
        client.optimise(12, {"Kp.k": {"min": Float32(0.5), "max": 2}}, objective=[], seed=Int64(4), wait=False)
        request = recorder.calls[-1][2]["json_body"]
        self.assertEqual(request["optimise"]["parameters"], {"Kp.k": {"min": 0.5, "max": 2.0}})
        self.assertEqual(request["optimise"]["seed"], 4)
        json.dumps(request)


class Polling(unittest.TestCase):
    def info(self, state, done, failed=0):
        return {"id": 12, "state": state, "runs_total": 4, "runs_done": done, "runs_failed": failed,
                "summary": {"best": {"run": 2}} if state == "done" else {}}

    def study(self, *infos):
        client = client_with(Recorder(infos))
        return tlmhub.Study(client, 12)

    def test_wait_polls_until_done_and_draws_one_line(self):
        study = self.study(self.info("queued", 0), self.info("running", 2, 1), self.info("done", 4, 1))
        stderr = io.StringIO()
        with mock.patch("tlmhub._websocket.available", return_value=False), \
                mock.patch("time.sleep"), contextlib.redirect_stderr(stderr):
            study.wait(progress=True)
        self.assertEqual((study.state, study.best), ("done", {"run": 2}))
        text = stderr.getvalue()
        self.assertEqual(text.count("\n"), 1)
        self.assertTrue(text.rsplit("\r", 1)[-1].startswith("[" + "#" * 30 + "] 4/4 runs, 1 failed, done"))

    def test_a_failed_study_raises(self):
        study = self.study(self.info("running", 1), {**self.info("failed", 1), "error": "model broke"})
        with mock.patch("tlmhub._websocket.available", return_value=False), mock.patch("time.sleep"):
            with self.assertRaises(tlmhub.SimulationFailed) as caught:
                study.wait()
        self.assertEqual((caught.exception.state, caught.exception.error), ("failed", "model broke"))


class Cancel(unittest.TestCase):
    def test_a_running_study_is_cancelled(self):
        recorder = Recorder([{"id": 12, "state": "running"}, {"state": "cancelling"}])
        study = tlmhub.Study(client_with(recorder), 12)
        self.assertEqual(study.cancel().state, "cancelling")
        self.assertEqual([c[:2] for c in recorder.calls], [("GET", "/studies/12"), ("DELETE", "/studies/12")])

    def test_a_finished_study_is_not_deleted(self):
        recorder = Recorder([{"id": 12, "state": "done"}])
        study = tlmhub.Study(client_with(recorder), 12)
        self.assertEqual(study.cancel().state, "done")
        self.assertEqual([c[:2] for c in recorder.calls], [("GET", "/studies/12")])


if __name__ == "__main__":
    unittest.main()
