#!/usr/bin/env bash
# No-panic proof (issue 8): builds nopanic/ — a thumbv7em-none-eabihf image calling every
# public contensou entry point and every C API function (capi/, issue 15) on black-boxed inputs, f32 and f64, at opt-level 3 + fat LTO —
# whose panic handler calls a function that is never defined. The image links only if no
# panic path survives optimisation. Fails loudly otherwise, naming the probes (entry points)
# that still reach core::panicking and the library lines involved.
# Also checks that the proof is not vacuous: every probe is in the image, and a deliberately
# panicking probe (feature `canary`) makes the link fail.
set -euo pipefail
cd "$(dirname "$0")/../nopanic"
elf=target/thumbv7em-none-eabihf/release/contensou-nopanic
log=target/no-panic-build.log
mkdir -p target

locate() {
    # Rebuild with a real handler and list every call site of the panic machinery.
    cargo build --release --features "locate${1:+,$1}" >/dev/null 2>&1 || { echo "locate build failed too" >&2; return; }
    arm-none-eabi-objdump -d -C --no-show-raw-insn "$elf" | awk '
        /^[0-9a-f]+ <.*>:$/ { fn = $0; sub(/^[0-9a-f]+ </, "", fn); sub(/>:$/, "", fn); next }
        /\tb(l|\.w)?(\.n)?\t.*<(core::panicking|core::option::|core::result::unwrap_failed|core::slice::index)/ {
            if (fn ~ /^core::/) next
            addr = $1; sub(/:$/, "", addr); tgt = $0; sub(/.*</, "", tgt); sub(/>.*/, "", tgt)
            print addr "\t" fn "\t-> " tgt }' | sort -u -k2,3 > target/no-panic-sites.txt
    echo "Panic call sites (probe = public entry point reaching a panic):" >&2
    while IFS=$'\t' read -r addr fn tgt; do
        echo "  $fn $tgt" >&2
        arm-none-eabi-addr2line -i -f -C -e "$elf" "0x$addr" | paste - - | sed 's/^/      at /' >&2
    done < target/no-panic-sites.txt
}

echo "no-panic: building nopanic/ (release, fat LTO, thumbv7em-none-eabihf)"
if ! cargo build --release ${NOPANIC_FEATURES:+--features "$NOPANIC_FEATURES"} >"$log" 2>&1; then
    echo "NO-PANIC PROOF FAILED: the image does not link." >&2
    grep -E 'undefined symbol|referenced by|error' "$log" | head -n 20 >&2
    if grep -q 'undefined symbol: contensou_panic_path_survived' "$log"; then
        echo "=> a panic path survives optimisation in some public entry point." >&2
        locate "${NOPANIC_FEATURES:-}"
    else
        cat "$log" >&2
    fi
    exit 1
fi
probes="$(arm-none-eabi-nm -C "$elf" | grep -c 'contensou_nopanic::.*probe_')"
# probes! entries, plus four per law_probes! line; each in f32 and f64
laws="$(grep -cE '^\s+[A-Za-z]+: probe_tangential_' src/main.rs)"
expected=$((2 * ($(grep -cE '^\s+fn probe_[a-z_]+<T>' src/main.rs) + 4 * laws)))
# the micromath twins' probes (`*_mm`) are instantiated in f32 only
mm=$(($(grep -cE '^\s+fn probe_[a-z_]+_mm<T>' src/main.rs) + 4 * $(grep -cE '^\s+[A-Za-z]+: probe_tangential_[a-z_]+_mm,' src/main.rs)))
expected=$((expected - mm))
# the C API's exported functions (src/capi.rs): `probe_capi_*` per precision, `probe_capi_any_*` once
capi=$((2 * $(grep -cE '^\s+fn probe_capi_[a-z_]+\(' src/capi.rs) + $(grep -cE '^fn probe_capi_any_[a-z_]+\(' src/capi.rs)))
expected=$((expected + capi))
if ((probes != expected)); then
    echo "NO-PANIC PROOF VACUOUS: $probes probe instances in the image, expected $expected" >&2
    exit 1
fi
echo "no-panic: canary (a probe that can panic must make the link fail)"
if cargo build --release --features canary >"$log" 2>&1; then
    echo "NO-PANIC PROOF BROKEN: the canary build linked" >&2
    exit 1
fi
grep -q 'undefined symbol: contensou_panic_path_survived' "$log" || { cat "$log" >&2; exit 1; }
cargo build --release >/dev/null 2>&1
# Firmware often builds for size or without LTO: the proof must hold there too.
for variant in OPT_LEVEL=z LTO=false; do
    echo "no-panic: variant profile.release.${variant,,}"
    if ! env "CARGO_PROFILE_RELEASE_$variant" CARGO_TARGET_DIR="target/variant-${variant,,}" \
        cargo build --release >"$log" 2>&1; then
        echo "NO-PANIC PROOF FAILED with CARGO_PROFILE_RELEASE_$variant:" >&2
        grep -E 'undefined symbol|error' "$log" | head -n 20 >&2
        exit 1
    fi
done
echo "no-panic: OK — $probes probe instances ($((probes / 2)) entry-point probes × f32/f64) link without any panic path (opt-level 3 + fat LTO; also opt-level z, and no LTO)"
