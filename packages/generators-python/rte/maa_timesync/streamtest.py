"""Stream tests of components (``*.stream`` files next to the models), run by ``maa-gen test``.

A file tests one component type of the application::

    // comments run to the end of the line
    component toast.Controller(threshold = 25);   // generic types: component lib.Delay<Long>;

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

    test "steps in order" {           // with `run` statements the body runs in file order:
      state == Idle;                  // the state after init
      distance = 100 Tk;              // delivered now
      run;                            // run until quiescent (`run 3;`: exactly 3 slices)
      state == Loading;               // the state between the steps
      distance = 20 Tk;
      run;
      transform code = c -> (char) c.intValue();   // a Java lambda applied to each value of code
      code == 'L' 'D';                // compared after the transform (types kept: 'L' is a char)
      empty distance;                 // nothing left buffered on the in port after the run
    }

Values are integers (``5L`` a long), floats (``1.5f`` a float), ``'c'`` characters,
``true``/``false``, ``"strings"``, and enum constants (``STOP`` or ``ToasterCmd.STOP``, resolved
by the port's type). Out ports the test does not mention are not compared. The lambdas of
``transform`` are the Java subset of :mod:`maa_timesync.javalambda`; a lambda outside it is an
error of the file. ``python -m maa_timesync.streamtest BUILD_DIR FILE...`` prints one line per
test and a JSON summary with ``--json``; the exit code is 1 when a test fails. ``--states OUT.json``
also writes the state traces of the tests (format ``maa-stream-states/1``, for automaton coverage):
per test of a component with an automaton (or a mode automaton) its state path before the first
tick and after every tick (an event-driven component's also after each message that changed it).
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

from maa_timesync.javalambda import LambdaError, item_transform, unescape
from maa_timesync.runtime import TICK, ComponentType, System
from maa_timesync.streams import bind_type_args, current_state, encode_item

_TOKEN = re.compile(
    r'\s*(?:(//[^\n]*)|("(?:\\.|[^"\\])*")|(==|~=|[=;(){},<>!])'
    r"|([-+]?\d+\.\d*(?:[eE][-+]?\d+)?[fF]?|[-+]?\d+[lL]?)|('(?:\\.|[^'\\])')|([A-Za-z_][\w.]*))"
)
_TRANSFORM = re.compile(r"\s*([A-Za-z_]\w*)\s*=\s*([^;]*);")
_KEYWORDS = ("component", "test", "state", "ticks", "Tk")
#: Words that start a statement only where a port name cannot stand (ports may be called so).
_SOFT = ("run", "empty", "features")


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
    #: The body in file order: ``("input", port, items)``, ``("run", ticks or None)``, ``("state", name, line)``.
    actions: list[tuple[Any, ...]] = field(default_factory=list)
    #: Whether the body has ``run`` statements (then it runs in file order).
    sequenced: bool = False
    #: Java lambdas per out port, applied to each observed value before comparing.
    transforms: dict[str, str] = field(default_factory=dict)
    #: In ports on which nothing may be left buffered after the run.
    empty: list[str] = field(default_factory=list)


@dataclass
class StreamTestFile:
    path: str
    component: str
    params: dict[str, object]
    tests: list[StreamTest]
    type_args: list[str] = field(default_factory=list)
    #: The feature configuration the test expects the build to have (``features (f = true)``).
    features: dict[str, bool] = field(default_factory=dict)


@dataclass(frozen=True)
class _Name:
    text: str


@dataclass(frozen=True)
class _Char:
    """A ``'c'`` literal (the runtime carries a char as its code)."""

    text: str


@dataclass(frozen=True)
class _Typed:
    """A number literal with a Java type suffix (``5L``, ``1.5f``)."""

    value: int | float
    type: str


def _tokens(text: str) -> list[tuple[str, object, int]]:
    out: list[tuple[str, object, int]] = []
    pos = 0
    while pos < len(text):
        if text[pos:].strip() == "":
            break
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos:
            line = text.count("\n", 0, pos) + 1
            raise StreamTestError(f"line {line}: unexpected {text[pos : pos + 10]!r}")
        line = text.count("\n", 0, m.start(m.lastindex or 0)) + 1  # the token's line, not its leading blanks
        pos = m.end()
        comment, string, punct, number, char, name = m.groups()
        if comment is not None:
            continue
        if string is not None:
            out.append(("value", json.loads(string), line))
        elif punct is not None:
            out.append((punct, punct, line))
        elif number is not None:
            out.append(("value", _number(number), line))
        elif char is not None:
            body = char[1:-1]
            out.append(("value", _Char(unescape(body)), line))
        elif name is not None:
            if name in ("true", "false"):
                out.append(("value", name == "true", line))
            elif name == "transform" and (t := _TRANSFORM.match(text, pos)):
                # The lambda is Java, not stream syntax: the rest of the statement is taken as it is.
                out.append(("transform", (t.group(1), t.group(2).strip()), line))
                pos = t.end()
            elif name in _KEYWORDS:
                out.append((name, name, line))
            else:
                out.append(("name", name, line))
    return out


def _number(text: str) -> object:
    suffix = text[-1].lower()
    if suffix == "l":
        return _Typed(int(text[:-1]), "long")
    if suffix == "f":
        from maa_behavior import f32

        return _Typed(f32(float(text[:-1])), "float")
    return float(text) if "." in text or "e" in text.lower() else int(text)


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

    def _soft(word: str) -> bool:
        """A soft keyword: the word, not followed by what makes it a port's stream statement."""
        nxt = toks[i + 1][0] if i + 1 < len(toks) else "<end>"
        return peek() == "name" and toks[i][1] == word and nxt not in ("=", "==", "~=")

    take("component")
    component = str(take("name"))
    type_args: list[str] = []
    if peek() == "<":
        take("<")
        type_args.append(str(take("name")))
        while peek() == ",":
            take(",")
            type_args.append(str(take("name")))
        take(">")
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
    features: dict[str, bool] = {}
    if peek() == "name" and toks[i][1] == "features":
        i += 1
        take("(")
        while peek() != ")":
            fname = str(take("name"))
            take("=")
            selected = take("value")
            if not isinstance(selected, bool):
                raise StreamTestError(f"{path}:{toks[i - 1][2]}: feature {fname} must be true or false")
            features[fname] = selected
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
            stmt_line = toks[i][2] if i < len(toks) else 0
            if peek() == "state":
                take("state")
                take("==")
                test.state = str(take("name"))
                test.actions.append(("state", test.state, stmt_line))
            elif peek() == "ticks":
                take("ticks")
                test.ticks = int(take("value"))  # type: ignore[arg-type]
            elif _soft("run"):
                i += 1
                n = take("value") if peek() == "value" else None
                if n is not None and (not isinstance(n, int) or isinstance(n, bool) or n < 0):
                    raise StreamTestError(f"{path}:{stmt_line}: 'run' takes a number of slices")
                test.actions.append(("run", n))
                test.sequenced = True
            elif _soft("empty"):
                i += 1
                test.empty.append(str(take("name")))
                while peek() == ",":
                    take(",")
                    test.empty.append(str(take("name")))
            elif peek() == "transform":
                port, lam = take("transform")
                try:
                    item_transform(lam)
                except LambdaError as exc:
                    raise StreamTestError(f"{path}:{stmt_line}: transform {port}: {exc}") from None
                test.transforms[port] = lam
                continue  # the transform token includes its ';'
            else:
                port = str(take("name"))
                target = test.expected if peek() in ("==", "~=") else test.inputs
                if peek() == "~=":
                    test.values_only.add(port)
                take(peek() if peek() in ("==", "~=", "=") else "=")
                items: list[object] = []
                while peek() not in (";", "<end>"):
                    items.append(TICK if peek() == "Tk" and take("Tk") else value())
                if target is test.inputs:
                    test.actions.append(("input", port, items))
                    target.setdefault(port, []).extend(items)
                else:
                    target[port] = items
            take(";")
        take("}")
        if test.sequenced and test.ticks is not None:
            raise StreamTestError(f"{path}:{line}: 'ticks' and 'run' do not mix: give the slices to 'run N'")
        tests.append(test)
    if peek() != "<end>":
        raise StreamTestError(f"{path}:{toks[i][2]}: expected test, found {peek()}")
    return StreamTestFile(path, component, params, tests, type_args, features)


def _resolve(item: object, port_type: object, enums: Mapping[str, type[enum.Enum]]) -> object:
    if isinstance(item, _Char):
        return ord(item.text)
    if isinstance(item, _Typed):
        return item.value
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


def _literal_item(item: object, enums: Mapping[str, type[enum.Enum]]) -> dict[str, Any]:
    """An expected literal of a transformed port as a JSON stream item (its Java type from the literal)."""
    if item is TICK:
        return {"tick": True}
    if isinstance(item, _Char):
        return {"char": item.text}
    if isinstance(item, _Typed):
        return encode_item(item.value, item.type)
    if isinstance(item, _Name):
        return encode_item(_resolve(item, None, enums))
    return encode_item(item)


def _show_items(items: Sequence[Mapping[str, Any]]) -> str:
    def one(x: Mapping[str, Any]) -> str:
        if x.get("tick"):
            return "Tk"
        if "char" in x:
            return repr(x["char"])
        msg = x.get("msg")
        if isinstance(msg, Mapping) and "literal" in msg:
            return str(msg["literal"])
        text = json.dumps(msg)
        return text + {"long": "L", "float": "f"}.get(str(x.get("type")), "") if x.get("type") in ("long", "float") else text

    return " ".join(one(x) for x in items) or "(empty)"


def _same_items(want: Sequence[Mapping[str, Any]], got: Sequence[Mapping[str, Any]]) -> bool:
    return len(want) == len(got) and all(
        json.dumps(w, sort_keys=True) == json.dumps(g, sort_keys=True) for w, g in zip(want, got, strict=True)
    )


STATES_FORMAT = "maa-stream-states/1"


def state_path(system: System) -> str | None:
    """The state of the component under test as the live values show it: its automaton's state path
    (``Outer.Inner``) or the mode of a mode automaton; None for a component without an automaton."""
    behavior = system.top.behavior
    if behavior is not None:
        return behavior.state_path()
    mode = getattr(system.top, "mode", None)  # maa_timesync.modes.ModeInstance
    return mode if isinstance(mode, str) else None


def _trace_states(system: System, trace: list[str]) -> None:
    """Records the state path of the component under test into ``trace``: now (before the first tick),
    then after every step of it that took a tick (one slice) or changed its state."""
    first = state_path(system)
    if first is None:
        return
    trace.append(first)
    top = system.top
    ticks = top.buffers[""]  # the hidden tick port: every slice of the component takes one tick off it
    execute = top.execute

    def traced() -> None:
        before = len(ticks)
        execute()
        state = state_path(system) or ""
        if len(ticks) < before or state != trace[-1]:
            trace.append(state)

    top.execute = traced  # type: ignore[method-assign]


def run_test(
    ctype: type[ComponentType],
    params: Mapping[str, object],
    test: StreamTest,
    enums: Mapping[str, type[enum.Enum]],
    port_types: Mapping[str, object] | None = None,
    trace: list[str] | None = None,
) -> list[str]:
    """Runs one test; returns the differences (empty when it passes). With ``trace`` the state path of
    the component is appended to it before the first tick and after every tick (nothing without an automaton)."""
    types = dict(ctype.PORT_TYPES) if port_types is None else dict(port_types)
    problems: list[str] = []
    for port in test.inputs:
        if port not in ctype.IN_PORTS:
            return [f"{ctype.NAME} has no in port '{port}'"]
    for port in test.transforms:
        if port not in ctype.OUT_PORTS:
            problems.append(f"transform: {ctype.NAME} has no out port '{port}'")
    for port in test.empty:
        if port not in ctype.IN_PORTS:
            problems.append(f"empty: {ctype.NAME} has no in port '{port}'")
    if problems:
        return problems
    system = System(ctype, params)
    system.init()
    if trace is not None:
        _trace_states(system, trace)

    def feed(port: str, items: Sequence[object]) -> None:
        for item in items:
            system.receive(port, item if item is TICK else _resolve(item, types.get(port), enums))

    def check_state(name: str, line: int) -> None:
        state = current_state(system)
        if state != name:
            problems.append(f"state (line {line}): expected {name}; got {state}")

    if test.sequenced:
        for action in test.actions:
            if action[0] == "input":
                feed(action[1], action[2])
            elif action[0] == "run":
                system.run(action[1])
            else:
                check_state(action[1], action[2])
    else:
        for port, items in test.inputs.items():
            feed(port, items)
        if test.ticks is not None:
            # `ticks N`: every in port gets ticks up to N slices (messages stop after the given ones).
            for port in ctype.IN_PORTS:
                given = sum(1 for x in test.inputs.get(port, ()) if x is TICK)
                for _ in range(test.ticks - given):
                    system.receive(port, TICK)
        system.run(test.ticks)
        for action in test.actions:
            if action[0] == "state":
                check_state(action[1], action[2])
    for port, items in test.expected.items():
        if port not in ctype.OUT_PORTS:
            problems.append(f"{ctype.NAME} has no out port '{port}'")
            continue
        if port in test.transforms:
            port_type = types.get(port)
            fn = item_transform(test.transforms[port], port_type if isinstance(port_type, str) else None)
            want_items = [_literal_item(x, enums) for x in items]
            try:
                got_items = [fn(encode_item(v, port_type)) for v in system.outputs[port]]
            except LambdaError as exc:
                problems.append(f"{port}: transform failed: {exc}")
                continue
            if port in test.values_only:
                want_items = [x for x in want_items if not x.get("tick")]
                got_items = [x for x in got_items if not x.get("tick")]
            if not _same_items(want_items, got_items):
                problems.append(f"{port}: expected {_show_items(want_items)}; got {_show_items(got_items)}")
            continue
        want = [x if x is TICK else _resolve(x, types.get(port), enums) for x in items]
        got = system.outputs[port]
        if port in test.values_only:
            want = [x for x in want if x is not TICK]
            got = [x for x in got if x is not TICK]
        same = len(want) == len(got) and all(
            w is g if w is TICK or g is TICK else (type(w) is type(g) and w == g) for w, g in zip(want, got, strict=False)
        )
        if not same:
            problems.append(f"{port}: expected {_show(want)}; got {_show(got)}")
    for port in test.empty:
        left = list(system.top.buffers.get(port, ()))
        if left:
            problems.append(f"empty {port}: {len(left)} item(s) left buffered: {_show(left)}")
    return problems


def _in_configuration(
    components: Mapping[str, type[ComponentType]], ctype: type[ComponentType], name: str, features: Mapping[str, bool], file: Path
) -> type[ComponentType]:
    """The build of component type ``name`` in the feature configuration ``features``: the type itself,
    or one of its variants (``<name>__<suffix>``: instances of one type in different configurations)."""

    def differ(c: type[ComponentType]) -> dict[str, bool] | None:
        built = getattr(c, "FEATURES", None)
        return {k: v for k, v in features.items() if built.get(k) != v} if isinstance(built, Mapping) else None

    own = differ(ctype)
    if own is None:
        raise StreamTestError(f"{file}: the build of {ctype.NAME} does not record a feature configuration")
    if not own:
        return ctype
    for key in sorted(components):
        if key.startswith(f"{name}__") and differ(components[key]) == {}:
            return components[key]
    built = dict(getattr(ctype, "FEATURES", {}))
    raise StreamTestError(f"{file}: the build of {ctype.NAME} has another feature configuration than {own} (it has {built})")


def run_files(build: Path, files: Sequence[Path], traces: list[dict[str, Any]] | None = None) -> list[dict[str, Any]]:
    """Runs the stream test files against a generated build; one result per test. With ``traces`` the
    state trace of every test of a component with an automaton is appended to it (``maa-stream-states/1``)."""
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
            try:
                port_types = bind_type_args(ctype, parsed.type_args or None)
            except ValueError as exc:
                raise StreamTestError(f"{file}: {exc}") from None
            if not parsed.type_args and getattr(ctype, "TYPE_PARAMETERS", ()):
                raise StreamTestError(f"{file}: {ctype.NAME} is generic: give its type arguments, e.g. component {ctype.NAME}<Integer>;")
            if parsed.features:
                ctype = _in_configuration(components, ctype, parsed.component, parsed.features, file)
        except (StreamTestError, OSError) as exc:
            results.append({"file": str(file), "test": None, "line": 0, "passed": False, "problems": [str(exc)]})
            continue
        for test in parsed.tests:
            trace: list[str] = []
            try:
                problems = run_test(ctype, params, test, enums, port_types, trace)
            except Exception as exc:  # the component crashed
                problems = [f"{type(exc).__name__}: {exc}"]
            if traces is not None and trace:
                traces.append({"file": str(file), "line": test.line, "test": test.name, "component": parsed.component, "states": trace})
            results.append({"file": str(file), "test": test.name, "line": test.line, "passed": not problems, "problems": problems})
    return results


def _write_states(path: Path, traces: list[dict[str, Any]]) -> None:
    """Writes the state traces atomically (a temporary file renamed into place)."""
    part = path.with_name(f".{path.name}.part")
    part.write_text(json.dumps({"format": STATES_FORMAT, "tests": traces}, indent=1) + "\n", encoding="utf-8")
    part.replace(path)


def _options(args: list[str]) -> tuple[bool, Path | None, list[str]] | str:
    """``--json`` and ``--states FILE`` taken out of the arguments; a message when they are bad."""
    as_json = "--json" in args
    args = [a for a in args if a != "--json"]
    states: Path | None = None
    if "--states" in args:
        at = args.index("--states")
        if at + 1 >= len(args) or args[at + 1].startswith("--"):
            return "--states needs a file name"
        states = Path(args[at + 1])
        del args[at : at + 2]
    if len(args) < 1:
        return "usage: python -m maa_timesync.streamtest BUILD_DIR [--json] [--states OUT.json] FILE..."
    return as_json, states, args


def main(argv: Sequence[str] | None = None) -> int:
    options = _options(list(sys.argv[1:] if argv is None else argv))
    if isinstance(options, str):
        print(options, file=sys.stderr)
        return 2
    as_json, states, args = options
    traces: list[dict[str, Any]] | None = [] if states is not None else None
    results = run_files(Path(args[0]), [Path(a) for a in args[1:]], traces)
    if states is not None and traces is not None:
        try:
            _write_states(states, traces)
        except OSError as exc:
            print(f"cannot write the state traces {states}: {exc}", file=sys.stderr)
            return 2
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
