"""The batch path from Python against hand-written numpy, and its scaling: markdown on stdout
(tools/batch-bench.sh puts it into bench-results/batch.md).

    python python/bench_batch.py [--quick]

- `Contact.wrench` on arrays (best, fixed, f64 and f32; the SIMD batch path) beside the pure
  numpy formula of the paper's simplified law (`numpy_simplified` in bench.py, circular patch)
  on the same rows, 1e4 … 1e6 rows: contacts per CPU-second of the calling thread.
- Threads: the rows split over k Python threads (concurrent.futures), each calling
  `Contact.wrench` on its chunk; the package releases the GIL for the whole call, so the
  chunks run in parallel. Wall-clock contacts/s, 1e6 rows.
"""

import argparse
import os
import sys
import time
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import contensou  # noqa: E402
from bench import CIRCLE, best_time, numpy_beside_contensou, steps_of  # noqa: E402


def wall(call, budget):
    """Minimum wall-clock time of `call()` (bench.best_time on time.perf_counter)."""
    return best_time(call, budget, clock=time.perf_counter)


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args()
    sizes = [10_000, 100_000] if args.quick else [10_000, 100_000, 1_000_000]
    budget = 0.05 if args.quick else 0.4
    print("### Python: `Contact.wrench` (batch path) against pure numpy")
    print()
    print("P = Q = 50 /m, E* = 115 GPa, c_d = 0.2, f = 0.3, δ = 1e-4 (bench.py's `CIRCLE`); rows from "
          "python/tests/rows.py. Contacts per CPU-second of the calling thread (minimum over repeats).")
    print()
    print("| rows | precision | numpy simplified | contensou simplified | contensou best | best / numpy |")
    print("|---:|---|---:|---:|---:|---:|")
    for n, precision, _, t_np, res in numpy_beside_contensou(sizes, budget):
        t = {law: time for law, (time, _) in res.items()}
        print(f"| {n:,} | {precision} | {n / t_np / 1e6:.1f} M | {n / t['simplified'] / 1e6:.1f} M "
              f"| {n / t['best'] / 1e6:.1f} M | {t_np / t['best']:.2f}× |")
    print()
    n = sizes[-1]
    cores = os.cpu_count() or 1
    print(f"### Python: threads (best, fixed, f32, {n:,} rows split in k chunks; wall clock, {cores} cores)")
    print()
    print("| threads | contacts/s | speedup |")
    print("|---:|---:|---:|")
    _, st = steps_of(n, "f32", seed=4)
    c = contensou.Contact(**CIRCLE, law="best", precision="f32")
    base = None
    for k in sorted({1, 2, cores}):
        chunks = [[col[i * n // k:(i + 1) * n // k] for col in st] for i in range(k)]
        with ThreadPoolExecutor(k) as pool:
            t = wall(lambda: list(pool.map(lambda ch: c.wrench(*ch), chunks)), budget)
        base = base or t
        print(f"| {k} | {n / t / 1e6:.1f} M | {base / t:.2f}× |")


if __name__ == "__main__":
    main()
