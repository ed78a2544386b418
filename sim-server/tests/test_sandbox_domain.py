"""The ROS 2 domain of a sandboxed simulation: the sandbox's ros_domain reaches maa-sim's own
domain lease (MAA_SIM_ROS_DOMAIN), since the lock files maa-sim otherwise coordinates domains
with live in /tmp, which is private to each sandbox."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from maa_sim.ros2 import DOMAIN_ENV, DomainLease
from maa_sim.sandbox import Limits, SandboxSpec
from maa_sim.sandbox.view import environment

SPEC = SandboxSpec(readonly=[], writable=[], cwd=Path("/tmp"), limits=Limits(1, 1, 1, 1, 1))


def test_the_sandbox_passes_its_domain_to_maa_sim() -> None:
    env = environment(replace(SPEC, ros_domain=42))
    assert env["ROS_DOMAIN_ID"] == "42"
    assert env[DOMAIN_ENV] == "42"
    assert DOMAIN_ENV not in environment(SPEC) and "ROS_DOMAIN_ID" not in environment(SPEC)


def test_a_given_domain_is_used_as_it_is(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setenv(DOMAIN_ENV, "42")
    leases = [DomainLease(), DomainLease()]  # no lock: the lab hands out the domains
    assert [lease.domain_id for lease in leases] == [42, 42]
    for lease in leases:
        lease.release()


@pytest.mark.parametrize("value", ["233", "-1", "abc"])
def test_a_bad_given_domain_is_an_error(monkeypatch: pytest.MonkeyPatch, value: str) -> None:
    monkeypatch.setenv(DOMAIN_ENV, value)
    with pytest.raises(RuntimeError, match="is not a ROS domain id"):
        DomainLease()


def test_without_a_given_domain_a_free_one_is_leased(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv(DOMAIN_ENV, raising=False)
    first, second = DomainLease(), DomainLease()
    try:
        assert first.domain_id != second.domain_id
        assert 1 <= first.domain_id <= 100
    finally:
        first.release()
        second.release()
