"""Java lambdas over stream values (``observed_value_transform`` of the montiarc-io cases, ``transform``
of ``.stream`` files), translated into Python functions over JSON stream items.

A transform such as ``c -> (char) c.intValue()`` is parsed into a small expression tree and
evaluated with Java's rules: the value keeps its Java type (``int``, ``long``, ``short``,
``byte``, ``char``, ``float``, ``double``, ``boolean``, ``String``, an enum), binary numeric
promotion, 32/64-bit wrap-around of integer arithmetic, integer division truncating toward zero,
narrowing casts (``(char) 97`` is ``'a'``, ``(byte) 200`` is ``-56``, ``(int) 2.9`` is ``2``).

The supported Java subset: a lambda ``x -> e``, ``(x) -> e`` or ``(Type x) -> e`` whose body is an
expression of the parameter, literals (``1``, ``1L``, ``1.5``, ``1.5f``, ``'a'``, ``"s"``,
``true``/``false``), parentheses, casts to the primitive types and their boxes, the unboxing and
conversion methods (``intValue()``, ``longValue()``, ``shortValue()``, ``byteValue()``,
``floatValue()``, ``doubleValue()``, ``charValue()``, ``booleanValue()``), ``toString()``,
``name()`` of enum constants, ``length()`` of strings, the static factories ``Integer.valueOf``,
``Long.valueOf``, ``Short.valueOf``, ``Byte.valueOf``, ``Float.valueOf``, ``Double.valueOf``,
``Character.valueOf``, ``Boolean.valueOf`` and ``String.valueOf``, ``Math.abs``, unary ``-``,
``+`` and ``!``, ``* / % + -`` (``+`` concatenates when one side is a ``String``), comparisons,
``== !=``, ``&& ||`` and ``?:``. Anything else is a :class:`LambdaError` when the lambda is
compiled, not when it runs.
"""

from __future__ import annotations

import math
import re
import struct
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

#: Java type names (boxes included) to the primitive type the value has.
PRIMITIVE = {
    "int": "int",
    "Integer": "int",
    "long": "long",
    "Long": "long",
    "short": "short",
    "Short": "short",
    "byte": "byte",
    "Byte": "byte",
    "char": "char",
    "Character": "char",
    "float": "float",
    "Float": "float",
    "double": "double",
    "Double": "double",
    "boolean": "boolean",
    "Boolean": "boolean",
    "String": "String",
}
_INTEGRAL = {"byte": 8, "short": 16, "char": 16, "int": 32, "long": 64}
_NUMERIC = ("byte", "short", "char", "int", "long", "float", "double")
_CONVERSIONS = {
    "intValue": "int",
    "longValue": "long",
    "shortValue": "short",
    "byteValue": "byte",
    "floatValue": "float",
    "doubleValue": "double",
    "charValue": "char",
    "booleanValue": "boolean",
}


class LambdaError(ValueError):
    """A lambda outside the supported subset, or one that fails on a value."""


@dataclass(frozen=True)
class JValue:
    """A Java value: its type (a primitive name, ``String``, or ``enum:T``) and a Python value
    (integral types and ``char`` as ints, ``float``/``double`` as floats)."""

    type: str
    value: Any


def _f32(x: float) -> float:
    if math.isnan(x) or math.isinf(x):
        return x
    try:
        result: float = struct.unpack("f", struct.pack("f", x))[0]
    except OverflowError:
        return math.copysign(math.inf, x)
    return result


def _wrap(n: int, bits: int, unsigned: bool = False) -> int:
    n &= (1 << bits) - 1
    if not unsigned and n >= 1 << (bits - 1):
        n -= 1 << bits
    return n


def convert(v: JValue, target: str) -> JValue:
    """A Java cast (or the unboxing conversion method) of ``v`` to the primitive ``target``."""
    if v.type == target:
        return v
    if target == "boolean" or v.type == "boolean":
        raise LambdaError(f"cannot convert {v.type} to {target}")
    if target == "String":
        return JValue("String", java_string(v))
    if v.type not in _NUMERIC:
        raise LambdaError(f"cannot convert {v.type} to {target}")
    if target in ("float", "double"):
        x = float(v.value)
        return JValue(target, _f32(x) if target == "float" else x)
    if target not in _INTEGRAL:
        raise LambdaError(f"cannot convert to {target}")
    if v.type in ("float", "double"):
        x = float(v.value)
        if math.isnan(x):
            n = 0
        else:
            bits = 64 if target == "long" else 32
            lo, hi = -(1 << (bits - 1)), (1 << (bits - 1)) - 1
            n = hi if x >= hi else lo if x <= lo else int(x)
            if target in ("long", "int"):
                return JValue(target, n)
        return JValue(target, _wrap(n, _INTEGRAL[target], target == "char"))
    return JValue(target, _wrap(int(v.value), _INTEGRAL[target], target == "char"))


def _float_text(x: float, single: bool) -> str:
    if math.isnan(x):
        return "NaN"
    if math.isinf(x):
        return "Infinity" if x > 0 else "-Infinity"
    if single:
        for digits in range(1, 10):
            text = f"{x:.{digits}g}"
            if _f32(float(text)) == x:
                x = float(text)
                break
    text = repr(x)
    if "e" in text:
        mantissa, _, exp = text.partition("e")
        if "." not in mantissa:
            mantissa += ".0"
        return f"{mantissa}E{int(exp)}"
    return text


def java_string(v: JValue) -> str:
    """``String.valueOf(v)``."""
    if v.type == "String":
        return str(v.value)
    if v.type == "char":
        return chr(int(v.value))
    if v.type == "boolean":
        return "true" if v.value else "false"
    if v.type in ("float", "double"):
        return _float_text(float(v.value), v.type == "float")
    return str(v.value)


# -- JSON stream items ----------------------------------------------------------------------------


def from_item(item: Mapping[str, Any], port_type: str | None = None) -> JValue:
    """A JSON stream item (``{"msg": v}``, ``{"msg": v, "type": t}``, ``{"char": c}``, an enum) as a Java value."""
    if "char" in item:
        return JValue("char", ord(str(item["char"])))
    msg = item.get("msg")
    if isinstance(msg, Mapping) and "enum" in msg:
        return JValue(f"enum:{msg['enum']}", str(msg["literal"]))
    if "enum" in item:
        return JValue(f"enum:{item['enum']}", str(item["literal"]))
    kind = item.get("type") or (PRIMITIVE.get(port_type or "") if port_type else None)
    if isinstance(msg, bool):
        return JValue("boolean", msg)
    if kind in ("float", "double"):
        x = float(str(msg).replace("Infinity", "inf")) if isinstance(msg, str) else float(msg)
        return JValue(str(kind), x)
    if isinstance(msg, str):
        if kind == "char" and len(msg) == 1:
            return JValue("char", ord(msg))
        return JValue("String", msg)
    if isinstance(msg, int):
        if kind == "char":
            return JValue("char", msg)
        return JValue(str(kind) if kind in _INTEGRAL else "int", msg)
    if isinstance(msg, float):
        return JValue("double", msg)
    raise LambdaError(f"a transform cannot take the value {msg!r}")


def to_item(v: JValue) -> dict[str, Any]:
    """A Java value as a JSON stream item (the form of the suite's ``expected`` streams)."""
    if v.type == "char":
        return {"char": chr(int(v.value))}
    if v.type.startswith("enum:"):
        return {"msg": {"enum": v.type[5:], "literal": v.value}}
    if v.type in ("float", "double"):
        x = float(v.value)
        out: object = "NaN" if math.isnan(x) else ("Infinity" if x > 0 else "-Infinity") if math.isinf(x) else x
        return {"msg": out, "type": v.type}
    if v.type in ("long", "short", "byte"):
        return {"msg": int(v.value), "type": v.type}
    return {"msg": v.value}


# -- parsing ---------------------------------------------------------------------------------------

_TOKEN = re.compile(
    r"\s*(?:(?P<num>(?:\d+\.\d*|\.\d+|\d+)(?:[eE][-+]?\d+)?[fFdDlL]?)"
    r"|(?P<chr>'(?:\\.|[^'\\])')|(?P<str>\"(?:\\.|[^\"\\])*\")"
    r"|(?P<op>->|==|!=|<=|>=|&&|\|\||[-+*/%()<>!?:.,])|(?P<name>[A-Za-z_$][\w$]*))"
)
_ESCAPES = {"n": "\n", "t": "\t", "r": "\r", "b": "\b", "f": "\f", "0": "\0", "'": "'", '"': '"', "\\": "\\"}

Node = tuple[Any, ...]


def unescape(body: str) -> str:
    """Java's escapes in a char or string literal's body."""
    return re.sub(r"\\(.)", lambda m: _ESCAPES.get(m.group(1), m.group(1)), body)


def _lex(text: str) -> list[tuple[str, str]]:
    out: list[tuple[str, str]] = []
    pos = 0
    while text[pos:].strip():
        m = _TOKEN.match(text, pos)
        if not m or m.end() == pos:
            raise LambdaError(f"unexpected {text[pos:].strip()[:10]!r} in {text!r}")
        kind = m.lastgroup or ""
        out.append((kind, m.group(kind)))
        pos = m.end()
    return out


class _Parser:
    def __init__(self, text: str) -> None:
        self.text = text
        self.toks = _lex(text)
        self.i = 0

    def peek(self, k: int = 0) -> str:
        return self.toks[self.i + k][1] if self.i + k < len(self.toks) else ""

    def kind(self, k: int = 0) -> str:
        return self.toks[self.i + k][0] if self.i + k < len(self.toks) else ""

    def take(self, text: str | None = None) -> str:
        if self.i >= len(self.toks) or (text is not None and self.peek() != text):
            raise LambdaError(f"expected {text or 'more'} in {self.text!r}, found {self.peek() or 'the end'}")
        self.i += 1
        return self.toks[self.i - 1][1]

    def lambda_(self) -> tuple[str, Node]:
        if self.peek() == "(":
            self.take("(")
            first = self.take()
            if self.peek() != ")":
                if first not in PRIMITIVE:
                    raise LambdaError(f"unsupported parameter type {first} in {self.text!r}")
                first = self.take()
            self.take(")")
            param = first
        else:
            param = self.take()
        if not re.fullmatch(r"[A-Za-z_$][\w$]*", param):
            raise LambdaError(f"not a lambda parameter: {param!r} in {self.text!r}")
        self.take("->")
        body = self.expr()
        if self.i != len(self.toks):
            raise LambdaError(f"unexpected {self.peek()!r} in {self.text!r}")
        return param, body

    def expr(self) -> Node:
        cond = self.binary(0)
        if self.peek() == "?":
            self.take("?")
            then = self.expr()
            self.take(":")
            return ("?", cond, then, self.expr())
        return cond

    _LEVELS = (("||",), ("&&",), ("==", "!="), ("<", ">", "<=", ">="), ("+", "-"), ("*", "/", "%"))

    def binary(self, level: int) -> Node:
        if level == len(self._LEVELS):
            return self.unary()
        left = self.binary(level + 1)
        while self.kind() == "op" and self.peek() in self._LEVELS[level]:
            op = self.take()
            left = ("bin", op, left, self.binary(level + 1))
        return left

    def unary(self) -> Node:
        if self.peek() in ("-", "+", "!"):
            return ("un", self.take(), self.unary())
        if self.peek() == "(" and self.kind(1) == "name" and self.peek(1) in PRIMITIVE and self.peek(2) == ")":
            self.take("(")
            target = PRIMITIVE[self.take()]
            self.take(")")
            return ("cast", target, self.unary())
        return self.postfix()

    def postfix(self) -> Node:
        node = self.primary()
        while self.peek() == ".":
            self.take(".")
            name = self.take()
            self.take("(")
            args: list[Node] = []
            while self.peek() != ")":
                args.append(self.expr())
                if self.peek() == ",":
                    self.take(",")
            self.take(")")
            node = ("call", node, name, tuple(args))
        return node

    def primary(self) -> Node:
        kind, text = self.kind(), self.peek()
        if kind == "num":
            self.take()
            return ("lit", _number(text))
        if kind == "chr":
            self.take()
            return ("lit", JValue("char", ord(unescape(text[1:-1]))))
        if kind == "str":
            self.take()
            return ("lit", JValue("String", unescape(text[1:-1])))
        if text in ("true", "false"):
            self.take()
            return ("lit", JValue("boolean", text == "true"))
        if text == "(":
            self.take("(")
            inner = self.expr()
            self.take(")")
            return inner
        if kind == "name":
            self.take()
            if text in ("Integer", "Long", "Short", "Byte", "Float", "Double", "Character", "Boolean", "String", "Math"):
                return ("class", text)
            return ("var", text)
        raise LambdaError(f"unexpected {text or 'end'} in {self.text!r}")


def _number(text: str) -> JValue:
    suffix = text[-1].lower()
    body = text[:-1] if suffix in "fdl" else text
    if suffix == "l":
        return JValue("long", _wrap(int(body), 64))
    if suffix == "f":
        return JValue("float", _f32(float(body)))
    if suffix == "d" or any(c in body for c in ".eE"):
        return JValue("double", float(body))
    n = int(body)
    if n > 2**31 - 1:
        raise LambdaError(f"integer literal out of range: {text}")
    return JValue("int", n)


# -- evaluation ------------------------------------------------------------------------------------


def _promote(a: JValue, b: JValue) -> str:
    for t in ("double", "float", "long"):
        if t in (a.type, b.type):
            return t
    return "int"


def _arith(op: str, a: JValue, b: JValue) -> JValue:
    if op == "+" and "String" in (a.type, b.type):
        return JValue("String", java_string(a) + java_string(b))
    if a.type not in _NUMERIC or b.type not in _NUMERIC:
        raise LambdaError(f"operator {op} on {a.type} and {b.type}")
    t = _promote(a, b)
    x, y = convert(a, t).value, convert(b, t).value
    if t in ("float", "double"):
        if op == "+":
            r = x + y
        elif op == "-":
            r = x - y
        elif op == "*":
            r = x * y
        elif op == "/":
            r = x / y if y != 0 else (math.nan if x == 0 or math.isnan(x) else math.copysign(math.inf, x) * math.copysign(1.0, y))
        else:
            r = math.fmod(x, y) if y != 0 else math.nan
        return JValue(t, _f32(r) if t == "float" else r)
    if op in ("/", "%") and y == 0:
        raise LambdaError("ArithmeticException: / by zero")
    if op == "+":
        n = x + y
    elif op == "-":
        n = x - y
    elif op == "*":
        n = x * y
    elif op == "/":
        n = abs(x) // abs(y) * (1 if (x >= 0) == (y >= 0) else -1)
    else:
        n = x - (abs(x) // abs(y) * (1 if (x >= 0) == (y >= 0) else -1)) * y
    return JValue(t, _wrap(n, _INTEGRAL[t]))


def _compare(op: str, a: JValue, b: JValue) -> JValue:
    if op in ("==", "!=") and (a.type not in _NUMERIC or b.type not in _NUMERIC):
        same = a.type == b.type and a.value == b.value
        return JValue("boolean", same if op == "==" else not same)
    if a.type not in _NUMERIC or b.type not in _NUMERIC:
        raise LambdaError(f"operator {op} on {a.type} and {b.type}")
    t = _promote(a, b)
    x, y = convert(a, t).value, convert(b, t).value
    result = {"==": x == y, "!=": x != y, "<": x < y, ">": x > y, "<=": x <= y, ">=": x >= y}[op]
    return JValue("boolean", result)


def _boolean(v: JValue) -> bool:
    if v.type != "boolean":
        raise LambdaError(f"a {v.type} is not a boolean")
    return bool(v.value)


_FACTORIES = {
    "Integer": "int",
    "Long": "long",
    "Short": "short",
    "Byte": "byte",
    "Float": "float",
    "Double": "double",
    "Character": "char",
    "Boolean": "boolean",
    "String": "String",
}


def _call(target: Node, name: str, args: list[JValue], env: Mapping[str, JValue]) -> JValue:
    if target[0] == "class":
        cls = target[1]
        if cls == "Math" and name == "abs" and len(args) == 1 and args[0].type in _NUMERIC:
            v = convert(args[0], _promote(args[0], JValue("int", 0)))
            if v.type in _INTEGRAL:
                return JValue(v.type, _wrap(abs(v.value), _INTEGRAL[v.type]))
            return JValue(v.type, abs(v.value))
        if name == "valueOf" and len(args) == 1 and cls in _FACTORIES:
            want = _FACTORIES[cls]
            if want == "String":
                return JValue("String", java_string(args[0]))
            if args[0].type != want and not (want not in ("boolean", "char") and args[0].type in _NUMERIC and _widens(args[0].type, want)):
                raise LambdaError(f"{cls}.valueOf({args[0].type})")
            return convert(args[0], want)
        raise LambdaError(f"unsupported method {cls}.{name}")
    receiver = _eval(target, env)
    if name in _CONVERSIONS and not args:
        want = _CONVERSIONS[name]
        if receiver.type in ("boolean", "char") or want in ("boolean", "char"):
            if receiver.type != want:
                raise LambdaError(f"{receiver.type} has no method {name}()")
            return receiver
        if receiver.type not in _NUMERIC:
            raise LambdaError(f"{receiver.type} has no method {name}()")
        return convert(receiver, want)
    if name == "toString" and not args:
        return JValue("String", java_string(receiver) if not receiver.type.startswith("enum:") else str(receiver.value))
    if name == "name" and not args and receiver.type.startswith("enum:"):
        return JValue("String", str(receiver.value))
    if name == "length" and not args and receiver.type == "String":
        return JValue("int", len(str(receiver.value)))
    if name == "equals" and len(args) == 1:
        return JValue("boolean", receiver.type == args[0].type and receiver.value == args[0].value)
    raise LambdaError(f"{receiver.type} has no supported method {name}")


def _widens(source: str, target: str) -> bool:
    order = ("byte", "short", "int", "long", "float", "double")
    if source == "char":
        return target in ("int", "long", "float", "double")
    return source in order and target in order and order.index(source) <= order.index(target)


def _eval(node: Node, env: Mapping[str, JValue]) -> JValue:
    tag = node[0]
    if tag == "lit":
        return node[1]  # type: ignore[no-any-return]
    if tag == "var":
        if node[1] not in env:
            raise LambdaError(f"unknown name {node[1]}")
        return env[node[1]]
    if tag == "cast":
        return convert(_eval(node[2], env), node[1])
    if tag == "un":
        v = _eval(node[2], env)
        if node[1] == "!":
            return JValue("boolean", not _boolean(v))
        if v.type not in _NUMERIC:
            raise LambdaError(f"unary {node[1]} on {v.type}")
        v = convert(v, _promote(v, JValue("int", 0)))
        if node[1] == "+":
            return v
        return _arith("-", JValue(v.type, 0), v) if v.type in _INTEGRAL else JValue(v.type, -v.value)
    if tag == "bin":
        op = node[1]
        if op in ("&&", "||"):
            left = _boolean(_eval(node[2], env))
            if (op == "&&" and not left) or (op == "||" and left):
                return JValue("boolean", left)
            return JValue("boolean", _boolean(_eval(node[3], env)))
        a, b = _eval(node[2], env), _eval(node[3], env)
        if op in ("==", "!=", "<", ">", "<=", ">="):
            return _compare(op, a, b)
        return _arith(op, a, b)
    if tag == "?":
        return _eval(node[2] if _boolean(_eval(node[1], env)) else node[3], env)
    if tag == "call":
        return _call(node[1], node[2], [_eval(a, env) for a in node[3]], env)
    if tag == "class":
        raise LambdaError(f"{node[1]} is a class, not a value")
    raise LambdaError(f"unsupported expression {tag}")


def _check_names(node: Node, param: str, text: str) -> None:
    if node[0] == "var" and node[1] != param:
        raise LambdaError(f"unknown name {node[1]} in {text!r} (only the parameter {param} is in scope)")
    if node[0] == "call" and node[1][0] == "class":
        if not ((node[1][1] == "Math" and node[2] == "abs") or (node[2] == "valueOf" and node[1][1] in _FACTORIES)):
            raise LambdaError(f"unsupported method {node[1][1]}.{node[2]} in {text!r}")
    elif node[0] == "call" and node[2] not in (*_CONVERSIONS, "toString", "name", "length", "equals"):
        raise LambdaError(f"unsupported method {node[2]} in {text!r}")
    for child in node[1:]:
        if isinstance(child, tuple) and child and isinstance(child[0], str):
            _check_names(child, param, text)
        elif isinstance(child, tuple):
            for c in child:
                if isinstance(c, tuple) and c and isinstance(c[0], str):
                    _check_names(c, param, text)


def compile_lambda(text: str) -> Callable[[JValue], JValue]:
    """Compiles a Java lambda of one parameter; :class:`LambdaError` when it is outside the subset."""
    param, body = _Parser(text).lambda_()
    _check_names(body, param, text)

    def apply(value: JValue) -> JValue:
        return _eval(body, {param: value})

    return apply


def item_transform(text: str, port_type: str | None = None) -> Callable[[Mapping[str, Any]], dict[str, Any]]:
    """A lambda as a function over JSON stream items (ticks pass unchanged)."""
    fn = compile_lambda(text)

    def apply(item: Mapping[str, Any]) -> dict[str, Any]:
        if item.get("tick"):
            return {"tick": True}
        return to_item(fn(from_item(item, port_type)))

    return apply


__all__ = ["JValue", "LambdaError", "compile_lambda", "convert", "from_item", "item_transform", "java_string", "to_item", "unescape"]
