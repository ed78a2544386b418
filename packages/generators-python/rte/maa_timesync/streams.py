"""The stream-test entry point: input streams per port (JSON) to output streams per port (JSON).

Items are ``{"msg": value}`` or ``{"tick": true}``; enum constants ``{"enum": T, "literal": L}``;
chars ``{"char": c}`` (on a ``char``/``Character`` port a ``{"msg": n}`` is the character with
code n); maps ``{"map": [[k, v], ...]}``; objects of the model's data types
``{"object": T, "fields": {...}}``; numbers of the Java types long, short, byte, float and double
carry a ``"type"``. A run description (the montiarc-io suite's case format)::

    {"params": {...}, "type_args": ["Integer"], "inputs": {"port": [items...]},
     "steps": [{"op": "init"}, {"op": "receive", "port": "i", "count": 2}, {"op": "run"},
               {"op": "observe_state"}],
     "run_ticks": null,
     "observed_value_transform": {"o": "c -> (char) c.intValue()"},
     "extra_assertions": [{"assert": "in_port_buffer_empty_after_run", "port": "i"}]}

``observe`` names further out ports of subcomponents to report (``"sub.port"``). Without
``steps``: init, every input stream in port order, run (``run_ticks`` slices or until
quiescent). ``type_args`` binds the type parameters of a generic component under test (a list in
the order of its ``TYPE_PARAMETERS``, or a mapping), which gives its ports their Java types.
``observed_value_transform`` applies a Java lambda (:mod:`maa_timesync.javalambda`) to each value
observed on a port. The result is ``{"outputs": {"port": [items...]}, "states": {...},
"state_trace": [state after each observe_state step], "assertions": [{"assert", "port", "holds",
"detail"}]}``; an unknown step or assertion is an error, never skipped.
"""

from __future__ import annotations

import dataclasses
import enum
import json
import math
import sys
from collections.abc import Mapping, Sequence
from typing import Any

from maa_behavior import f32
from maa_timesync.runtime import TICK, ComponentType, System

TYPED = {
    "long": "long",
    "Long": "long",
    "short": "short",
    "Short": "short",
    "byte": "byte",
    "Byte": "byte",
    "float": "float",
    "Float": "float",
    "double": "double",
    "Double": "double",
}


CHARS = ("char", "Character")


def _hashable(value: object) -> object:
    return tuple(value) if isinstance(value, list) else value


def _data_class(name: str) -> Any:
    """The generated class of a model data type by its (simple or qualified) name, among the loaded modules."""
    simple = name.rpartition(".")[2]
    for module in list(sys.modules.values()):
        mod_name = getattr(module, "__name__", "")
        if mod_name.startswith(("maa_", "_")):
            continue
        cls = getattr(module, simple, None)
        if isinstance(cls, type) and dataclasses.is_dataclass(cls):
            return cls
    raise ValueError(f"unknown data type {name}")


def decode_value(raw: object, kind: object = None, port_type: object = None, enums: Mapping[str, type[enum.Enum]] | None = None) -> object:
    """A JSON value (``{"enum": T, "literal": L}``, ``{"value": v, "type": t}``, ``"NaN"``...) to a Python value."""
    if isinstance(raw, Mapping):
        if "enum" in raw:
            cls = port_type if isinstance(port_type, type) and issubclass(port_type, enum.Enum) else (enums or {}).get(str(raw["enum"]))
            if cls is None:
                raise ValueError(f"unknown enum type {raw['enum']}")
            return cls[str(raw["literal"])]
        if "char" in raw:
            return ord(str(raw["char"]))
        if "map" in raw:
            return {_hashable(decode_value(k, None, None, enums)): decode_value(v, None, None, enums) for k, v in raw["map"]}
        if "object" in raw:
            cls = _data_class(str(raw["object"]))
            fields = raw.get("fields") or {}
            return cls(**{name: decode_value(v, None, None, enums) for name, v in fields.items()})
        if "value" in raw:
            return decode_value(raw["value"], raw.get("type"), port_type, enums)
        return {k: decode_value(v, None, None, enums) for k, v in raw.items()}
    if kind is None and port_type in CHARS and isinstance(raw, int) and not isinstance(raw, bool):
        return raw
    if isinstance(raw, list):
        return [decode_value(v, None, None, enums) for v in raw]
    if kind in ("float", "double") and raw is not None:
        number = float(raw) if not isinstance(raw, str) else float(raw.replace("Infinity", "inf"))
        return f32(number) if kind == "float" else number
    return raw


def decode_item(item: Mapping[str, Any], port_type: object = None, enums: Mapping[str, type[enum.Enum]] | None = None) -> object:
    """One JSON item to a stream item (a value or :data:`TICK`)."""
    if item.get("tick"):
        return TICK
    if "enum" in item or "char" in item:
        return decode_value(item, None, port_type, enums)
    if port_type in CHARS and "type" not in item and isinstance(item.get("msg"), int) and not isinstance(item.get("msg"), bool):
        return int(item["msg"])
    return decode_value(item.get("msg"), item.get("type"), port_type, enums)


def _float_json(value: float, single: bool) -> object:
    if math.isnan(value):
        return "NaN"
    if math.isinf(value):
        return "Infinity" if value > 0 else "-Infinity"
    if single:
        for digits in range(1, 10):
            text = f"{value:.{digits}g}"
            if f32(float(text)) == value:
                return float(text)
    return value


def encode_item(value: object, port_type: object = None) -> dict[str, Any]:
    """One stream item to JSON (the port's model type names the Java number type)."""
    if value is TICK:
        return {"tick": True}
    if isinstance(value, enum.Enum):
        return {"msg": {"enum": type(value).__name__, "literal": value.name}}
    if port_type in CHARS and isinstance(value, (int, str)) and not isinstance(value, bool):
        return {"char": chr(value) if isinstance(value, int) else value}
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {"msg": _plain(value), "class": type(value).__name__}
    if isinstance(value, dict):
        return {"msg": _plain(value)}
    if isinstance(port_type, str) and port_type in TYPED and isinstance(value, (int, float)) and not isinstance(value, bool):
        kind = TYPED[port_type]
        if kind in ("float", "double"):
            return {"msg": _float_json(float(value), kind == "float"), "type": kind}
        return {"msg": int(value), "type": kind}
    if isinstance(value, float):
        return {"msg": _float_json(value, False)}
    return {"msg": value}


def _plain(value: object) -> object:
    if isinstance(value, enum.Enum):
        return value.name
    if dataclasses.is_dataclass(value) and not isinstance(value, type):
        return {f.name: _plain(getattr(value, f.name)) for f in dataclasses.fields(value)}
    if isinstance(value, list):
        return [_plain(v) for v in value]
    if isinstance(value, dict):
        return {"map": [[_plain(k), _plain(v)] for k, v in value.items()]}
    return value


def bind_type_args(ctype: type[ComponentType], type_args: object) -> dict[str, object]:
    """The port types of a (generic) component with its type parameters bound to ``type_args``."""
    params: tuple[str, ...] = getattr(ctype, "TYPE_PARAMETERS", ())  # generated for generic component types only
    if type_args is None:
        binding: dict[str, object] = {}
    elif isinstance(type_args, Mapping):
        binding = {str(k): v for k, v in type_args.items()}
    elif isinstance(type_args, (list, tuple)):
        if len(type_args) != len(params):
            raise ValueError(f"{ctype.NAME} has {len(params)} type parameter(s) {list(params)}, the test gives {len(type_args)}")
        binding = dict(zip(params, type_args, strict=True))
    else:
        raise ValueError(f"type_args must be a list or a mapping, not {type_args!r}")
    unknown = [k for k in binding if k not in params]
    if unknown:
        raise ValueError(f"{ctype.NAME} has no type parameter {', '.join(unknown)}")

    def bound(t: object) -> object:
        if isinstance(t, str):
            name = t.removesuffix("[]")
            if name in binding:
                arg = binding[name]
                return f"{arg}[]" if t.endswith("[]") and isinstance(arg, str) else arg
        return t

    return {port: bound(t) for port, t in ctype.PORT_TYPES.items()}


def current_state(system: System) -> str | None:
    """The top component's current automaton state: its behavior's state, or the mode of a mode automaton."""
    behavior = system.top.behavior
    if behavior is not None:
        return behavior.current_state()
    mode = getattr(system.top, "mode", None)  # maa_timesync.modes.ModeInstance
    return mode if isinstance(mode, str) else None


def _assertion(system: System, spec: Mapping[str, Any]) -> dict[str, Any]:
    kind = spec.get("assert")
    port = str(spec.get("port", ""))
    if kind == "in_port_buffer_empty_after_run":
        if port not in system.top.ctype.IN_PORTS:
            raise ValueError(f"{system.top.ctype.NAME} has no in port '{port}'")
        left = list(system.top.buffers.get(port, ()))
        detail = None if not left else f"{len(left)} item(s) left buffered on {port}: {[encode_item(x) for x in left]}"
        return {"assert": kind, "port": port, "holds": not left, "detail": detail}
    raise ValueError(f"unknown extra assertion {kind!r}")


def run_streams(
    ctype: type[ComponentType],
    spec: Mapping[str, Any],
    enums: Mapping[str, type[enum.Enum]] | None = None,
) -> dict[str, Any]:
    """Runs a component on input streams and returns its output streams (JSON-ready)."""
    from maa_timesync.javalambda import item_transform

    port_types = bind_type_args(ctype, spec.get("type_args"))
    transforms = {
        port: item_transform(str(text), port_types.get(port) if isinstance(port_types.get(port), str) else None)  # type: ignore[arg-type]
        for port, text in (spec.get("observed_value_transform") or {}).items()
    }
    params = {name: decode_value(raw, None, None, enums) for name, raw in (spec.get("params") or {}).items()}
    system = System(ctype, params)
    inputs: Mapping[str, Sequence[Mapping[str, Any]]] = spec.get("inputs") or {}
    pending = {port: list(items) for port, items in inputs.items()}
    for port, items in pending.items():
        if port not in ctype.IN_PORTS and items:
            raise ValueError(f"{ctype.NAME} has no in port '{port}'")
    observed: dict[str, tuple[list[object], object]] = {}
    for name in spec.get("observe") or []:
        path, _, port = str(name).rpartition(".")
        if not path:
            continue
        inst = next((i for i in system.instances if ".".join(i.path) == path), None)
        if inst is None or port not in inst.ctype.OUT_PORTS:
            raise ValueError(f"no out port {name}")
        stream: list[object] = []
        inst.observers[port] = stream
        observed[name] = (stream, inst.ctype.PORT_TYPES.get(port))
    state_trace: list[str | None] = []
    steps = spec.get("steps")
    if steps is None:
        steps = [{"op": "init"}] + [{"op": "receive", "port": p, "count": len(v)} for p, v in pending.items()]
        steps.append({"op": "run", "ticks": spec.get("run_ticks")} if spec.get("run_ticks") is not None else {"op": "run"})
    for step in steps:
        op = step["op"]
        if op == "init":
            system.init()
        elif op == "receive":
            port = str(step["port"])
            count = int(step.get("count", len(pending.get(port, []))))
            for raw in pending[port][:count]:
                system.receive(port, decode_item(raw, port_types.get(port), enums))
            del pending[port][:count]
        elif op == "run":
            ticks = step.get("ticks")
            system.run(int(ticks) if ticks is not None else None)
        elif op == "observe_state":
            state_trace.append(current_state(system))
        else:
            raise ValueError(f"unknown step {op}")
    assertions = [_assertion(system, a) for a in spec.get("extra_assertions") or []]
    outputs = {port: [encode_item(v, port_types.get(port)) for v in items] for port, items in system.outputs.items()}
    for name, (stream, port_type) in observed.items():
        outputs[name] = [encode_item(v, port_type) for v in stream]
    for port, transform in transforms.items():
        if port not in outputs:
            raise ValueError(f"observed_value_transform names no observed port '{port}'")
        outputs[port] = [transform(item) for item in outputs[port]]
    states = {".".join(i.path): i.behavior.current_state() for i in system.instances if i.behavior is not None}
    return {"outputs": outputs, "states": states, "state_trace": state_trace, "assertions": assertions}


def main(argv: Sequence[str] | None = None) -> int:
    """``python -m maa_timesync.streams module:Class [spec.json]``: reads the spec (or stdin), prints the result."""
    import importlib

    args = list(sys.argv[1:] if argv is None else argv)
    if not args:
        print("usage: python -m maa_timesync.streams module:Class [spec.json]", file=sys.stderr)
        return 2
    module_name, _, class_name = args[0].partition(":")
    module = importlib.import_module(module_name)
    ctype = getattr(module, class_name)
    text = open(args[1], encoding="utf-8").read() if len(args) > 1 else sys.stdin.read()
    enums = getattr(importlib.import_module("maa_app"), "ENUMS", None) if _has_app() else None
    print(json.dumps(run_streams(ctype, json.loads(text), enums)))
    return 0


def _has_app() -> bool:
    import importlib.util

    return importlib.util.find_spec("maa_app") is not None


if __name__ == "__main__":
    raise SystemExit(main())
