"""Runs untrusted commands (students' generated and handwritten components) in a bubblewrap sandbox.

``run_sandboxed(argv, SandboxSpec(...)) -> SandboxResult``: a minimal read-only file system view
(system folders, the interpreter's prefixes, the given read-only folders) with the given writable
folders, new pid/ipc/uts/net namespaces (the host network only when asked), a separate
unprivileged uid per run when the caller is root, rlimits (CPU, address space, processes, file
size, open files) and a wall-clock kill of the whole sandbox. ``python -m maa_sim.sandbox`` is the
same for other programs (the lab's live simulations). See docs/lab.md, "Sandbox".
"""

from .run import describe, run_sandboxed
from .spec import Limits, SandboxError, SandboxResult, SandboxSpec
from .view import python_view

__all__ = ["Limits", "SandboxError", "SandboxResult", "SandboxSpec", "describe", "python_view", "run_sandboxed"]
