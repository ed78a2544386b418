"""A rosbridge v2 endpoint (WebSocket, JSON) over a `Transport`: the subset roslib 2.x uses.

Operations: advertise, unadvertise, publish, subscribe (throttle_rate, queue_length),
unsubscribe, call_service (rosapi/topics, rosapi/topic_type, rosapi/services, rosapi/nodes,
rosapi/message_details and the simulator's control services), set_level. Errors get a `status`
reply with the request's id. Nothing a client sends stops the server: every frame is handled in a try block, frames over
`MAX_FRAME_BYTES` are refused with a status error, frames over `WS_MAX_SIZE` close that
connection only (the WebSocket library's limit), and slow clients lose messages rather than
growing the server's memory.

The server runs its own asyncio loop in a thread; transport callbacks arrive from other threads
and are handed over with `call_soon_threadsafe`.
"""

from __future__ import annotations

import asyncio
import contextlib
import json
import math
import threading
import time
from collections import deque
from collections.abc import Callable
from dataclasses import dataclass, field
from http import HTTPStatus
from typing import Any

from websockets.asyncio.server import Server, ServerConnection, serve
from websockets.exceptions import ConnectionClosed
from websockets.http11 import Request, Response

from .access import AccessPolicy, resolve_token
from .messages import JsonMessage, MessageError, message_details, normalize_type, validate
from .transport import Subscription, Transport

#: Frames larger than this get a status error (bytes).
MAX_FRAME_BYTES = 1 << 20
#: The WebSocket library closes connections that send larger messages.
WS_MAX_SIZE = 16 << 20
#: Messages waiting for one client before newer ones are dropped.
CLIENT_QUEUE = 1000
#: Largest queue_length a subscription may ask for.
MAX_QUEUE_LENGTH = 1000

_LEVELS = {"none": 0, "error": 1, "warning": 2, "info": 3}

ServiceHandler = Callable[[JsonMessage], JsonMessage]


class BlockingService:
    """A service handler that may take long (seconds): it runs on a worker thread, not the server's loop."""

    blocking = True

    def __init__(self, handler: ServiceHandler) -> None:
        self.handler = handler

    def __call__(self, args: JsonMessage) -> JsonMessage:
        return self.handler(args)


class ServiceError(Exception):
    """A service that fails with a message for the client."""


class RequestError(Exception):
    """A request that cannot be carried out; answered with a status error."""


def _url_host(host: str) -> str:
    """An IPv6 address goes in brackets in a URL."""
    return f"[{host}]" if ":" in host and not host.startswith("[") else host


def _dumps(message: JsonMessage) -> str:
    try:
        return json.dumps(message, allow_nan=False, separators=(",", ":"))
    except ValueError:
        return json.dumps(_finite(message), separators=(",", ":"))


def _finite(value: Any) -> Any:
    if isinstance(value, float) and not math.isfinite(value):
        return None
    if isinstance(value, dict):
        return {k: _finite(v) for k, v in value.items()}
    if isinstance(value, list):
        return [_finite(v) for v in value]
    return value


def _field(request: JsonMessage, name: str, kind: type | tuple[type, ...], required: bool = True) -> Any:
    value = request.get(name)
    if value is None:
        if required:
            raise RequestError(f"missing field '{name}'")
        return None
    if isinstance(value, bool) and bool not in (kind if isinstance(kind, tuple) else (kind,)):
        raise RequestError(f"field '{name}' has the wrong type")
    if not isinstance(value, kind):
        raise RequestError(f"field '{name}' has the wrong type")
    return value


def _topic_name(request: JsonMessage) -> str:
    topic: str = _field(request, "topic", str)
    if not topic or len(topic) > 256 or any(c.isspace() for c in topic):
        raise RequestError("invalid topic name")
    return topic if topic.startswith("/") else "/" + topic


@dataclass
class _TopicSubscription:
    """One client's subscription to one topic (several subscribe ids may share it)."""

    topic: str
    ids: dict[str | None, tuple[int, int]] = field(default_factory=dict)  # id -> (throttle ms, queue length)
    handle: Subscription | None = None
    last_sent: float = 0.0
    pending: deque[JsonMessage] = field(default_factory=lambda: deque(maxlen=1))
    flush_scheduled: bool = False

    @property
    def throttle(self) -> float:
        return min(t for t, _ in self.ids.values()) / 1000.0 if self.ids else 0.0

    @property
    def queue_length(self) -> int:
        return max(q for _, q in self.ids.values()) if self.ids else 1


class _Client:
    def __init__(self, server: RosbridgeServer, ws: ServerConnection) -> None:
        self.server = server
        self.ws = ws
        self.loop = asyncio.get_running_loop()
        self.outbox: asyncio.Queue[str] = asyncio.Queue(maxsize=CLIENT_QUEUE)
        self.subscriptions: dict[str, _TopicSubscription] = {}
        self.advertised: dict[str, str] = {}
        self.level = _LEVELS["error"]
        self.dropped = 0
        self.closed = False

    # ----------------------------------------------------------------------------- sending

    def send(self, message: JsonMessage) -> None:
        if self.closed:
            return
        try:
            self.outbox.put_nowait(_dumps(message))
        except asyncio.QueueFull:
            self.dropped += 1

    def status(self, level: str, msg: str, request_id: Any = None) -> None:
        if _LEVELS.get(level, 1) > self.level:
            return
        reply: JsonMessage = {"op": "status", "level": level, "msg": msg}
        if isinstance(request_id, str | int) and not isinstance(request_id, bool):
            reply["id"] = request_id
        self.send(reply)

    async def writer(self) -> None:
        with contextlib.suppress(ConnectionClosed, asyncio.CancelledError):
            while True:
                text = await self.outbox.get()
                await self.ws.send(text)

    # ----------------------------------------------------------------------------- topics

    def on_message(self, topic: str, msg: JsonMessage) -> None:
        """From any thread: a message on a subscribed topic."""
        with contextlib.suppress(RuntimeError):  # loop closed while shutting down
            self.loop.call_soon_threadsafe(self._deliver, topic, msg)

    def _deliver(self, topic: str, msg: JsonMessage) -> None:
        sub = self.subscriptions.get(topic)
        if sub is None or self.closed:
            return
        throttle = sub.throttle
        now = time.monotonic()
        if throttle <= 0 and not sub.pending:
            self._publish(sub, msg, now)
            return
        if sub.pending.maxlen != sub.queue_length:
            sub.pending = deque(sub.pending, maxlen=sub.queue_length)
        sub.pending.append(msg)
        if not sub.flush_scheduled:
            delay = max(0.0, sub.last_sent + throttle - now)
            sub.flush_scheduled = True
            self.loop.call_later(delay, self._flush, topic)

    def _flush(self, topic: str) -> None:
        sub = self.subscriptions.get(topic)
        if sub is None:
            return
        sub.flush_scheduled = False
        if sub.pending:
            now = time.monotonic()
            if sub.throttle > 0:
                self._publish(sub, sub.pending.popleft(), now)
            else:
                while sub.pending:
                    self._publish(sub, sub.pending.popleft(), now)
            if sub.pending and not sub.flush_scheduled:
                sub.flush_scheduled = True
                self.loop.call_later(sub.throttle, self._flush, topic)

    def _publish(self, sub: _TopicSubscription, msg: JsonMessage, now: float) -> None:
        sub.last_sent = now
        self.send({"op": "publish", "topic": sub.topic, "msg": msg})

    def close(self) -> None:
        self.closed = True
        for sub in self.subscriptions.values():
            if sub.handle is not None:
                self.server.transport.unsubscribe(sub.handle)
        self.subscriptions.clear()
        for topic in list(self.advertised):
            self.server.release_advertisement(topic)
        self.advertised.clear()


class RosbridgeServer:
    """The WebSocket endpoint. `start()` returns once it listens; `port` is the bound port."""

    def __init__(
        self,
        transport: Transport,
        host: str = "127.0.0.1",
        port: int = 9090,
        services: dict[str, ServiceHandler] | None = None,
        on_publish: Callable[[str, JsonMessage], bool] | None = None,
        latched: Callable[[str], JsonMessage | None] | None = None,
        access: AccessPolicy | None = None,
        check_publish: Callable[[str, JsonMessage], None] | None = None,
    ) -> None:
        self.transport = transport
        self.host = host
        self.port = port
        #: Host, Origin and token rules of the handshake (maa_sim.access); without one given, a
        #: fresh random token: the endpoint is never open to anyone who finds the port.
        self.access = access if access is not None else AccessPolicy(resolve_token(), bind_host=host)
        self.services: dict[str, ServiceHandler] = {
            "rosapi/topics": self._topics,
            "rosapi/topic_type": self._topic_type,
            "rosapi/services": self._services,
            "rosapi/nodes": self._nodes,
            "rosapi/message_details": self._message_details,
        }
        self.services.update(services or {})
        #: Called before a client's message is published; returning True means it was consumed.
        self.on_publish = on_publish
        #: Checks a client's message (already fitted to its type) beyond its type; raises MessageError.
        self.check_publish = check_publish
        #: The current message of a latched topic (None: none), sent to a client when it subscribes.
        self.latched = latched
        self.clients: set[_Client] = set()
        self._advertisers: dict[str, int] = {}
        self._loop: asyncio.AbstractEventLoop | None = None
        self._thread: threading.Thread | None = None
        self._server: Server | None = None
        self._ready = threading.Event()
        self._error: BaseException | None = None
        self._tasks: set[asyncio.Task[None]] = set()
        self.frames = 0
        self.errors = 0
        self.refused = 0

    # ----------------------------------------------------------------------------- lifecycle

    def start(self, timeout: float = 10.0) -> None:
        self._thread = threading.Thread(target=self._run, name="maa-sim-rosbridge", daemon=True)
        self._thread.start()
        if not self._ready.wait(timeout):
            raise RuntimeError("rosbridge server did not start")
        if self._error is not None:
            raise RuntimeError(f"rosbridge server could not start: {self._error}") from self._error

    def _run(self) -> None:
        loop = asyncio.new_event_loop()
        self._loop = loop
        asyncio.set_event_loop(loop)
        try:
            loop.run_until_complete(self._open())
        except BaseException as exc:  # noqa: BLE001 - handed to start()
            self._error = exc
            self._ready.set()
            loop.close()
            return
        self._ready.set()
        try:
            loop.run_forever()
        finally:
            loop.run_until_complete(loop.shutdown_asyncgens())
            loop.close()

    async def _open(self) -> None:
        self._server = await serve(
            self._handle,
            self.host,
            self.port,
            max_size=WS_MAX_SIZE,
            max_queue=64,
            ping_interval=20,
            ping_timeout=20,
            process_request=self._authorize,
        )
        sockets = list(self._server.sockets)
        if sockets:
            self.port = int(sockets[0].getsockname()[1])
        self.access.port = self.port

    def _authorize(self, connection: ServerConnection, request: Request) -> Response | None:
        """The websockets library's handshake hook: a refused request gets 403 and no connection."""
        verdict = self.access.check(request.path, request.headers.get_all)
        if verdict.allowed:
            return None
        self.refused += 1
        return connection.respond(HTTPStatus.FORBIDDEN, f"maa-sim: {verdict.reason}\n")

    def stop(self) -> None:
        loop = self._loop
        if loop is None or self._thread is None:
            return

        async def close() -> None:
            if self._server is not None:
                self._server.close()
                with contextlib.suppress(Exception):
                    await asyncio.wait_for(self._server.wait_closed(), 3)
            for client in list(self.clients):
                client.close()
            loop.stop()

        with contextlib.suppress(RuntimeError):
            asyncio.run_coroutine_threadsafe(close(), loop)
        self._thread.join(timeout=5)

    @property
    def url(self) -> str:
        """The endpoint's address (without the token: see `url_with_token`)."""
        return f"ws://{_url_host(self.host)}:{self.port}"

    @property
    def url_with_token(self) -> str:
        """The address for a person or a browser client, which cannot send an Authorization header."""
        return f"{self.url}/?token={self.access.token}"

    def broadcast_status(self, level: str, msg: str) -> None:
        """An unsolicited status to every client (e.g. a crashed node), from any thread."""
        loop = self._loop
        if loop is None:
            return

        def send() -> None:
            for client in list(self.clients):
                client.status(level, msg)

        with contextlib.suppress(RuntimeError):
            loop.call_soon_threadsafe(send)

    # ----------------------------------------------------------------------------- connection

    async def _handle(self, ws: ServerConnection) -> None:
        client = _Client(self, ws)
        self.clients.add(client)
        writer = asyncio.create_task(client.writer())
        try:
            async for frame in ws:
                self.frames += 1
                try:
                    self._frame(client, frame)
                except Exception as exc:  # noqa: BLE001 - never let one frame stop the server
                    self.errors += 1
                    client.status("error", f"internal error: {type(exc).__name__}: {exc}")
        except ConnectionClosed:
            pass
        finally:
            client.close()
            self.clients.discard(client)
            # let queued replies go out before the writer stops
            with contextlib.suppress(Exception):
                await asyncio.wait_for(self._drain(client), 0.5)
            writer.cancel()
            with contextlib.suppress(asyncio.CancelledError):
                await writer

    @staticmethod
    async def _drain(client: _Client) -> None:
        while not client.outbox.empty():
            await asyncio.sleep(0.01)

    def _frame(self, client: _Client, frame: str | bytes) -> None:
        if isinstance(frame, bytes):
            self.errors += 1
            client.status("error", "binary frames (CBOR/BSON) are not supported; send JSON text")
            return
        if len(frame) > MAX_FRAME_BYTES:
            self.errors += 1
            client.status("error", f"frame too large ({len(frame)} bytes; at most {MAX_FRAME_BYTES})")
            return
        try:
            request = json.loads(frame)
        except (ValueError, RecursionError) as exc:
            self.errors += 1
            client.status("error", f"invalid JSON: {str(exc)[:200]}")
            return
        if not isinstance(request, dict):
            self.errors += 1
            client.status("error", "a frame must be a JSON object")
            return
        request_id = request.get("id")
        try:
            op = _field(request, "op", str)
            handler = self._ops.get(op)
            if handler is None:
                raise RequestError(f"unknown or unsupported op '{op[:64]}'")
            handler(self, client, request)
        except (RequestError, MessageError) as exc:
            self.errors += 1
            client.status("error", str(exc), request_id)

    # ----------------------------------------------------------------------------- operations

    def _op_advertise(self, client: _Client, request: JsonMessage) -> None:
        topic = _topic_name(request)
        type_name = normalize_type(_field(request, "type", str))
        if client.advertised.get(topic) == type_name:
            return
        if topic in client.advertised:
            raise RequestError(f"{topic} is already advertised with type {client.advertised[topic]}")
        self.transport.advertise(topic, type_name)
        client.advertised[topic] = type_name
        self._advertisers[topic] = self._advertisers.get(topic, 0) + 1

    def _op_unadvertise(self, client: _Client, request: JsonMessage) -> None:
        topic = _topic_name(request)
        if topic not in client.advertised:
            client.status("warning", f"{topic} was not advertised", request.get("id"))
            return
        del client.advertised[topic]
        self.release_advertisement(topic)

    def release_advertisement(self, topic: str) -> None:
        count = self._advertisers.get(topic, 0) - 1
        if count <= 0:
            self._advertisers.pop(topic, None)
        else:
            self._advertisers[topic] = count

    def _op_publish(self, client: _Client, request: JsonMessage) -> None:
        topic = _topic_name(request)
        msg = request.get("msg", {})
        if not isinstance(msg, dict):
            raise RequestError("field 'msg' must be an object")
        type_name = client.advertised.get(topic) or self.transport.topic_type(topic)
        if type_name is None:
            raise RequestError(f"{topic} is not advertised and its type is unknown")
        # Checked here, whatever the transport, before anything reaches the application: wrong
        # or unknown fields are refused, missing ones take their defaults (as in ROS 2).
        checked = validate(type_name, msg)
        if self.check_publish is not None:
            self.check_publish(topic, checked)
        if self.on_publish is not None and self.on_publish(topic, msg):
            return
        self.transport.publish(topic, msg)

    def _op_subscribe(self, client: _Client, request: JsonMessage) -> None:
        topic = _topic_name(request)
        type_value = _field(request, "type", str, required=False)
        type_name = normalize_type(type_value) if type_value else None
        throttle = _field(request, "throttle_rate", int, required=False) or 0
        queue_length = _field(request, "queue_length", int, required=False) or 0
        if throttle < 0 or throttle > 3_600_000:
            raise RequestError("throttle_rate must be between 0 and 3600000 ms")
        if queue_length < 0 or queue_length > MAX_QUEUE_LENGTH:
            raise RequestError(f"queue_length must be between 0 and {MAX_QUEUE_LENGTH}")
        compression = request.get("compression")
        if compression not in (None, "none"):
            client.status("warning", f"compression {compression!r} is not supported; sending JSON", request.get("id"))
        sub_id = request.get("id")
        key = sub_id if isinstance(sub_id, str) else None
        sub = client.subscriptions.get(topic)
        if sub is None:
            sub = _TopicSubscription(topic)
            sub.handle = self.transport.subscribe(topic, type_name, client.on_message)
            client.subscriptions[topic] = sub
            initial = self.latched(topic) if self.latched is not None else None
            if initial is not None:
                client.on_message(topic, initial)  # the current value of a latched topic, at once
        elif type_name is not None:
            known = self.transport.topic_type(topic)
            if known is not None and known != type_name:
                raise RequestError(f"{topic} has type {known}, not {type_name}")
        sub.ids[key] = (throttle, max(queue_length, 1))

    def _op_unsubscribe(self, client: _Client, request: JsonMessage) -> None:
        topic = _topic_name(request)
        sub = client.subscriptions.get(topic)
        if sub is None:
            client.status("warning", f"not subscribed to {topic}", request.get("id"))
            return
        sub_id = request.get("id")
        if isinstance(sub_id, str) and sub_id in sub.ids and len(sub.ids) > 1:
            del sub.ids[sub_id]
            return
        if sub.handle is not None:
            self.transport.unsubscribe(sub.handle)
        del client.subscriptions[topic]

    def _op_call_service(self, client: _Client, request: JsonMessage) -> None:
        service: str = _field(request, "service", str)
        args = request.get("args", {})
        if args is None or args == []:
            args = {}
        if not isinstance(args, dict):
            raise RequestError("field 'args' must be an object")
        name = service.strip("/")
        reply: JsonMessage = {"op": "service_response", "service": service}
        if "id" in request and isinstance(request["id"], str | int) and not isinstance(request["id"], bool):
            reply["id"] = request["id"]
        handler = self.services.get(name)
        if handler is None:
            reply.update(result=False, values=f"unknown service {service}")
            client.send(reply)
            client.status("error", f"unknown service {service}", request.get("id"))
            return
        if getattr(handler, "blocking", False):
            # a slow service (a reset that restarts node processes): runs on a worker thread, so
            # the endpoint keeps serving every client meanwhile; the reply comes when it is done
            task = asyncio.get_running_loop().create_task(self._call_blocking(client, request, handler, args, reply))
            self._tasks.add(task)
            task.add_done_callback(self._tasks.discard)
            return
        try:
            values = handler(args)
        except (ServiceError, MessageError, ValueError, TypeError) as exc:
            self._service_failed(client, request, reply, exc)
            return
        except Exception as exc:  # noqa: BLE001 - a caller still gets its service_response
            self.errors += 1
            self._service_failed(client, request, reply, RuntimeError(f"internal error: {exc!r}"))
            return
        reply.update(result=True, values=values)
        client.send(reply)

    async def _call_blocking(
        self, client: _Client, request: JsonMessage, handler: ServiceHandler, args: JsonMessage, reply: JsonMessage
    ) -> None:
        try:
            values = await asyncio.to_thread(handler, args)
        except (ServiceError, MessageError, ValueError, TypeError) as exc:
            self._service_failed(client, request, reply, exc)
            return
        except Exception as exc:  # noqa: BLE001 - never let a service stop the server
            self._service_failed(client, request, reply, RuntimeError(f"internal error: {exc!r}"))
            return
        reply.update(result=True, values=values)
        client.send(reply)

    @staticmethod
    def _service_failed(client: _Client, request: JsonMessage, reply: JsonMessage, exc: Exception) -> None:
        reply.update(result=False, values=str(exc))
        client.send(reply)
        client.status("error", f"{request.get('service')}: {exc}", request.get("id"))

    def _op_set_level(self, client: _Client, request: JsonMessage) -> None:
        level = _field(request, "level", str)
        if level not in _LEVELS:
            raise RequestError(f"level must be one of {', '.join(_LEVELS)}")
        client.level = _LEVELS[level]

    _ops: dict[str, Callable[[RosbridgeServer, _Client, JsonMessage], None]] = {
        "advertise": _op_advertise,
        "unadvertise": _op_unadvertise,
        "publish": _op_publish,
        "subscribe": _op_subscribe,
        "unsubscribe": _op_unsubscribe,
        "call_service": _op_call_service,
        "set_level": _op_set_level,
    }

    # ----------------------------------------------------------------------------- rosapi

    def _topics(self, _args: JsonMessage) -> JsonMessage:
        topics = self.transport.topics()
        return {"topics": [t for t, _ in topics], "types": [ty for _, ty in topics]}

    def _topic_type(self, args: JsonMessage) -> JsonMessage:
        topic = args.get("topic")
        if not isinstance(topic, str):
            raise ServiceError("args.topic must be a string")
        return {"type": self.transport.topic_type(topic) or ""}

    def _services(self, _args: JsonMessage) -> JsonMessage:
        return {"services": sorted("/" + name for name in self.services)}

    def _nodes(self, _args: JsonMessage) -> JsonMessage:
        return {"nodes": self.transport.nodes()}

    def _message_details(self, args: JsonMessage) -> JsonMessage:
        type_name = args.get("type")
        if not isinstance(type_name, str):
            raise ServiceError("args.type must be a string")
        return {"typedefs": message_details(type_name)}
