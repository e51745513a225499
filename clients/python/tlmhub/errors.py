"""The two errors a script sees: the server refused a call, or a simulation did not end well."""
from __future__ import annotations


class ApiError(Exception):
    """An error answer of the server: the HTTP status and the body's stable `code`
    (`not_found`, `unauthorized`, ...) and human `message` (protocol/README.md, "Errors").
    Status 0: an error reply on the WebSocket, which has no HTTP status."""

    def __init__(self, status: int, code: str, message: str):
        super().__init__(f"{status} {code}: {message}")
        self.status = status
        self.code = code
        self.message = message


class SimulationFailed(Exception):
    """A job or study that ended `failed`, `cancelled` or `interrupted` while a script waited
    for its results."""

    def __init__(self, kind: str, id: int, state: str, error: str):
        super().__init__(f"{kind} {id} {state}" + (f": {error}" if error else ""))
        self.kind = kind
        self.id = id
        self.state = state
        self.error = error
