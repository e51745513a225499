"""The errors a script sees: the server could not be reached or refused a call (ApiError and
its kinds, to catch by what to do about them), or a simulation did not end well."""
from __future__ import annotations


class ApiError(Exception):
    """An error answer of the server: the HTTP status and the body's stable `code`
    (`not_found`, `unauthorized`, ...) and human `message` (protocol/README.md, "Errors").
    Status 0: an error reply on the WebSocket, which has no HTTP status. `retry_after`: the
    seconds the server's Retry-After asked for (429, 503), or None."""

    def __init__(self, status: int, code: str, message: str, retry_after: float | None = None):
        super().__init__(f"{status} {code}: {message}")
        self.status = status
        self.code = code
        self.message = message
        self.retry_after = retry_after


class ConnectionFailed(ApiError):
    """No answer: the server could not be reached (refused, unknown host, timed out, TLS).
    Status 0, code `connection_failed`; `reason` is the underlying error (an OSError, an
    ssl.SSLCertVerificationError, ...)."""

    def __init__(self, message: str, reason: object = None):
        super().__init__(0, "connection_failed", message)
        self.reason = reason


class Unauthorized(ApiError):
    """401: no token, or one that is wrong, expired or revoked: log in again."""


class NotFound(ApiError):
    """404: no such object for this user (another user's objects are not found either)."""


class LimitExceeded(ApiError):
    """413 or 422 (`limit_exceeded`): the request can never succeed as sent (a step count,
    a body size); the message names the limit and its flag. 429 (`rate_limited`): a limit of
    what runs at once, which frees up; `retry_after` is the server's wait in seconds."""


class Refused(ApiError):
    """Another 4xx: the request is wrong as sent (400 bad_request, 403, 409 conflict, ...)."""


def error_for(status: int, code: str, message: str, retry_after: float | None = None) -> ApiError:
    """The ApiError kind of an error answer."""
    if status == 401:
        kind = Unauthorized
    elif status == 404:
        kind = NotFound
    elif status in (413, 422, 429) or code in ("limit_exceeded", "rate_limited"):
        kind = LimitExceeded
    elif 400 <= status < 500:
        kind = Refused
    else:
        kind = ApiError
    return kind(status, code, message, retry_after)


class SimulationFailed(Exception):
    """A job or study that ended `failed`, `cancelled` or `interrupted` while a script waited
    for its results."""

    def __init__(self, kind: str, id: int, state: str, error: str):
        super().__init__(f"{kind} {id} {state}" + (f": {error}" if error else ""))
        self.kind = kind
        self.id = id
        self.state = state
        self.error = error
