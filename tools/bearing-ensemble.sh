#!/usr/bin/env bash
# The bearing's step-aware figures against fine-step RK4 over five load ramps and 60–80 ms means:
# builds the runner (examples/scene.rs) and writes bench-results/bearing-ensemble.{csv,md}
# (tools/bearing-ensemble.py). A few minutes on a loaded 2-core machine.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --features scenes --example scene
python3 tools/bearing-ensemble.py
