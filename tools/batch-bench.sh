#!/usr/bin/env bash
# The batch path's throughput, one command:
#   tools/batch-bench.sh            # regenerates bench-results/batch.csv, batch.md,
#                                   # batch-scaling.csv and docs/report/batch/scaling.png
# 1. criterion (benches/batch.rs): the scalar loop and wrench_many on the same 4,096 rows, every
#    law × form × precision in one run → batch.csv (law,form,precision,scalar_ns,batch_ns,speedup;
#    ns per contact, criterion's mean).
# 2. examples/batch_scaling.rs: contacts/s against rows 1e3…1e7 and over threads → the chart.
# 3. python/bench_batch.py: Contact.wrench (the batch path) against pure numpy, and threads;
#    the package is built into a private directory (maturin; nothing installed in the venv).
#    PYTHON (default: the tools' own venv, tools/venv.sh → target/tools-venv, created on first
#    use) needs numpy and maturin.
# The machine's SIMD level (what the batch path dispatched to) is written into batch.md.
set -euo pipefail
cd "$(dirname "$0")/.."
py="${PYTHON:-$(tools/venv.sh)}"
md=bench-results/batch.md
csv=bench-results/batch.csv
log="$(mktemp)"

echo "batch-bench: criterion (benches/batch.rs)"
cargo bench --bench batch 2>"$log" >/dev/null || { cat "$log" >&2; exit 1; }
level="$(sed -n 's/^batch level: //p' "$log" | head -n 1)"
"$py" - "$csv" <<'PY'
import json, sys
from pathlib import Path
rows = ["law,form,precision,scalar_ns,batch_ns,speedup"]
for law in ["best", "simplified", "pade", "ellipsoid", "coulomb"]:
    for form in ["fixed", "varying", "varying_at"]:
        for precision in ["f32", "f64"]:
            d = Path(f"target/criterion/batch_{law}_{form}_{precision}")
            ns = [json.loads((d / k / "new/estimates.json").read_text())["mean"]["point_estimate"] / 4096
                  for k in ["scalar", "batch"]]
            rows.append(f"{law},{form},{precision},{ns[0]:.2f},{ns[1]:.2f},{ns[0] / ns[1]:.2f}")
Path(sys.argv[1]).write_text("\n".join(rows) + "\n")
PY

echo "batch-bench: scaling (examples/batch_scaling.rs)"
cargo run --release --quiet --example batch_scaling 2>>"$log"

echo "batch-bench: Python (python/bench_batch.py)"
pydir="$(mktemp -d)"
(cd python && "$py" -m maturin build --release --quiet -o "$pydir/wheel" >/dev/null 2>>"$log")
"$py" -m pip install --quiet --no-deps --target "$pydir/site" "$pydir"/wheel/*.whl
python_md="$(PYTHONPATH="$pydir/site" "$py" python/bench_batch.py)"
rm -rf "$pydir"

flags="$(grep -m1 -o -w -E 'avx512f|avx2|avx|sse4_2|sse2|fma' /proc/cpuinfo 2>/dev/null | sort -u | tr '\n' ' ' || true)"
cpu="$(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | sed 's/.*: //' || uname -m)"
{
    echo "# Batch path throughput (\`tools/batch-bench.sh\`)"
    echo
    echo "Regenerate: \`tools/batch-bench.sh\`. Machine: $cpu, $(nproc) cores, load average at the end $(cut -d' ' -f1-3 /proc/loadavg);"
    echo "CPU flags: ${flags:-?}. **SIMD level used by the batch path: ${level:-?}** (8 × f32 / 4 × f64 lanes for avx2, 4 / 2 for sse2)."
    echo
    echo "## Rust: scalar loop against \`wrench_many\` (criterion, same run)"
    echo
    echo "ns per contact on 4,096 rows (benches/batch.rs: the contract's contact, Hunt–Crossley damping, rows in"
    echo "contact with mixed slips); every batch row is bit for bit the scalar call's (host-tests/batch.rs). Forms:"
    echo "\`fixed\` (Contact), \`varying\` (VaryingContact, P, Q per row), \`varying_at\` (one P, Q for every row:"
    echo "\`wrench_many_at\`, the path of DynContact, the C API and Python)."
    echo
    echo "| law | form | precision | scalar ns | batch ns | speedup |"
    echo "|---|---|---|---:|---:|---:|"
    tail -n +2 "$csv" | awk -F, '{ printf "| %s | %s | %s | %s | %s | %s× |\n", $1, $2, $3, $4, $5, $6 }'
    echo
    echo "## Scaling with rows and threads (best, fixed; examples/batch_scaling.rs)"
    echo
    echo "![contacts/s against rows](../docs/report/batch/scaling.png)"
    echo
    echo "| precision | path | threads | rows | ns/contact | contacts/s |"
    echo "|---|---|---:|---:|---:|---:|"
    tail -n +2 bench-results/batch-scaling.csv | awk -F, '{ printf "| %s | %s | %s | %s | %s | %.3g |\n", $1, $2, $3, $4, $5, $6 }'
    echo
    echo "$python_md"
} >"$md"
rm -f "$log"
echo "batch-bench: wrote $md, $csv, bench-results/batch-scaling.csv, docs/report/batch/scaling.png"
