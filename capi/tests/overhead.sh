#!/usr/bin/env bash
# The C boundary's cost on the host, in instructions per step (valgrind callgrind, exact and
# load-independent): inside `contensou_contact_wrench_*` (the exported function, as C calls
# it) against inside `rust_step_*` (`DynContact::wrench` directly), per law × form ×
# precision, 1,024 calls each (examples/overhead.rs). Prints a CSV on stdout.
set -euo pipefail
cd "$(dirname "$0")/.."
cargo build --release --quiet --example overhead
exe=target/release/examples/overhead
out="$(mktemp -d)"
trap 'rm -rf "$out"' EXIT
echo "law,form,precision,c_insns,rust_insns"
for form in fixed varying; do
    for law in best simplified pade ellipsoid coulomb; do
        for precision in f32 f64; do
            n=()
            for fn in "contensou_contact_wrench_$precision" "*rust_step_$precision"; do
                valgrind --tool=callgrind --callgrind-out-file="$out/cg" --toggle-collect="$fn" \
                    "$exe" "$law" "$form" >/dev/null 2>&1
                ir="$(callgrind_annotate "$out/cg" 2>/dev/null | awk '/PROGRAM TOTALS/ { gsub(",", "", $1); print $1 }')"
                n+=("$((ir / 1024))")
            done
            echo "$law,$form,$precision,${n[0]},${n[1]}"
        done
    done
done
