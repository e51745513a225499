"""The client: one object per server and identity, with the API's collections as attributes
(`client.models`, `client.jobs`, ...) and the common tasks (`run`, `sweep`, ...) as methods."""
from __future__ import annotations

import os
import ssl
import time
from dataclasses import dataclass, field
from typing import Any, Iterator, Mapping, Sequence, Union

from . import _values, _websocket
from ._http import Transport, new_idempotency_key
from ._outage import Outage
from .errors import ConnectionFailed, SimulationFailed
from .models import ModelEditor, Parameter, Variable, parameters_of
from .results import Result, variables_query
from .studies import Study

JOB_FINAL_STATES = ("done", "failed", "cancelled", "interrupted")


@dataclass
class Model:
    """A stored model: `info` is the server's summary (or, from `models.get`, its detail
    with the model structure). A Model the client gave knows it, for `parameters()`,
    `variables()` and `edit()`."""
    id: int
    name: str
    info: dict[str, Any] = field(default_factory=dict, repr=False)
    _client: Any = field(default=None, repr=False, compare=False)

    @classmethod
    def from_json(cls, info: dict[str, Any], client: "Client | None" = None) -> "Model":
        return cls(int(info["id"]), str(info.get("name", "")), info, _client=client)

    def parameters(self) -> dict[str, Parameter]:
        """The model's parameters as stored, by name (`client.models.parameters`)."""
        return self._models().parameters(self.id)

    def variables(self) -> dict[str, Variable]:
        """The variables a run of the model logs, by name (`client.models.variables`)."""
        return self._models().variables(self.id)

    def edit(self) -> ModelEditor:
        """The model opened for editing (`client.models.edit`)."""
        return self._models().edit(self.id)

    def _models(self) -> "Models":
        if self._client is None:
            raise ValueError(f"model {self.id} was made without a client: use client.models.parameters(id), "
                             "client.models.variables(id) or client.models.edit(id)")
        return self._client.models


ModelRef = Union[int, str, "os.PathLike[str]", Model]


def model_source(model: ModelRef) -> dict[str, Any]:
    """The request fields naming a model: a stored one by id or Model, else the text of an
    .hmf file (sent inline, so a script's runs leave no models behind)."""
    if isinstance(model, Model):
        return {"model_id": model.id}
    if isinstance(model, bool):
        raise TypeError("model must be an id, a Model, .hmf text or the path of an .hmf file")
    if isinstance(model, int):
        return {"model_id": model}
    if isinstance(model, str) and model.lstrip().startswith("<"):
        return {"hmf": model}
    with open(model, encoding="utf-8") as hmf:
        return {"hmf": hmf.read()}


class Job:
    """A simulation job. `info` is its last fetched JobInfo."""

    def __init__(self, client: "Client", info: dict[str, Any]):
        self._client = client
        self.id = int(info["id"])
        self.info = info

    @property
    def state(self) -> str:
        return str(self.info.get("state"))

    def refresh(self) -> "Job":
        self.info = self._client.jobs.get(self.id).info
        return self

    def wait(self, timeout: float | None = None, on_interrupt: str = "cancel") -> "Job":
        """Polls until the job ends; raises SimulationFailed unless it ended `done`.
        A server that cannot be reached (a restart) is tried again for the client's
        `reconnect_timeout`. Ctrl-C (KeyboardInterrupt) while waiting cancels the job before
        it is raised again; `on_interrupt="detach"` leaves it running."""
        _check_on_interrupt(on_interrupt)
        deadline = None if timeout is None else time.monotonic() + timeout
        interval = 0.02
        outage = Outage(self._client.reconnect_timeout)
        try:
            while True:
                try:
                    if self.refresh().state in JOB_FINAL_STATES:
                        break
                    outage.reached()
                except ConnectionFailed as error:
                    outage.failed(error)
                if deadline is not None and time.monotonic() > deadline:
                    raise TimeoutError(f"job {self.id} did not finish in time")
                time.sleep(interval)
                interval = min(interval * 2, 0.5)
        except KeyboardInterrupt:
            if on_interrupt == "cancel":
                self.cancel()
            raise
        if self.state != "done":
            raise SimulationFailed("job", self.id, self.state, self.info.get("error") or "")
        return self

    def results(self, variables: Sequence[str] | str | None = None) -> Result:
        return self._client.jobs.results(self.id, variables)

    def cancel(self) -> "Job":
        self.info = self._client.jobs.cancel(self.id).info
        return self

    def __repr__(self) -> str:
        return f"<Job {self.id} {self.state}>"


def _check_on_interrupt(on_interrupt: str) -> None:
    if on_interrupt not in ("cancel", "detach"):
        raise ValueError(f"on_interrupt: 'cancel' or 'detach', not {on_interrupt!r}")


class _Collection:
    def __init__(self, client: "Client"):
        self._client = client
        self._transport = client._transport


class Tokens(_Collection):
    """Personal API tokens (docs/studies.md, "API tokens")."""

    def create(self, name: str, expires_in_days: int | None = None) -> dict[str, Any]:
        """A new token: `{id, name, token, created_at, expires_at, last_used_at}`; this is
        the only time the server shows `token`."""
        body: dict[str, Any] = {"name": name}
        if expires_in_days is not None:
            body["expires_in_days"] = expires_in_days
        return self._transport.json("POST", "/tokens", json_body=body)

    def list(self) -> list[dict[str, Any]]:
        """The caller's tokens (without their secret), newest first."""
        return self._transport.json("GET", "/tokens")["tokens"]

    def delete(self, id: int) -> None:
        """Revokes a token at once (its open WebSockets end too)."""
        self._transport.request("DELETE", f"/tokens/{id}")


class Models(_Collection):
    def upload(self, path_or_text: str | bytes | os.PathLike[str], name: str | None = None) -> Model:
        """Stores an .hmf, given as a file path or as its text. A file is named after the
        file (as `tlmhub-cli remote` names it), text after its root system, unless `name`."""
        data = _hmf_bytes(path_or_text)
        if name is None and not isinstance(path_or_text, bytes) and not _is_text(path_or_text):
            name = os.path.splitext(os.path.basename(os.fspath(path_or_text)))[0]
        return Model.from_json(self._transport.json(
            "POST", "/models", query={"name": name}, body=data, content_type="application/xml"),
            self._client)

    def list(self) -> list[Model]:
        """The caller's models and the examples."""
        return [Model.from_json(m, self._client) for m in self._transport.json("GET", "/models")]

    def get(self, id: int) -> Model:
        return Model.from_json(self._transport.json("GET", f"/models/{id}"), self._client)

    def update(self, id: int, path_or_text: str | bytes | os.PathLike[str], name: str | None = None) -> Model:
        """Replaces a stored model's text with an .hmf, given as a file path or as its text
        (`PUT /models/{id}`); `name` renames it too. Only its owner (or the admin) may."""
        data = _hmf_bytes(path_or_text)
        if name is None:
            info = self._transport.json("PUT", f"/models/{id}", body=data, content_type="application/xml")
        else:
            info = self._transport.json("PUT", f"/models/{id}", json_body={"name": name, "hmf": data.decode()})
        return Model.from_json(info, self._client)

    def parameters(self, id: int) -> dict[str, Parameter]:
        """The stored model's parameters by name (`GainP.k`, `Mass.m`, a system parameter's
        own name ...; see `tlmhub.Parameter`), from its detail: system parameters first, then
        each component's, in the model's order."""
        detail = self._transport.json("GET", f"/models/{id}")
        if "model" not in detail:
            raise ValueError(f"model {id} does not load: {detail.get('load_error', '?')}")
        return parameters_of(detail["model"])

    def variables(self, id: int) -> dict[str, Variable]:
        """The variables a run of the stored model logs (`Mass#P2#Position`), by name, with
        their units. Only a run tells which ports log and the units of signals, so this
        runs the model for one time step, reads the names and units, and deletes that job."""
        detail = self._transport.json("GET", f"/models/{id}")
        simulation = detail.get("model", {}).get("system", {}).get("simulation", {})
        start = float(simulation.get("start", 0.0))
        step = float(simulation.get("step") or detail["model"]["system"]["timestep"])
        job = self._client.jobs.submit(id, start=start, step=step, stop=start + step, log_samples=1)
        try:
            job.wait()
            listed = self._transport.json("GET", f"/jobs/{job.id}/variables")
        finally:
            if job.state in JOB_FINAL_STATES:
                self._client.jobs.delete(job.id)
        return {v["name"]: Variable(str(v["name"]), str(v.get("unit", ""))) for v in listed["variables"]}

    def edit(self, id: int) -> ModelEditor:
        """Opens a stored model for editing over the WebSocket (needs websocket-client),
        best used as `with client.models.edit(id) as m: ...`; `m.save()` stores the changes,
        closing without it drops them (see `tlmhub.ModelEditor`)."""
        return ModelEditor(self._client, id)

    def hmf(self, id: int) -> str:
        """The model's .hmf text as stored."""
        return self._transport.request("GET", f"/models/{id}", query={"format": "hmf"})[1].decode()

    def delete(self, id: int) -> None:
        self._transport.request("DELETE", f"/models/{id}")


def _is_text(path_or_text: Any) -> bool:
    return isinstance(path_or_text, str) and path_or_text.lstrip().startswith("<")


def _hmf_bytes(path_or_text: str | bytes | os.PathLike[str]) -> bytes:
    """The .hmf given as bytes, as text, or as the path of a file."""
    if isinstance(path_or_text, bytes):
        return path_or_text
    if _is_text(path_or_text):
        return path_or_text.encode()
    with open(path_or_text, "rb") as hmf:
        return hmf.read()


class Jobs(_Collection):
    def submit(self, model: ModelRef, parameters: Mapping[str, Any] | None = None,
               start: float | None = None, step: float | None = None,
               stop: float | None = None, log_samples: int | None = None, keep: bool = True) -> Job:
        """Queues a job (`client.run(..., wait=False)` is the same). `keep=False`: its
        results are given once, to the first `results()`, and then dropped by the server (the
        job stays in the history; reading them again raises Refused, status 410 `gone`)."""
        body = {**model_source(model), **_values.settings(start, step, stop, log_samples)}
        if parameters:
            body["parameters"] = _values.parameters(parameters)
        if not keep:
            body["keep"] = False
        created = self._transport.json("POST", "/jobs", json_body=body, idempotency_key=new_idempotency_key())
        return Job(self._client, created)

    def list(self) -> list[Job]:
        return [Job(self._client, info) for info in self._transport.json("GET", "/jobs")]

    def get(self, id: int) -> Job:
        return Job(self._client, self._transport.json("GET", f"/jobs/{id}"))

    def cancel(self, id: int) -> Job:
        """Cancels a queued or running job; a finished one is returned as it is. (The same
        DELETE deletes a finished job, so its state is read first: only a job that ends in
        between those two calls is deleted instead.)"""
        job = self.get(id)
        if job.state in JOB_FINAL_STATES:
            return job
        info = self._transport.json("DELETE", f"/jobs/{id}")
        return Job(self._client, info) if info else job

    def delete(self, id: int) -> None:
        """Deletes a finished job and its results (frees the owner's stored bytes)."""
        self._transport.request("DELETE", f"/jobs/{id}")

    def results(self, id: int, variables: Sequence[str] | str | None = None) -> Result:
        """The job's results, with the units of its variables (asked first: the CSV has none,
        and a `keep=False` job's results are gone once given)."""
        units = {v["name"]: v["unit"] for v in self._transport.json("GET", f"/jobs/{id}/variables")["variables"]}
        _, csv = self._transport.request(
            "GET", f"/jobs/{id}/results",
            query={"format": "csv", "variables": variables_query(variables)})
        return Result(csv, units=units)


class Studies(_Collection):
    def list(self) -> list[Study]:
        return [Study(self._client, int(s["id"]), s)
                for s in self._transport.json("GET", "/studies")["studies"]]

    def get(self, id: int) -> Study:
        return Study(self._client, id).refresh()

    def create(self, request: Mapping[str, Any]) -> Study:
        """A study from a request exactly as docs/studies.md gives it."""
        created = self._transport.json("POST", "/studies", json_body=dict(request),
                                       idempotency_key=new_idempotency_key())
        return Study(self._client, int(created["id"]), {**created, "state": "queued"})


class Client:
    """A tlmhub server, as one user.

    `Client(url, token)` with an API token (`tlmh_...`), or `Client.login(url, user,
    password)` for a login session. `url` is the server's address (`http://host:8080`),
    with or without `/api/v1`. `retries`: how many times a GET, a DELETE or a submit (with
    its Idempotency-Key) is sent again after no answer or 429/502/503/504 (0: never).
    `reconnect_timeout`: how long `wait()` keeps trying to reach a server that went away (a
    restart) before it raises ConnectionFailed, in seconds."""

    def __init__(self, url: str, token: str, *, timeout: float = 60.0,
                 ssl_context: ssl.SSLContext | None = None, retries: int = 5,
                 reconnect_timeout: float = 120.0):
        self._transport = Transport(url, token, timeout=timeout, ssl_context=ssl_context, retries=retries)
        self.reconnect_timeout = reconnect_timeout
        self.tokens = Tokens(self)
        self.models = Models(self)
        self.jobs = Jobs(self)
        self.studies = Studies(self)

    @classmethod
    def login(cls, url: str, username: str, password: str, **options: Any) -> "Client":
        """A client on a login session (it expires; scripts that run unattended should use
        an API token instead)."""
        transport_options = {k: v for k, v in options.items() if k != "reconnect_timeout"}
        reply = Transport(url, None, **transport_options).json(
            "POST", "/auth/login", json_body={"username": username, "password": password})
        return cls(url, reply["token"], **options)

    @property
    def url(self) -> str:
        return self._transport.base

    def me(self) -> dict[str, Any]:
        return self._transport.json("GET", "/auth/me")

    def components(self) -> list[dict[str, Any]]:
        """The server's component catalogue (`GET /components`): per type its `type`, `kind`
        (C, Q, S), `domain`, `ports` (`name`, `nodetype`, `porttype`, ...) and `parameters`
        (`name`, `default`, `unit`, ...)."""
        return self._transport.json("GET", "/components")

    def logout(self) -> None:
        """Ends a login session (an API token is revoked with `tokens.delete` instead)."""
        self._transport.request("POST", "/auth/logout")

    def run(self, model: ModelRef, parameters: Mapping[str, Any] | None = None,
            start: float | None = None, step: float | None = None, stop: float | None = None,
            log_samples: int | None = None, wait: bool = True, keep: bool = True) -> Result | Job:
        """Runs a model once: its Result, or with `wait=False` the queued Job.
        `parameters` override values for this run (`"GainP.k": 0.03`). `keep=False` leaves
        nothing stored on the server once the Result is read (a script's thousandth run then
        fits a small quota as the first did); see `Jobs.submit`."""
        job = self.jobs.submit(model, parameters, start=start, step=step, stop=stop,
                               log_samples=log_samples, keep=keep)
        return job.wait().results() if wait else job

    def stream(self, job_id: int, variables: Sequence[str] | None = None) -> Iterator[dict[str, list[float]]]:
        """The frames of a job while it runs (needs websocket-client): each a dict of `time`
        and each variable to the samples logged since the previous frame, floats. All
        logged variables when `variables` is None (the server streams at most 16)."""
        if not _websocket.available():
            raise ImportError("Client.stream " + _websocket.WEBSOCKET_MISSING)

        def rest(seen: int) -> dict[str, list[float]]:
            result = self.jobs.results(job_id, variables)
            return {name: list(result[name])[seen:] for name in ["time"] + result.names}

        return _websocket.job_frames(self._transport, job_id,
                                     list(variables) if variables is not None else None, rest)

    def sweep(self, model: ModelRef, parameters: Mapping[str, Any], mode: str = "grid",
              outputs: Sequence[str] = (), values: Sequence[str] = ("final",), full: bool = False,
              fixed: Mapping[str, Any] | None = None, samples: int | None = None,
              seed: int | None = None, name: str | None = None, start: float | None = None,
              step: float | None = None, stop: float | None = None,
              log_samples: int | None = None, wait: bool = True) -> Study:
        """A parameter sweep. `parameters` maps each swept parameter to a list of values or
        `{"from": a, "to": b, "steps": n}` (the server orders them by name, whatever the
        dict's order); `mode` is `grid` (every combination), `list`
        (the i-th values together) or `random` (`samples` runs, `seed`). Each of `outputs`
        (result variables) gives a table column per `values` entry (`final`, `min`, `max`,
        `mean`); `full=True` keeps each run's whole result (`Study.run_result`)."""
        swept = {k: _values.swept(k, v) for k, v in parameters.items()}
        sweep: dict[str, Any] = {"mode": mode, "parameters": swept}
        if samples is not None:
            sweep["samples"] = _values.whole("samples", samples, 1)
        if seed is not None:
            sweep["seed"] = _values.whole("seed", seed, 0)
        return self._study("sweep", sweep, model, name, fixed, outputs, values, full,
                           _values.settings(start, step, stop, log_samples), wait)

    def sensitivity(self, model: ModelRef, parameters: Mapping[str, Any], runs: int,
                    outputs: Sequence[str], seed: int | None = None,
                    values: Sequence[str] = ("final",), full: bool = False,
                    fixed: Mapping[str, Any] | None = None, name: str | None = None,
                    start: float | None = None, step: float | None = None,
                    stop: float | None = None, log_samples: int | None = None,
                    wait: bool = True) -> Study:
        """A Monte Carlo sensitivity analysis of `runs` runs. `parameters` maps names to
        `("normal", mean, sd)` or `("uniform", min, max)`. Results: `Study.bands()` and the
        correlations in `study.summary["correlations"]`."""
        sensitivity: dict[str, Any] = {
            "runs": _values.whole("runs", runs, 2),
            "parameters": {k: _distribution(k, v) for k, v in parameters.items()}}
        if seed is not None:
            sensitivity["seed"] = _values.whole("seed", seed, 0)
        return self._study("sensitivity", sensitivity, model, name, fixed, outputs, values, full,
                           _values.settings(start, step, stop, log_samples), wait)

    def optimise(self, model: ModelRef, parameters: Mapping[str, Any],
                 objective: Sequence[Mapping[str, Any]], algorithm: str = "complex-rf",
                 goal: str = "minimise", max_evaluations: int = 200, seed: int = 1,
                 tolerance: float | None = None, options: Mapping[str, Any] | None = None,
                 outputs: Sequence[str] = (), values: Sequence[str] = ("final",),
                 fixed: Mapping[str, Any] | None = None, name: str | None = None,
                 start: float | None = None, step: float | None = None,
                 stop: float | None = None, log_samples: int | None = None,
                 wait: bool = True) -> Study:
        """An optimisation: `parameters` maps names to `(min, max)`, `(min, max, start)` or
        `{"min": a, "max": b[, "start": c]}`;
        `objective` is a list of terms as docs/studies.md gives them, e.g.
        `{"function": "ise", "variable": "Mass#P2#Position", "reference_variable":
        "Step#out#Value"}`. The best run: `study.best`."""
        bounds = {key: _values.bound(key, bound) for key, bound in parameters.items()}
        optimise: dict[str, Any] = {
            "algorithm": algorithm, "parameters": bounds,
            "objective": {"goal": goal, "terms": [dict(t) for t in objective]},
            "max_evaluations": _values.whole("max_evaluations", max_evaluations, 1),
            "seed": _values.whole("seed", seed, 0)}
        if tolerance is not None:
            optimise["tolerance"] = _values.number("tolerance", tolerance)
            if optimise["tolerance"] <= 0:
                raise ValueError(f"tolerance: {optimise['tolerance']} is not positive")
        if options:
            optimise["options"] = dict(options)
        return self._study("optimise", optimise, model, name, fixed, outputs, values, False,
                           _values.settings(start, step, stop, log_samples), wait)

    def _study(self, kind: str, spec: dict[str, Any], model: ModelRef, name: str | None,
               fixed: Mapping[str, Any] | None, outputs: Sequence[str], values: Sequence[str],
               full: bool, settings: dict[str, Any], wait: bool) -> Study:
        request: dict[str, Any] = {"kind": kind, "name": name or f"{kind} (python)",
                                   **model_source(model), **settings, kind: spec}
        if fixed:
            request["parameters"] = _values.parameters(fixed)
        if outputs or full:
            request["outputs"] = {"variables": list(outputs), "values": list(values), "full": full}
        study = self.studies.create(request)
        return study.wait() if wait else study


def _distribution(name: str, spec: Any) -> dict[str, Any]:
    """`("normal", mean, sd)` or `("uniform", min, max)` as the request's object (a dict
    passes as it is)."""
    if isinstance(spec, Mapping):
        return dict(spec)
    kind, a, b = spec
    if kind == "normal":
        return {"distribution": "normal", "mean": _values.number(f"{name} mean", a),
                "sd": _values.number(f"{name} sd", b)}
    if kind == "uniform":
        return {"distribution": "uniform", "min": _values.number(f"{name} min", a),
                "max": _values.number(f"{name} max", b)}
    raise ValueError(f"{name}: distribution must be 'normal' or 'uniform', not {kind!r}")
