#!/usr/bin/env python3
"""The bearing's step-aware figures against fine-step RK4 in the steady state, over an ensemble
of load ramps (examples/scene.rs: `bearing --law table`, `--ramp`, `--end`).

Why: the load's 5 ms ramp leaves the inner ring vibrating axially on the balls (≈ 500 Hz,
≈ 35 mm/s), and that vibration decays over ≈ 150 ms; until it has, the means carry it (the
step sweep's 15–20 ms means move by up to 10 % in ring torque when the ramp changes by 2 %, and
60–80 ms means by ±2 %). Here each run lasts 400 ms and its figures are the means over 300–400 ms
(the runner's last quarter), where the ring's vibration is down to ≈ 0.2 mm/s; three ramps
(4.9, 5, 5.1 ms) give the spread. RK4 at 0.1 µs is the reference, run by examples/bearing.rs's
`steady` (the same scene and window; the runner's RK4 check of h × the creep rate flags a 400 ms
run at 0.1 µs, a heuristic: RK4's bound is 2.785, the check's 2), which also gives the means'
batch-means standard error. Run by tools/bearing-ensemble.sh (which builds both). Writes bench-results/bearing-ensemble.{csv,md}. Two runs at a time,
nice'd; ≈ 8 minutes of CPU (the three RK4 references).
"""
import csv
import json
import os
import pathlib
import statistics as st
import subprocess
import sys
from concurrent.futures import ThreadPoolExecutor

RUNNER = os.environ.get("SCENE_RUNNER", "target/release/examples/scene")
STEADY = os.environ.get("BEARING_EXAMPLE", "target/release/examples/bearing")
RAMPS = ["4.9e-3", "5e-3", "5.1e-3"]
END = 0.4
# (label, integrator, step, extra options)
PLAN = [("rk4 (ref)", "rk4", 1e-7, [])] + [
    ("step-aware", "step-aware", h, []) for h in [1e-5, 2e-5, 3e-5, 4e-5, 5e-5, 6e-5, 7e-5, 1e-4]
] + [("step-aware --ring predicted", "step-aware", h, ["--ring", "predicted"])
     for h in [2e-5, 5e-5]]
KEYS = ["ring_torque", "spin_moment_inner", "spin_moment_outer", "cage"]


def run(label, integ, dt, extra, ramp):
    if integ == "rk4":
        cmd = ["nice", "-n", "10", STEADY, "out", "steady", "rk4", repr(dt), repr(END), ramp,
               repr(0.75 * END)]
        out = subprocess.run(cmd, capture_output=True, text=True, check=True).stdout
        ev = json.loads(out.strip().splitlines()[-1])
        r = {"stable": True, "reason": None, "events": ev, "dt": dt, "cpu_s": float("nan")}
        r.update(label=label, ramp=ramp)
        print(label, dt, ramp, ev, file=sys.stderr)
        return r
    cmd = ["nice", "-n", "10", RUNNER, "bearing", "--law", "table", "--dt", repr(dt),
           "--integrator", integ, "--end", repr(END), "--ramp", ramp] + extra
    r = json.loads(subprocess.run(cmd, capture_output=True, text=True, check=True).stdout)
    r.update(label=label, ramp=ramp)
    print(label, dt, ramp, r["stable"], r["reason"], r["events"], file=sys.stderr)
    return r


def main():
    jobs = [(lab, integ, dt, extra, ramp) for lab, integ, dt, extra in PLAN for ramp in RAMPS]
    with ThreadPoolExecutor(max_workers=2) as ex:
        rows = list(ex.map(lambda j: run(*j), jobs))
    with open("bench-results/bearing-ensemble.csv", "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["label", "dt", "ramp", "stable"] + KEYS + ["cpu_s"])
        for r in rows:
            ev = r["events"] or {}
            w.writerow([r["label"], r["dt"], r["ramp"], int(r["stable"])]
                       + ["" if ev.get(k) is None else f"{ev[k]:.6g}" for k in KEYS]
                       + [f"{r['cpu_s']:.3f}"])
    groups = {}
    for r in rows:
        groups.setdefault((r["label"], r["dt"]), []).append(r)

    def means(rs):
        ok = [r for r in rs if r["stable"]]
        if len(ok) < len(rs):
            return None
        return {k: [r["events"][k] for r in ok] for k in KEYS}

    ref = means(groups[("rk4 (ref)", 1e-7)])
    refm = {k: st.mean(v) for k, v in ref.items()}
    md = ["# The bearing in the steady state, over an ensemble of load ramps", "",
          "Regenerate: `tools/bearing-ensemble.sh` (this file and bearing-ensemble.csv). The 209 "
          "bearing, creep law `table`, f = 0.07; each figure the mean over 300–400 ms of a "
          "400 ms run (the ring's axial vibration from the load's ramp has decayed by then), "
          "averaged over three runs whose load ramp is 4.9, 5 and 5.1 ms (± the runs' standard "
          "deviation, in % of the mean); deviations against RK4 at 0.1 µs (the same ensemble). "
          "Ring torque and Σ|T_z| in N·mm; cage: the mean orbital speed over ω_c − 1, its "
          "deviation that of the speed itself. A step that any of the runs does not hold "
          "(the runner's `stable: false`) is marked unstable. The reference's own batch-means "
          "standard error (20 ms batches, mean over the ramps): ring torque REF_SE. CPU: the "
          "runner's per simulated second (mean over the ramps).", "",
          "| integrator | step | ring torque | Σ\\|T_z\\| inner | Σ\\|T_z\\| outer | cage speed | CPU / s |",
          "|---|---|---|---|---|---|---|"]
    for (label, dt), rs in groups.items():
        m = means(rs)
        if m is None:
            md.append(f"| {label} | {dt * 1e6:g} µs | unstable in {sum(not r['stable'] for r in rs)}"
                      f" of {len(rs)} runs | | | | |")
            continue
        cells = []
        for k in KEYS:
            mu, sd = st.mean(m[k]), st.stdev(m[k])
            if k == "cage":
                v = f"{100 * mu:+.3f} % (± {100 * sd:.3f})"
                if label != "rk4 (ref)":
                    v += f": speed {100 * ((1 + mu) / (1 + refm[k]) - 1):+.2f} %"
            else:
                v = f"{1e3 * mu:.3f} (± {100 * sd / abs(mu):.1f} %)"
                if label != "rk4 (ref)":
                    v += f": {100 * (mu / refm[k] - 1):+.1f} %"
            cells.append(v)
        cpu = st.mean(r["cpu_s"] for r in rs) / END
        cells.append("" if cpu != cpu else f"{cpu:.1f} s")
        md.append(f"| {label} | {dt * 1e6:g} µs | " + " | ".join(cells) + " |")
    se = st.mean(r["events"]["ring_torque_se"] for r in groups[("rk4 (ref)", 1e-7)])
    md[2] = md[2].replace("REF_SE", f"± {100 * se / abs(refm['ring_torque']):.2f} %")
    pathlib.Path("bench-results/bearing-ensemble.md").write_text("\n".join(md + [""]))


if __name__ == "__main__":
    main()
