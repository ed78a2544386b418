"""The batch grading driver: runs a grade job's tasks on Ray, each in the sandbox.

`python -m maa_sim.grading run --job JOB.json --out DIR` (docs/lab.md, "Grading"): every task of the
job (`maa-grade-job/1`, written by `@maa/grading`) is a Ray task. Its input directory travels to the
worker as a tar in the task's argument, the worker unpacks it, runs the task's argv with
`maa_sim.sandbox.run_sandboxed` and sends back what the command wrote into `{output}`, so a
cluster of machines without a shared file system works. Ray is local (`ray.init()` on this
machine) unless `RAY_ADDRESS` names a cluster. `python -m maa_sim.grading cluster start|stop`
starts and stops a small local cluster (a head node and worker node processes on 127.0.0.1) for
tests and the benchmark.
"""

from __future__ import annotations

from maa_sim.grading.job import JobError, JobTask, load_job

__all__ = ["JobError", "JobTask", "load_job"]
