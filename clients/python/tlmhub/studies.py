"""Studies (docs/studies.md): many runs of one model as a sweep, a sensitivity analysis or an
optimisation, and waiting for them with a progress bar."""
from __future__ import annotations

import sys
import time
from typing import TYPE_CHECKING, Any, Sequence

from . import _websocket
from ._outage import Outage
from .errors import ApiError, ConnectionFailed, SimulationFailed
from .results import Result, Table, variables_query

if TYPE_CHECKING:
    from .client import Client

FINAL_STATES = ("done", "failed", "cancelled", "interrupted")


class Study:
    """A study on the server. `info` is its last fetched StudyInfo; `refresh()` fetches it
    again, `wait()` until it ends."""

    def __init__(self, client: "Client", id: int, info: dict[str, Any] | None = None):
        self._client = client
        self.id = id
        self.info: dict[str, Any] = info or {"id": id}

    @property
    def state(self) -> str | None:
        return self.info.get("state")

    @property
    def summary(self) -> dict[str, Any]:
        return self.info.get("summary") or {}

    @property
    def best(self) -> dict[str, Any] | None:
        """An optimisation's best run so far, `{run, parameters, objective}`, as of the last
        refresh (or progress event while waiting)."""
        return self.summary.get("best")

    def refresh(self) -> "Study":
        self.info = self._client._transport.json("GET", f"/studies/{self.id}")
        return self

    def wait(self, progress: bool = False, timeout: float | None = None,
             on_interrupt: str = "cancel") -> "Study":
        """Waits until the study ends and returns it; raises SimulationFailed unless it ended
        `done` (runs that failed inside a done study are rows with `ok` 0, not an error).

        With websocket-client installed it listens to `event.study.progress`, otherwise it
        polls GET /studies/{id}. A lost WebSocket is opened and subscribed again, and a
        server that cannot be reached (a restart) is tried again for the client's
        `reconnect_timeout`; a study the restart interrupted ends the wait `interrupted`
        (`resume()` goes on with it). `progress=True` draws a one-line bar on stderr. Ctrl-C
        (KeyboardInterrupt) while waiting cancels the study before it is raised again, so an
        interrupted script leaves nothing running against its study limit;
        `on_interrupt="detach"` leaves it running (`resume()` continues a cancelled one)."""
        if on_interrupt not in ("cancel", "detach"):
            raise ValueError(f"on_interrupt: 'cancel' or 'detach', not {on_interrupt!r}")
        deadline = None if timeout is None else time.monotonic() + timeout
        bar = _ProgressBar() if progress else None
        outage = Outage(self._client.reconnect_timeout)
        events = _websocket.available()
        try:
            while True:
                try:
                    if not (events and self._wait_for_events(deadline, bar, outage)):
                        events = False
                        self._poll(deadline, bar, outage)
                    break
                except ConnectionFailed as error:
                    outage.failed(error)
        except KeyboardInterrupt:
            if bar:
                bar.finish()
            if on_interrupt == "cancel":
                self.cancel()
            raise
        if bar:
            bar.draw(self.info)
            bar.finish()
        if self.state != "done":
            raise SimulationFailed("study", self.id, str(self.state), self.info.get("error") or "")
        return self

    def _wait_for_events(self, deadline: float | None, bar: "_ProgressBar | None", outage: Outage) -> bool:
        """Waits on the WebSocket; False when the socket or the subscription is refused (a
        proxy without WebSockets, a server without studies): polling then says why, or works.
        A quiet socket is still backed by a GET every few seconds, so a lost event cannot
        leave the wait hanging. A socket that cannot be opened because the server is away,
        or that breaks, raises ConnectionFailed (the caller tries again)."""
        try:
            socket = _websocket.Socket(self._client._transport, timeout=1.0)
        except OSError as error:
            raise ConnectionFailed(f"WebSocket: {error}", error) from None
        except ApiError as error:
            if error.code == "websocket_error":
                raise ConnectionFailed(error.message, error) from None
            return False
        with socket:
            try:
                socket.call("study.subscribe", study_id=self.id)
            except OSError as error:
                raise ConnectionFailed(f"WebSocket: {error}", error) from None
            except ApiError as error:
                if error.code == "closed":
                    raise ConnectionFailed(error.message, error) from None
                return False
            last_fetch = time.monotonic()
            self.refresh()
            outage.reached()
            while self.state not in FINAL_STATES:
                if bar:
                    bar.draw(self.info)
                _check(deadline, self.id)
                try:
                    event = socket.next_event()
                except OSError as error:
                    raise ConnectionFailed(f"WebSocket: {error}", error) from None
                except ApiError as error:
                    raise ConnectionFailed(error.message, error) from None
                if (event and event.get("type") == "event.study.progress"
                        and event.get("study_id") == self.id):
                    self._apply(event)
                if self.state in FINAL_STATES or time.monotonic() - last_fetch > 5:
                    self.refresh()
                    last_fetch = time.monotonic()
        return True

    def _apply(self, event: dict[str, Any]) -> None:
        for key in ("state", "runs_done", "runs_failed", "runs_total"):
            if key in event:
                self.info[key] = event[key]
        if "best" in event:
            self.info["summary"] = {**self.summary, "best": event["best"]}

    def _poll(self, deadline: float | None, bar: "_ProgressBar | None", outage: Outage) -> None:
        interval = 0.05
        while self.refresh().state not in FINAL_STATES:
            outage.reached()
            if bar:
                bar.draw(self.info)
            _check(deadline, self.id)
            time.sleep(interval)
            interval = min(interval * 2, 1.0)

    def table(self) -> Table:
        """The results table so far: one row per finished run."""
        transport = self._client._transport
        path = f"/studies/{self.id}/results"
        data = transport.json("GET", path, query={"format": "json"})
        return Table(data, lambda: transport.request("GET", path, query={"format": "csv"})[1])

    def run_result(self, index: int, variables: Sequence[str] | str | None = None) -> Result:
        """One run's whole result (for a study created with `full=True`)."""
        _, csv = self._client._transport.request(
            "GET", f"/studies/{self.id}/runs/{index}/results",
            query={"format": "csv", "variables": variables_query(variables)})
        return Result(csv)

    def bands(self) -> dict[str, Any]:
        """A sensitivity study's bands (per variable: time, mean, mean±σ, mean±2σ), as the
        server's JSON gives them."""
        return self._client._transport.json("GET", f"/studies/{self.id}/bands",
                                            query={"format": "json"})

    def cancel(self) -> "Study":
        """Cancels a queued or running study: its state becomes `cancelling`, then
        `cancelled` (`wait()` for it). A finished study is left as it is: the same DELETE
        would delete it, so the state is read first (only a study that ends in between
        those two calls is deleted instead)."""
        if self.refresh().state in FINAL_STATES:
            return self
        reply = self._client._transport.json("DELETE", f"/studies/{self.id}")
        if reply and "id" in reply:
            self.info = reply
        elif reply:
            self.info["state"] = reply["state"]
        return self

    def resume(self) -> "Study":
        """Queues an interrupted or cancelled study again: it runs only the runs it lacks
        (an optimisation walks on from its stored runs, to the trace an uninterrupted one with
        the same seed gives). `wait()` for it. Any other state is refused (409)."""
        self.info = self._client._transport.json("POST", f"/studies/{self.id}/resume", json_body={})
        return self

    def delete(self) -> None:
        """Deletes a finished study with its runs."""
        self._client._transport.request("DELETE", f"/studies/{self.id}")

    def __repr__(self) -> str:
        return f"<Study {self.id} {self.state}>"


def _check(deadline: float | None, study_id: int) -> None:
    if deadline is not None and time.monotonic() > deadline:
        raise TimeoutError(f"study {study_id} did not finish in time")


class _ProgressBar:
    """`[#########...........]  45/100 runs, 2 failed, running` redrawn in place on stderr."""

    WIDTH = 30

    def __init__(self) -> None:
        self._last = ""

    def draw(self, info: dict[str, Any]) -> None:
        total = max(int(info.get("runs_total") or 0), 1)
        done = int(info.get("runs_done") or 0)
        filled = min(self.WIDTH, self.WIDTH * done // total)
        line = (f"[{'#' * filled}{'.' * (self.WIDTH - filled)}] {done}/{total} runs"
                + (f", {info['runs_failed']} failed" if info.get("runs_failed") else "")
                + f", {info.get('state', '?')}")
        if line != self._last:
            sys.stderr.write("\r" + line.ljust(len(self._last)))
            sys.stderr.flush()
            self._last = line

    def finish(self) -> None:
        if self._last:
            sys.stderr.write("\n")
            sys.stderr.flush()
