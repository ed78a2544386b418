"""A minimal synchronous rosbridge client for the tests (the websockets library's sync client)."""

from __future__ import annotations

import json
import time
from typing import Any, Protocol

from websockets.sync.client import ClientConnection, connect


class _Endpoint(Protocol):
    @property
    def url(self) -> str: ...

    @property
    def access(self) -> Any: ...


class Client:
    """Presents the endpoint's token as the IDE backend's proxy does (Authorization: Bearer)."""

    def __init__(self, url: str, token: str | None = None, headers: dict[str, str] | None = None) -> None:
        extra = dict(headers or {})
        if token is not None:
            extra["Authorization"] = f"Bearer {token}"
        self.ws: ClientConnection = connect(url, max_size=None, open_timeout=30, additional_headers=extra)

    @classmethod
    def of(cls, server: _Endpoint) -> Client:
        """A client of a running RosbridgeServer, with its token."""
        return cls(server.url, token=server.access.token)

    def send(self, message: dict[str, Any] | str | bytes) -> None:
        self.ws.send(message if isinstance(message, str | bytes) else json.dumps(message))

    def recv(self, timeout: float = 5.0) -> dict[str, Any]:
        result: dict[str, Any] = json.loads(self.ws.recv(timeout=timeout))
        return result

    def recv_until(self, predicate: Any, timeout: float = 5.0) -> dict[str, Any]:
        deadline = time.monotonic() + timeout
        while True:
            remaining = deadline - time.monotonic()
            if remaining <= 0:
                raise TimeoutError("no matching message")
            message = self.recv(remaining)
            if predicate(message):
                return message

    def call(self, service: str, args: dict[str, Any] | None = None, timeout: float = 5.0) -> dict[str, Any]:
        request_id = f"call:{service}:{time.monotonic_ns()}"
        self.send({"op": "call_service", "id": request_id, "service": service, "args": args or {}})
        return self.recv_until(lambda m: m.get("op") == "service_response" and m.get("id") == request_id, timeout)

    def close(self) -> None:
        self.ws.close()
