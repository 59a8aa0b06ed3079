"""The contensou.contact MuJoCo plugin from Python: load the plugin library, load a model file
that declares it, reset to keyframe 0 and step — no callback code.

    mujoco/build.sh                                    # builds mujoco/build/libcontensou_mujoco.so
    python mujoco/examples/run_models.py               # the scenes: tippe top, ball, rattleback (full slip, rolling) 2 s each
    python mujoco/examples/run_models.py --end 0.1     # a smoke run
    python mujoco/examples/run_models.py --fine        # the same at the small steps with step = explicit

The model files ship at MuJoCo's default step, 2 ms, with the step-aware contact (`step =
aware`, integrator implicitfast, `step_point` per model: STEP_POINT); `explicit(name)` gives
the same model at its small reference step with the plain contact (`step = explicit`: bit for
bit the Python callback of python/examples/floor_contact.py; FINE), which the agreement tests
and the speed table's callback rows use.

Prints per scene what the library's own scene reports: the tippe top's t(θ = π/2) and touch-down
(θ ≥ θ*), the ball's time to pure rolling and spin decay rate (with the analytic values of
python/examples/mujoco_ball.py), the rattleback's spin reversal or stall (definitions of
examples/rattleback.rs).
"""

import argparse
import math
import os
import re
import time
from pathlib import Path

import mujoco
import numpy as np

ROOT = Path(__file__).resolve().parents[1]
# The plugin library; CONTENSOU_MUJOCO_PLUGIN names another build (the tests, the examples).
PLUGIN = Path(os.environ.get("CONTENSOU_MUJOCO_PLUGIN", ROOT / "build" / "libcontensou_mujoco.so"))
MODELS = ROOT / "models"
THETA_STAR = math.acos((5e-3 - 15e-3) / (16e-3 - 3e-3))  # both spheres of the top on the floor


def load_plugin(path=PLUGIN):
    """Registers contensou.contact (idempotent: loading the same library twice is harmless)."""
    if not Path(path).exists():
        raise FileNotFoundError(f"{path}: run mujoco/build.sh first")
    mujoco.mj_loadPluginLibrary(str(path))


# The model files' step: MuJoCo's default, with step = aware.
SHIPPED_DT = 0.002
# step_point θ of each shipped model (where the step-aware contact takes the free velocity
# within the step; measured, mujoco/README.md).
STEP_POINT = {"tippe_top": 0.25, "ball": 0.25, "rattleback": 0.5, "rattleback_rolling": 0.55}
# Each model's small reference step and integrator with step = explicit (the Rust scene's step:
# tippe top and ball Euler 10 / 20 µs as the Python-callback examples, rattlebacks RK4 0.1 ms).
FINE = {"tippe_top": (1e-5, "Euler"), "ball": (2e-5, "Euler"), "rattleback": (2e-5, "RK4"),
        "rattleback_rolling": (1e-4, "RK4")}


def explicit(name, text=None):
    """The MJCF text of model `name` (or of `text`, a model file's text) at its FINE step and
    integrator with the plain contact: step = explicit, no step_point."""
    text = text if text is not None else (MODELS / f"{name}.xml").read_text()
    dt, integrator = FINE[name]
    text = text.replace('<config key="step" value="aware"/>', '<config key="step" value="explicit"/>')
    text = re.sub(r'\n\s*<config key="step_point" value="[^"]*"/>', "", text)
    text = re.sub(r'timestep="[^"]*" integrator="[^"]*"', f'timestep="{dt!r}" integrator="{integrator}"', text, count=1)
    return text


# What load() gives by default: the FINE explicit models (the tests' references); main() runs
# the files as shipped unless --fine.
SHIPPED = False


def load(name, key=0, timestep=None, shipped=None):
    """The model mujoco/models/<name>.xml — as shipped if `shipped` (default SHIPPED), else at its
    FINE step with step = explicit — (its `timestep` replaced if given) and a data at its
    keyframe `key`."""
    path = MODELS / f"{name}.xml"
    shipped = SHIPPED if shipped is None else shipped
    m = mujoco.MjModel.from_xml_path(str(path)) if shipped else mujoco.MjModel.from_xml_string(explicit(name))
    if timestep is not None:
        m.opt.timestep = timestep
    d = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, d, key)
    mujoco.mj_forward(m, d)
    return m, d


def contacts(m, d):
    """The plugin sensor as rows N, Fx, Fy, Tz, a, b, h (one per contact pair)."""
    return d.sensordata[: m.sensor_dim[0]].reshape(-1, 7)


def tilt(d, body=1):
    """θ: the angle between the body's z axis and the vertical."""
    e3 = d.xmat[body].reshape(3, 3)[:, 2]
    return math.atan2(math.hypot(e3[0], e3[1]), e3[2])


def crossing(ts, xs, level):
    """First time the sampled series reaches `level` (linear interpolation), None if never."""
    for i in range(1, len(xs)):
        if xs[i - 1] < level <= xs[i]:
            return ts[i - 1] + (level - xs[i - 1]) / (xs[i] - xs[i - 1]) * (ts[i] - ts[i - 1])
    return None


def run_tippe_top(end, sample=1e-4):
    m, d = load("tippe_top")
    every = max(1, round(sample / m.opt.timestep))
    ts, thetas = [d.time], [tilt(d)]
    start, cpu = time.perf_counter(), time.process_time()
    for _ in range(round(end / m.opt.timestep / every)):
        mujoco.mj_step(m, d, every)
        ts.append(d.time)
        thetas.append(tilt(d))
    return {"t_half": crossing(ts, thetas, math.pi / 2), "t_touch": crossing(ts, thetas, THETA_STAR),
            "theta": thetas[-1], "spin": float((d.xmat[1].reshape(3, 3) @ d.qvel[3:6]) @ d.xmat[1].reshape(3, 3)[:, 2]),
            "wall": time.perf_counter() - start, "cpu": time.process_time() - cpu, "end": d.time}


def ball_slip(d, radius):
    w = d.xmat[1].reshape(3, 3) @ d.qvel[3:6]
    slip = d.qvel[0:3] + np.cross(w, [0.0, 0.0, -radius])
    return math.hypot(slip[0], slip[1]), float(w[2])


def run_ball(end, check=1e-3, rolling=1e-3):
    """Time to pure rolling (slip below `rolling` m/s, checked every `check` s) and the spin
    ω_z(t) sampled every `check` s."""
    m, d = load("ball")
    radius = float(m.geom_size[0 if m.geom_type[0] == mujoco.mjtGeom.mjGEOM_SPHERE else 1][0])
    every = max(1, round(check / m.opt.timestep))
    t_roll, ts, spins = None, [d.time], [ball_slip(d, radius)[1]]
    start, cpu = time.perf_counter(), time.process_time()
    for _ in range(round(end / m.opt.timestep / every)):
        mujoco.mj_step(m, d, every)
        slip, spin = ball_slip(d, radius)
        if t_roll is None and slip < rolling:
            t_roll = d.time
        ts.append(d.time)
        spins.append(spin)
    return {"t_roll": t_roll, "t": np.array(ts), "spin": np.array(spins),
            "wall": time.perf_counter() - start, "cpu": time.process_time() - cpu}


def spin_rate(run, t0, t1):
    """Least-squares slope of ω_z(t) over [t0, t1] (rad/s²)."""
    k = (run["t"] >= t0) & (run["t"] <= t1)
    return float(np.polyfit(run["t"][k], run["spin"][k], 1)[0])


def run_rattleback(end, sample=1e-2, name="rattleback", key=0, timestep=None):
    """Spin ω·ẑ every `sample` s; reversal (turned and reached 10 % of |ω₀| the other way) or
    stall (braked below 10 % of |ω₀| without reversal), as examples/rattleback.rs. `name`:
    the model (rattleback_rolling: Kalker's creep), `key`: its keyframe (rattleback_rolling's
    1: ω₀ = +2 rad/s)."""
    m, d = load(name, key, timestep)
    every = max(1, round(sample / m.opt.timestep))
    spin0 = float((d.xmat[1].reshape(3, 3) @ d.qvel[3:6])[2])
    ts, spins = [d.time], [spin0]
    start, cpu = time.perf_counter(), time.process_time()
    for _ in range(round(end / m.opt.timestep / every)):
        mujoco.mj_step(m, d, every)
        ts.append(d.time)
        spins.append(float((d.xmat[1].reshape(3, 3) @ d.qvel[3:6])[2]))
    sign = math.copysign(1.0, spin0)
    reversal = next((t for t, s in zip(ts, spins) if s * sign <= -0.1 * abs(spin0)), None)
    stall = None if reversal else next((t for t, s in zip(ts, spins) if abs(s) < 0.1 * abs(spin0)), None)
    return {"spin0": spin0, "reversal": reversal, "stall": stall, "spin": spins[-1], "t": ts, "spins": spins,
            "wall": time.perf_counter() - start, "cpu": time.process_time() - cpu}


def fmt(x, unit="s", digits=4):
    return "—" if x is None else f"{x:.{digits}f} {unit}"


def main():
    ap = argparse.ArgumentParser(description="the three scenes through the contensou.contact MuJoCo plugin")
    ap.add_argument("--end", type=float, default=2.0, help="end time of each scene (s)")
    ap.add_argument("--fine", action="store_true", help="the small steps with step = explicit (default: as shipped)")
    args = ap.parse_args()
    global SHIPPED
    SHIPPED = not args.fine
    load_plugin()
    print(f"MuJoCo {mujoco.__version__}, plugin {PLUGIN}")
    top = run_tippe_top(args.end)
    print(f"tippe top: t(θ = π/2) {fmt(top['t_half'])}, touch-down (θ ≥ θ*) {fmt(top['t_touch'])}, "
          f"θ({args.end:g} s) = {top['theta']:.3f} rad; {top['wall']:.2f} s wall, {top['cpu']:.2f} s CPU")
    ball = run_ball(args.end)
    msg = f"ball: pure rolling at {fmt(ball['t_roll'])} (analytic 2v₀/(7fg) = {2 / (7 * 0.1 * 9.81):.4f} s)"
    if args.end >= 1.0:
        msg += f", spin decay {-spin_rate(ball, 0.5, args.end):.4f} rad/s²"
    print(msg + f"; {ball['wall']:.2f} s wall, {ball['cpu']:.2f} s CPU")
    rb = run_rattleback(args.end)
    print(f"rattleback: ω₀ = {rb['spin0']:+.2f} rad/s, reversal {fmt(rb['reversal'], digits=2)}, "
          f"stall {fmt(rb['stall'], digits=2)}, spin({args.end:g} s) = {rb['spin']:+.3f} rad/s; "
          f"{rb['wall']:.2f} s wall, {rb['cpu']:.2f} s CPU")
    for key, label in ((0, "ω₀ = −2"), (1, "ω₀ = +2")):
        rb = run_rattleback(args.end, sample=1e-3, name="rattleback_rolling", key=key)
        print(f"rattleback rolling (table), {label}: reversal {fmt(rb['reversal'], digits=3)}, "
              f"stall {fmt(rb['stall'], digits=3)}, spin({args.end:g} s) = {rb['spin']:+.3f} rad/s; "
              f"{rb['wall']:.2f} s wall, {rb['cpu']:.2f} s CPU")


if __name__ == "__main__":
    main()
