"""A checking pass-through in front of a loopback HTTP/WebSocket server (the viser panel).

viser serves its page and its WebSocket from one `websockets` server whose request hook is a
private function inside viser, with no way to add a check. So viser listens on an internal
loopback port and this gate owns the public one: it reads the head of each connection's request,
applies the `AccessPolicy` (403 when refused) and then relays the bytes both ways unchanged, which
carries HTTP and WebSocket alike. One request per connection is enough: viser's server answers a
plain HTTP request and closes the connection, and a WebSocket stays on the connection it was
checked on. A valid `?token=` on a plain GET adds the token cookie to the response, so the page's
own WebSocket (opened at the page's URL, without the query) gets in too.

Every forwarded request carries `X-Maa-Sim-Gate: <secret>`, so the upstream can refuse WebSockets
that did not come through the gate (see viewer.py).
"""

from __future__ import annotations

import asyncio
import contextlib
import http.client
import io
import secrets
import threading
from http import HTTPStatus

from .access import AccessPolicy

#: The header the gate adds to every request it forwards.
GATE_HEADER = "X-Maa-Sim-Gate"
#: Longest request head (request line and headers) the gate reads.
MAX_HEAD = 64 * 1024
#: Seconds a client may take to send its request head.
HEAD_TIMEOUT = 30.0
_CHUNK = 64 * 1024


class _BadRequest(Exception):
    pass


def _parse_head(head: bytes) -> tuple[str, str, http.client.HTTPMessage]:
    """(method, target, headers) of a request head; _BadRequest when it is none."""
    line, _, rest = head.partition(b"\r\n")
    parts = line.decode("latin-1").split(" ")
    if len(parts) != 3 or not parts[2].startswith("HTTP/1."):
        raise _BadRequest("not an HTTP/1.x request")
    try:
        headers = http.client.parse_headers(io.BytesIO(rest))
    except http.client.HTTPException as exc:
        raise _BadRequest(f"bad headers: {exc}") from None
    return parts[0], parts[1], headers


def _response(status: HTTPStatus, text: str) -> bytes:
    body = text.encode("utf-8")
    return (
        f"HTTP/1.1 {status.value} {status.phrase}\r\nContent-Type: text/plain; charset=utf-8\r\n"
        f"Content-Length: {len(body)}\r\nConnection: close\r\n\r\n"
    ).encode("latin-1") + body


class Gate:
    """Listens on `host:port` and passes checked connections to `127.0.0.1:upstream_port`."""

    def __init__(self, access: AccessPolicy, upstream_port: int, host: str = "127.0.0.1", port: int = 0) -> None:
        self.access = access
        self.upstream_port = upstream_port
        self.host = host
        self.port = port
        #: what the upstream checks to know a request came through this gate
        self.secret = secrets.token_urlsafe(32)
        self.refused = 0
        self._loop: asyncio.AbstractEventLoop | None = None
        self._server: asyncio.Server | None = None
        self._thread: threading.Thread | None = None
        self._ready = threading.Event()
        self._error: BaseException | None = None
        self._connections: set[asyncio.Task[None]] = set()

    # ----------------------------------------------------------------------------- lifecycle

    def start(self, timeout: float = 10.0) -> None:
        self._thread = threading.Thread(target=self._run, name="maa-sim-gate", daemon=True)
        self._thread.start()
        if not self._ready.wait(timeout):
            raise RuntimeError("the viser gate did not start")
        if self._error is not None:
            raise RuntimeError(f"the viser gate could not listen on {self.host}:{self.port}: {self._error}")

    def _run(self) -> None:
        loop = asyncio.new_event_loop()
        self._loop = loop
        try:
            self._server = loop.run_until_complete(
                asyncio.start_server(self._handle, self.host, self.port, limit=MAX_HEAD)
            )
        except OSError as exc:
            self._error = exc
            self._ready.set()
            loop.close()
            return
        self.port = int(self._server.sockets[0].getsockname()[1])
        self.access.port = self.port
        self._ready.set()
        try:
            loop.run_forever()
        finally:
            loop.close()

    def stop(self) -> None:
        loop, thread = self._loop, self._thread
        if loop is None or thread is None:
            return

        async def close() -> None:
            if self._server is not None:
                self._server.close()
            for task in list(self._connections):
                task.cancel()
            await asyncio.gather(*self._connections, return_exceptions=True)
            loop.stop()

        with contextlib.suppress(RuntimeError):  # loop already closed
            asyncio.run_coroutine_threadsafe(close(), loop)
        thread.join(timeout=5)

    # ----------------------------------------------------------------------------- connections

    async def _handle(self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        task = asyncio.current_task()
        assert task is not None
        self._connections.add(task)
        try:
            await self._serve(reader, writer)
        except (ConnectionError, asyncio.IncompleteReadError, TimeoutError):
            pass  # the client went away or never finished its request
        finally:
            self._connections.discard(task)
            writer.close()
            with contextlib.suppress(Exception):
                await writer.wait_closed()

    async def _serve(self, reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        try:
            head = await asyncio.wait_for(reader.readuntil(b"\r\n\r\n"), HEAD_TIMEOUT)
            method, target, headers = _parse_head(head)
        except (asyncio.LimitOverrunError, _BadRequest) as exc:
            writer.write(_response(HTTPStatus.BAD_REQUEST, f"maa-sim: {exc}\n"))
            await writer.drain()
            return
        verdict = self.access.check(target, lambda name: headers.get_all(name) or [])
        if not verdict.allowed:
            self.refused += 1
            writer.write(_response(HTTPStatus.FORBIDDEN, f"maa-sim: {verdict.reason}\n"))
            await writer.drain()
            return
        is_upgrade = (headers.get("Upgrade") or "").lower() == "websocket"
        set_cookie = verdict.token_in_query and method == "GET" and not is_upgrade
        try:
            up_reader, up_writer = await asyncio.open_connection("127.0.0.1", self.upstream_port, limit=MAX_HEAD)
        except OSError as exc:
            writer.write(_response(HTTPStatus.BAD_GATEWAY, f"maa-sim: the panel does not answer ({exc.strerror})\n"))
            await writer.drain()
            return
        try:
            marker = f"{GATE_HEADER}: {self.secret}\r\n".encode("latin-1")
            up_writer.write(head[:-2] + marker + b"\r\n")
            await up_writer.drain()
            upstream = asyncio.ensure_future(self._pipe(reader, up_writer, half_close=True))
            try:
                if set_cookie:
                    await self._relay_head_with_cookie(up_reader, writer)
                await self._pipe(up_reader, writer, half_close=False)
            finally:
                upstream.cancel()
                await asyncio.gather(upstream, return_exceptions=True)
        finally:
            up_writer.close()
            with contextlib.suppress(Exception):
                await up_writer.wait_closed()

    async def _relay_head_with_cookie(self, up_reader: asyncio.StreamReader, writer: asyncio.StreamWriter) -> None:
        """Copies the upstream's response head with the token cookie added."""
        head = await up_reader.readuntil(b"\r\n\r\n")
        cookie = f"Set-Cookie: {self.access.set_cookie_header()}\r\n".encode("latin-1")
        writer.write(head[:-2] + cookie + b"\r\n")
        await writer.drain()

    @staticmethod
    async def _pipe(reader: asyncio.StreamReader, writer: asyncio.StreamWriter, half_close: bool) -> None:
        """Copies bytes until end of stream; then half-closes (client to upstream) or returns."""
        with contextlib.suppress(ConnectionError):
            while data := await reader.read(_CHUNK):
                writer.write(data)
                await writer.drain()
            if half_close and writer.can_write_eof():
                writer.write_eof()
