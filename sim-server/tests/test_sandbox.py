"""maa_sim.sandbox: a valid run works, and each rule of the sandbox contains an attack and says why.

Every attack is a real Python program run with the sim-server venv's interpreter in the sandbox;
each test asserts that the attack was contained (on the host) and that the result's reason names
the rule in plain words."""

from __future__ import annotations

import json
import os
import shutil
import signal
import socket
import subprocess
import sys
import tempfile
import threading
import time
import uuid
from pathlib import Path

import pytest

from maa_sim.sandbox import Limits, SandboxError, SandboxResult, SandboxSpec, run_sandboxed
from maa_sim.sandbox.run import DEFAULT_UIDS
from maa_sim.sandbox.view import build_command

pytestmark = pytest.mark.skipif(
    not (shutil.which("bwrap") or os.path.exists("/usr/bin/bwrap")),
    reason="bubblewrap is not installed (the test command installs Debian's bubblewrap: scripts/ensure-bubblewrap.mjs)",
)

PYTHON = sys.executable
ROOT = os.geteuid() == 0
GENEROUS = Limits(wall_seconds=300, cpu_seconds=120, memory_mb=2048, processes=64, file_size_mb=64)


def spec(tmp_path: Path, limits: Limits = GENEROUS, **extra: object) -> SandboxSpec:
    out = tmp_path / "out"
    out.mkdir(exist_ok=True)
    return SandboxSpec(readonly=[], writable=[out], cwd=out, limits=limits, **extra)  # type: ignore[arg-type]


def run_python(code: str, sandbox: SandboxSpec, *args: str) -> SandboxResult:
    return run_sandboxed([PYTHON, "-c", code, *args], sandbox)


def processes_with(marker: str) -> list[int]:
    """Host pids whose command line contains the marker (a unique argument given to the attack)."""
    found = []
    for entry in os.scandir("/proc"):
        if entry.name.isdigit():
            try:
                cmdline = Path(entry.path, "cmdline").read_bytes()
            except OSError:
                continue
            if marker.encode() in cmdline and int(entry.name) != os.getpid():
                found.append(int(entry.name))
    return found


def test_a_valid_run_simulates_and_writes_its_output_folder(tmp_path: Path) -> None:
    code = """
import json, os, mujoco
import maa_sim.world as w
kitchen = w.ToastKitchen()
for _ in range(50):
    kitchen.step()
json.dump({"uid": os.getuid(), "mujoco": mujoco.__version__, "time": kitchen.data.time}, open("result.json", "w"))
"""
    sandbox = spec(tmp_path)
    result = run_python(code, sandbox)
    assert result.ok, result.stderr
    assert result.reason == "exited with 0"
    out = json.loads((tmp_path / "out" / "result.json").read_text())
    assert out["time"] > 0
    if ROOT:
        assert DEFAULT_UIDS[0] <= out["uid"] <= DEFAULT_UIDS[1]
        # the output folder and what the run wrote belong to the caller again
        assert (tmp_path / "out" / "result.json").stat().st_uid == os.getuid()
        assert (tmp_path / "out").stat().st_uid == os.getuid()


def test_the_environment_is_cleared_but_for_what_the_spec_passes(
    tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setenv("MAA_LAB_SECRET", "do-not-leak")
    sandbox = spec(tmp_path, env={"MAA_SIM_TOKEN": "abc"}, ros_domain=17)
    result = run_python("import json, os; print(json.dumps(dict(os.environ)))", sandbox)
    env = json.loads(result.stdout)
    assert "MAA_LAB_SECRET" not in env
    assert env["HOME"] == "/tmp"
    assert env["ROS_DOMAIN_ID"] == "17"
    assert env["ROS_LOCALHOST_ONLY"] == "1"
    assert env["MAA_SIM_TOKEN"] == "abc"


def test_it_cannot_read_another_workspace_or_the_database(tmp_path: Path) -> None:
    other = tmp_path / "workspaces" / "42" / "toast"
    other.mkdir(parents=True)
    (other / "Controller.arc").write_text("component Controller { secret solution }")
    database = tmp_path / "lab.sqlite"
    database.write_text("password hashes")
    for p in (other / "Controller.arc", database):
        p.chmod(0o644)
    code = """
import sys
for path in sys.argv[1:]:
    try:
        print("READ", open(path).read())
    except OSError as e:
        print("DENIED", path, type(e).__name__, file=sys.stderr)
open(sys.argv[1])
"""
    result = run_python(code, spec(tmp_path), str(other / "Controller.arc"), str(database), "/work", str(tmp_path))
    assert "READ" not in result.stdout
    assert "secret solution" not in result.stdout and "password" not in result.stdout
    assert result.stderr.count("DENIED") == 4
    assert result.exit_code == 1
    assert result.reason.startswith("exited with 1: FileNotFoundError")
    assert str(other / "Controller.arc") in result.reason


def test_it_cannot_write_outside_its_writable_folder(tmp_path: Path) -> None:
    given = tmp_path / "input"
    given.mkdir()
    (given / "world.json").write_text("{}")
    neighbour = tmp_path / "neighbour"
    neighbour.mkdir()
    code = """
import sys
errors = []
for path in sys.argv[1:]:
    try:
        open(path, "w").write("owned")
    except OSError as e:
        errors.append(f"{path}: {e.strerror}")
print("\\n".join(errors), file=sys.stderr)
sys.exit(len(errors))
"""
    targets = [given / "world.json", given / "new.txt", neighbour / "x.txt", Path("/usr/pwned"), Path(PYTHON)]
    sandbox = SandboxSpec(readonly=[given], writable=[tmp_path / "out"], cwd=given, limits=GENEROUS)
    (tmp_path / "out").mkdir()
    result = run_python(code, sandbox, *map(str, targets))
    assert result.exit_code == len(targets), result.stderr
    assert "Read-only file system" in result.stderr
    assert (given / "world.json").read_text() == "{}"
    assert not (given / "new.txt").exists() and not (neighbour / "x.txt").exists()
    assert not Path("/usr/pwned").exists()
    assert result.reason.startswith(f"exited with {len(targets)}")


def test_it_cannot_connect_to_a_server_on_the_host(tmp_path: Path) -> None:
    server = socket.socket()
    server.bind(("127.0.0.1", 0))
    server.listen(8)
    port = server.getsockname()[1]
    try:
        code = "import socket, sys; socket.create_connection(('127.0.0.1', int(sys.argv[1])), timeout=20)"
        result = run_python(code, spec(tmp_path), str(port))
        server.setblocking(False)
        with pytest.raises(BlockingIOError):
            server.accept()  # nothing arrived
    finally:
        server.close()
    assert result.exit_code == 1
    assert "ConnectionRefusedError" in result.reason
    assert "the sandbox has no network" in result.reason


def test_a_fork_bomb_is_stopped_by_the_process_limit(tmp_path: Path) -> None:
    marker = f"forkbomb-{uuid.uuid4()}"
    limits = Limits(wall_seconds=300, cpu_seconds=60, memory_mb=1024, processes=32, file_size_mb=16)
    result = run_python("import os\nwhile True:\n    os.fork()", spec(tmp_path, limits), marker)
    assert result.exit_code == 1
    assert result.reason == "process limit (32 processes) reached"
    assert "BlockingIOError" in result.stderr
    # nothing of it is left, and the machine still runs programs
    assert processes_with(marker) == []
    assert subprocess.run(["true"], check=False).returncode == 0


def test_unbounded_allocation_is_reported_as_memory(tmp_path: Path) -> None:
    limits = Limits(wall_seconds=300, cpu_seconds=60, memory_mb=768, processes=32, file_size_mb=16)
    code = "chunks = []\nwhile True:\n    chunks.append(bytearray(50 * 1024 * 1024))"
    result = run_python(code, spec(tmp_path, limits))
    assert result.exit_code == 1
    assert "MemoryError" in result.stderr
    assert result.reason == "out of memory: the memory limit (768 MB) was reached"


def test_a_busy_loop_is_killed_by_the_cpu_limit(tmp_path: Path) -> None:
    limits = Limits(wall_seconds=600, cpu_seconds=2, memory_mb=1024, processes=32, file_size_mb=16)
    result = run_python("while True:\n    pass", spec(tmp_path, limits))
    assert result.signal == signal.SIGXCPU
    assert result.exit_code is None and not result.timed_out
    assert result.reason == "killed: CPU time limit (2 s)"


def test_a_sleeper_and_its_detached_child_are_killed_at_the_wall_limit(tmp_path: Path) -> None:
    marker = f"sleeper-{uuid.uuid4()}"
    # long enough for the program to start its child on a loaded machine
    limits = Limits(wall_seconds=15, cpu_seconds=60, memory_mb=1024, processes=32, file_size_mb=16)
    code = """
import subprocess, sys, time
subprocess.Popen([sys.executable, "-c", "import time; time.sleep(1000)", sys.argv[1]], start_new_session=True)
print("started", flush=True)
time.sleep(1000)
"""
    result = run_python(code, spec(tmp_path, limits), marker)
    assert result.timed_out
    assert result.reason == "killed: wall time limit (15 s)"
    assert result.stdout == "started\n"
    assert processes_with(marker) == []


def test_a_huge_file_is_stopped_by_the_file_size_limit(tmp_path: Path) -> None:
    limits = Limits(wall_seconds=300, cpu_seconds=60, memory_mb=1024, processes=32, file_size_mb=4)
    code = "f = open('big.bin', 'wb')\nwhile True:\n    f.write(b'x' * 1024 * 1024)"
    result = run_python(code, spec(tmp_path, limits))
    assert result.reason == "file size limit (4 MB) reached"
    assert (tmp_path / "out" / "big.bin").stat().st_size <= 4 * 1024 * 1024
    # a program that does not ignore SIGXFSZ (Python does) is killed by it
    shell = run_sandboxed(["/bin/sh", "-c", "head -c 10000000 /dev/zero > big2.bin"], spec(tmp_path, limits))
    assert shell.signal == signal.SIGXFSZ
    assert shell.reason == "killed: file size limit (4 MB) reached"


@pytest.mark.skipif(not ROOT, reason="set-id bits and ownership are handled when the service runs as root")
def test_set_id_bits_of_the_output_are_removed(tmp_path: Path) -> None:
    code = "import os, shutil\nshutil.copy('/bin/true', 'suid')\nos.chmod('suid', 0o6755)\n"
    code += "os.symlink('/etc/shadow', 'link')"
    result = run_python(code, spec(tmp_path))
    assert result.ok, result.stderr
    copied = tmp_path / "out" / "suid"
    assert copied.stat().st_uid == 0
    assert copied.stat().st_mode & 0o6000 == 0
    assert Path("/etc/shadow").stat().st_uid == 0  # the symlink was not followed by the chown back


def test_two_sandboxes_at_once_do_not_see_each_other(tmp_path: Path) -> None:
    code = """
import json, os, sys, time
mine, other, marker = sys.argv[1], sys.argv[2], sys.argv[3]
open("secret.txt", "w").write(marker)
open("ready", "w").close()
while not os.path.exists("go"):
    time.sleep(0.05)
pids = [p for p in os.listdir("/proc") if p.isdigit()]
cmdlines = [open(f"/proc/{p}/cmdline", "rb").read().decode(errors="replace") for p in pids]
json.dump({"uid": os.getuid(), "pids": pids, "cmdlines": cmdlines,
           "sees_other": os.path.exists(os.path.join(other, "secret.txt"))}, open("seen.json", "w"))
"""
    names = ("a", "b")
    dirs = {n: tmp_path / n for n in names}
    for d in dirs.values():
        d.mkdir()
    markers = {n: f"sandbox-{n}-{uuid.uuid4()}" for n in names}
    results: dict[str, SandboxResult] = {}

    def run(n: str) -> None:
        other = dirs["b" if n == "a" else "a"]
        sandbox = SandboxSpec(readonly=[], writable=[dirs[n]], cwd=dirs[n], limits=GENEROUS)
        results[n] = run_python(code, sandbox, str(dirs[n]), str(other), markers[n])

    threads = [threading.Thread(target=run, args=(n,)) for n in names]
    for t in threads:
        t.start()
    deadline = time.monotonic() + 240
    while not all((d / "ready").exists() for d in dirs.values()) and time.monotonic() < deadline:
        if not all(t.is_alive() for t in threads):
            break
        time.sleep(0.05)
    for d in dirs.values():
        (d / "go").write_text("")
    for t in threads:
        t.join()
    seen = {n: json.loads((dirs[n] / "seen.json").read_text()) for n in names}
    for n in names:
        assert results[n].ok, results[n].stderr
        other_marker = markers["b" if n == "a" else "a"]
        assert seen[n]["sees_other"] is False
        assert not any(other_marker in c for c in seen[n]["cmdlines"])
        assert len(seen[n]["pids"]) <= 3  # its pid 1, itself (and nothing of the host)
    if ROOT:
        assert seen["a"]["uid"] != seen["b"]["uid"]


def test_bad_specs_are_sandbox_errors(tmp_path: Path) -> None:
    with pytest.raises(SandboxError, match="does not exist"):
        run_sandboxed(["/bin/true"], SandboxSpec([tmp_path / "missing"], [], Path("/tmp"), GENEROUS))
    with pytest.raises(SandboxError, match="system path"):
        run_sandboxed(["/bin/true"], SandboxSpec([Path("/")], [], Path("/tmp"), GENEROUS))
    with pytest.raises(SandboxError, match="not inside the sandbox's view"):
        run_sandboxed(["/bin/true"], SandboxSpec([], [], tmp_path, GENEROUS))
    bad = Limits(wall_seconds=1, cpu_seconds=0, memory_mb=1, processes=1, file_size_mb=1)
    with pytest.raises(SandboxError, match="cpu_seconds"):
        run_sandboxed(["/bin/true"], SandboxSpec([], [], Path("/tmp"), bad))


def cli(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(
        [PYTHON, "-m", "maa_sim.sandbox", *args], capture_output=True, text=True, check=False, timeout=300
    )


def test_the_cli_explains_itself_and_its_errors(tmp_path: Path) -> None:
    assert "--ros-domain" in cli("--help").stdout
    missing = cli("--ro", str(tmp_path / "nope"), "--", "/bin/true")
    assert missing.returncode == 125
    assert missing.stderr.strip() == f"maa-sandbox: the read-only path {tmp_path / 'nope'} does not exist"
    no_command = cli("--rw", str(tmp_path))
    assert no_command.returncode == 2 and "no command given" in no_command.stderr


def test_the_cli_passes_output_and_exit_code_through(tmp_path: Path) -> None:
    code = "import os, sys; print(os.environ['ROS_DOMAIN_ID'], os.getcwd()); sys.exit(3)"
    done = cli("--rw", str(tmp_path), "--ros-domain", "5", "--", PYTHON, "-c", code)
    assert done.stdout == f"5 {tmp_path}\n"
    assert done.returncode == 3
    assert done.stderr.strip().endswith("maa-sandbox: exited with 3")


def test_the_cli_forwards_sigterm_so_the_command_stops_gracefully(tmp_path: Path) -> None:
    code = """
import signal, sys, time
signal.signal(signal.SIGTERM, lambda *_: (print("stopping", flush=True), sys.exit(0)))
print("ready", flush=True)
while True:
    time.sleep(1)
"""
    proc = subprocess.Popen(
        [PYTHON, "-m", "maa_sim.sandbox", "--rw", str(tmp_path), "--", PYTHON, "-c", code],
        stdout=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    assert proc.stdout is not None
    assert proc.stdout.readline() == "ready\n"
    os.killpg(proc.pid, signal.SIGTERM)  # as the lab's simulation sessions stop a simulation
    assert proc.stdout.read() == "stopping\n"
    assert proc.wait(timeout=120) == 0


@pytest.mark.skipif(not ROOT, reason="becomes another user with setpriv to play a service that is not root")
def test_a_service_that_is_not_root_gets_a_user_namespace_instead() -> None:
    # The interpreter lies under /root here, so the sandbox's command line (as built for a caller
    # that is not root) is run by `nobody` with a shell program instead of run_sandboxed itself.
    base = Path(tempfile.mkdtemp(prefix="maa-sandbox-nobody-"))  # pytest's tmp_path is root's own
    try:
        check_as_nobody(base)
    finally:
        shutil.rmtree(base)


def check_as_nobody(base: Path) -> None:
    out = base / "out"
    out.mkdir()
    os.chown(base, 65534, 65534)
    os.chown(out, 65534, 65534)
    secret = base / "secret.txt"
    secret.write_text("other student's work")
    secret.chmod(0o644)
    limits = Limits(wall_seconds=60, cpu_seconds=10, memory_mb=512, processes=16, file_size_mb=16)
    sandbox = SandboxSpec(readonly=[], writable=[out], cwd=out, limits=limits)
    program = f"id -u; echo written > out.txt; cat {secret} || echo unreadable; grep CapEff /proc/self/status"
    command = build_command(["/bin/sh", "-c", program], sandbox, [], None, None, nproc_base=8)
    assert "--unshare-user" in command and "setpriv" not in command
    done = subprocess.run(
        ["setpriv", "--reuid=65534", "--regid=65534", "--clear-groups", *command],
        capture_output=True,
        text=True,
        check=False,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr
    lines = done.stdout.split("\n")
    assert lines[0] == "65534"
    assert lines[1] == "unreadable"
    assert lines[2].split() == ["CapEff:", "0000000000000000"]
    assert (out / "out.txt").read_text() == "written\n"


def test_an_interpreter_with_a_repository_root_on_its_path_is_refused(tmp_path: Path) -> None:
    # A stand-in interpreter that answers what python_view asks: its prefixes and sys.path.
    venv = tmp_path / "repo" / ".venv"
    (venv / "bin").mkdir(parents=True)
    fake = venv / "bin" / "python"
    answer = json.dumps(["/usr", "/usr", str(venv), "/usr/lib/python3", str(tmp_path / "repo")])
    fake.write_text(f"#!/bin/sh\necho '{answer}'\n")
    fake.chmod(0o755)
    with pytest.raises(SandboxError, match="which holds its whole venv"):
        run_sandboxed([str(fake), "-c", "pass"], spec(tmp_path))
