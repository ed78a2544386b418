"""Shared test helpers: fixture paths and the fixture applications on sys.path."""

from __future__ import annotations

import sys
from pathlib import Path

import pytest

TESTS = Path(__file__).resolve().parent
FIXTURES = TESTS / "fixtures"
TOAST_APP = FIXTURES / "toast_app"
FAULTY_APP = FIXTURES / "faulty_app"
SIM_SERVER = TESTS.parent

if str(TOAST_APP) not in sys.path:
    sys.path.insert(0, str(TOAST_APP))


@pytest.fixture
def toast_app_dir() -> Path:
    return TOAST_APP


@pytest.fixture
def faulty_app_dir() -> Path:
    return FAULTY_APP
