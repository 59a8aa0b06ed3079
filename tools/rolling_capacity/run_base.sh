#!/bin/bash
# Build /tmp/roll caches and reach parameters (the order of fit_rolling_long.py's docstring).
set -e
cd "$(dirname "$0")/../.."
PY="$(tools/venv.sh)"
[ -f /tmp/roll/reach_prm.npy ] || nice -n 10 $PY tools/fit_rolling_reach.py --degree 3
[ -f /tmp/roll/reach_prm_long.npy ] || nice -n 10 $PY tools/fit_rolling_long.py --refit-base --strip --variant log --kfold 0
