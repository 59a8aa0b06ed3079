"""The shipped models at other steps, changing only `<option timestep>` (and, with `--config`,
plugin config keys): per model and step the scene's figures, whether the run stayed sane, and
the CPU time per simulated second.

    mujoco/build.sh
    python mujoco/examples/step_sweep.py                          # every model at shipped, 0.5, 1, 2 ms
    python mujoco/examples/step_sweep.py --models ball --dt 0.002 --config step=aware
    python mujoco/examples/step_sweep.py --json                   # one JSON object per run
    python mujoco/examples/step_sweep.py --config step=explicit --dt shipped,0.0005,0.002   # the plain contact

The model files ship at 2 ms with step = aware (implicitfast); with `--config step=explicit`
each starts from its small reference step and integrator instead (run_models.explicit), where
`shipped` means that step.

Per run (`run()`): `stable` — no MuJoCo NaN/instability warning, no body leaving its support
(its height above the start by more than `LEAVE` m), `energy_max_rise` — the largest rise of
MuJoCo's mechanical energy (kinetic + gravitational, `mjENBL_ENERGY`) over one step, relative to
the start energy, the contacts' elastic energy included as Σ (2/5)·N·h from the sensor (Hertz:
N ∝ h^{3/2}; with step = aware N is the step's normal force, so this term is approximate); and
the events, as run_models.py defines them:

- ball: `roll` (slip below 1 mm/s, checked every 1 ms; analytic 2v₀/(7fg) = 0.29125 s),
  `spin_rate` (−dω_z/dt over 0.5–1.5 s; analytic (3π/16)fNa/I = 0.398358 rad/s²);
- tippe top: `half` (θ = π/2, θ every 0.1 ms or every step), `touch` (θ ≥ θ*);
- rattleback, rattleback_rolling: per keyframe (`launch` ω₀ = −2 rad/s; rattleback_rolling also
  `steady`, +2 rad/s) `reversal` or `stall` (10 % of |ω₀|, spin every 1 ms or every step).
"""

import argparse
import json
import math
import sys
import time
from pathlib import Path

import mujoco
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import run_models  # noqa: E402

LEAVE = 0.01  # m: a body whose height rises this much above its start has left its support
ENDS = {"ball": 1.5, "tippe_top": 2.0, "rattleback": 3.0, "rattleback_rolling": 3.0}


def load(name, dt, config, integrator=None):
    """The model file with `timestep` = dt (None: as shipped), the integrator (None: as shipped;
    Euler, RK4, implicit, implicitfast) and the plugin config keys of `config` replaced or
    added."""
    text = (run_models.MODELS / f"{name}.xml").read_text()
    if config.get("step") == "explicit":
        # The plain contact: the file at its small reference step (run_models.explicit; `dt`
        # None keeps that step), step_point dropped.
        text = run_models.explicit(name, text)
    for key, value in config.items():
        tag = f'<config key="{key}" value="'
        if tag in text:
            start = text.index(tag) + len(tag)
            text = text[:start] + value + text[text.index('"', start):]
        else:
            text = text.replace("</instance>", f'  <config key="{key}" value="{value}"/>\n      </instance>', 1)
    return model_from(text, dt, integrator)


def model_from(text, dt=None, integrator=None):
    """The model of MJCF `text` with `timestep` = dt and the integrator (None: as in the text),
    MuJoCo's energy computed (mjENBL_ENERGY)."""
    m = mujoco.MjModel.from_xml_string(text)
    if dt is not None:
        m.opt.timestep = dt
    if integrator is not None:
        m.opt.integrator = getattr(mujoco.mjtIntegrator, f"mjINT_{integrator.upper()}")
    m.opt.enableflags |= int(mujoco.mjtEnableBit.mjENBL_ENERGY)
    return m


def crossing(ts, xs, level):
    return run_models.crossing(ts, xs, level)


def run(name, dt=None, config=None, key=0, end=None, integrator=None):
    """One run of model `name` from keyframe `key`; a dict of the figures (module docs)."""
    m = load(name, dt, config or {}, integrator)
    d = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, d, key)
    mujoco.mj_forward(m, d)
    end = end or ENDS[name]
    h = m.opt.timestep
    every = max(1, round((1e-4 if name == "tippe_top" else 1e-3) / h))
    z0 = float(d.xipos[1][2])

    def energy():
        rows = run_models.contacts(m, d)
        return float(d.energy.sum()) + 0.4 * float(np.sum(rows[:, 0] * np.maximum(rows[:, 6], 0.0)))

    e0 = energy()
    scale = abs(e0) if e0 != 0 else 1.0
    ts, series = [d.time], []
    rise, stable, left = 0.0, True, False
    spheres = [g for g in range(m.ngeom) if m.geom_type[g] == mujoco.mjtGeom.mjGEOM_SPHERE]
    radius = float(m.geom_size[spheres[0]][0]) if name == "ball" else 0.0

    def sample():
        if name == "ball":
            w = d.xmat[1].reshape(3, 3) @ d.qvel[3:6]
            slip = d.qvel[0:3] + np.cross(w, [0.0, 0.0, -radius])
            return (math.hypot(slip[0], slip[1]), float(w[2]))
        if name == "tippe_top":
            return run_models.tilt(d)
        return float((d.xmat[1].reshape(3, 3) @ d.qvel[3:6])[2])

    series.append(sample())
    cpu = time.process_time()
    nstep = round(end / h)
    for i in range(nstep):
        before = energy()
        mujoco.mj_step(m, d)
        after = energy()
        if not math.isfinite(after) or d.warning[mujoco.mjtWarning.mjWARN_BADQACC].number > 0:
            stable = False
            break
        rise = max(rise, (after - before) / scale)
        if d.xipos[1][2] > z0 + LEAVE:
            left = True
            stable = False
            break
        if (i + 1) % every == 0:
            ts.append(d.time)
            series.append(sample())
    cpu = time.process_time() - cpu
    names = {int(v): k[len("mjINT_"):] for k, v in mujoco.mjtIntegrator.__members__.items()}
    out = {"model": name, "dt": h, "integrator": names.get(int(m.opt.integrator), "?"), "key": m.key(key).name if m.nkey else "", "config": config or {},
           "stable": stable, "left_support": left, "t_end": d.time, "energy_max_rise": rise,
           "cpu_per_s": cpu / max(d.time, 1e-12)}
    if name == "ball":
        slips = [s[0] for s in series]
        out["roll"] = next((t for t, s in zip(ts, slips) if s < 1e-3), None)
        t = np.array(ts)
        spins = np.array([s[1] for s in series])
        k = (t >= 0.5) & (t <= 1.5)
        out["spin_rate"] = -float(np.polyfit(t[k], spins[k], 1)[0]) if stable and k.sum() > 10 else None
    elif name == "tippe_top":
        out["half"] = crossing(ts, series, math.pi / 2)
        out["touch"] = crossing(ts, series, run_models.THETA_STAR)
    else:
        spin0 = series[0]
        sign = math.copysign(1.0, spin0)
        rev = next((t for t, s in zip(ts, series) if s * sign <= -0.1 * abs(spin0)), None)
        out["reversal"] = rev
        out["stall"] = None if rev else next((t for t, s in zip(ts, series) if abs(s) < 0.1 * abs(spin0)), None)
    return out


def keys(name):
    return [0, 1] if name == "rattleback_rolling" else [0]


def fmt(x, digits=4):
    return "—" if x is None else f"{x:.{digits}f}"


def row(r):
    ev = {k: r[k] for k in ("roll", "spin_rate", "half", "touch", "reversal", "stall") if k in r}
    events = ", ".join(f"{k} {fmt(v)}" for k, v in ev.items())
    state = "stable" if r["stable"] else ("left its support" if r["left_support"] else "UNSTABLE")
    return (f"| {r['model']}{' ' + r['key'] if r['key'] not in ('', 'launch') else ''} | {r['dt'] * 1e3:g} ms "
            f"{r['integrator']} | "
            f"{events} | {state} at {r['t_end']:.3f} s | {r['energy_max_rise']:.2e} | {r['cpu_per_s']:.3f} |")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--models", default="ball,tippe_top,rattleback,rattleback_rolling")
    ap.add_argument("--dt", default="shipped,0.0005,0.001,0.002", help="steps (s), 'shipped' for the file's")
    ap.add_argument("--config", action="append", default=[], help="plugin config key=value (repeatable)")
    ap.add_argument("--integrator", default=None, help="Euler, RK4, implicit, implicitfast (default: as shipped)")
    ap.add_argument("--end", type=float, default=None, help="simulated time (s; default per model)")
    ap.add_argument("--json", action="store_true", help="one JSON object per run instead of a table")
    ap.add_argument("--plugin", default=str(run_models.PLUGIN), help="the plugin library")
    args = ap.parse_args()
    run_models.load_plugin(args.plugin)
    config = dict(c.split("=", 1) for c in args.config)
    if not args.json:
        print("| model | step | events (s; ball spin_rate rad/s²) | run | energy rise / step (rel.) | CPU s per sim. s |")
        print("|---|---|---|---|---|---|")
    for name in args.models.split(","):
        for dt in args.dt.split(","):
            for key in keys(name):
                r = run(name, None if dt == "shipped" else float(dt), config, key, args.end, args.integrator)
                print(json.dumps(r) if args.json else row(r), flush=True)


if __name__ == "__main__":
    main()
