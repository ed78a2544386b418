"""Runs the montiarc-io conformance cases against generated python-timesync builds.

``python io_cases.py SUITE_DIR CACHE_DIR [REPORT]``: for every component of the suite, runs its
cases in a fresh interpreter on the build that ``scripts/generate-io-cases.mjs`` wrote to
``CACHE_DIR/builds/<component>/timesync``, compares every expected output stream item by item
(value types respected) and writes a JSON report: per case ``passed`` and a reason.
"""

from __future__ import annotations

import json
import math
import struct
import subprocess
import sys
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


def same_item(expected: Mapping[str, Any], actual: Mapping[str, Any]) -> bool:
    """Equality of two stream items with Java's ``equals`` (an int 1 is not a long 1)."""
    if expected.get("tick") or actual.get("tick"):
        return bool(expected.get("tick")) and bool(actual.get("tick"))
    if "char" in expected or "char" in actual:
        return expected.get("char") == actual.get("char")
    if expected.get("type") != actual.get("type"):
        return False
    a, b = expected.get("msg"), actual.get("msg")
    kind = expected.get("type")
    if kind in ("float", "double"):
        a, b = _num(a), _num(b)
        if a is None or b is None:
            return False
        return _same_number(_f32(float(a)), _f32(float(b))) if kind == "float" else _same_number(float(a), float(b))
    return type(a) is type(b) and a == b


def compare(case: Mapping[str, Any], outputs: Mapping[str, list[dict[str, Any]]]) -> str | None:
    """None when the case passes, else the first difference."""
    modes = case.get("compare") or {}
    for port, expected in case["expected"].items():
        actual = outputs.get(port)
        if actual is None:
            return f"no out port {port}"
        if modes.get(port) == "values_only":
            expected = [i for i in expected if not i.get("tick")]
            actual = [i for i in actual if not i.get("tick")]
        if len(expected) != len(actual) or not all(same_item(e, a) for e, a in zip(expected, actual, strict=True)):
            return f"{port}: expected {json.dumps(expected)} got {json.dumps(actual)}"
    return None


def run_component(build: Path, cases: list[dict[str, Any]]) -> list[dict[str, Any]]:
    """Runs inside a fresh interpreter whose sys.path holds the build."""
    import importlib

    sys.path.insert(0, str(build))
    from maa_timesync import run_streams  # type: ignore[import-not-found]

    app = importlib.import_module("maa_app")
    results = []
    for case in cases:
        try:
            spec = dict(case)
            spec["observe"] = [p for p in case["expected"] if "." in p]
            out = run_streams(app.ROOT, spec, getattr(app, "ENUMS", None))
            reason = compare(case, out["outputs"])
        except Exception as exc:  # a crash is a failed case
            reason = f"{type(exc).__name__}: {exc}"
        results.append({"id": case["id"], "passed": reason is None, "reason": reason})
    return results


def main(argv: list[str]) -> int:
    if len(argv) >= 2 and argv[0] == "--component":
        build = Path(argv[1])
        cases = json.loads(sys.stdin.read())
        print(json.dumps(run_component(build, cases)))
        return 0
    suite, cache = Path(argv[0]), Path(argv[1])
    report_file = Path(argv[2]) if len(argv) > 2 else cache / "report.json"
    cases = json.loads((suite / "io_cases.json").read_text(encoding="utf-8"))["cases"]
    generation = json.loads((cache / "generation.json").read_text(encoding="utf-8"))
    by_component: dict[str, list[dict[str, Any]]] = {}
    for case in cases:
        by_component.setdefault(case["component"], []).append(case)
    results: list[dict[str, Any]] = []
    for component, group in sorted(by_component.items()):
        gen = generation.get(component)
        if not gen or not gen["ok"]:
            why = "; ".join(gen["errors"]) if gen else "not generated"
            results += [{"id": c["id"], "passed": False, "reason": f"generation failed: {why}"} for c in group]
            continue
        proc = subprocess.run(
            [sys.executable, __file__, "--component", gen["dir"]],
            input=json.dumps(group),
            capture_output=True,
            text=True,
            timeout=120,
        )
        if proc.returncode != 0:
            results += [{"id": c["id"], "passed": False, "reason": f"runner crashed: {proc.stderr[-500:]}"} for c in group]
            continue
        results += json.loads(proc.stdout)
    report_file.write_text(json.dumps(results, indent=1) + "\n", encoding="utf-8")
    passed = sum(1 for r in results if r["passed"])
    print(f"montiarc-io: {passed}/{len(results)} cases passed")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
