"""Checks of the wire contracts maa-sim reads (@maa/protocol; schemas in the generated `protocol.py`).

A problem is told as `<where>: <JSON pointer>: <message>`, the message being the schema's
`errorMessage` for the field (`{key}` replaced by the field's name) when it has one.
"""

from __future__ import annotations

from typing import Any

from jsonschema import Draft202012Validator, ValidationError
from jsonschema.exceptions import best_match


def validator(schema: dict[str, Any]) -> Draft202012Validator:
    Draft202012Validator.check_schema(schema)
    return Draft202012Validator(schema)


def _missing(error: ValidationError) -> str | None:
    """The property a `required` error misses."""
    if error.validator != "required" or not isinstance(error.instance, dict):
        return None
    return next((str(k) for k in error.validator_value if k not in error.instance), None)


def _pointer(error: ValidationError) -> str:
    path = [*error.absolute_path, *([m] if (m := _missing(error)) else [])]
    return "".join(f"/{str(p).replace('~', '~0').replace('/', '~1')}" for p in path)


def _message(error: ValidationError) -> str:
    """The schema's `errorMessage` (`{key}`: the field's name), else the most specific inner message;
    a missing property is told by the property's own message."""
    schema = error.schema if isinstance(error.schema, dict) else {}
    missing = _missing(error)
    if missing is not None:
        field = schema.get("properties", {}).get(missing, {})
        custom = field.get("errorMessage") if isinstance(field, dict) else None
        return custom.replace("{key}", missing) if isinstance(custom, str) else f"{missing} is required"
    custom = schema.get("errorMessage")
    if isinstance(custom, str):
        key = str(error.absolute_path[-1]) if error.absolute_path else ""
        return custom.replace("{key}", key)
    if error.context:
        return _message(best_match(error.context))
    return str(error.message)


def problem(checker: Draft202012Validator, data: Any) -> str | None:
    """The first problem of `data` (by JSON pointer) as `<pointer>: <message>`, or None when it keeps the contract."""
    errors = sorted(checker.iter_errors(data), key=lambda e: [str(p) for p in e.absolute_path])
    if not errors:
        return None
    return f"{_pointer(errors[0]) or '/'}: {_message(errors[0])}"
