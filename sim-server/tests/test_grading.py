"""The grading driver (`python -m maa_sim.grading`): Ray tasks in the sandbox, their lines and outputs.

Real runs: the driver as a subprocess with a local Ray instance (2 CPUs), and the same job on a
local 2-node Ray cluster (a head and a worker node process on 127.0.0.1) started and stopped by
the test. Jobs are small: this machine has 2 cores.
"""

from __future__ import annotations

import io
import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
import ray
import warm_maa_gen

from maa_sim.contracts import problem, validator
from maa_sim.grading.bundle import BundleError, pack_input, pack_outputs, unpack
from maa_sim.grading.cluster import LocalCluster, start_cluster, stop_cluster
from maa_sim.grading.driver import Lines, Options, run_job
from maa_sim.grading.job import JobTask, check_job
from maa_sim.protocol import GRADE_DRIVER_LINE_SCHEMA

REPO = Path(__file__).resolve().parents[2]
TOAST_APP = REPO / "examples" / "toast-service" / "TR.arcapp"
CONTROLLER_STREAM = REPO / "examples" / "toast-service" / "toast" / "Controller.stream"
LINE = validator(GRADE_DRIVER_LINE_SCHEMA)
LIMITS = {"wallSeconds": 30, "cpuSeconds": 20, "memoryMB": 1024, "processes": 32, "fileSizeMB": 16}
TIMEOUT = 240

WRITER = """
import pathlib, sys
data = pathlib.Path(sys.argv[1]).read_text()
out = pathlib.Path(sys.argv[2])
(out / "upper.txt").write_text(data.upper())
(out / "sub").mkdir()
(out / "sub" / "count.json").write_text('{"chars": %d}' % len(data))
print("wrote", len(data), "chars")
print("a warning", file=sys.stderr)
"""

#: Writes a marker into its output folder, then sleeps until the test kills it (argv[2]: a token the
#: test finds it by).
VICTIM = """
import pathlib, sys, time
(pathlib.Path(sys.argv[1]) / "started").write_text("x")
time.sleep(120)
"""


def task(task_id: str, input_dir: Path, argv: list[str], **limits: Any) -> dict[str, Any]:
    return {"id": task_id, "input": str(input_dir), "argv": argv, "limits": {**LIMITS, **limits}, "env": {}}


def write_job(path: Path, tasks: list[dict[str, Any]]) -> Path:
    path.write_text(json.dumps({"format": "maa-grade-job/1", "tasks": tasks}), encoding="utf-8")
    return path


def driver(job: Path, out: Path, env: dict[str, str] | None = None, *extra: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [sys.executable, "-m", "maa_sim.grading", "run", "--job", str(job), "--out", str(out), *extra],
        capture_output=True,
        text=True,
        timeout=TIMEOUT,
        check=False,
        env=env,
    )


def lines_of(stdout: str) -> list[dict[str, Any]]:
    lines = [json.loads(line) for line in stdout.splitlines()]
    for line in lines:
        assert problem(LINE, line) is None, line
    return lines


def by_id(lines: list[dict[str, Any]]) -> dict[str, dict[str, Any]]:
    return {line["id"]: line for line in lines if line["event"] == "task"}


@pytest.fixture(scope="module")
def toast_build(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """An input folder with the example's generated timesync build and its Controller stream test."""
    if shutil.which("node") is None:
        pytest.skip("node is needed to generate the timesync build")
    root = tmp_path_factory.mktemp("toast-input")
    gen = tmp_path_factory.mktemp("toast-gen")
    result = warm_maa_gen.run(["generate", str(TOAST_APP), "--platform", "timesync", "--out", str(gen)])
    assert result.returncode == 0, f"maa-gen generate failed:\n{result.stdout}\n{result.stderr}"
    shutil.copytree(gen / "timesync", root / "build")
    shutil.copy(CONTROLLER_STREAM, root / "Controller.stream")
    return root


@pytest.fixture(scope="module")
def job_dir(tmp_path_factory: pytest.TempPathFactory, toast_build: Path) -> Path:
    """A job of real tasks: a command writing outputs, one failing, one hanging, a stream test."""
    root = tmp_path_factory.mktemp("job")
    data = root / "data"
    data.mkdir()
    (data / "words.txt").write_text("toast and jam\n")
    streamtest = ["{python}", "-m", "maa_timesync.streamtest", "{input}/build", "--json", "{input}/Controller.stream"]
    tasks = [
        task("write", data, ["{python}", "-c", WRITER, "{input}/words.txt", "{output}"]),
        task("fail", data, ["{python}", "-c", "import sys; print('no'); sys.exit(3)"]),
        task("hang", data, ["{python}", "-c", "import time; time.sleep(300)"], wallSeconds=2),
        {**task("streamtest", toast_build, streamtest), "env": {"PYTHONPATH": "{input}/build"}},
    ]
    write_job(root / "job.json", tasks)
    return root


def stream_results(out: Path) -> list[tuple[str, bool]]:
    """The stream tests' names and verdicts of the streamtest task (the report before its summary line)."""
    report = (out / "streamtest" / "stdout.txt").read_text()
    return [(r["test"], r["passed"]) for r in json.loads(report[: report.rindex("]") + 1])]


def check_local_results(out: Path, lines: list[dict[str, Any]]) -> None:
    tasks = by_id(lines)
    assert set(tasks) == {"write", "fail", "hang", "streamtest"}
    assert tasks["write"]["status"] == "ok"
    assert tasks["write"]["exitCode"] == 0
    assert (out / "write" / "upper.txt").read_text() == "TOAST AND JAM\n"
    assert json.loads((out / "write" / "sub" / "count.json").read_text()) == {"chars": 14}
    assert (out / "write" / "stdout.txt").read_text() == "wrote 14 chars\n"
    assert "a warning" in (out / "write" / "stderr.txt").read_text()
    assert tasks["fail"]["status"] == "failed"
    assert tasks["fail"]["exitCode"] == 3
    assert (out / "fail" / "stdout.txt").read_text() == "no\n"
    assert tasks["hang"]["status"] == "timeout"
    assert "wall time" in tasks["hang"]["message"]
    assert tasks["streamtest"]["status"] == "ok", (out / "streamtest" / "stderr.txt").read_text()
    results = stream_results(out)
    assert len(results) >= 3
    assert all(passed for _, passed in results)
    for task_id, line in tasks.items():
        assert json.loads((out / task_id / "result.json").read_text()) == line


@pytest.fixture(scope="module")
def local_run(job_dir: Path) -> tuple[Path, list[dict[str, Any]]]:
    out = job_dir / "out-local"
    result = driver(job_dir / "job.json", out)
    assert result.returncode == 0, result.stderr
    return out, lines_of(result.stdout)


def test_a_local_run_gives_a_line_per_task_and_its_outputs(local_run: tuple[Path, list[dict[str, Any]]]) -> None:
    out, lines = local_run
    assert lines[0]["event"] == "started"
    assert lines[0]["mode"] == "local"
    assert lines[0]["tasks"] == 4
    assert lines[0]["nodes"] == 1
    assert lines[-1]["event"] == "finished"
    assert lines[-1]["counts"] == {"ok": 2, "failed": 1, "timeout": 1, "killed": 0, "error": 0}
    assert [line["event"] for line in lines[1:-1]] == ["task"] * 4
    check_local_results(out, lines)


@pytest.fixture
def cluster() -> Iterator[LocalCluster]:
    directory = Path(tempfile.mkdtemp(prefix="maa-test-cluster-", dir="/tmp"))
    try:
        started = start_cluster(directory, nodes=2, cpus_per_node=1)
        try:
            yield started
        finally:
            stop_cluster(directory)
            members = [p for p in started.pids if Path(f"/proc/{p}").exists()]
            assert not members, f"node processes left: {members}"
    finally:
        shutil.rmtree(directory, ignore_errors=True)


def test_a_two_node_cluster_gives_the_same_results(
    cluster: LocalCluster, job_dir: Path, local_run: tuple[Path, list[dict[str, Any]]]
) -> None:
    out = job_dir / "out-cluster"
    result = driver(job_dir / "job.json", out, {**os.environ, **cluster.env()})
    assert result.returncode == 0, result.stderr
    lines = lines_of(result.stdout)
    assert lines[0]["mode"] == "cluster"
    assert lines[0]["address"] == cluster.address
    assert lines[0]["nodes"] == 2
    assert lines[0]["cpus"] == 2
    check_local_results(out, lines)
    local = {k: (v["status"], v["exitCode"]) for k, v in by_id(local_run[1]).items()}
    assert {k: (v["status"], v["exitCode"]) for k, v in by_id(lines).items()} == local
    for task_id in ("write", "fail", "streamtest"):
        files = sorted(str(p.relative_to(out / task_id)) for p in (out / task_id).rglob("*") if p.is_file())
        local_out = local_run[0] / task_id
        assert files == sorted(str(p.relative_to(local_out)) for p in local_out.rglob("*") if p.is_file())
    assert (out / "write" / "stdout.txt").read_text() == (local_run[0] / "write" / "stdout.txt").read_text()
    assert stream_results(out) == stream_results(local_run[0])


def processes_with(token: str) -> list[int]:
    """The Python processes with `token` among their arguments (not the sandbox's bwrap that starts them)."""
    found = []
    for entry in Path("/proc").iterdir():
        if entry.name.isdigit():
            try:
                args = (entry / "cmdline").read_bytes().decode(errors="replace").split("\0")
            except OSError:
                continue
            if token in args and "python" in Path(args[0]).name:
                found.append(int(entry.name))
    return found


def parent_of(pid: int) -> int:
    return int((Path(f"/proc/{pid}") / "stat").read_text().rsplit(")", 1)[1].split()[1])


def ray_worker_of(pid: int) -> int:
    """The Ray worker process above `pid` (its command line is `ray::<task>`)."""
    current = pid
    while current > 1:
        current = parent_of(current)
        if (Path(f"/proc/{current}") / "cmdline").read_bytes().startswith(b"ray::"):
            return current
    raise AssertionError(f"no Ray worker above {pid}")


def wait_for_marker(scratch: Path, task_id: str, process: subprocess.Popen[str]) -> None:
    while not list(scratch.glob(f"maa-grade-*-{task_id}-*/output/started")):
        assert process.poll() is None, process.communicate()
        time.sleep(0.1)


def test_a_killed_command_and_a_dead_worker_are_reported_and_the_others_finish(tmp_path: Path) -> None:
    data = tmp_path / "data"
    data.mkdir()
    (data / "words.txt").write_text("bread\n")
    scratch = tmp_path / "scratch"
    scratch.mkdir()
    job = write_job(
        tmp_path / "job.json",
        [
            task("victim", data, ["{python}", "-c", VICTIM, "{output}", "victim-token-3141"], wallSeconds=100),
            task("worker", data, ["{python}", "-c", VICTIM, "{output}", "worker-token-2718"], wallSeconds=100),
            task("write-1", data, ["{python}", "-c", WRITER, "{input}/words.txt", "{output}"]),
            task("write-2", data, ["{python}", "-c", WRITER, "{input}/words.txt", "{output}"]),
        ],
    )
    out = tmp_path / "out"
    # The workers' scratch folders go to TMPDIR (the local Ray instance passes the driver's environment on).
    process = subprocess.Popen(
        [sys.executable, "-m", "maa_sim.grading", "run", "--job", str(job), "--out", str(out), "--workers", "2"],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env={**os.environ, "TMPDIR": str(scratch)},
    )
    try:
        wait_for_marker(scratch, "victim", process)
        (victim,) = processes_with("victim-token-3141")
        os.kill(victim, signal.SIGKILL)
        wait_for_marker(scratch, "worker", process)
        (command,) = processes_with("worker-token-2718")
        os.kill(ray_worker_of(command), signal.SIGKILL)
        stdout, stderr = process.communicate(timeout=TIMEOUT)
    finally:
        if process.poll() is None:  # SIGTERM: the driver shuts its Ray instance down
            process.terminate()
            process.communicate(timeout=60)
    assert process.returncode == 0, stderr
    lines = lines_of(stdout)
    tasks = by_id(lines)
    assert tasks["victim"]["status"] == "killed"
    assert tasks["victim"]["signal"] == signal.SIGKILL
    assert tasks["worker"]["status"] == "error"
    assert "worker" in tasks["worker"]["message"]
    assert tasks["write-1"]["status"] == tasks["write-2"]["status"] == "ok"
    assert (out / "write-2" / "upper.txt").read_text() == "BREAD\n"
    assert lines[-1]["counts"] == {"ok": 2, "failed": 0, "timeout": 0, "killed": 1, "error": 1}
    assert not processes_with("worker-token-2718"), "the dead worker's command is left running"


def sleep_past_every_limit(task: dict[str, Any], bundle: bytes) -> dict[str, Any]:
    """A task function that hangs outside the sandbox (as a stuck worker would)."""
    del task, bundle
    time.sleep(600)
    raise AssertionError("not cancelled")


def test_a_task_past_its_wall_time_and_grace_is_cancelled(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.delenv("RAY_ADDRESS", raising=False)
    monkeypatch.setenv("RAY_AUTH_MODE", "token")
    monkeypatch.setenv("RAY_AUTH_TOKEN", os.urandom(16).hex())
    data = tmp_path / "data"
    data.mkdir()
    tasks = check_job({"format": "maa-grade-job/1", "tasks": [task("stuck", data, ["true"], wallSeconds=1)]}, "job")
    # the workers import this test module by value (it is not installed)
    cloudpickle: Any = ray.cloudpickle
    cloudpickle.register_pickle_by_value(sys.modules[__name__])
    stream = io.StringIO()
    run_job(tasks, tmp_path / "out", Lines(stream), Options(workers=1, grace=1), function=sleep_past_every_limit)
    lines = lines_of(stream.getvalue())
    (stuck,) = [line for line in lines if line["event"] == "task"]
    assert stuck["status"] == "timeout"
    assert stuck["message"] == "cancelled: still running 1 s after its wall time limit (1 s)"
    assert lines[-1]["counts"]["timeout"] == 1
    assert json.loads((tmp_path / "out" / "stuck" / "result.json").read_text()) == stuck


@pytest.mark.parametrize(
    ("content", "message"),
    [
        ("{", "not JSON"),
        ('{"format": "maa-grade-job/2", "tasks": []}', "/format: format must be 'maa-grade-job/1'"),
        ('{"format": "maa-grade-job/1"}', "/tasks: tasks must be a list of tasks"),
        ('{"format": "maa-grade-job/1", "tasks": [{"id": "a"}]}', "/tasks/0"),
        (
            json.dumps({"format": "maa-grade-job/1", "tasks": [task("a b", Path("/tmp"), ["true"])]}),
            "/tasks/0/id: a task id is letters, digits, ., _ and -",
        ),
        (
            json.dumps({"format": "maa-grade-job/1", "tasks": [task("a", Path("/no/such/dir"), ["true"])]}),
            "/tasks/0/input: /no/such/dir is not a directory",
        ),
        (
            json.dumps({"format": "maa-grade-job/1", "tasks": [task("a", Path("/tmp"), ["true"])] * 2}),
            "/tasks/1/id: the task id 'a' is used twice",
        ),
    ],
)
def test_a_bad_job_exits_with_2_and_says_why(tmp_path: Path, content: str, message: str) -> None:
    job = tmp_path / "job.json"
    job.write_text(content)
    result = driver(job, tmp_path / "out")
    assert result.returncode == 2
    assert result.stdout == ""
    assert "bad job" in result.stderr
    assert message in result.stderr
    assert not (tmp_path / "out").exists()


def test_a_missing_job_file_and_bad_options_exit_with_2(tmp_path: Path) -> None:
    result = driver(tmp_path / "nothing.json", tmp_path / "out")
    assert result.returncode == 2
    assert "cannot read the job file" in result.stderr
    job = write_job(tmp_path / "job.json", [])
    assert "--workers must be at least 1" in driver(job, tmp_path / "out", None, "--workers", "0").stderr


def test_help_names_the_commands() -> None:
    result = subprocess.run(
        [sys.executable, "-m", "maa_sim.grading", "--help"], capture_output=True, text=True, check=False, timeout=60
    )
    assert result.returncode == 0
    assert "run --job JOB.json --out DIR" in result.stdout
    assert "cluster start" in result.stdout
    assert "RAY_ADDRESS" in result.stdout


def test_an_input_bundle_keeps_links_inside_and_refuses_links_out(tmp_path: Path) -> None:
    root = tmp_path / "in"
    (root / "sub").mkdir(parents=True)
    (root / "sub" / "a.txt").write_text("a")
    (root / "link.txt").symlink_to("sub/a.txt")
    target = tmp_path / "unpacked"
    unpack(pack_input(root), target)
    assert (target / "sub" / "a.txt").read_text() == "a"
    assert (target / "link.txt").is_symlink()
    assert (target / "link.txt").read_text() == "a"
    (root / "secret").symlink_to("/etc/passwd")
    with pytest.raises(BundleError, match="leading out of the input directory"):
        pack_input(root)


def test_outputs_leave_out_links_special_files_and_what_is_over_the_budget(tmp_path: Path) -> None:
    root = tmp_path / "out"
    root.mkdir()
    (root / "small.txt").write_text("x" * 10)
    (root / "big.bin").write_bytes(b"y" * 1000)
    (root / "passwd").symlink_to("/etc/passwd")
    os.mkfifo(root / "pipe")
    packed = pack_outputs(root, budget_bytes=100)
    assert packed.files == 1
    assert sorted(packed.skipped) == [
        "big.bin (1000 bytes, over the output budget)",
        "passwd (not a regular file)",
        "pipe (not a regular file)",
    ]
    target = tmp_path / "back"
    unpack(packed.data, target)
    assert [p.name for p in target.iterdir()] == ["small.txt"]


def test_job_tasks_travel_as_plain_data(tmp_path: Path) -> None:
    (parsed,) = check_job(
        {
            "format": "maa-grade-job/1",
            "tasks": [{**task("t", tmp_path, ["{python}", "x"]), "env": {"A": "{input}/b"}}],
        },
        "job",
    )
    assert isinstance(parsed, JobTask)
    assert parsed.wire() == {"id": "t", "argv": ["{python}", "x"], "env": {"A": "{input}/b"}, "limits": LIMITS}


def test_an_unreachable_cluster_fails_fast_with_exit_1(tmp_path: Path) -> None:
    data = tmp_path / "data"
    data.mkdir()
    job = write_job(tmp_path / "job.json", [task("a", data, ["true"])])
    with socket.socket() as probe:  # a port nobody listens on
        probe.bind(("127.0.0.1", 0))
        address = f"127.0.0.1:{probe.getsockname()[1]}"
    result = driver(job, tmp_path / "out", {**os.environ, "RAY_ADDRESS": address})
    assert result.returncode == 1
    assert f"cannot reach the Ray cluster at RAY_ADDRESS={address}" in result.stderr
    assert result.stdout == ""


def ray_dirs() -> set[str]:
    return {entry.name for entry in Path("/tmp").glob("maa-ray-*")}


def test_sigterm_stops_the_driver_its_tasks_and_its_ray_instance(tmp_path: Path) -> None:
    data = tmp_path / "data"
    data.mkdir()
    scratch = tmp_path / "scratch"
    scratch.mkdir()
    job = write_job(
        tmp_path / "job.json",
        [task("long", data, ["{python}", "-c", VICTIM, "{output}", "sigterm-token-1618"], wallSeconds=100)],
    )
    before = ray_dirs()
    process = subprocess.Popen(
        [sys.executable, "-m", "maa_sim.grading", "run", "--job", str(job), "--out", str(tmp_path / "out")],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        env={**os.environ, "TMPDIR": str(scratch)},
    )
    try:
        wait_for_marker(scratch, "long", process)
        mine = ray_dirs() - before
        process.terminate()
        stdout, stderr = process.communicate(timeout=120)
    finally:
        if process.poll() is None:
            process.kill()
            process.wait()
    assert process.returncode == 128 + signal.SIGTERM, stderr
    assert [json.loads(line)["event"] for line in stdout.splitlines()] == ["started"]
    deadline = time.monotonic() + 30  # Ray's workers end after the raylet that the shutdown stopped
    while processes_with("sigterm-token-1618") and time.monotonic() < deadline:
        time.sleep(0.2)
    assert not processes_with("sigterm-token-1618"), "the task's command is left running"
    assert not (mine & ray_dirs()), "the local Ray instance's folder is left"


def test_the_cluster_commands_say_what_is_wrong(tmp_path: Path) -> None:
    def cluster(*args: str) -> subprocess.CompletedProcess[str]:
        command = [sys.executable, "-m", "maa_sim.grading", "cluster", *args, "--dir", str(tmp_path)]
        return subprocess.run(command, capture_output=True, text=True, check=False, timeout=60)

    stopped = cluster("stop")
    assert stopped.returncode == 1
    assert f"no cluster in {tmp_path}" in stopped.stderr
    refused = cluster("start", "--nodes", "0")
    assert refused.returncode == 2
    assert "--nodes and --cpus-per-node must be at least 1" in refused.stderr
    assert not (tmp_path / "cluster.json").exists()
