#!/usr/bin/env bash
# The rattleback's sliding laws at the δ → 0 limit (fine-step RK4 per law, spin and δ): builds
# the runner (examples/scene.rs) and writes bench-results/rattleback-delta.{csv,md}
# (tools/rattleback-delta.py). A few minutes on a loaded 2-core machine.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --features scenes --example scene
python3 tools/rattleback-delta.py
