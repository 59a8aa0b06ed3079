#!/usr/bin/env bash
# The scene table of contensou::select → bench-results/scenes.csv: per scene configuration ×
# precision, the contact type chosen, M4F instructions per step (QEMU, the firmware's `scenes`
# binary: same rig and input set as tools/qemu-bench.sh's stage `scene` rows), flash bytes the
# configuration adds to an empty firmware (size probe: Select::build + one wrench step, see
# tools/flash-bench.sh) and the max error against exact references on the host
# (`cargo run --release --example scene_error`). Prints the same table as markdown.
# Takes about 1 minute (18 probe builds, one QEMU run, one host example run).
# Needs: what tools/qemu-bench.sh and tools/flash-bench.sh need.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$root/bench-results"
tmp="$(mktemp -d)"
trap 'rm -rf "$tmp"' EXIT

(cd "$root/firmware" && cargo run --release --locked --quiet --bin scenes | tr -d '\r') |
    awk '$1 == "BENCH" && $2 == "scene" { sub(/^insns=/, "", $5); print $3 "," $4 "," $5 }' \
        >"$tmp/insns.csv"
"$root/tools/flash-bench.sh" --stage scene | sed 's/^scene,//' >"$tmp/flash.csv"
# Without the feature: every configuration (libm); with it: the f32 rows resolving to a
# micromath twin (keys ending -micromath).
(cd "$root" && cargo run --release --quiet --example scene_error) | tail -n +2 >"$tmp/err.csv"
(cd "$root" && cargo run --release --quiet --features micromath --example scene_error) |
    tail -n +2 >>"$tmp/err.csv"

{
    echo "# contensou::select scene table (tools/scene-bench.sh). scene: the configuration"
    echo "# (<geometry>-spin-<budget> or <geometry>-nospin[-rough]; sphere-plane = Circular+Fixed,"
    echo "# ball-race = Elliptic+Fixed, varying = Elliptic+Varying; -micromath: what an f32"
    echo "# declaration resolves to with the feature micromath, where that differs; rough rows"
    echo "# without it = the coarse ones); contact, normal, law: what the declaration resolves to;"
    echo "# insns: M4F instructions per step (QEMU, 64 mixed slips);"
    echo "# flash_bytes: .text+.rodata+.data the configuration adds to an empty firmware"
    echo "# (construction from curvatures + step); n_rel, a_rel: max relative error of N and a;"
    echo "# force_fn, torque_fna: max |F - F_exact|/(fN), |T - T_exact|/(fNa) against f64 Newton"
    echo "# Hertz + the exact integrals (e2 <= 0.99, delta = 0); *_bound_*: the budget's bounds"
    echo "# (N, a: 2e-6, rough 6.5e-2)."
    echo "scene,precision,contact,normal,law,insns,flash_bytes,n_rel,a_rel,force_fn,torque_fna,force_bound_fn,torque_bound_fna"
    awk -F, -v OFS=, '
        FILENAME == ARGV[1] { insns[$1 "," $2] = $3; next }
        FILENAME == ARGV[2] { flash[$1 "," $2] = $3; next }
        {
            k = $1 "," $2
            if (!(k in insns) || !(k in flash)) { print "scene-bench: no count for " k > "/dev/stderr"; exit 1 }
            print $1, $2, $3, $4, $5, insns[k], flash[k], $6, $7, $8, $9, $10, $11
        }' "$tmp/insns.csv" "$tmp/flash.csv" "$tmp/err.csv"
} >"$out/scenes.csv"

echo "| scene | precision | contact | normal | law | insns/step | flash bytes | N rel. | F (fN) | T_z (fNa) |"
echo "|---|---|---|---|---|---|---|---|---|---|"
grep -v '^#' "$out/scenes.csv" | tail -n +2 |
    awk -F, '{ printf "| %s | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n", $1, $2, $3, $4, $5, $6, $7, $8, $10, $11 }'
echo "wrote bench-results/scenes.csv" >&2
