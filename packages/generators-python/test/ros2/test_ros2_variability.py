"""Variable architectures on ROS 2 for real: the generated nodes of a feature configuration run as
rclpy processes and behave as that configuration says.

- the variability fixture (lamp.Room) in the configurations ``dim = true`` (a doubler node feeds a
  dimmable lamp: brightness = level) and ``dim = false`` (no doubler, a plain lamp: 100 for any
  positive level);
- the variability-instances fixture (hall.Hall): instances of one type in different configurations,
  generated as variants of the type (``Lamp``, ``Lamp__no_dimmable``, ``Wing``, ``Wing__dimmed``),
  each node behaving as its own instance's configuration says.

The fixtures need no message package of their own (their ports are ``int``), so the generated
packages run from their folder (deployment.json's ``python_path``) without being built or installed.
The nodes are started and stopped by the mode tests' helpers (``probing``: deployed_nodes and a Probe).
"""

from __future__ import annotations

import json
import shutil
from collections.abc import Iterator
from pathlib import Path

import pytest
from ros2_support import PACKAGE_DIR
from test_ros2_modes import Probe, generate_package, probing

pytest.importorskip("rclpy")

FIXTURES = PACKAGE_DIR / "test" / "fixtures"
ROOM_APP = FIXTURES / "variability" / "Variability.arcapp"
HALL_APP = FIXTURES / "variability-instances" / "Instances.arcapp"


def room_package(dim: bool, out: Path) -> Path:
    """lamp.Room generated for rospython from a copy of the fixture whose application binds ``dim``."""
    copy = out / "model"
    shutil.copytree(ROOM_APP.parent, copy)
    app = copy / ROOM_APP.name
    text = app.read_text(encoding="utf-8")
    assert "lamp.Room(dim = true)" in text
    binding = f"lamp.Room(dim = {'true' if dim else 'false'})"
    app.write_text(text.replace("lamp.Room(dim = true)", binding), encoding="utf-8")
    return generate_package(app, out / "gen", "room")


@pytest.fixture(scope="module")
def dimmed_room(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return room_package(True, tmp_path_factory.mktemp("room-dimmed"))


@pytest.fixture(scope="module")
def plain_room(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return room_package(False, tmp_path_factory.mktemp("room-plain"))


@pytest.fixture(scope="module")
def hall(tmp_path_factory: pytest.TempPathFactory) -> Path:
    return generate_package(HALL_APP, tmp_path_factory.mktemp("hall"), "hall")


def node_names(package: Path) -> list[str]:
    data = json.loads((package / "deployment.json").read_text(encoding="utf-8"))
    return sorted(f"{n['namespace'].rstrip('/')}/{n['name']}" for n in data["nodes"])


@pytest.fixture()
def dimmed_probe(dimmed_room: Path, ros_domain: int, tmp_path: Path) -> Iterator[Probe]:
    del ros_domain
    with probing(dimmed_room, tmp_path, "/room/level", {"brightness": "/room/lamp/brightness"}, {}) as p:
        yield p


@pytest.fixture()
def plain_probe(plain_room: Path, ros_domain: int, tmp_path: Path) -> Iterator[Probe]:
    del ros_domain
    with probing(plain_room, tmp_path, "/room/level", {"brightness": "/room/lamp/brightness"}, {}) as p:
        yield p


HALL_OUTPUTS = {
    "a": "/hall/a/brightness",
    "b": "/hall/b/brightness",
    "c": "/hall/c/brightness",
    "w1": "/hall/w1/lamp/brightness",
    "w2": "/hall/w2/lamp/brightness",
}


@pytest.fixture()
def hall_probe(hall: Path, ros_domain: int, tmp_path: Path) -> Iterator[Probe]:
    del ros_domain
    with probing(hall, tmp_path, "/hall/level", HALL_OUTPUTS, {}) as p:
        yield p


def test_each_configuration_deploys_its_own_nodes(dimmed_room: Path, plain_room: Path, hall: Path) -> None:
    assert node_names(dimmed_room) == ["/room/doubler", "/room/lamp"]
    assert node_names(plain_room) == ["/room/lamp"]
    # two nodes named lamp, in the namespaces of their wings
    assert node_names(hall) == ["/hall/a", "/hall/b", "/hall/c", "/hall/w1/lamp", "/hall/w2/lamp"]


def test_the_dimmed_room_doubles_the_level_for_its_dimmable_lamp(dimmed_probe: Probe) -> None:
    probe = dimmed_probe
    # level 10 -> doubler 20 -> dimmable lamp 20 / 2
    probe.wait_for("brightness", 10, resend=10)
    since = probe.mark()
    probe.send(7)
    probe.wait_for("brightness", 7, since)
    since = probe.mark()
    probe.send(0)
    probe.wait_for("brightness", 0, since)


def test_the_plain_room_switches_its_lamp_fully_on(plain_probe: Probe) -> None:
    probe = plain_probe
    probe.wait_for("brightness", 100, resend=10)
    since = probe.mark()
    probe.send(0)
    probe.wait_for("brightness", 0, since)
    since = probe.mark()
    probe.send(7)
    probe.wait_for("brightness", 100, since)
    seen = probe.values("brightness")
    assert set(seen) <= {0, 100}, f"a plain lamp knows two brightnesses: {seen}"


def test_each_lamp_of_the_hall_behaves_as_its_instance_is_configured(hall_probe: Probe) -> None:
    probe = hall_probe
    # dimmable lamps (a, c, the lamp of wing w2) halve the level; plain ones (b, the lamp of w1) switch
    expected = {
        10: {"a": 5, "b": 100, "c": 5, "w1": 100, "w2": 5},
        7: {"a": 3, "b": 100, "c": 3, "w1": 100, "w2": 3},
        0: {"a": 0, "b": 0, "c": 0, "w1": 0, "w2": 0},
    }
    first = True
    for level, outputs in expected.items():
        since = probe.mark()
        if not first:
            probe.send(level)
        for name, value in outputs.items():
            probe.wait_for(name, value, since, resend=level if first else None)
        first = False
    for name in ("b", "w1"):
        assert set(probe.values(name)) <= {0, 100}, f"{name} is a plain lamp: {probe.values(name)}"
    for name in ("a", "c", "w2"):
        assert 100 not in probe.values(name), f"{name} is a dimmable lamp: {probe.values(name)}"
