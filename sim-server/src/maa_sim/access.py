"""Who may use maa-sim's network endpoints (rosbridge and viser): Host, Origin and a secret token.

A web page the user visits can reach 127.0.0.1 too: cross-site (WebSockets have no same-origin
rule, only an `Origin` header) or by DNS rebinding (its own host name resolving to 127.0.0.1, so
the browser sends that name as `Host`). So a request must pass, in this order:

- Host: the host name of its `Host` header is a loopback name or the address maa-sim was told
  to bind (`--host`); anything else is a rebound name.
- Origin: when present, the server's own origin (`http://<Host>`) or one listed in
  `MAA_SIM_ALLOWED_ORIGINS` (comma separated). Non-browser clients (the IDE backend's proxy)
  send none.
- Token: `Authorization: Bearer <token>`, `?token=<token>` in the URL, or the cookie
  `maa-sim-token-<port>` (set when a person opens the printed viser URL with `?token=`, because
  viser's page opens its WebSocket at the page's URL without the query). The token comes from
  `MAA_SIM_TOKEN` or is made per start.

Every refusal is HTTP 403 with the reason (WebSocket handshakes included).
"""

from __future__ import annotations

import hmac
import os
import re
import secrets
from collections.abc import Callable, Iterable
from dataclasses import dataclass, field
from http.cookies import CookieError, SimpleCookie
from urllib.parse import parse_qs, urlsplit

#: The environment variable with the token (unset or empty: maa-sim makes one).
TOKEN_ENV = "MAA_SIM_TOKEN"
#: The environment variable with further allowed origins (comma separated).
ORIGINS_ENV = "MAA_SIM_ALLOWED_ORIGINS"
LOOPBACK_NAMES = frozenset({"127.0.0.1", "localhost", "::1"})
#: A token goes into URLs and cookies unescaped, so it is made of URL-safe characters.
_TOKEN_RE = re.compile(r"^[A-Za-z0-9._~-]+$")

#: A header lookup: every value of a header (case-insensitive name), in order.
HeaderValues = Callable[[str], list[str]]


def resolve_token(explicit: str | None = None) -> str:
    """The token: the one given, else `MAA_SIM_TOKEN`, else a new random one (256 bits).

    ValueError when a given token has characters a URL or a cookie would have to escape."""
    for candidate in (explicit, os.environ.get(TOKEN_ENV)):
        if candidate:  # an empty token would let `?token=` through: treated as unset
            if not _TOKEN_RE.match(candidate):
                raise ValueError(f"{TOKEN_ENV} may only contain letters, digits and . _ ~ -")
            return candidate
    return secrets.token_urlsafe(32)


def allowed_origins_from_env() -> frozenset[str]:
    text = os.environ.get(ORIGINS_ENV, "")
    return frozenset(_normalize_origin(part) for part in text.split(",") if part.strip())


def cookie_name(port: int) -> str:
    """Cookies are not kept apart by port, so the port is part of the name."""
    return f"maa-sim-token-{port}"


def _normalize_origin(origin: str) -> str:
    return origin.strip().rstrip("/").lower()


def _host_name(host_header: str) -> str | None:
    """`localhost:9090` -> `localhost`, `[::1]:9090` -> `::1`; None when it does not parse."""
    try:
        parts = urlsplit("//" + host_header.strip())
        parts.port  # noqa: B018 - raises ValueError on a malformed port
    except ValueError:
        return None
    return parts.hostname


def _same_token(given: str, token: str) -> bool:
    # bytes: compare_digest refuses non-ASCII str, and a client chooses what it sends
    return hmac.compare_digest(given.encode("utf-8", "surrogateescape"), token.encode("utf-8"))


@dataclass(frozen=True)
class Verdict:
    allowed: bool
    reason: str = ""
    #: the token came in the URL's query (a person opening a printed URL): worth a cookie
    token_in_query: bool = False


@dataclass
class AccessPolicy:
    """The rules of one endpoint; `port` is the port it listens on (known once bound)."""

    token: str
    bind_host: str = "127.0.0.1"
    allowed_origins: frozenset[str] = field(default_factory=allowed_origins_from_env)
    port: int = 0

    def check(self, target: str, headers: HeaderValues) -> Verdict:
        """Checks a request (its target `/path?query` and its headers); the first failing rule wins."""
        host_values = headers("Host")
        if len(host_values) != 1:
            return Verdict(False, "a request needs exactly one Host header")
        host = host_values[0]
        name = _host_name(host)
        if name is None or name.lower() not in self._host_names():
            return Verdict(False, f"Host {host[:100]!r} is not this server's address")
        origins = headers("Origin")
        if len(origins) > 1:
            return Verdict(False, "more than one Origin header")
        if origins and not self._origin_allowed(origins[0], host):
            return Verdict(False, f"Origin {origins[0][:100]!r} is not allowed")
        return self._check_token(target, headers)

    def _host_names(self) -> frozenset[str]:
        return LOOPBACK_NAMES | {self.bind_host.strip("[]").lower()}

    def _origin_allowed(self, origin: str, host: str) -> bool:
        normalized = _normalize_origin(origin)
        return normalized == f"http://{host.strip().lower()}" or normalized in self.allowed_origins

    def _check_token(self, target: str, headers: HeaderValues) -> Verdict:
        for value in headers("Authorization"):
            scheme, _, given = value.strip().partition(" ")
            if scheme.lower() == "bearer" and _same_token(given.strip(), self.token):
                return Verdict(True)
        query = parse_qs(urlsplit(target).query, keep_blank_values=True).get("token", [])
        if any(_same_token(given, self.token) for given in query):
            return Verdict(True, token_in_query=True)
        if any(_same_token(given, self.token) for given in self._cookie_tokens(headers("Cookie"))):
            return Verdict(True)
        return Verdict(False, "a valid token is needed (Authorization: Bearer, ?token= or the cookie)")

    def _cookie_tokens(self, cookie_headers: Iterable[str]) -> list[str]:
        name = cookie_name(self.port)
        found: list[str] = []
        for header in cookie_headers:
            jar = SimpleCookie()
            try:
                jar.load(header)
            except CookieError:
                continue  # a malformed cookie header is no token
            if name in jar:
                found.append(jar[name].value)
        return found

    def set_cookie_header(self) -> str:
        """The `Set-Cookie` value that keeps the token for this port's later requests."""
        return f"{cookie_name(self.port)}={self.token}; Path=/; HttpOnly; SameSite=Strict"
