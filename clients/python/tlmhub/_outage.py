"""Waiting through a server that went away for a while (a restart, a network blip): a wait
keeps trying until the server has been unreachable for the client's `reconnect_timeout`,
then raises the ConnectionFailed it last got."""
from __future__ import annotations

import time

from .errors import ConnectionFailed


class Outage:
    """One wait's view of the server's reachability: `failed(error)` after each failed try
    (raises it once the server has been away too long, else pauses before the next try),
    `reached()` after each answer."""

    def __init__(self, tolerance: float):
        self.tolerance = tolerance
        self.since: float | None = None

    def reached(self) -> None:
        self.since = None

    def failed(self, error: ConnectionFailed) -> None:
        now = time.monotonic()
        if self.since is None:
            self.since = now
        if now - self.since >= self.tolerance:
            raise error
        time.sleep(min(1.0, max(0.05, now - self.since)))
