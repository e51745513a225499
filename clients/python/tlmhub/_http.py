"""The REST transport: one small wrapper over urllib so that every call sends the token the
same way, every failure becomes an ApiError of its kind, and a call that may safely be sent
again (GET, DELETE, a POST with an Idempotency-Key) is, after a failure that passes: no
answer, or 429/502/503/504."""
from __future__ import annotations

import json
import random
import ssl
import time
import urllib.error
import urllib.parse
import urllib.request
import uuid
from typing import Any, Mapping

from .errors import ApiError, ConnectionFailed, error_for


def new_idempotency_key() -> str:
    """A fresh Idempotency-Key for one POST and its retries (random: 122 bits)."""
    return str(uuid.uuid4())


def api_base(url: str) -> str:
    """The API root for a server URL given with or without its `/api/v1` suffix."""
    url = url.rstrip("/")
    if url.endswith("/api/v1"):
        url = url[: -len("/api/v1")]
    scheme = urllib.parse.urlsplit(url).scheme
    if scheme not in ("http", "https"):
        raise ValueError(f"tlmhub URL must start with http:// or https://, got {url!r}")
    return url + "/api/v1"


class Transport:
    """Sends requests below `/api/v1` with `Authorization: Bearer TOKEN`.

    https uses `ssl.create_default_context()`: the system's trust store, or the file
    `SSL_CERT_FILE` names (OpenSSL reads that variable), unless a context is given."""

    # Idempotent methods, and POSTs with an Idempotency-Key: the server gives a POST sent again
    # with its key what the first one made, so a lost answer never makes two jobs.
    RETRIED_METHODS = ("GET", "HEAD", "DELETE")
    RETRIED_STATUSES = (429, 502, 503, 504)

    def __init__(self, url: str, token: str | None, *, timeout: float = 60.0,
                 ssl_context: ssl.SSLContext | None = None, retries: int = 5,
                 backoff: float = 0.5, max_backoff: float = 30.0):
        self.base = api_base(url)
        self.token = token
        self.timeout = timeout
        self.ssl_context = ssl_context or (ssl.create_default_context()
                                           if self.base.startswith("https:") else None)
        self.retries = retries
        self.backoff = backoff
        self.max_backoff = max_backoff

    def request(self, method: str, path: str, **kwargs: Any) -> tuple[int, bytes]:
        """The status and raw body of a successful (2xx) answer; raises ApiError otherwise.
        GET and DELETE, and a POST given an `idempotency_key`, are sent again up to `retries`
        times after no answer or 429/502/503/504, waiting the server's Retry-After or an
        exponential backoff with jitter."""
        retried = method in self.RETRIED_METHODS or kwargs.get("idempotency_key") is not None
        attempt = 0
        while True:
            try:
                return self._send(method, path, **kwargs)
            except ApiError as error:
                # An untrusted certificate does not pass; a refused connection may.
                unreachable = isinstance(error, ConnectionFailed) and not isinstance(error.reason, ssl.SSLError)
                passing = unreachable or error.status in self.RETRIED_STATUSES
                if not retried or not passing or attempt >= self.retries:
                    raise
                time.sleep(self._pause(attempt, error))
                attempt += 1

    def _pause(self, attempt: int, error: ApiError) -> float:
        if error.retry_after is not None:
            return min(error.retry_after, self.max_backoff)
        # Full jitter: clients that failed together do not come back together.
        return random.uniform(0, min(self.max_backoff, self.backoff * 2 ** attempt))

    def _send(self, method: str, path: str, *, query: Mapping[str, Any] | None = None,
              json_body: Any = None, body: bytes | None = None,
              content_type: str | None = None, idempotency_key: str | None = None) -> tuple[int, bytes]:
        url = self.base + path
        if query:
            url += "?" + urllib.parse.urlencode({k: v for k, v in query.items() if v is not None})
        headers = {"Accept": "application/json"}
        if self.token:
            headers["Authorization"] = "Bearer " + self.token
        if json_body is not None:
            body = json.dumps(json_body).encode()
            content_type = "application/json"
        if content_type:
            headers["Content-Type"] = content_type
        if idempotency_key is not None:
            headers["Idempotency-Key"] = idempotency_key
        request = urllib.request.Request(url, data=body, headers=headers, method=method)
        try:
            with urllib.request.urlopen(request, timeout=self.timeout,
                                        context=self.ssl_context) as response:
                return response.status, response.read()
        except urllib.error.HTTPError as error:
            try:
                body = error.read()
            finally:
                error.close()   # its connection, which the collector would otherwise close
            raise _api_error(error.code, body, error.headers.get("Retry-After")) from None
        except (urllib.error.URLError, OSError) as error:
            reason = getattr(error, "reason", error)
            host = urllib.parse.urlsplit(self.base).netloc
            raise ConnectionFailed(f"cannot reach {host}: {reason}", reason) from None

    def json(self, method: str, path: str, **kwargs: Any) -> Any:
        """The decoded JSON answer, or None for an empty one (204)."""
        status, data = self.request(method, path, **kwargs)
        if not data:
            return None
        try:
            return json.loads(data)
        except ValueError:
            # A web page where the API should answer: most often a URL that is not the server's.
            raise ApiError(status, "bad_reply", f"the answer to {method} {self.base + path} is not JSON: is "
                           f"{self.base[: -len('/api/v1')]} the tlmhub server's address?") from None


def _api_error(status: int, data: bytes, retry_after: str | None = None) -> ApiError:
    """The ApiError of an error body; a body that is not the server's (a proxy's page, say)
    keeps its text as the message."""
    wait = float(retry_after) if retry_after and retry_after.strip().isdigit() else None
    try:
        error = json.loads(data)["error"]
        return error_for(status, str(error["code"]), str(error["message"]), wait)
    except (ValueError, KeyError, TypeError):
        return error_for(status, "http_error", data.decode(errors="replace").strip()[:500], wait)
