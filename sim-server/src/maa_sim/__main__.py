"""`python -m maa_sim ...`: the `maa-sim` command line (the grading tasks run the simulator so)."""

from __future__ import annotations

import sys

from .cli import main

sys.exit(main())
