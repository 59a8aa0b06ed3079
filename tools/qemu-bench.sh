#!/usr/bin/env bash
# MCU rig (rig B): build the benchmark firmware for thumbv7em-none-eabihf, run it (and its
# `scenes` binary) twice under
# QEMU (netduinoplus2, -icount shift=0: TIM2 counts executed instructions), check the counts are
# deterministic, and write
#   bench-results/qemu.csv            stage,method,precision,insns (per call, overhead subtracted)
#   bench-results/qemu-run.txt        the firmware's full output (OVERHEAD, BENCH, DETAIL lines)
#   bench-results/firmware-size.txt   .text size (arm-none-eabi-size) and the toolchain used
#   bench-results/vsqrt-disasm.txt    disassembly proving f32 sqrt executes vsqrt.f32
#   bench-results/c-firmware-size.txt flash of the C firmware images (capi/examples/firmware/)
#   bench-results/cycles.csv          stage,method,precision,insns,cycles_lo,cycles_mid,cycles_hi
#                                     (Cortex-M4F cycle estimates per call, one row per qemu.csv
#                                     row: tools/cycle_model.py on a third, traced run)
#   bench-results/cycle-mix.csv       the executed mix per row (instructions, mid cycles by class)
#   bench-results/cycle-model-check.csv  the model against the TRM's stated cycles (bin `model`)
# The C image bench.elf (the C API's staticlib called from C, built by
# capi/examples/firmware/build.sh) runs after the Rust binaries: rows wrench,c-*-best,f32.
# Fails if a run fails, the runs differ, no BENCH line is printed, vsqrt.f32 is absent, or the
# traced instruction counts differ from the TIM2 counts (tools/cycle_model.py checks).
# Takes ≈2 min of CPU (the traced runs; 8 min wall measured on a loaded shared 2-core
# machine; ≈5 s without them).
# Needs: rustup, qemu-system-arm, binutils-arm-none-eabi (arm-none-eabi-objdump/-size/-nm),
# gcc-arm-none-eabi and libnewlib-arm-none-eabi (the C image), python3.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$root/bench-results"
mkdir -p "$out"

# Built from its own directory: firmware/.cargo/config.toml (target, runner) and
# firmware/rust-toolchain.toml (pinned compiler) apply only there, not with --manifest-path.
cd "$root/firmware"
chan="$(sed -n 's/^channel *= *"\(.*\)"/\1/p' rust-toolchain.toml)"
rustup toolchain list | grep -q "^$chan" || rustup toolchain install "$chan" --profile minimal
rustup target list --installed --toolchain "$chan" | grep -q '^thumbv7em-none-eabihf$' ||
    rustup target add --toolchain "$chan" thumbv7em-none-eabihf

cargo build --release --locked
"$root/capi/examples/firmware/build.sh" >/dev/null
c_bench="$root/capi/target/firmware/bench.elf"
elf="target/thumbv7em-none-eabihf/release/contensou-firmware"

# The main firmware, then the `scenes` binary (stage `scene` rows of contensou::select's
# configurations; a binary of its own so the main firmware's code and counts are unaffected),
# then `tippe` (row scene,tippe_top_8s,f32: 8 s of the tippe top, ≈2e8 instructions), then
# `step_scenes` (rows scene-step,<scene>,f32: one step-aware step of each scene), then
# `step_bearing` (row scene-step,bearing,f32: the bearing's step, a binary of its own), then the
# C image under the same QEMU command as the Rust runner (.cargo/config.toml).
runner="$(sed -n 's/^runner *= *"\(.*\)"/\1/p' .cargo/config.toml)"
run() {
    {
        cargo run --release --locked --quiet
        cargo run --release --locked --quiet --bin scenes
        cargo run --release --locked --quiet --bin tippe
        cargo run --release --locked --quiet --bin step_scenes
        cargo run --release --locked --quiet --bin step_bearing
        $runner "$c_bench"
    } | tr -d '\r'
}
first="$(run)"
second="$(run)"
if [[ "$first" != "$second" ]]; then
    echo "qemu-bench: counts differ between two runs" >&2
    diff <(echo "$first") <(echo "$second") >&2 || true
    exit 1
fi
echo "$first"

# Cycles: the same binaries (the C image too) once more under QEMU's exec log (tools/cycle_model.py, which
# also checks every traced count against TIM2), then the model's validation binary. The QEMU
# command is the cargo runner of .cargo/config.toml without its `timeout 120` and `-kernel`.
qemu="${runner#timeout * }"
qemu=(timeout 1800 ${qemu% -kernel})
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT
dir="target/thumbv7em-none-eabihf/release"
for bin in contensou-firmware scenes tippe step_scenes step_bearing c-bench; do
    bin_elf="$dir/$bin"
    [[ $bin != c-bench ]] || bin_elf="$c_bench"
    python3 "$root/tools/cycle_model.py" --elf "$bin_elf" --csv "$tmp/cycles.csv" \
        --mix "$tmp/mix.csv" $([[ $bin != contensou-firmware ]] || echo --mix-header) \
        --stdout "$tmp/traced-$bin.txt" -- "${qemu[@]}"
done
if [[ "$first" != "$(cat "$tmp"/traced-{contensou-firmware,scenes,tippe,step_scenes,step_bearing,c-bench}.txt | tr -d '\r')" ]]; then
    echo "qemu-bench: the traced run's counts differ from the plain run's" >&2
    exit 1
fi
python3 "$root/tools/cycle_model.py" --elf "$dir/model" --csv /dev/null \
    --check "$tmp/check.csv" -- "${qemu[@]}"

bench="$(grep '^BENCH ' <<<"$first" || true)"
[[ -n "$bench" ]] || { echo "qemu-bench: no BENCH line" >&2; exit 1; }
printf '%s\n' "$first" >"$out/qemu-run.txt"
{
    echo "stage,method,precision,insns"
    awk '$1 == "BENCH" {
        if (NF != 5 || $5 !~ /^insns=[0-9]+$/) { print "bad line: " $0 > "/dev/stderr"; exit 1 }
        sub(/^insns=/, "", $5); print $2 "," $3 "," $4 "," $5 }' <<<"$bench"
} >"$out/qemu.csv"
{
    echo "stage,method,precision,insns,cycles_lo,cycles_mid,cycles_hi"
    cat "$tmp/cycles.csv"
} >"$out/cycles.csv"
cp "$tmp/mix.csv" "$out/cycle-mix.csv"
cp "$tmp/check.csv" "$out/cycle-model-check.csv"

text="$(arm-none-eabi-size -A "$elf" | awk '$1 == ".text" { print $2 }')"
{
    echo ".text: $text bytes (contensou-firmware, release: opt-level 3, lto, codegen-units 1)"
    echo
    rustc --version
    qemu-system-arm --version | head -n 1
    echo
    echo "Allocated sections (arm-none-eabi-size -A; debug sections omitted):"
    arm-none-eabi-size -A "$elf" | awk 'NR > 1 && $1 ~ /^\./ && $1 !~ /^\.(debug|comment|ARM)/'
    echo
    echo "arm-none-eabi-size -B:"
    arm-none-eabi-size -B "$elf" | sed "s|$elf|contensou-firmware|"
    echo
    echo "Code size of the benchmarked functions and the crate's own symbols (bytes; the rest"
    echo "of .text is mostly semihosting formatting and soft-float/libm support routines):"
    arm-none-eabi-nm -S -C --size-sort "$elf" |
        grep -E ' [[:alpha:]] (contensou_firmware::bench_|contensou::)' |
        while read -r _ size _ name; do printf '%6d  %s\n' "$((16#$size))" "$name"; done
} >"$out/firmware-size.txt"

cp "$root/capi/target/firmware/size.txt" "$out/c-firmware-size.txt"

# vsqrt proof: Real::sqrt for f32 is inline `vsqrt.f32` (src/hw_sqrt.rs): the sqrt benchmark
# executes it, and the f32 AGM executes it with no call to a software sqrt.
dis="$(arm-none-eabi-objdump -d -C --no-show-raw-insn "$elf")"
func() { awk -v pat="$1" 'index($0, pat) && /^[0-9a-f]+ <.*>:$/ { p = 1 } p && /^$/ { exit } p' <<<"$dis"; }
bench_fn="$(func '<contensou_firmware::bench_core::sqrt_vsqrt>:')"
# The f32 AGM: the benchmark wrapper, plus the library function if the wrapper calls it.
agm32="$(func '<contensou_firmware::bench_elliptic::integrals::<contensou::elliptic::agm::Agm, f32>>:')
$(func '<<contensou::elliptic::agm::Agm as contensou::elliptic::Method>::integrals::<f32>>:')"
{
    echo "# arm-none-eabi-objdump -d -C $(basename "$elf")  (regenerated by tools/qemu-bench.sh)"
    echo "# Real::sqrt for f32 = contensou::hw_sqrt::imp::sqrtf, inline asm: vmov s0 / vsqrt.f32 / vmov."
    echo "# The core/vsqrt benchmark function:"
    echo "$bench_fn"
    echo
    echo "# vsqrt.f32 inside the f32 AGM (one per square root), and any call to a sqrt routine:"
    grep -E 'vsqrt\.f32|b(l|\.w)?[[:space:]].*sqrt' <<<"$agm32" || true
} >"$out/vsqrt-disasm.txt"
fail=0
grep -q 'vsqrt\.f32' <<<"$bench_fn" ||
    { echo "qemu-bench: core/vsqrt benchmark does not execute vsqrt.f32" >&2; fail=1; }
grep -q 'vsqrt\.f32' <<<"$agm32" ||
    { echo "qemu-bench: f32 AGM does not execute vsqrt.f32" >&2; fail=1; }
if grep -qE 'bl?(\.w)?[[:space:]].*<[^>]*sqrt' <<<"$agm32"; then
    echo "qemu-bench: f32 AGM calls a square-root routine" >&2; fail=1
fi
((fail == 0)) || exit 1
echo "vsqrt check: ok"

echo "wrote bench-results/{qemu.csv,cycles.csv,cycle-mix.csv,cycle-model-check.csv,qemu-run.txt,firmware-size.txt,c-firmware-size.txt,vsqrt-disasm.txt} (.text $text bytes)"
