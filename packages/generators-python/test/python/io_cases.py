"""Runs the montiarc-io conformance cases against generated python-timesync builds.

``python io_cases.py SUITE_DIR CACHE_DIR [REPORT]``: for every component of the suite, runs its
cases in a process of its own (forked from this one) on the build that ``scripts/generate-io-cases.mjs`` wrote to
``CACHE_DIR/builds/<variant>/timesync`` (``generation.json`` maps each case to its build: one per
component and feature configuration), compares every expected output stream item by item (value
types respected, ``compare: values_only`` dropping ticks, ``observed_value_transform`` applied),
the state trace of ``kind: state_trace`` cases with ``expected_states``, and every
``extra_assertions`` entry, and writes a JSON report: per case ``passed`` and a reason. A field
or value form the harness does not know fails the case instead of being ignored.
"""

from __future__ import annotations

import json
import math
import os
import selectors
import struct
import sys
import time
import traceback
from collections.abc import Mapping
from pathlib import Path
from typing import Any


def _f32(x: float) -> float:
    if math.isnan(x) or math.isinf(x):
        return x
    result: float = struct.unpack("f", struct.pack("f", x))[0]
    return result


def _same_number(a: float, b: float) -> bool:
    if math.isnan(a) and math.isnan(b):
        return True
    return a == b and math.copysign(1.0, a) == math.copysign(1.0, b)


def _num(x: object) -> float | None:
    if isinstance(x, str):
        try:
            return float(x.replace("Infinity", "inf"))
        except ValueError:
            return None
    if isinstance(x, (int, float)) and not isinstance(x, bool):
        return float(x)
    return None


#: The case fields the harness reads; any other field fails the case (it might carry a condition).
KNOWN_FIELDS = frozenset(
    {
        "id",
        "test_file",
        "test_method",
        "invocation",
        "kind",
        "component",
        "model_files",
        "model_sources",
        "params",
        "features",
        "type_args",
        "inputs",
        "expected",
        "run_ticks",
        "steps",
        "test_line",
        "junit_args",
        "compare",
        "implicit_empty_inputs",
        "extra_assertions",
        "observed_value_transform",
        "expected_states",
        "port_accessors",
    }
)
CHARS = ("char", "Character")


def same_value(a: object, b: object) -> bool:
    """Equality of two JSON message values (maps unordered, objects by type and fields)."""
    if isinstance(a, Mapping) and isinstance(b, Mapping):
        if "map" in a or "map" in b:
            pa, pb = a.get("map"), b.get("map")
            if not isinstance(pa, list) or not isinstance(pb, list) or len(pa) != len(pb):
                return False
            return all(any(same_value(k1, k2) and same_value(v1, v2) for k2, v2 in pb) for k1, v1 in pa)
        if a.keys() != b.keys():
            return False
        return all(same_value(a[k], b[k]) for k in a)
    if isinstance(a, list) and isinstance(b, list):
        return len(a) == len(b) and all(same_value(x, y) for x, y in zip(a, b, strict=True))
    return type(a) is type(b) and a == b


def same_item(expected: Mapping[str, Any], actual: Mapping[str, Any]) -> bool:
    """Equality of two stream items with Java's ``equals`` (an int 1 is not a long 1)."""
    if expected.get("tick") or actual.get("tick"):
        return bool(expected.get("tick")) and bool(actual.get("tick"))
    if "char" in expected or "char" in actual:
        return expected.get("char") == actual.get("char")
    a, b = expected.get("msg"), actual.get("msg")
    if isinstance(a, Mapping) and "object" in a:
        # {"object": T, "fields": {...}} against the runtime's {"msg": fields, "class": T}.
        return str(a["object"]).rpartition(".")[2] == actual.get("class") and same_value(a.get("fields") or {}, b)
    if expected.get("type") != actual.get("type"):
        return False
    kind = expected.get("type")
    if kind in ("float", "double"):
        a, b = _num(a), _num(b)
        if a is None or b is None:
            return False
        return _same_number(_f32(float(a)), _f32(float(b))) if kind == "float" else _same_number(float(a), float(b))
    return same_value(a, b)


def char_items(items: list[dict[str, Any]], port_type: object) -> list[dict[str, Any]]:
    """On a ``char``/``Character`` port the suite may write a character as its code ``{"msg": 97}``."""
    if port_type not in CHARS:
        return items
    return [
        {"char": chr(i["msg"])} if isinstance(i.get("msg"), int) and not isinstance(i.get("msg"), bool) and "type" not in i else i
        for i in items
    ]


def compare(case: Mapping[str, Any], result: Mapping[str, Any], port_types: Mapping[str, object] | None = None) -> str | None:
    """None when the case passes (streams, state trace, extra assertions), else the first difference."""
    unknown = sorted(set(case) - KNOWN_FIELDS)
    if unknown:
        return f"unknown case field(s) {unknown}"
    kind = case.get("kind", "io")
    if kind not in ("io", "state_trace"):
        return f"unknown case kind {kind!r}"
    outputs: Mapping[str, list[dict[str, Any]]] = result["outputs"]
    modes = case.get("compare") or {}
    for port, mode in modes.items():
        if mode != "values_only":
            return f"unknown compare mode {mode!r} for {port}"
    transforms = case.get("observed_value_transform") or {}
    for port, expected in case["expected"].items():
        if port not in transforms:
            expected = char_items(expected, (port_types or {}).get(port))
        actual = outputs.get(port)
        if actual is None:
            return f"no out port {port}"
        if modes.get(port) == "values_only":
            expected = [i for i in expected if not i.get("tick")]
            actual = [i for i in actual if not i.get("tick")]
        if len(expected) != len(actual) or not all(same_item(e, a) for e, a in zip(expected, actual, strict=True)):
            return f"{port}: expected {json.dumps(expected)} got {json.dumps(actual)}"
    if kind == "state_trace":
        want = case.get("expected_states")
        if not isinstance(want, list):
            return "a state_trace case without expected_states"
        if list(result.get("state_trace") or []) != want:
            return f"states: expected {want} got {result.get('state_trace')}"
    elif case.get("expected_states") is not None:
        return "expected_states in a case that is not a state_trace"
    for check in result.get("assertions") or []:
        if not check["holds"]:
            return f"{check['assert']} {check['port']}: {check['detail']}"
    return None


def run_component(build: Path, cases: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Runs inside a process of the build's own (see run_isolated), with the build on sys.path."""
    import importlib

    sys.path.insert(0, str(build))
    from maa_timesync import run_streams  # type: ignore[import-not-found]
    from maa_timesync.streams import bind_type_args  # type: ignore[import-not-found]

    app = importlib.import_module("maa_app")
    results = []
    for case in cases:
        try:
            spec = dict(case)
            spec["observe"] = [p for p in case["expected"] if "." in p]
            out = run_streams(app.ROOT, spec, getattr(app, "ENUMS", None))
            reason = compare(case, out, bind_type_args(app.ROOT, case.get("type_args")))
        except Exception as exc:  # a crash is a failed case
            reason = f"{type(exc).__name__}: {exc}"
        results.append({"id": case["id"], "passed": reason is None, "reason": reason})
    return results


#: The standard library the run-time environment imports: imported here once, before the forks,
#: so no build's process imports it again (the build's own modules are imported in its process).
_RTE_STDLIB = ("collections", "dataclasses", "decimal", "enum", "importlib", "re", "typing")
TIMEOUT_S = 120


def run_isolated(build: str, cases: list[dict[str, Any]]) -> list[dict[str, Any]] | str:
    """The results of ``run_component`` in a child forked from this interpreter, or why it failed.

    Every build has its own ``maa_app`` and copy of the run-time environment under the same module
    names, so each runs in a process of its own, as in a fresh interpreter; a fork costs neither
    the interpreter's start nor the standard library's imports. The child answers through a pipe:
    its result or its traceback as JSON.
    """
    read_end, write_end = os.pipe()
    pid = os.fork()
    if pid == 0:  # the child: never returns
        os.close(read_end)
        code = 0
        try:
            answer: dict[str, Any] = {"results": run_component(Path(build), cases)}
        except BaseException:  # a crash of the runner is reported, whatever it is
            answer, code = {"crash": traceback.format_exc()[-500:]}, 1
        with os.fdopen(write_end, "wb") as out:
            out.write(json.dumps(answer).encode("utf-8"))
        sys.stdout.flush()
        sys.stderr.flush()
        os._exit(code)
    os.close(write_end)
    data = _read_all(read_end, pid)
    _, status = os.waitpid(pid, 0)
    if data is None:
        return f"timed out after {TIMEOUT_S} s"
    try:
        answer = json.loads(data)
    except ValueError:
        return f"exit status {os.waitstatus_to_exitcode(status)}, no answer"
    return answer["results"] if "results" in answer else str(answer["crash"])


def _read_all(fd: int, pid: int) -> bytes | None:
    """Everything the child writes to ``fd`` until it closes it; None (and the child killed) after the timeout."""
    chunks: list[bytes] = []
    deadline = time.monotonic() + TIMEOUT_S
    with selectors.DefaultSelector() as sel:
        sel.register(fd, selectors.EVENT_READ)
        while True:
            left = deadline - time.monotonic()
            if left <= 0 or not sel.select(left):
                os.kill(pid, 9)
                os.close(fd)
                return None
            chunk = os.read(fd, 1 << 16)
            if not chunk:
                os.close(fd)
                return b"".join(chunks)
            chunks.append(chunk)


def main(argv: list[str]) -> int:
    for name in _RTE_STDLIB:
        __import__(name)
    suite, cache = Path(argv[0]), Path(argv[1])
    report_file = Path(argv[2]) if len(argv) > 2 else cache / "report.json"
    cases = json.loads((suite / "io_cases.json").read_text(encoding="utf-8"))["cases"]
    generation = json.loads((cache / "generation.json").read_text(encoding="utf-8"))
    by_build: dict[str, list[dict[str, Any]]] = {}
    for case in cases:
        by_build.setdefault(generation["cases"].get(case["id"], "?"), []).append(case)
    results: list[dict[str, Any]] = []
    for variant, group in sorted(by_build.items()):
        gen = generation["builds"].get(variant)
        if not gen or not gen["ok"]:
            why = "; ".join(gen["errors"]) if gen else "not generated"
            results += [{"id": c["id"], "passed": False, "reason": f"generation failed: {why}"} for c in group]
            continue
        outcome = run_isolated(gen["dir"], group)
        if isinstance(outcome, str):
            results += [{"id": c["id"], "passed": False, "reason": f"runner crashed: {outcome}"} for c in group]
            continue
        results += outcome
    report_file.write_text(json.dumps(results, indent=1) + "\n", encoding="utf-8")
    passed = sum(1 for r in results if r["passed"])
    print(f"{suite.name}: {passed}/{len(results)} cases passed")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
