"""The scheduler's bookkeeping of ticks (maa_timesync.runtime): a sync instance is ready exactly when
every in-port buffer holds a tick, as a scan of the buffers says, after any mix of messages, ticks,
several slices buffered ahead, and slices taken off; the values each slice yields stay the same."""

from __future__ import annotations

import random
from collections.abc import Mapping

from maa_behavior import Behavior
from maa_timesync import TICK, AtomicComponent, ComposedComponent, System


class SumBehavior(Behavior):
    TIMING = "sync"
    IN_PORTS = ("a", "b", "c")
    OUT_PORTS = ("o",)

    def __init__(self, emit: object, params: Mapping[str, object] | None = None) -> None:
        super().__init__(emit, params)  # type: ignore[arg-type]
        self.seen: list[dict[str, object]] = []

    def step(self, inputs: Mapping[str, object]) -> None:
        self.seen.append(dict(inputs))
        self._emit("o", sum(v for v in inputs.values() if isinstance(v, int)))


class Sum(AtomicComponent):
    NAME = "t.Sum"
    IN_PORTS = ("a", "b", "c")
    OUT_PORTS = ("o",)
    PORT_TYPES = {"a": "int", "b": "int", "c": "int", "o": "int"}
    BEHAVIOR = SumBehavior


class Top(ComposedComponent):
    NAME = "t.Top"
    IN_PORTS = ("a", "b", "c")
    OUT_PORTS = ("o",)
    CONNECTORS = (
        ("", "a", (("s", "a"),)),
        ("", "b", (("s", "b"),)),
        ("", "c", (("s", "c"),)),
        ("s", "o", (("", "o"),)),
    )

    @classmethod
    def subcomponents(cls, params: Mapping[str, object]) -> list[tuple[str, type, dict[str, object]]]:
        del params
        return [("s", Sum, {})]


def scanned_ready(buffers: Mapping[str, object]) -> bool:
    """The definition the counters replace: every buffer holds a tick."""
    return all(any(x is TICK for x in buf) for buf in buffers.values())  # type: ignore[attr-defined]


def expected_slices(fed: dict[str, list[object]]) -> list[dict[str, object]]:
    """The last message of every port per slice complete on every buffer (a reference model)."""
    per_port: dict[str, list[object]] = {}
    for port, items in fed.items():
        slices: list[object] = []
        last: object = None
        for item in items:
            if item is TICK:
                slices.append(last)
                last = None
            else:
                last = item
        per_port[port] = slices
    complete = min(len(s) for s in per_port.values())
    return [{p: per_port[p][i] for p in ("a", "b", "c")} for i in range(complete)]


def test_ready_counts_agree_with_a_scan_of_the_buffers_on_random_streams() -> None:
    rng = random.Random(7)
    slices_run = 0
    for _case in range(200):
        system = System(Top)
        system.init()
        inst = next(i for i in system.instances if i.path == ("s",))
        # the sum's buffers: its three ports and the tick port "" its parent's slices arrive on
        fed: dict[str, list[object]] = {"a": [], "b": [], "c": [], "": []}
        for _event in range(rng.randrange(1, 60)):
            port = rng.choice(("a", "b", "c", ""))
            item: object = TICK if port == "" or rng.random() < 0.4 else rng.randrange(100)
            fed[port].append(item)
            inst.deliver(port, item)
            assert inst.ready() == scanned_ready(inst.buffers)
            if rng.random() < 0.3:
                while inst.ready():  # takes the complete slices off
                    inst.execute()
                    assert inst.ready() == scanned_ready(inst.buffers)
        while inst.ready():
            inst.execute()
        assert not scanned_ready(inst.buffers)
        assert inst.behavior is not None
        seen = inst.behavior.seen  # type: ignore[attr-defined]
        assert seen == expected_slices(fed)
        slices_run += len(seen)
    assert slices_run > 200  # the random streams did complete slices
