#!/usr/bin/env bash
# The scenes' step sweep, plain RK4 against the step-aware integrator: builds the runner
# (examples/scene.rs) and writes bench-results/step-sweep.csv and bench-results/step-sweep.md
# (tools/step-sweep.py). About 7 minutes on a loaded 2-core machine, most of it the bearing's three
# creep references (RK4 at 0.1 µs, ramps 5, 4.9 and 5.1 ms).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --features scenes --example scene
python3 tools/step-sweep.py
