"""Helpers and fixtures of the ROS 2 tests: the example generated for rospython, built and installed.

conftest.py registers the fixtures.

Run with the venv of scripts/setup_ros2_venv.sh:
``packages/generators-python/.venv-ros2/bin/python -m pytest packages/generators-python/test/ros2``.
"""

from __future__ import annotations

import fcntl
import hashlib
import os
import shutil
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from dataclasses import dataclass
from pathlib import Path
from typing import IO

import pytest

HERE = Path(__file__).resolve().parent
PACKAGE_DIR = HERE.parents[1]
REPO = PACKAGE_DIR.parents[1]
EXAMPLE_APP = REPO / "examples" / "toast-service" / "TR.arcapp"
SIM_SERVER_TESTS = REPO / "sim-server" / "tests"
RUFF_CONFIG = HERE / "ruff-generated.toml"
INSTALL_INTERFACES = PACKAGE_DIR / "scripts" / "install_ros2_interfaces.sh"
PKG = "toast_service_robot"
IFACE = f"{PKG}_interfaces"


def install_interfaces_command(interfaces: Path) -> list[str]:
    """scripts/install_ros2_interfaces.sh for this venv, under the lock maa-gen and the IDE backend take.

    The lock is @maa/protocol's ros2EnvironmentLock(venv): Vitest's tests (maa-gen sim, the IDE
    backend's ROS 2 session) install the same interface package into this venv while npm test runs
    this suite beside them, and two installs at once would write the same files.
    """
    digest = hashlib.sha256(os.path.abspath(sys.prefix).encode()).hexdigest()[:16]
    command = ["bash", str(INSTALL_INTERFACES), sys.prefix, str(interfaces)]
    flock = shutil.which("flock")
    lock = Path(tempfile.gettempdir()) / f"maa-ide-ros2-{digest}.lock"
    return [flock, str(lock), *command] if flock else command


@dataclass(frozen=True)
class Generated:
    out: Path

    @property
    def platform(self) -> Path:
        return self.out / "rospython"

    @property
    def package(self) -> Path:
        return self.platform / PKG

    @property
    def interfaces(self) -> Path:
        return self.platform / IFACE


def maa_gen(args: list[str]) -> subprocess.CompletedProcess[str]:
    """``maa-gen ARGS`` in the session's warm Node process (sim-server's tests/warm_maa_gen.py):
    about half a second of CPU per generation instead of two for a cold ``maa-gen`` process."""
    if str(SIM_SERVER_TESTS) not in sys.path:
        sys.path.insert(0, str(SIM_SERVER_TESTS))
    import warm_maa_gen

    return warm_maa_gen.run(args)


def generate(out: Path) -> Generated:
    result = maa_gen(["generate", str(EXAMPLE_APP), "--platform", "rospython", "--out", str(out)])
    assert result.returncode == 0, f"maa-gen generate failed:\n{result.stdout}\n{result.stderr}"
    return Generated(out)


@pytest.fixture(scope="session")
def generated(tmp_path_factory: pytest.TempPathFactory) -> Generated:
    return generate(tmp_path_factory.mktemp("gen"))


@dataclass(frozen=True)
class Installed:
    generated: Generated
    build_seconds: float
    install_seconds: float


@pytest.fixture(scope="session")
def installed(generated: Generated, tmp_path_factory: pytest.TempPathFactory) -> Installed:
    """Builds the interface package with the PyPI rosidl toolchain and installs both packages into this venv."""
    pytest.importorskip("rclpy", reason="needs the venv of scripts/setup_ros2_venv.sh")
    pytest.importorskip("rosidl_adapter", reason="needs the venv of scripts/setup_ros2_venv.sh")
    if shutil.which("cmake") is None or shutil.which("g++") is None:
        pytest.fail("cmake and g++ are needed (scripts/setup_ros2_venv.sh installs them)")
    # the script users run for their own venv (it skips the build while the sources are unchanged)
    start = time.monotonic()
    result = subprocess.run(
        install_interfaces_command(generated.interfaces),
        capture_output=True,
        text=True,
        check=False,
    )
    output = f"{result.stdout[-4000:]}\n{result.stderr[-4000:]}"
    assert result.returncode == 0, f"install_ros2_interfaces.sh failed:\n{output}"
    build_seconds = time.monotonic() - start
    start = time.monotonic()
    result = subprocess.run(
        [sys.executable, "-m", "pip", "install", "-q", "--no-deps", "--no-build-isolation", str(generated.package)],
        capture_output=True,
        text=True,
        check=False,
    )
    assert result.returncode == 0, f"pip install failed:\n{result.stdout}\n{result.stderr}"
    return Installed(generated, build_seconds, time.monotonic() - start)


class DomainLease:
    """A ROS domain id of its own for a test session (lock files, like maa-sim's, in another range)."""

    RANGE = range(120, 200)

    def __init__(self) -> None:
        lock_dir = Path(tempfile.gettempdir()) / "maa-ros2-test-domains"
        lock_dir.mkdir(parents=True, exist_ok=True)
        start = os.getpid() % len(self.RANGE)
        for i in range(len(self.RANGE)):
            domain = self.RANGE[(start + i) % len(self.RANGE)]
            handle: IO[str] = (lock_dir / f"{domain}.lock").open("a")
            try:
                fcntl.flock(handle, fcntl.LOCK_EX | fcntl.LOCK_NB)
            except OSError:
                handle.close()
                continue
            self.domain_id = domain
            self._handle = handle
            return
        raise RuntimeError("no free ROS domain id for the test")

    def release(self) -> None:
        fcntl.flock(self._handle, fcntl.LOCK_UN)
        self._handle.close()


@pytest.fixture()
def ros_domain(monkeypatch: pytest.MonkeyPatch) -> Iterator[int]:
    lease = DomainLease()
    monkeypatch.setenv("ROS_DOMAIN_ID", str(lease.domain_id))
    monkeypatch.setenv("ROS_AUTOMATIC_DISCOVERY_RANGE", "LOCALHOST")
    monkeypatch.delenv("ROS_LOCALHOST_ONLY", raising=False)
    monkeypatch.delenv("ROS_STATIC_PEERS", raising=False)
    try:
        yield lease.domain_id
    finally:
        lease.release()


def pytest_configure(config: pytest.Config) -> None:
    # lark (used by the rosidl generators) imports deprecated stdlib modules
    config.addinivalue_line("filterwarnings", "ignore:module 'sre_:DeprecationWarning")
