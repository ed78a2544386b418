"""Host, Origin and token rules of the rosbridge and viser endpoints (maa_sim.access), attacked.

Requests are written by hand on a socket, so every header (Host above all) is exactly what a
hostile page, a DNS-rebound name or the IDE backend's proxy would send.
"""

from __future__ import annotations

import base64
import json
import os
import socket
import subprocess
import sys
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path

import pytest
from rosbridge_client import Client
from toast_app.lockstep import create_controller
from websockets.exceptions import ConnectionClosed, InvalidStatus
from websockets.sync.client import connect

from maa_sim.access import AccessPolicy, HeaderValues, allowed_origins_from_env, cookie_name, resolve_token
from maa_sim.rosbridge import RosbridgeServer
from maa_sim.runs import lockstep_session
from maa_sim.transport import LocalBus
from maa_sim.viewer import SceneView

TOKEN = "test-token-0123456789abcdefghijklmnopqrstuv"
ALLOWED = "http://ide.example:3000"
SIM_SERVER = Path(__file__).resolve().parent.parent


@dataclass
class Endpoint:
    name: str
    port: int
    #: whether a plain HTTP GET is served (viser's page) or only WebSockets (rosbridge)
    serves_http: bool


@pytest.fixture(scope="module")
def rosbridge() -> Iterator[Endpoint]:
    bus = LocalBus()
    access = AccessPolicy(TOKEN, allowed_origins=frozenset({ALLOWED}))
    server = RosbridgeServer(bus, port=0, access=access)
    server.start()
    yield Endpoint("rosbridge", server.port, serves_http=False)
    server.stop()


@pytest.fixture(scope="module")
def viser_view() -> Iterator[SceneView]:
    _, runner = lockstep_session(create_controller({}))
    view = SceneView(runner, port=0, access=AccessPolicy(TOKEN, allowed_origins=frozenset({ALLOWED})))
    view.start()
    yield view
    view.stop()


@pytest.fixture(scope="module")
def viser(viser_view: SceneView) -> Endpoint:
    return Endpoint("viser", viser_view.port, serves_http=True)


@pytest.fixture(params=["rosbridge", "viser"])
def endpoint(request: pytest.FixtureRequest) -> Endpoint:
    result: Endpoint = request.getfixturevalue(request.param)
    return result


@dataclass
class Reply:
    status: int
    headers: dict[str, str]
    body: bytes


def send(port: int, target: str = "/", headers: dict[str, str] | None = None, websocket: bool = False) -> Reply:
    """One request with exactly these headers (Host included: no default is added)."""
    lines = [f"GET {target} HTTP/1.1"]
    for name, value in (headers or {}).items():
        lines.append(f"{name}: {value}")
    if websocket:
        key = base64.b64encode(os.urandom(16)).decode()
        lines += ["Upgrade: websocket", "Connection: Upgrade", f"Sec-WebSocket-Key: {key}", "Sec-WebSocket-Version: 13"]
    else:
        lines.append("Connection: close")
    with socket.create_connection(("127.0.0.1", port), timeout=30) as sock:
        sock.sendall(("\r\n".join(lines) + "\r\n\r\n").encode("latin-1"))
        data = b""
        while b"\r\n\r\n" not in data:
            chunk = sock.recv(65536)
            if not chunk:
                break
            data += chunk
        head, _, body = data.partition(b"\r\n\r\n")
        if not websocket:  # the rest of the body, up to the server's close
            while chunk := sock.recv(65536):
                body += chunk
    status_line, *header_lines = head.decode("latin-1").split("\r\n")
    parsed = {}
    for line in header_lines:
        name, _, value = line.partition(":")
        parsed[name.strip().lower()] = value.strip()
    return Reply(int(status_line.split(" ")[1]), parsed, body)


def host(port: int) -> str:
    return f"127.0.0.1:{port}"


def bearer(token: str = TOKEN) -> dict[str, str]:
    return {"Authorization": f"Bearer {token}"}


def accepted(reply: Reply, websocket: bool) -> bool:
    return reply.status == (101 if websocket else 200)


KINDS = [False, True]  # plain HTTP, WebSocket handshake


def kinds(endpoint: Endpoint) -> list[bool]:
    return KINDS if endpoint.serves_http else [True]


# ----------------------------------------------------------------------------------------- refused


def test_foreign_host_is_refused(endpoint: Endpoint) -> None:
    """DNS rebinding: the page's own name resolves to 127.0.0.1, the browser sends that name."""
    for websocket in kinds(endpoint):
        for name in (f"evil.example:{endpoint.port}", f"localhost.evil.example:{endpoint.port}", "127.0.0.2"):
            reply = send(endpoint.port, headers={"Host": name, **bearer()}, websocket=websocket)
            assert reply.status == 403, (name, websocket, reply)
            assert b"not this server's address" in reply.body
        reply = send(endpoint.port, headers=bearer(), websocket=websocket)  # no Host at all
        assert reply.status == 403


def test_foreign_origin_is_refused(endpoint: Endpoint) -> None:
    """A cross-site page (WebSockets have no same-origin rule), even with the right token."""
    for websocket in kinds(endpoint):
        for origin in ("http://evil.example", "null", f"https://127.0.0.1:{endpoint.port}", "http://127.0.0.1:1"):
            headers = {"Host": host(endpoint.port), "Origin": origin, **bearer()}
            reply = send(endpoint.port, headers=headers, websocket=websocket)
            assert reply.status == 403, (origin, websocket, reply)
            assert b"Origin" in reply.body


def test_missing_or_wrong_token_is_refused(endpoint: Endpoint) -> None:
    wrong = [
        {},
        bearer("wrong"),
        bearer(TOKEN + "x"),
        bearer(""),
        {"Authorization": f"Basic {TOKEN}"},
        {"Cookie": f"{cookie_name(endpoint.port)}=wrong"},
        {"Cookie": f"{cookie_name(endpoint.port + 1)}={TOKEN}"},  # another port's cookie
        {"Cookie": 'x="unterminated'},
        bearer("t\u00e9st"),
    ]
    for websocket in kinds(endpoint):
        for headers in wrong:
            reply = send(endpoint.port, headers={"Host": host(endpoint.port), **headers}, websocket=websocket)
            assert reply.status == 403, (headers, websocket, reply)
            assert b"token" in reply.body
        for target in ("/?token=wrong", "/?token=", f"/?tok={TOKEN}"):
            reply = send(endpoint.port, target, {"Host": host(endpoint.port)}, websocket=websocket)
            assert reply.status == 403, (target, reply)


# ----------------------------------------------------------------------------------------- accepted


def test_right_token_by_header_query_or_cookie_is_accepted(endpoint: Endpoint) -> None:
    for websocket in kinds(endpoint):
        ways = [
            ("/", bearer()),
            (f"/?token={TOKEN}", {}),
            (f"/?x=1&token={TOKEN}", {}),
            ("/", {"Cookie": f"other=1; {cookie_name(endpoint.port)}={TOKEN}"}),
        ]
        for target, headers in ways:
            reply = send(endpoint.port, target, {"Host": host(endpoint.port), **headers}, websocket=websocket)
            assert accepted(reply, websocket), (target, headers, websocket, reply)


def test_the_proxy_way_and_own_or_listed_origins_are_accepted(endpoint: Endpoint) -> None:
    port = endpoint.port
    for websocket in kinds(endpoint):
        # the IDE backend's proxy: no Origin, a loopback Host, the bearer token
        for name in (f"127.0.0.1:{port}", f"localhost:{port}", f"[::1]:{port}", "localhost"):
            reply = send(port, headers={"Host": name, **bearer()}, websocket=websocket)
            assert accepted(reply, websocket), (name, reply)
        # a browser on the server's own origin, and an origin listed in MAA_SIM_ALLOWED_ORIGINS
        for origin in (f"http://127.0.0.1:{port}", ALLOWED, ALLOWED + "/"):
            reply = send(port, headers={"Host": host(port), "Origin": origin, **bearer()}, websocket=websocket)
            assert accepted(reply, websocket), (origin, reply)


def test_rosbridge_client_with_and_without_token(rosbridge: Endpoint) -> None:
    url = f"ws://127.0.0.1:{rosbridge.port}"
    client = Client(url, token=TOKEN)
    try:
        assert client.call("rosapi/topics")["result"] is True
    finally:
        client.close()
    for headers in ({}, {"Origin": "http://evil.example", "Authorization": f"Bearer {TOKEN}"}):
        with pytest.raises(InvalidStatus) as refused:
            connect(url, additional_headers=headers, open_timeout=30)
        assert refused.value.response.status_code == 403


def test_viser_page_sets_the_token_cookie_for_its_websocket(viser: Endpoint) -> None:
    """A person opens the printed URL (with ?token=); the page's WebSocket then has only the cookie."""
    port = viser.port
    page = send(port, f"/?token={TOKEN}", {"Host": host(port)})
    assert page.status == 200 and b"<html" in page.body.lower()
    cookie = page.headers["set-cookie"]
    assert cookie.startswith(f"{cookie_name(port)}={TOKEN};")
    assert "HttpOnly" in cookie and "SameSite=Strict" in cookie
    # with the header, the token is not repeated in a cookie
    assert "set-cookie" not in send(port, "/", {"Host": host(port), **bearer()}).headers
    jar = cookie.split(";", 1)[0]
    origin = f"http://127.0.0.1:{port}"
    ws = send(port, "/", {"Host": host(port), "Origin": origin, "Cookie": jar}, websocket=True)
    assert ws.status == 101
    # a cross-site page cannot use that cookie: its Origin gives it away
    assert send(port, "/", {"Host": host(port), "Origin": "http://evil.example", "Cookie": jar}, True).status == 403


def test_viser_internal_port_refuses_websockets_that_bypass_the_gate(viser_view: SceneView) -> None:
    """viser's own port is loopback only but findable: a WebSocket straight to it is closed at once."""
    internal = viser_view.gate.upstream_port
    import viser as viser_module

    with connect(f"ws://127.0.0.1:{internal}", subprotocols=[f"viser-v{viser_module.__version__}"]) as ws:  # type: ignore[list-item]
        with pytest.raises(ConnectionClosed) as closed:
            while True:
                ws.recv(timeout=30)
        assert closed.value.rcvd is not None and closed.value.rcvd.code == 1008


# ----------------------------------------------------------------------------------------- token source


def test_token_from_environment_or_made_per_start(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("MAA_SIM_TOKEN", "from-env")
    assert resolve_token() == "from-env"
    assert resolve_token("given") == "given"
    monkeypatch.setenv("MAA_SIM_TOKEN", "")  # empty: as if unset, never an empty token
    first, second = resolve_token(), resolve_token()
    assert first != second and len(first) >= 40
    monkeypatch.delenv("MAA_SIM_TOKEN")
    assert len(resolve_token()) >= 40
    for bad in ("has space", "semi;colon", 'quote"', "t\u00e9st"):
        monkeypatch.setenv("MAA_SIM_TOKEN", bad)
        with pytest.raises(ValueError, match="MAA_SIM_TOKEN"):
            resolve_token()


def test_allowed_origins_from_environment(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv("MAA_SIM_ALLOWED_ORIGINS", " http://A.example:1/ ,, https://b.example ")
    assert allowed_origins_from_env() == frozenset({"http://a.example:1", "https://b.example"})
    monkeypatch.delenv("MAA_SIM_ALLOWED_ORIGINS")
    assert allowed_origins_from_env() == frozenset()


def test_bind_host_is_an_accepted_host() -> None:
    policy = AccessPolicy(TOKEN, bind_host="192.168.1.5", allowed_origins=frozenset(), port=9)

    def headers_of(values: dict[str, str]) -> HeaderValues:
        return lambda name: [v for k, v in values.items() if k.lower() == name.lower()]

    assert policy.check("/", headers_of({"Host": "192.168.1.5:9", **bearer()})).allowed
    assert not policy.check("/", headers_of({"Host": "192.168.1.6:9", **bearer()})).allowed
    assert not policy.check("/", headers_of({"Host": "127.0.0.1:notaport", **bearer()})).allowed


def test_cli_ready_line_has_the_token_and_the_endpoints_require_it(toast_app_dir: Path) -> None:
    env = {**os.environ, "MAA_SIM_TOKEN": "cli-token-123"}
    command = [
        sys.executable, "-m", "maa_sim.cli", "run", "--package", str(toast_app_dir), "--mode", "lockstep",
        "--paused", "--rosbridge-port", "0", "--viser-port", "0", "--status-json",
    ]  # fmt: skip
    process = subprocess.Popen(
        command, stdout=subprocess.PIPE, stderr=subprocess.DEVNULL, text=True, cwd=SIM_SERVER, env=env
    )
    try:
        assert process.stdout is not None
        ready = json.loads(process.stdout.readline())
        assert ready["event"] == "ready" and ready["token"] == "cli-token-123"
        assert "token" not in ready["rosbridge"]  # the machine-readable URLs stay plain
        client = Client(ready["rosbridge"], token=ready["token"])
        assert client.call("/sim/get_status")["result"] is True
        client.close()
        with pytest.raises(InvalidStatus):
            connect(ready["rosbridge"], open_timeout=30)
        viser_port = int(ready["viser"].rsplit(":", 1)[1])
        assert send(viser_port, "/", {"Host": host(viser_port)}).status == 403
        assert send(viser_port, "/", {"Host": host(viser_port), **bearer("cli-token-123")}).status == 200
    finally:
        process.terminate()
        process.wait(timeout=60)
