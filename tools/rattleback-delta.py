#!/usr/bin/env python3
"""The rattleback's sliding laws at the δ → 0 limit: fine-step RK4 event times per law, spin and
slip scale δ (examples/scene.rs, `--delta`), each at h = 0.1·δ/(1 mm/s) ms and at half of it.

Run by tools/rattleback-delta.sh (which builds the runner first). Writes
bench-results/rattleback-delta.csv (one row per run) and bench-results/rattleback-delta.md (per law
and spin: outcome and event time at each δ, its change with the halved step, and whether it is
within 1 ms of the smallest δ's). `ellipsoid` is not run: it ignores δ (Coulomb's sign law at
rest), and the runner's RK4 check rejects it at every step (its rate grows as 1/|slip|). Two runs
at a time, nice'd (a shared 2-core machine): about 6 minutes of CPU in all.
"""
import csv
import json
import os
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

RUNNER = os.environ.get("SCENE_RUNNER", "target/release/examples/scene")
LAWS = ["best", "simplified", "coulomb"]
SPINS = [-2, 2]
DELTAS_MM = [1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01, 0.005]
END = 3.0
# Events to 1 ms: the convergence criterion.
TOL = 1e-3


def run(law, spin, delta_mm, dt):
    cmd = ["nice", "-n", "10", RUNNER, "rattleback", "--law", law, "--dt", repr(dt),
           "--end", repr(END), "--spin", str(spin), "--delta", repr(delta_mm * 1e-3)]
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    r = json.loads(out)
    r.update(law=law, spin=spin, delta_mm=delta_mm)
    print(law, spin, delta_mm, dt, r["stable"], r["events"], file=sys.stderr)
    return r


def outcome(r):
    """('R', t) for a reversal, ('S', t) for a stall, ('-', None) for neither, ('X', None) when
    the run was not stable."""
    ev = r["events"]
    if not r["stable"] or ev is None:
        return ("X", None)
    if ev.get("reversal") is not None:
        return ("R", ev["reversal"])
    if ev.get("stall") is not None:
        return ("S", ev["stall"])
    return ("-", None)


def cell(o):
    return "none" if o[0] == "-" else ("unstable" if o[0] == "X" else f"{o[0]} {o[1]:.4f}")


def main():
    jobs = []
    for law in LAWS:
        for spin in SPINS:
            for d in DELTAS_MM:
                h = 1e-4 * d
                jobs += [(law, spin, d, h), (law, spin, d, 0.5 * h)]
    with ThreadPoolExecutor(max_workers=2) as ex:
        rows = list(ex.map(lambda j: run(*j), jobs))
    with open("bench-results/rattleback-delta.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["law", "spin", "delta_mm_s", "dt", "stable", "reversal", "stall",
                    "peak_reversed", "energy_max_rise", "cpu_s"])
        for r in rows:
            ev = r["events"] or {}
            w.writerow([r["law"], r["spin"], r["delta_mm"], r["dt"], int(r["stable"])]
                       + ["" if ev.get(e) is None else f"{ev[e]:.9g}"
                          for e in ["reversal", "stall", "peak_reversed"]]
                       + [f"{r['energy_max_rise']:.3e}", f"{r['cpu_s']:.3f}"])
    md = ["# The rattleback's sliding laws at the δ → 0 limit", "",
          "Regenerate: `tools/rattleback-delta.sh` (this file and rattleback-delta.csv). Kane & "
          "Levinson's start (tilt 0.5°, ω₀ = ∓2 rad/s, f = 0.3), plain RK4 at h = 0.1·δ/(1 mm/s) "
          "ms and at h/2, over 3 s. R = reversal (spin back through 10 % of |ω₀|), S = stall "
          "(braked to 10 % of |ω₀| without reversal), none = neither by 3 s; time in s at h, "
          "then the change at h/2 (ms). ✓: the same outcome as at the smallest δ and the time "
          "within 1 ms of it; ✗: not. `ellipsoid` ignores δ and is not listed.", ""]
    by = {(r["law"], r["spin"], r["delta_mm"], r["dt"]): r for r in rows}
    for law in LAWS:
        md += [f"## `{law}`", "", "| δ (mm/s) | ω₀ = −2 rad/s | ω₀ = +2 rad/s |",
               "|---|---|---|"]
        for d in DELTAS_MM:
            cells = []
            for spin in SPINS:
                h = 1e-4 * d
                o, o2 = outcome(by[(law, spin, d, h)]), outcome(by[(law, spin, d, 0.5 * h)])
                last = outcome(by[(law, spin, DELTAS_MM[-1], 1e-4 * DELTAS_MM[-1])])
                c = cell(o)
                if o[1] is not None and o2[0] == o[0]:
                    c += f" ({1e3 * (o2[1] - o[1]):+.3f} ms)"
                elif o2[0] != o[0]:
                    c += f" (h/2: {cell(o2)})"
                same = o[0] == last[0] and (o[1] is None or abs(o[1] - last[1]) <= TOL)
                cells.append(c + (" ✓" if same else " ✗"))
            md.append(f"| {d:g} | " + " | ".join(cells) + " |")
        md.append("")
    with open("bench-results/rattleback-delta.md", "w") as f:
        f.write("\n".join(md))


if __name__ == "__main__":
    main()
