#!/usr/bin/env bash
# The scenes' step sweep, plain RK4 against the step-aware integrator: builds the runner
# (examples/scene.rs) and writes bench-results/step-sweep.csv and bench-results/step-sweep.md
# (tools/step-sweep.py). About 2 minutes on 2 cores, most of it the bearing's creep reference.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --features scenes --example scene
python3 tools/step-sweep.py
