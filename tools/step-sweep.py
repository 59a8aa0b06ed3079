#!/usr/bin/env python3
"""Step sweep of the scenes: plain RK4 against the step-aware integrator (examples/scene.rs).

Run by tools/step-sweep.sh (which builds the runner first). Writes bench-results/step-sweep.csv
(one row per run: the runner's JSON flattened, the rattleback's energy split in the last
columns) and bench-results/step-sweep.md (per scene, law
and spin: outcome, event times and their deviation from the fine-step RK4 reference row,
energy rise, CPU seconds per simulated second).
"""
import csv
import json
import subprocess
import sys

RUNNER = "target/release/examples/scene"

# (scene, law, spin, end, reference RK4 step (None: the group's reference comes from another
# entry), [RK4 steps], [step-aware steps], extra args (shown with the integrator's name))
PLAN = [
    ("ball", "best", None, 0.9, 2e-5, [1e-4, 2e-4, 1e-3], [1e-4, 1e-3, 2e-3, 5e-3, 1e-2], []),
    ("tippe-top", "best", None, 2.5, 1e-5, [1e-4, 2e-4, 3e-4, 1e-3],
     [1e-4, 5e-4, 1e-3, 1.5e-3, 2e-3], []),
]
for law in ["best", "simplified", "coulomb", "table"]:
    # The creep law's reference at 50 µs: at 0.1 ms RK4 does not follow its stall (README);
    # the sliding laws at their δ → 0 limits (scenes::rattleback::BEST_DELTA, SIMPLIFIED_DELTA
    # 0.1 mm/s: 10 µs, from 20 µs (spin +2) the friction ramp's mode exceeds RK4's step;
    # COULOMB_DELTA 0.01 mm/s: 2 µs; bench-results/rattleback-delta.md).
    ref, rk = {"table": (5e-5, [1e-4, 2e-4, 5e-4, 1e-3]),
               "best": (1e-5, [2e-5, 1e-4, 5e-4, 1e-3]),
               "simplified": (1e-5, [2e-5, 1e-4, 5e-4, 1e-3]),
               "coulomb": (2e-6, [5e-6, 1e-4, 1e-3])}[law]
    for spin in [-2, 2]:
        PLAN.append(("rattleback", law, spin, 3.0, ref, rk,
                     [5e-5, 1e-4, 2e-4, 5e-4, 1e-3, 2e-3], []))
PLAN.append(("bearing", "best", None, 0.02, 5e-7, [1e-6, 2e-6, 5e-6], [2e-5], []))
PLAN.append(("bearing", "best", None, 0.02, None, [], [2e-5, 1e-4], ["--ring", "predicted"]))
PLAN.append(("bearing", "table", None, 0.02, 1e-7, [2.5e-7, 1e-6],
             [2e-6, 5e-6, 1e-5, 2e-5, 3e-5, 4e-5, 5e-5, 1e-4], []))
PLAN.append(("bearing", "table", None, 0.02, None, [], [2e-5, 5e-5, 1e-4],
             ["--ring", "predicted"]))
# The reference's own sensitivity: RK4 at the reference step with the load's ramp 2 % shorter
# and longer (a physically negligible change; the bearing's 15–20 ms means move by several %).
for ramp in ["4.9e-3", "5.1e-3"]:
    PLAN.append(("bearing", "table", None, 0.02, None, [1e-7], [], ["--ramp", ramp]))

EVENTS = {
    "tippe-top": ["half", "touch"],
    "ball": ["roll", "spin_rate"],
    "rattleback": ["reversal", "stall", "peak_reversed"],
    "bearing": ["ring_torque", "spin_moment_inner", "spin_moment_outer", "cage"],
}
ALL_EVENTS = [e for v in EVENTS.values() for e in v]
# The step-aware rattleback's energy split over the run, of E₀ (the runner's `energy_split`:
# the rotation update, the normal force with gravity, friction).
SPLIT = ["rotation", "normal", "friction"]


def run(scene, law, spin, end, dt, integrator, extra):
    cmd = [RUNNER, scene, "--law", law, "--dt", repr(dt), "--integrator", integrator,
           "--end", repr(end)] + extra
    if spin is not None:
        cmd += ["--spin", str(spin)]
    out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
    return json.loads(out)


def main():
    rows = []
    for scene, law, spin, end, ref, rk, sa, extra in PLAN:
        for integ, steps in [("rk4", ([] if ref is None else [ref]) + rk), ("step-aware", sa)]:
            for dt in steps:
                r = run(scene, law, spin, end, dt, integ, extra)
                r["spin"] = spin
                r["reference"] = integ == "rk4" and dt == ref
                r["label"] = " ".join([integ] + extra)
                rows.append(r)
                print(scene, law, spin, integ, dt, r["stable"], r["events"], file=sys.stderr)
    with open("bench-results/step-sweep.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["scene", "law", "spin", "integrator", "options", "dt", "end", "reference",
                    "stable",
                    "energy_max_rise"] + ALL_EVENTS + ["cpu_s", "cpu_per_sim_s", "reason"]
                   + ["energy_" + p for p in SPLIT])
        for r in rows:
            ev = r["events"] or {}
            w.writerow([r["scene"], r["law"], "" if r["spin"] is None else r["spin"],
                        r["integrator"], r["label"][len(r["integrator"]):].strip(), r["dt"],
                        r["end"], int(r["reference"]),
                        int(r["stable"]),
                        "" if r["energy_max_rise"] is None else f"{r['energy_max_rise']:.3e}"]
                       + ["" if ev.get(e) is None else f"{ev[e]:.6g}" for e in ALL_EVENTS]
                       + [f"{r['cpu_s']:.3f}", f"{r['cpu_s'] / r['end']:.3f}",
                          r["reason"] or ""]
                       + ["" if not r.get("energy_split") else f"{r['energy_split'][p]:.3e}"
                          for p in SPLIT])
    md = ["# Step sweep: plain RK4 against the step-aware integrator",
          "",
          "Regenerate: `tools/step-sweep.sh` (this file and step-sweep.csv). Deviations are "
          "value / reference − 1 against the fine-step RK4 row (ref) of the same scene, law and "
          "spin (for the bearing's `cage` = ω/ω_c − 1: the deviation of the cage speed "
          "itself); an outcome in bold differs from the reference. Units: s (events), rad/s "
          "(peak_reversed), rad/s² (spin_rate), N·m (ring torque, spin moments). CPU: the "
          "runner's thread CPU time per simulated second on the shared 2-core sweep machine. "
          "Bearing: `--ring start` (default) / `predicted` is where the balls see the inner "
          "ring within a step (`scenes::bearing::RingCoupling`); the `--ramp` rows are RK4 at "
          "the reference step with the load's ramp 2 % shorter / longer: how far the 15–20 ms "
          "means move by themselves (a deviation within theirs is not resolved by one run). "
          "These 15–20 ms means sit in the decay of the ring's axial vibration after the "
          "load's ramp; the bearing's verdict per step is the steady state (300–400 ms means "
          "over three ramps): bench-results/bearing-ensemble.md (`tools/bearing-ensemble.sh`).",
          ""]
    groups = {}
    for r in rows:
        groups.setdefault((r["scene"], r["law"], r["spin"]), []).append(r)
    for (scene, law, spin), rs in groups.items():
        ref = next(r for r in rs if r["reference"])
        evs = EVENTS[scene]
        title = f"## {scene}, `{law}`" + ("" if spin is None else f", spin {spin:+d} rad/s")
        md += [title, "",
               "| integrator | step | stable | " + " | ".join(evs)
               + " | energy rise | CPU s / sim s |",
               "|---|---|---|" + "---|" * len(evs) + "---|---|"]
        for r in rs:
            cells = []
            for e in evs:
                v = (r["events"] or {}).get(e)
                rv = (ref["events"] or {}).get(e)
                if not r["stable"]:
                    cells.append("—")
                elif v is None:
                    cells.append("**none**" if rv is not None else "none")
                elif r["reference"] or rv is None or rv == 0:
                    cells.append(f"{v:.5g}" + (" **(ref: none)**" if rv is None
                                               and not r["reference"] else ""))
                elif e == "cage":
                    # The cage speed ratio ω/ω_c = 1 + cage: its own relative deviation.
                    cells.append(f"{v:.5g} (speed {100 * ((1 + v) / (1 + rv) - 1):+.2f} %)")
                else:
                    cells.append(f"{v:.5g} ({100 * (v / rv - 1):+.2f} %)")
            stable = "yes" if r["stable"] else f"**no**: {r['reason']}"
            rise = "" if r["energy_max_rise"] is None else f"{r['energy_max_rise']:.1e}"
            md.append(f"| {r['label']}{' (ref)' if r['reference'] else ''} | "
                      f"{r['dt'] * 1e3:g} ms | {stable} | " + " | ".join(cells)
                      + f" | {rise} | {r['cpu_s'] / r['end']:.3g} |")
        md.append("")
    md += real_time(rows)
    with open("bench-results/step-sweep.md", "w") as f:
        f.write("\n".join(md))


# The M4F rows (bench-results/cycles.csv, tools/qemu-bench.sh: firmware/src/bin/step_scenes.rs,
# step_bearing.rs)
# and the sweep run each scene's largest holding step is read from: (M4F row, scene, law, spin,
# step).
HOLDING = [
    ("ball", "ball", "best", None, 5e-3),
    ("tippe-top", "tippe-top", "best", None, 2e-3),
    ("tippe-top-two-contacts", None, None, None, 2e-3),
    ("rattleback", "rattleback", "best", -2, 2e-3),
    ("rattleback-table", "rattleback", "table", -2, 1e-3),
    ("bearing", "bearing", "table", None, 4e-5),
]


def real_time(rows):
    """The real-time factor per scene at its largest holding step: M4F at 168 MHz from the
    cycle model's mid estimate of one step-aware step, host from the sweep's CPU time."""
    cycles = {}
    try:
        with open("bench-results/cycles.csv") as f:
            for r in csv.DictReader(f):
                if r["stage"] == "scene-step" and r["precision"] == "f32":
                    cycles[r["method"]] = (int(r["insns"]), int(r["cycles_mid"]))
    except FileNotFoundError:
        pass
    md = ["## Real-time factors at the largest holding step", "",
          "M4F: one step-aware step in f32 (QEMU instructions, cycle model mid, "
          "bench-results/cycles.csv rows `scene-step`), at 168 MHz. Real-time factor = "
          "compute time per simulated time (below 1: faster than real time, as in the README): "
          "M4F cycles / (Δt·168e6); host: CPU s per simulated s of the sweep's run (f64; `—` "
          "below the timer's resolution).",
          "", "| scene | step | M4F insns / step | M4F cycles / step | M4F real-time factor "
          "| host real-time factor |", "|---|---|---|---|---|---|"]
    for m4f, scene, law, spin, dt in HOLDING:
        host = "—"
        for r in rows:
            if (r["scene"], r["law"], r["spin"], r["label"]) == (scene, law, spin,
                                                               "step-aware") \
                    and abs(r["dt"] - dt) < 1e-12 and r["cpu_s"] > 0:
                host = f"{r['cpu_s'] / r['end']:.3g}"
        ins, cyc = cycles.get(m4f, (None, None))
        m = "not measured" if cyc is None else f"{cyc / (dt * 168e6):.3g}"
        md.append(f"| {m4f or scene} | {dt * 1e3:g} ms | {ins or '—'} | {cyc or '—'} | {m} "
                  f"| {host} |")
    md.append("")
    return md


if __name__ == "__main__":
    main()
