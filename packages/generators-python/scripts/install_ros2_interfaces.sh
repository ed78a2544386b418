#!/usr/bin/env bash
# Builds a generated <pkg>_interfaces package (ros2.DataTypes) and installs it into the prefix of a
# Python venv that has rclpy (PyPI ROS 2 wheels), so that nodes run by that Python, and maa-sim when
# it runs there, import the generated messages:
#
#   bash packages/generators-python/scripts/install_ros2_interfaces.sh VENV INTERFACES_DIR
#   e.g. ... sim-server/.venv generated/rospython/toast_service_robot_interfaces
#
# Installs the rosidl toolchain (the pins of requirements-ros2.txt) into VENV when it is missing, and
# Debian's cmake and g++ are needed. Skips the build while the package's sources are unchanged (a
# digest in VENV/share/<pkg>/maa-source.sha256). Do not point LD_LIBRARY_PATH at a separate install
# prefix instead: that crashes rclpy (docs/generating-ros2.md).
set -euo pipefail

if [[ $# -ne 2 ]]; then
  echo "usage: $0 VENV INTERFACES_DIR" >&2
  exit 2
fi
here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
venv="$(cd "$1" && pwd)"
src="$(cd "$2" && pwd)"
python="$venv/bin/python"
pkg="$(basename "$src")"
[[ -x "$python" ]] || { echo "install_ros2_interfaces: $python is missing" >&2; exit 1; }
[[ -f "$src/package.xml" && -f "$src/CMakeLists.txt" ]] || { echo "install_ros2_interfaces: $src is no ament_cmake package" >&2; exit 1; }
for tool in cmake g++; do
  command -v "$tool" >/dev/null 2>&1 || { echo "install_ros2_interfaces: $tool is needed (apt-get install cmake g++)" >&2; exit 1; }
done
"$python" -c 'import rclpy' 2>/dev/null || { echo "install_ros2_interfaces: $python has no rclpy" >&2; exit 1; }

if ! "$python" -c 'import rosidl_adapter, catkin_pkg, ament_package' 2>/dev/null; then
  echo "install_ros2_interfaces: installing the rosidl toolchain into $venv"
  grep -E '^(ros-rosidl|ros-ament|catkin-pkg|setuptools|wheel)' "$here/requirements-ros2.txt" > "$venv/.maa-rosidl-requirements.txt"
  PIP_DISABLE_PIP_VERSION_CHECK=1 "$python" -m pip install --quiet -r "$venv/.maa-rosidl-requirements.txt"
fi

digest="$(cd "$src" && find . -type f -print0 | sort -z | xargs -0 sha256sum | sha256sum | cut -d' ' -f1)"
stamp="$venv/share/$pkg/maa-source.sha256"
if [[ -f "$stamp" && "$(cat "$stamp")" == "$digest" ]] && "$python" -c "import $pkg.msg" 2>/dev/null; then
  echo "install_ros2_interfaces: $pkg is up to date in $venv"
  exit 0
fi

build="$(mktemp -d "${TMPDIR:-/tmp}/maa-iface-XXXXXX")"
trap 'rm -rf "$build"' EXIT
export AMENT_PREFIX_PATH="$venv" PATH="$venv/bin:$PATH"
cd "$build"
cmake "$src" -DCMAKE_INSTALL_PREFIX="$venv" -DPython3_EXECUTABLE="$python" -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF >build.log 2>&1 \
  && cmake --build . --parallel 2 >>build.log 2>&1 \
  && cmake --install . >>build.log 2>&1 \
  || { tail -40 build.log >&2; echo "install_ros2_interfaces: the build of $pkg failed" >&2; exit 1; }
"$python" -c "import $pkg.msg"
echo "$digest" > "$stamp"
echo "install_ros2_interfaces: $pkg installed into $venv"
