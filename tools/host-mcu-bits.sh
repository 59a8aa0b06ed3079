#!/usr/bin/env bash
# Host = MCU, bit for bit (issue 15 item 5): the shared f32 test vectors
# (capi/examples/firmware/vectors.rs and its C twin vectors.c: 10,240 states × 5 laws × 2 forms,
# valid extremes included) evaluated on the Cortex-M4F under QEMU must give exactly the bits
# that x86-64 gives through contensou::dynamic (examples/host_mcu_bits.rs).
#
# MCU images (each streams one line of hex output bits per state over semihosting, ≈6 MB):
#   rust  firmware/src/bin/bits.rs        contensou::dynamic, rustc → thumbv7em-none-eabihf
# QEMU runs without -icount (nothing is counted here; it only slows the run down).
# Writes bench-results/host-mcu-bits.txt (the per-law verdicts and the time taken); fails on any
# differing bit, with the first differing state and the largest difference in ulps.
# Needs: rustup, qemu-system-arm.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
cd "$root"
start=$SECONDS
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
qemu=(timeout 120 qemu-system-arm -cpu cortex-m4 -machine netduinoplus2 -nographic
    -semihosting-config enable=on,target=native -kernel)

# Rust image: built from firmware/ (its .cargo/config.toml and pinned toolchain apply there only).
(cd firmware && cargo build --release --locked --quiet --bin bits)
"${qemu[@]}" firmware/target/thumbv7em-none-eabihf/release/bits >"$tmp/rust-mcu.txt"

cargo build --quiet --example host_mcu_bits
status=0
(cd "$tmp" && "$root/target/debug/examples/host_mcu_bits" *.txt) >"$tmp/verdict" || status=$?
{
    echo "# tools/host-mcu-bits.sh: x86-64 (contensou::dynamic) vs Cortex-M4F under QEMU"
    echo "# $(rustc --version); firmware $(cd firmware && rustc --version); $(qemu-system-arm --version | head -n 1)"
    cat "$tmp/verdict"
    echo "# $((SECONDS - start)) s (build included)"
} | tee bench-results/host-mcu-bits.txt
exit "$status"
