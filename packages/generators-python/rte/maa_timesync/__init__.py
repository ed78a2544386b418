"""maa_timesync: the python-timesync platform's run-time environment.

A generated timesync build describes every component type as a subclass of
:class:`AtomicComponent` (wrapping a ``maa_behavior`` class) or :class:`ComposedComponent`
(subcomponents and connectors). :class:`System` instantiates the hierarchy in one process and
schedules it with MontiArc's stream semantics (SEMANTICS.md of the montiarc-io suite):
time slices ended by ticks, sync and event-driven components, delayed ports.
"""

from maa_timesync.modes import ModeComponent
from maa_timesync.runtime import (
    TICK,
    AtomicComponent,
    ComponentType,
    ComposedComponent,
    Instance,
    System,
    Tick,
)
from maa_timesync.streams import decode_item, decode_value, encode_item, run_streams

__all__ = [
    "TICK",
    "AtomicComponent",
    "ComponentType",
    "ComposedComponent",
    "Instance",
    "ModeComponent",
    "System",
    "Tick",
    "decode_item",
    "decode_value",
    "encode_item",
    "run_streams",
]
