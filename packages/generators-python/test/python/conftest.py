"""pytest setup of the Python generators' tests: the run-time environments are importable."""

from __future__ import annotations

import importlib
import sys
from collections.abc import Iterator
from pathlib import Path
from types import ModuleType

RTE = Path(__file__).resolve().parents[2] / "rte"
if str(RTE) not in sys.path:
    sys.path.insert(0, str(RTE))


GOLDEN = Path(__file__).resolve().parents[1] / "golden"


def import_golden_app(build: str, package: str) -> Iterator[ModuleType]:
    """The generated app module (`maa_app`) of the golden timesync build `build`, whose model
    package is `package`: importable while the test runs, forgotten afterwards (another test may
    import another build's modules of the same names)."""

    def forget() -> None:
        for name in [m for m in sys.modules if m == "maa_app" or m == package or m.startswith(f"{package}.")]:
            del sys.modules[name]

    folder = str(GOLDEN / build)
    sys.path.insert(0, folder)
    forget()
    try:
        yield importlib.import_module("maa_app")
    finally:
        sys.path.remove(folder)
        forget()
