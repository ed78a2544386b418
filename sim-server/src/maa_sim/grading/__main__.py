"""`python -m maa_sim.grading` (see maa_sim.grading.cli)."""

import sys

from maa_sim.grading.cli import main

sys.exit(main())
