"""Stream tests of components (``*.stream`` files next to the models), run by ``maa-gen test``.

A file tests one component type of the application::

    // comments run to the end of the line
    component toast.Controller(threshold = 25);

    test "a plate starts loading the bread" {
      distance  = 100 Tk 20 Tk;       // input stream of a port: messages and ticks (Tk)
      armStatus = Tk Tk;
      toaster  == STOP Tk Tk;         // expected output stream of a port (compared item by item)
      arm      == NONE Tk LOAD_BREAD Tk;
      status   ~= IDLE BUSY;           // ~= compares the messages only (ticks ignored)
      state    == Loading;            // optional: the automaton's state at the end
      ticks 2;                        // optional: run exactly 2 slices, in ports padded with ticks
                                      // (default: as many slices as the inputs supply)
    }

Values are integers, floats, ``true``/``false``, ``"strings"``, and enum constants (``STOP`` or
``ToasterCmd.STOP``, resolved by the port's type). Out ports the test does not mention are not
compared. ``python -m maa_timesync.streamtest BUILD_DIR FILE...`` prints one line per test and a
JSON summary with ``--json``; the exit code is 1 when a test fails.
"""

from __future__ import annotations

import enum
import importlib
import json
import re
import sys
from collections.abc import Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from maa_timesync.runtime import TICK, ComponentType, System

_TOKEN = re.compile(r'\s*(?:(//[^\n]*)|("(?:\\.|[^"\\])*")|(==|~=|[=;(){},])|([-+]?\d+\.\d*(?:[eE][-+]?\d+)?|[-+]?\d+)|([A-Za-z_][\w.]*))')


class StreamTestError(Exception):
    """A malformed stream test file."""


@dataclass
class StreamTest:
    name: str
    inputs: dict[str, list[object]] = field(default_factory=dict)
    expected: dict[str, list[object]] = field(default_factory=dict)
    values_only: set[str] = field(default_factory=set)
    state: str | None = None
    ticks: int | None = None
    line: int = 0


@dataclass
class StreamTestFile:
    path: str
    component: str
    params: dict[str, object]
    tests: list[StreamTest]


@dataclass(frozen=True)
class _Name:
    text: str


def _tokens(text: str) -> list[tuple[str, object, int]]:
    out: list[tuple[str, object, int]] = []
    pos = 0
    while pos < len(text):
        if text[pos:].strip() == "":
            break
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos:
            line = text.count("\n", 0, pos) + 1
            raise StreamTestError(f"line {line}: unexpected {text[pos:pos + 10]!r}")
        line = text.count("\n", 0, m.start()) + 1
        pos = m.end()
        comment, string, punct, number, name = m.groups()
        if comment is not None:
            continue
        if string is not None:
            out.append(("value", json.loads(string), line))
        elif punct is not None:
            out.append((punct, punct, line))
        elif number is not None:
            out.append(("value", float(number) if "." in number or "e" in number.lower() else int(number), line))
        elif name is not None:
            if name in ("true", "false"):
                out.append(("value", name == "true", line))
            elif name in ("component", "test", "state", "ticks", "Tk"):
                out.append((name, name, line))
            else:
                out.append(("name", name, line))
    return out


def parse(text: str, path: str = "<stream>") -> StreamTestFile:
    """Parses a ``.stream`` file."""
    toks = _tokens(text)
    i = 0

    def peek() -> str:
        return toks[i][0] if i < len(toks) else "<end>"

    def take(kind: str) -> Any:
        nonlocal i
        if peek() != kind:
            line = toks[i][2] if i < len(toks) else (toks[-1][2] if toks else 1)
            raise StreamTestError(f"{path}:{line}: expected {kind}, found {peek()}")
        i += 1
        return toks[i - 1][1]

    def value() -> object:
        if peek() == "value":
            return take("value")
        return _Name(str(take("name")))

    take("component")
    component = str(take("name"))
    params: dict[str, object] = {}
    if peek() == "(":
        take("(")
        while peek() != ")":
            pname = str(take("name"))
            take("=")
            params[pname] = value()
            if peek() == ",":
                take(",")
        take(")")
    take(";")
    tests: list[StreamTest] = []
    while peek() == "test":
        line = toks[i][2]
        take("test")
        test = StreamTest(name=str(take("value")), line=line)
        take("{")
        while peek() != "}":
            if peek() == "state":
                take("state")
                take("==")
                test.state = str(take("name"))
            elif peek() == "ticks":
                take("ticks")
                test.ticks = int(take("value"))  # type: ignore[arg-type]
            else:
                port = str(take("name"))
                target = test.expected if peek() in ("==", "~=") else test.inputs
                if peek() == "~=":
                    test.values_only.add(port)
                take(peek() if peek() in ("==", "~=", "=") else "=")
                items: list[object] = []
                while peek() not in (";", "<end>"):
                    items.append(TICK if peek() == "Tk" and take("Tk") else value())
                target[port] = items
            take(";")
        take("}")
        tests.append(test)
    if peek() != "<end>":
        raise StreamTestError(f"{path}:{toks[i][2]}: expected test, found {peek()}")
    return StreamTestFile(path, component, params, tests)


def _resolve(item: object, port_type: object, enums: Mapping[str, type[enum.Enum]]) -> object:
    if not isinstance(item, _Name):
        if isinstance(item, int) and not isinstance(item, bool) and port_type in ("float", "double", "Float", "Double"):
            return float(item)
        return item
    type_name, _, literal = item.text.rpartition(".")
    cls = port_type if isinstance(port_type, type) and issubclass(port_type, enum.Enum) else enums.get(type_name.split(".")[-1])
    if cls is None or literal not in cls.__members__:
        raise StreamTestError(f"unknown value {item.text}")
    return cls[literal]


def _show(items: Sequence[object]) -> str:
    return " ".join("Tk" if x is TICK else x.name if isinstance(x, enum.Enum) else json.dumps(x) for x in items) or "(empty)"


def run_test(ctype: type[ComponentType], params: Mapping[str, object], test: StreamTest, enums: Mapping[str, type[enum.Enum]]) -> list[str]:
    """Runs one test; returns the differences (empty when it passes)."""
    system = System(ctype, params)
    system.init()
    for port, items in test.inputs.items():
        if port not in ctype.IN_PORTS:
            return [f"{ctype.NAME} has no in port '{port}'"]
        for item in items:
            system.receive(port, item if item is TICK else _resolve(item, ctype.PORT_TYPES.get(port), enums))
    if test.ticks is not None:
        # `ticks N`: every in port gets ticks up to N slices (messages stop after the given ones).
        for port in ctype.IN_PORTS:
            given = sum(1 for x in test.inputs.get(port, ()) if x is TICK)
            for _ in range(test.ticks - given):
                system.receive(port, TICK)
    system.run(test.ticks)
    problems: list[str] = []
    for port, items in test.expected.items():
        if port not in ctype.OUT_PORTS:
            problems.append(f"{ctype.NAME} has no out port '{port}'")
            continue
        want = [x if x is TICK else _resolve(x, ctype.PORT_TYPES.get(port), enums) for x in items]
        got = system.outputs[port]
        if port in test.values_only:
            want = [x for x in want if x is not TICK]
            got = [x for x in got if x is not TICK]
        same = len(want) == len(got) and all(w is g if w is TICK or g is TICK else (type(w) is type(g) and w == g) for w, g in zip(want, got, strict=False))
        if not same:
            problems.append(f"{port}: expected {_show(want)}; got {_show(got)}")
    if test.state is not None:
        behavior = system.top.behavior
        state = behavior.current_state() if behavior is not None else None
        if state != test.state:
            problems.append(f"state: expected {test.state}; got {state}")
    return problems


def run_files(build: Path, files: Sequence[Path]) -> list[dict[str, Any]]:
    """Runs the stream test files against a generated build; one result per test."""
    if str(build) not in sys.path:
        sys.path.insert(0, str(build))
    app = importlib.import_module("maa_app")
    components: Mapping[str, type[ComponentType]] = app.COMPONENTS
    enums: Mapping[str, type[enum.Enum]] = getattr(app, "ENUMS", {})
    results: list[dict[str, Any]] = []
    for file in files:
        try:
            parsed = parse(file.read_text(encoding="utf-8"), str(file))
            ctype = components.get(parsed.component)
            if ctype is None:
                raise StreamTestError(f"{file}: the application has no component type {parsed.component}")
            params = {k: _resolve(v, None, enums) for k, v in parsed.params.items()}
        except (StreamTestError, OSError) as exc:
            results.append({"file": str(file), "test": None, "line": 0, "passed": False, "problems": [str(exc)]})
            continue
        for test in parsed.tests:
            try:
                problems = run_test(ctype, params, test, enums)
            except Exception as exc:  # the component crashed
                problems = [f"{type(exc).__name__}: {exc}"]
            results.append({"file": str(file), "test": test.name, "line": test.line, "passed": not problems, "problems": problems})
    return results


def main(argv: Sequence[str] | None = None) -> int:
    args = list(sys.argv[1:] if argv is None else argv)
    as_json = "--json" in args
    args = [a for a in args if a != "--json"]
    if len(args) < 1:
        print("usage: python -m maa_timesync.streamtest BUILD_DIR [--json] FILE...", file=sys.stderr)
        return 2
    results = run_files(Path(args[0]), [Path(a) for a in args[1:]])
    if as_json:
        print(json.dumps(results, indent=1))
    else:
        for r in results:
            mark = "ok  " if r["passed"] else "FAIL"
            print(f"{mark} {r['file']}:{r['line']} {r['test'] or ''}")
            for p in r["problems"]:
                print(f"       {p}")
    passed = sum(1 for r in results if r["passed"])
    print(f"stream tests: {passed} passed, {len(results) - passed} failed", file=sys.stderr)
    return 0 if passed == len(results) else 1


if __name__ == "__main__":
    raise SystemExit(main())
