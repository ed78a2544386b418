#!/usr/bin/env bash
# Creates packages/generators-python/.venv with the machine's python3 and the tools the tests of
# the Python generators need (pytest, ruff; pinned below). Idempotent: returns at once when the
# venv is up to date (same script, same interpreter). MAA_PY_FORCE_SETUP=1 reinstalls.
set -euo pipefail

here="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
venv="$here/.venv"
python="${PYTHON:-python3}"
stamp="$venv/.maa-setup"
packages=("pytest==9.2.0" "ruff==0.17.6")

if ! "$python" -c 'import sys; sys.exit(0 if sys.version_info >= (3, 11) else 1)' 2>/dev/null; then
  echo "setup_venv: Python 3.11 or newer is needed ($python)" >&2
  exit 1
fi
want="$(sha256sum "$0" | cut -d' ' -f1) $("$python" -c 'import sys; print(sys.version)' | head -1)"
if [[ "${MAA_PY_FORCE_SETUP:-0}" != 1 && -f "$stamp" && -x "$venv/bin/python" ]] && [[ "$(cat "$stamp")" == "$want" ]]; then
  echo "setup_venv: $venv is up to date"
  exit 0
fi
echo "setup_venv: creating $venv"
if [[ ! -x "$venv/bin/python" ]]; then
  "$python" -m venv "$venv"
fi
export PIP_DISABLE_PIP_VERSION_CHECK=1
"$venv/bin/python" -m pip install --quiet "${packages[@]}"
"$venv/bin/python" -c 'import pytest' && "$venv/bin/ruff" --version >/dev/null
echo "$want" > "$stamp"
echo "setup_venv: ready ($("$venv/bin/python" --version), $("$venv/bin/ruff" --version))"
