#!/usr/bin/env bash
# The bearing's step-aware figures against fine-step RK4 in the steady state (300–400 ms means, three load ramps):
# builds the runner (examples/scene.rs) and writes bench-results/bearing-ensemble.{csv,md}
# (tools/bearing-ensemble.py). ≈ 8 minutes of CPU (two runs at a time).
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --features scenes --example scene --example bearing
python3 tools/bearing-ensemble.py
