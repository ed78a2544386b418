"""Component toast.ToasterController for the python-timesync platform (generated)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import ClassVar

from maa_timesync import AtomicComponent
from toast.toaster_controller_behavior import ToasterControllerBehavior
from toast.types.types import ToasterCmd


class ToasterController(AtomicComponent):
    """Component type toast.ToasterController (generated)."""

    NAME = "toast.ToasterController"
    IN_PORTS = ("cmd",)
    OUT_PORTS = ("leverDown",)
    PORT_TYPES: ClassVar[Mapping[str, object]] = {"cmd": ToasterCmd, "leverDown": "boolean"}
    PARAMETERS = ("maxSlices",)
    BEHAVIOR = ToasterControllerBehavior

    @classmethod
    def defaults(cls, params: Mapping[str, object]) -> dict[str, object]:
        params = dict(params)
        params.setdefault("maxSlices", 600)
        return params
