#!/usr/bin/env bash
# The tools' own Python environment, on any machine: prints the path of a Python interpreter
# that has tools/requirements.txt (numpy, mpmath, matplotlib, maturin, scipy), creating or updating
# the venv target/tools-venv/ (git-ignored, reused by later runs: pip runs only when
# tools/requirements.txt is newer than the venv's stamp).
#
#   tools/batch-bench.sh                               # uses it itself
#   "$(tools/venv.sh)" tools/gen_hertz_ref.py          # any tools/*.py that imports numpy/mpmath/…
#   PYTHON=/my/venv/bin/python tools/batch-bench.sh    # or take your own environment
#
# Needs python3 with the venv module (Debian: python3-venv) and the package registry.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
venv="${CONTENSOU_TOOLS_VENV:-$root/target/tools-venv}"
req="$root/tools/requirements.txt"
if [[ ! -x "$venv/bin/python" ]]; then
    python3 -m venv "$venv" >&2
fi
if [[ ! -e "$venv/.requirements" || "$req" -nt "$venv/.requirements" ]]; then
    "$venv/bin/python" -m pip install --quiet --upgrade pip >&2
    "$venv/bin/python" -m pip install --quiet -r "$req" >&2
    cp "$req" "$venv/.requirements"
fi
echo "$venv/bin/python"
