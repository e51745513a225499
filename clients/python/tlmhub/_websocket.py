"""The WebSocket side (protocol/README.md): live frames of a job and a study's progress.

websocket-client is optional; only these features need it. The token goes in the upgrade's
`Authorization: Bearer` header, never in the URL: `/ws?token=` accepts login sessions only,
and URLs end up in logs."""
from __future__ import annotations

import itertools
import json
import math
import time
from typing import Any, Iterator

from ._http import Transport
from .errors import ApiError, SimulationFailed, error_for

try:
    import websocket
except ImportError:
    websocket = None

WEBSOCKET_MISSING = ("needs websocket-client, which is not installed: "
                     "pip install 'tlmhub[stream]' (or apt-get install python3-websocket)")


def available() -> bool:
    return websocket is not None


class Socket:
    """One authenticated WebSocket: sends requests, waits for their replies, and hands the
    events that come meanwhile to the caller."""

    def __init__(self, transport: Transport, timeout: float | None = None):
        if websocket is None:
            raise ImportError("streaming " + WEBSOCKET_MISSING)
        url = "ws" + transport.base[len("http"):] + "/ws"
        sslopt = {"context": transport.ssl_context} if transport.ssl_context else None
        try:
            self._ws = websocket.create_connection(
                url, header=[f"Authorization: Bearer {transport.token}"], timeout=timeout,
                sslopt=sslopt)
        except websocket.WebSocketBadStatusException as error:
            raise error_for(error.status_code, "unauthorized" if error.status_code == 401
                            else "http_error", f"WebSocket upgrade refused: {error}") from None
        except websocket.WebSocketException as error:
            raise ApiError(0, "websocket_error", f"WebSocket to {url}: {error}") from None
        self._ids = itertools.count(1)
        self.pending: list[dict[str, Any]] = []
        hello = None
        deadline = time.monotonic() + 30
        while hello is None and time.monotonic() < deadline:
            hello = self.receive()
        if hello is None or hello.get("type") != "hello":
            self.close()
            raise ApiError(0, "bad_reply", f"expected hello, got {hello!r}")

    def close(self) -> None:
        self._ws.close()

    def __enter__(self) -> "Socket":
        return self

    def __exit__(self, *exc: object) -> None:
        self.close()

    def receive(self) -> dict[str, Any] | None:
        """The next message, or None when the read timeout passes first."""
        try:
            text = self._ws.recv()
        except websocket.WebSocketTimeoutException:
            return None
        except websocket.WebSocketConnectionClosedException:
            text = ""
        except (websocket.WebSocketException, OSError) as error:
            raise ApiError(0, "closed", f"the WebSocket broke: {error}") from None
        if not text:
            raise ApiError(0, "closed", "the server closed the WebSocket")
        return json.loads(text)

    def call(self, type_: str, **fields: Any) -> dict[str, Any]:
        """Sends a request and returns its reply's `data`; events that arrive first wait in
        `pending`. An error reply raises ApiError (status 0: not HTTP)."""
        request_id = next(self._ids)
        self._ws.send(json.dumps({"id": request_id, "type": type_, **fields}))
        while True:
            message = self.receive()
            if message is None:
                continue
            if message.get("id") != request_id:
                self.pending.append(message)
            elif message.get("type") == "error":
                raise ApiError(0, message["error"]["code"], message["error"]["message"])
            else:
                return message.get("data", {})

    def next_event(self) -> dict[str, Any] | None:
        return self.pending.pop(0) if self.pending else self.receive()


def _floats(values: list[Any]) -> list[float]:
    """JSON frames write NaN and infinities as null."""
    return [math.nan if v is None else float(v) for v in values]


def job_frames(transport: Transport, job_id: int, variables: list[str] | None,
               fetch_rest: Any) -> Iterator[dict[str, list[float]]]:
    """The frames of a job as it runs: each a dict of `time` and each variable to the
    samples logged since the previous frame; together they equal the stored result.

    If the server gives up streaming to a slow reader (`event.resync`), the rest comes as one
    last frame read from the stored result (`fetch_rest(samples_seen)`)."""
    with Socket(transport) as socket:
        fields: dict[str, Any] = {"job_id": job_id}
        if variables is not None:
            fields["variables"] = list(variables)
        socket.call("log.subscribe", **fields)
        seen = 0
        resync = False
        while True:
            event = socket.next_event()
            if event is None or event.get("job_id") != job_id:
                continue
            kind = event.get("type")
            if kind == "event.frame" and not resync:
                frame = {"time": _floats(event["time"])}
                frame.update({name: _floats(v) for name, v in event["variables"].items()})
                seen += len(frame["time"])
                yield frame
            elif kind == "event.resync":
                resync = True
            elif kind == "event.done":
                if resync:
                    yield fetch_rest(seen)
                if event.get("state") != "done":
                    raise SimulationFailed("job", job_id, event.get("state", "?"),
                                           event.get("error", ""))
                return
