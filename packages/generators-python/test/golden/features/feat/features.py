"""Component feat.Features for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from feat.counter import Counter
from feat.lamp import Lamp
from feat.types.data import Mode, Reading
from maa_timesync import ComponentType, ComposedComponent


class Features(ComposedComponent):
    """Component type feat.Features (generated)."""

    NAME = "feat.Features"
    IN_PORTS = ("inc", "mode", "press", "level")
    OUT_PORTS = ("total", "otherTotal", "text", "otherText", "log", "brightness", "reading", "pair")
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"inc": "int", "mode": Mode, "press": "boolean", "level": "int", "total": "int", "otherTotal": "int", "text": "String", "otherText": "String", "log": "String", "brightness": "int", "reading": Reading, "pair": "Pair<Integer>"}
    PARAMETERS = ("factor",)
    CONNECTORS = (
        ("", "inc", (("counter", "inc"), ("other", "inc"))),
        ("", "mode", (("counter", "mode"), ("other", "mode"))),
        ("", "press", (("lamp", "press"),)),
        ("", "level", (("lamp", "level"),)),
        ("counter", "total", (("", "total"),)),
        ("counter", "text", (("", "text"),)),
        ("counter", "reading", (("", "reading"),)),
        ("counter", "pair", (("", "pair"),)),
        ("other", "total", (("", "otherTotal"),)),
        ("other", "text", (("", "otherText"),)),
        ("lamp", "log", (("", "log"),)),
        ("lamp", "brightness", (("", "brightness"),)),
    )

    @classmethod
    def defaults(cls, params: Mapping[str, object]) -> dict[str, object]:
        params = dict(params)
        params.setdefault("factor", 3)
        return params

    @classmethod
    def subcomponents(cls, params: Mapping[str, object]) -> list[tuple[str, type[ComponentType], dict[str, object]]]:
        return [
            ("counter", Counter, {"step": params["factor"]}),
            ("lamp", Lamp, {}),
            ("other", Counter, {"step": 1}),
        ]
