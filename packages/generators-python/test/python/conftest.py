"""pytest setup of the Python generators' tests: the run-time environments are importable."""

from __future__ import annotations

import sys
from pathlib import Path

RTE = Path(__file__).resolve().parents[2] / "rte"
if str(RTE) not in sys.path:
    sys.path.insert(0, str(RTE))
