#!/usr/bin/env bash
# Creates sim-server/.venv with the machine's python3 and installs maa-sim with its test and grade extras
# (pinned versions, see pyproject.toml). Idempotent: when the venv is up to date (same
# pyproject.toml, same interpreter) it returns at once. Set MAA_SIM_FORCE_SETUP=1 to reinstall.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
venv="$here/.venv"
python="${PYTHON:-python3}"
stamp="$venv/.maa-sim-setup"

if ! command -v "$python" >/dev/null 2>&1; then
  echo "setup_env: $python not found (Python 3.11 or newer is needed)" >&2
  exit 1
fi
if ! "$python" -c 'import sys; sys.exit(0 if sys.version_info >= (3, 11) else 1)'; then
  echo "setup_env: $("$python" --version 2>&1) is too old (Python 3.11 or newer is needed)" >&2
  exit 1
fi

# maa_sim.sandbox runs students' code in bubblewrap (grading runs, the lab's live simulations); the
# test command installs Debian's bubblewrap when missing (scripts/ensure-bubblewrap.mjs).
if ! command -v bwrap >/dev/null 2>&1 && [[ ! -x "${MAA_BWRAP:-/usr/bin/bwrap}" ]]; then
  echo "setup_env: bubblewrap (bwrap) is missing; maa_sim.sandbox needs it: apt-get install -y bubblewrap" >&2
fi

want="$(cat "$here/pyproject.toml" "$0" | sha256sum | cut -d' ' -f1) $("$python" -c 'import sys; print(sys.version)' | head -1)"
if [[ "${MAA_SIM_FORCE_SETUP:-0}" != 1 && -f "$stamp" && -x "$venv/bin/python" ]] && [[ "$(cat "$stamp")" == "$want" ]]; then
  echo "setup_env: $venv is up to date"
  exit 0
fi

echo "setup_env: creating $venv"
if [[ ! -x "$venv/bin/python" ]]; then
  "$python" -m venv "$venv"
fi
export PIP_DISABLE_PIP_VERSION_CHECK=1
"$venv/bin/python" -m pip install --quiet --upgrade "pip>=24"
"$venv/bin/python" -m pip install --quiet -e "$here[test,grade]"
# a quick check that the pieces load (rclpy needs its libraries, MuJoCo its model compiler)
"$venv/bin/python" -c 'import rclpy, mujoco, viser, websockets, std_msgs.msg, sensor_msgs.msg, rosgraph_msgs.msg, rcl_interfaces.srv; import maa_sim.world as w; w.ToastKitchen()'
echo "$want" > "$stamp"
echo "setup_env: ready ($("$venv/bin/python" --version), mujoco $("$venv/bin/python" -c 'import mujoco; print(mujoco.__version__)'))"
