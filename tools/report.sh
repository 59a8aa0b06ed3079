#!/usr/bin/env bash
# The one command: re-measure, then regenerate docs/report.md and docs/report/*.png.
#
#   tools/report.sh              # benches (host ns, QEMU, and flash/scenes/stability if their
#                                # scripts exist), then the report
#   tools/report.sh --no-bench   # the report alone, from the recorded bench-results/*.csv
#
# Steps (each optional one is skipped when its script or example is absent):
#   tools/host-ns.sh                        -> bench-results/host-ns.csv (criterion, short runs)
#   tools/qemu-bench.sh                     -> bench-results/qemu.csv (needs qemu-system-arm)
#   tools/flash-bench.sh                    -> bench-results/flash.csv
#   tools/scene-bench.sh                    -> bench-results/scenes.csv
#   cargo run --release --example stability -> docs/report/stability/*.csv, stability.md
#   cargo run --release --example report    -> docs/report.md, docs/report/*.png
set -euo pipefail
cd "$(dirname "$0")/.."
bench=1
for a in "$@"; do
    case "$a" in
        --no-bench) bench=0 ;;
        *) echo "usage: tools/report.sh [--no-bench]" >&2; exit 2 ;;
    esac
done
step() { echo "== $*" >&2; }
if [[ $bench == 1 ]]; then
    step "host ns (criterion)"
    tools/host-ns.sh
    step "QEMU instructions"
    tools/qemu-bench.sh >/dev/null
    for s in flash-bench scene-bench; do
        if [[ -x tools/$s.sh ]]; then
            step "$s"
            "tools/$s.sh"
        fi
    done
fi
if [[ -e examples/stability.rs || -e examples/stability/main.rs ]]; then
    step "stability"
    cargo run --release --quiet --example stability
fi
step "report"
# optional backends declared in Cargo.toml go on the charts as their own points
features=()
grep -q '^micromath *=' Cargo.toml && features=(--features micromath)
cargo run --release --quiet "${features[@]}" --example report
