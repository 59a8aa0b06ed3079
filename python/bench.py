"""Throughput of the Python package: contacts per second, written to bench-results/python.md.

    python python/bench.py                 # the full table (≈2 min), into bench-results/python.md
    python python/bench.py --quick --out -  # a smoke run (CI), printed

Times are CPU seconds of the calling thread (time.thread_time: the row loop runs there with
the GIL released; on a shared machine wall time also counts other processes), the minimum
over repeats. Steps are random valid rows (tests/rows.py: e^2 of the patch fixed per contact,
slip, spin and approach over decades, 10 % contact loss).

Cases, side by side in one run:
- Contact.wrench(h, hdot, vx, vy, omega) on arrays: a contact built once (an ellipse, P/Q = 0.4);
- contensou.wrench(...) per row, every row its own contact (all 11 columns arrays), and with
  scalar contact columns (the contact is then reused);
- one scalar call (Python floats in, numpy scalars out);
- a pure-numpy implementation of the simplified law on a circular patch (sphere on plane,
  closed-form Hertz), beside contensou's simplified and best on the same contact.
"""

import argparse
import platform
import sys
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent / "tests"))
import contensou  # noqa: E402
from rows import contract_rows  # noqa: E402

ELLIPSE = {"P": 20.0, "Q": 50.0, "estar": 1.15e11, "cd": 0.2, "f": 0.3, "delta": 1e-4}
CIRCLE = {"P": 50.0, "Q": 50.0, "estar": 1.15e11, "cd": 0.2, "f": 0.3, "delta": 1e-4}
STEPS = contensou.INPUTS[6:]
DTYPE = {"f32": np.float32, "f64": np.float64}


def best_time(call, budget, clock=time.thread_time):
    """Minimum time of `call()` on `clock` (default: the calling thread's CPU time) over
    repeats filling `budget` seconds (at least 2 calls, one if a call exceeds the budget)."""
    times = []
    spent = 0.0
    while len(times) < 2 or spent < budget:
        t0 = clock()
        call()
        dt = clock() - t0
        times.append(dt)
        spent += dt
        if dt > budget:
            break
    return min(times)


def numpy_beside_contensou(sizes, budget):
    """Pure numpy's simplified law beside contensou's simplified and best on `CIRCLE` (a Contact
    built once), for each size and precision (rows from steps_of, seed 3): yields (rows,
    precision, the step columns, numpy's time, {law: (contensou's time, its result)})."""
    for n in sizes:
        for precision in ["f64", "f32"]:
            _, st = steps_of(n, precision, seed=3)
            t_np = best_time(lambda: numpy_simplified(CIRCLE, *st), budget)
            res = {}
            for law in ["simplified", "best"]:
                c = contensou.Contact(**CIRCLE, law=law, precision=precision)
                res[law] = (best_time(lambda: c.wrench(*st), budget), c.wrench(*st))
            yield n, precision, st, t_np, res


def numpy_simplified(spec, h, hdot, vx, vy, omega):
    """The simplified law (src/friction/simplified.rs) on a circular Hertz patch (P = Q):
    R = 1/(2P), a = sqrt(R h), N = (4/3) E* sqrt(R) h^(3/2) (1 + (3/2) c_d hdot) >= 0;
    A = B = 3π/8, C = 3π/16, u_T = 1/(5C); every component on its own width (δ regularized)."""
    dtype = h.dtype.type
    one = dtype(1)
    r = one / (dtype(2) * dtype(spec["P"]))
    hp = np.maximum(h, dtype(0))
    a = np.sqrt(r * hp)
    n = dtype(4.0 / 3.0) * dtype(spec["estar"]) * np.sqrt(r) * hp * np.sqrt(hp)
    n = np.maximum(n * (one + dtype(1.5 * spec["cd"]) * hdot), dtype(0))
    fn = dtype(spec["f"]) * n
    delta = max(dtype(spec["delta"]), np.finfo(dtype).tiny)
    knee, c = dtype(8 / (3 * np.pi)), dtype(3 * np.pi / 16)
    aw = a * omega
    abs_aw = np.abs(aw)
    v2 = vx * vx + vy * vy
    v = np.sqrt(v2)
    denom = np.maximum(np.maximum(v, delta), abs_aw * knee)
    with np.errstate(divide="ignore", invalid="ignore"):
        fx = -fn * vx / denom
        fy = -fn * vy / denom
        plateau = c / abs_aw
        hyperbola = v2 / (dtype(5) * v2 * v)
        t = -aw * np.where(hyperbola < plateau, hyperbola, plateau)
        spin = abs_aw / (dtype(5) * c)
        t = np.where(spin < delta, np.where(spin > 0, t * (spin / delta), dtype(0)), t)
    return {"N": n, "Fx": fx, "Fy": fy, "Tz": fn * a * t, "a": a, "b": a}


def steps_of(n, precision, seed=1):
    rows = contract_rows(n, seed=seed, dtype=DTYPE[precision])
    return rows, [rows[c] for c in STEPS]


def grid(sizes, seed):
    """(rows, precision, law, form, steps_of(...)) over the benchmark grid."""
    for n in sizes:
        for precision in ["f64", "f32"]:
            data = steps_of(n, precision, seed=seed)
            for law in ["best", "simplified"]:
                for form in ["fixed", "varying"]:
                    yield n, precision, law, form, data
            print(f"{n} {precision}", file=sys.stderr)


def rate(n, seconds):
    return n / seconds


def fmt(x):
    return f"{x / 1e6:.2f} M" if x >= 1e6 else f"{x / 1e3:.0f} k"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", default=str(Path(__file__).resolve().parents[1] / "bench-results/python.md"),
                    help="markdown file to write ('-': stdout)")
    ap.add_argument("--quick", action="store_true", help="sizes 1e3 and 1e4 only, short budget (smoke run)")
    args = ap.parse_args()
    sizes = [1_000, 10_000] if args.quick else [1_000, 100_000, 1_000_000]
    budget = 0.02 if args.quick else 0.5
    lines = []
    out = lines.append

    out("# Python package throughput (`python/bench.py`)")
    out("")
    out(f"Regenerate: `python python/bench.py` (in a venv with `pip install ./python numpy`). "
        f"CPU time of the calling thread, minimum over repeats; contacts per CPU-second on one core.")
    out("")
    out(f"Machine: {platform.machine()}, {platform.processor() or cpu_name()}; Python {platform.python_version()}, "
        f"numpy {np.__version__}, contensou {contensou.__version__}; load average at start "
        f"{load()}.")
    out("")

    # 1. Built contact, arrays of steps.
    e2 = contensou.Contact(**ELLIPSE).step(1e-6, 0, 0, 0, 0)[6]
    out(f"## `Contact.wrench` on arrays (contact built once; P/Q = {ELLIPSE['P'] / ELLIPSE['Q']:g}, e² = {e2:.3f})")
    out("")
    out("| rows | precision | law | form | contacts/s | ns/contact |")
    out("|---:|---|---|---|---:|---:|")
    for n, precision, law, form, (_, st) in grid(sizes, seed=1):
        c = contensou.Contact(**ELLIPSE, law=law, form=form, precision=precision)
        t = best_time(lambda: c.wrench(*st), budget)
        out(f"| {n:,} | {precision} | {law} | {form} | {fmt(rate(n, t))} | {t / n * 1e9:.0f} |")
    out("")

    # 2. Per-row function.
    out("## `contensou.wrench` per row (a contact built for every row)")
    out("")
    out("| rows | precision | law | form | contact columns | contacts/s | ns/contact |")
    out("|---:|---|---|---|---|---:|---:|")
    for n, precision, law, form, (rows, _) in grid(sizes, seed=2):
        t = best_time(lambda: contensou.wrench(**rows, law=law, form=form, precision=precision), budget)
        out(f"| {n:,} | {precision} | {law} | {form} | arrays (a contact per row) "
            f"| {fmt(rate(n, t))} | {t / n * 1e9:.0f} |")
    for n in sizes:
        _, st = steps_of(n, "f64")
        t = best_time(lambda: contensou.wrench(**ELLIPSE, **dict(zip(STEPS, st))), budget)
        out(f"| {n:,} | f64 | best | fixed | scalars (one contact, reused) | {fmt(rate(n, t))} | {t / n * 1e9:.0f} |")
    out("")

    # 3. Scalar calls.
    out("## One scalar call (Python floats in)")
    out("")
    out("| call | calls/s | µs/call |")
    out("|---|---:|---:|")
    c = contensou.Contact(**ELLIPSE)
    reps = 2_000 if args.quick else 50_000

    def many_contact():
        for _ in range(reps):
            c.wrench(1e-6, 0.0, 0.01, 0.0, 30.0)

    def many_steps():
        for _ in range(reps):
            c.step(1e-6, 0.0, 0.01, 0.0, 30.0)

    def many_rows():
        for _ in range(reps):
            contensou.wrench(20.0, 50.0, 1.15e11, 0.2, 0.3, 1e-4, 1e-6, 0.0, 0.01, 0.0, 30.0)

    for name, call in [("`Contact.step(h, hdot, vx, vy, omega)` → tuple of floats (best, fixed, f64)", many_steps),
                       ("`Contact.wrench(h, hdot, vx, vy, omega)` → dict of numpy scalars", many_contact),
                       ("`contensou.wrench(11 floats)` (best, fixed, f64; builds the contact)", many_rows)]:
        t = best_time(call, budget)
        out(f"| {name} | {fmt(reps / t)} | {t / reps * 1e6:.2f} |")
    out("")

    # 4. numpy's simplified beside contensou on a circle.
    out("## Pure numpy (simplified law, circular patch) beside contensou on the same contact")
    out("")
    out("P = Q = 50 /m (a 10 mm sphere on a plane), E* = 115 GPa; the numpy code is "
        "`numpy_simplified` in bench.py (closed-form Hertz for a circle, the law's formula from "
        "src/friction/simplified.rs). `max dev` is its largest deviation from contensou's "
        "simplified over the rows (relative to the row's fN, fNa).")
    out("")
    out("| rows | precision | numpy simplified | contensou simplified | contensou best | numpy max dev F / T_z |")
    out("|---:|---|---:|---:|---:|---|")
    for n, precision, st, t_np, res in numpy_beside_contensou(sizes, budget):
        got = numpy_simplified(CIRCLE, *st)
        ref = res["simplified"][1]
        touch = ref["N"] > 0
        g = {k: v[touch].astype(np.float64) for k, v in got.items()}
        r = {k: v[touch].astype(np.float64) for k, v in ref.items()}
        fn = CIRCLE["f"] * r["N"]
        dev_f = np.max(np.hypot(g["Fx"] - r["Fx"], g["Fy"] - r["Fy"]) / fn)
        dev_t = np.max(np.abs(g["Tz"] - r["Tz"]) / (fn * r["a"]))
        out(f"| {n:,} | {precision} | {fmt(rate(n, t_np))} | {fmt(rate(n, res['simplified'][0]))} "
            f"| {fmt(rate(n, res['best'][0]))} | {dev_f:.1e} / {dev_t:.1e} |")
        print(f"numpy {n} {precision}", file=sys.stderr)
    out("")
    text = "\n".join(lines) + "\n"
    if args.out == "-":
        sys.stdout.write(text)
    else:
        Path(args.out).write_text(text)
        print(f"wrote {args.out}", file=sys.stderr)


def cpu_name():
    try:
        for line in Path("/proc/cpuinfo").read_text().splitlines():
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return "?"


def load():
    try:
        return Path("/proc/loadavg").read_text().split()[0]
    except OSError:
        return "?"


if __name__ == "__main__":
    main()
