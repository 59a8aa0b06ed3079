"""The paper's tippe top in MuJoCo: its own contact against contensou's, beside the Rust scene.

    python python/examples/mujoco_tippe_top.py             # 8 s, every run (≈ 3 min), the table
    python python/examples/mujoco_tippe_top.py --end 0.2   # a smoke run (CI)

The top (src/scenes/tippe_top.rs, Params::paper): m = 6 g, I = 8e-7 / 8e-7 / 7e-7 kg·m² about
the centre of mass G, two sphere geoms on the symmetry axis e₃ in one body — R = 15 mm at
ε_R = 3 mm, r = 5 mm at ε_r = 16 mm from G — launched with θ₀ = 0.1 rad, ω₀ = 180 rad/s about
e₃, the big sphere touching the floor; f = 0.3.

Runs: (a) MuJoCo's contact (pyramidal cone, friction "0.3 0.005 0.0001"), condim 3, 4 and 6,
at the defaults (timestep 2 ms, solref "0.02 1") and stiff (timestep 0.1 ms, solref "0.0002 1");
(b) the floor contact computed by contensou at each integrator stage (floor_contact.py:
E* = 5 GPa, Hunt–Crossley c_d = 5 s/m, δ = 1e-4 m/s, MuJoCo's contact disabled for the top's
geoms), RK4 at 10 µs as the Rust scene; (c) the Rust scene itself
(`cargo run --release --features scenes --example tippe_top`, its CSVs).

θ is the angle between e₃ and the vertical; "touch" the first time θ ≥ θ* = arccos((r − R)/(ε_r −
ε_R)) ≈ 2.448 rad, where both spheres reach a rigid floor (the Rust scene's "inversion"; the same
criterion for every run, from θ alone); energy ½m|v|² + ½ωᵀIω + m g z_G + Hertz elastic energy.
"""

import argparse
import csv
import math
import re
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import mujoco
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from floor_contact import SphereFloor, hertz_energy  # noqa: E402

REPO = Path(__file__).resolve().parents[2]
MASS, I_EQ, I_POLAR = 6e-3, 8e-7, 7e-7
R_BIG, R_SMALL, E_BIG, E_SMALL = 15e-3, 5e-3, 3e-3, 16e-3
ESTAR, CD, F, DELTA, G = 5e9, 5.0, 0.3, 1e-4, 9.81
THETA0, SPIN0 = 0.1, 180.0
SAMPLE = 2e-3
THETA_STAR = math.acos((R_SMALL - R_BIG) / (E_SMALL - E_BIG))
# contensou inside MuJoCo: the Rust scene's step (10 µs ≈ 1/68 of the 1.5 kHz contact period).
DT, INTEGRATOR = 1e-5, "Euler"

XML = """
<mujoco model="tippe top">
  <option timestep="{dt}" integrator="{integrator}" gravity="0 0 -{g}"/>
  <worldbody>
    <geom name="floor" type="plane" size="1 1 0.1" condim="{condim}" friction="{f} 0.005 0.0001"
          solref="{solref}" contype="{floor_type}" conaffinity="{floor_type}"/>
    <body name="top">
      <freejoint/>
      <inertial pos="0 0 0" mass="{m}" diaginertia="{ieq} {ieq} {ipol}"/>
      <geom name="big" type="sphere" size="{rb}" pos="0 0 {eb}" condim="{condim}" friction="{f} 0.005 0.0001"
            solref="{solref}" contype="{top_type}" conaffinity="{top_type}"/>
      <geom name="small" type="sphere" size="{rs}" pos="0 0 {es}" condim="{condim}" friction="{f} 0.005 0.0001"
            solref="{solref}" contype="{top_type}" conaffinity="{top_type}"/>
    </body>
  </worldbody>
</mujoco>
"""


def model(condim=3, dt=2e-3, solref="0.02 1", integrator="Euler", native=True):
    xml = XML.format(dt=dt, integrator=integrator, g=G, condim=condim, f=F, solref=solref,
                     floor_type=1, top_type=1 if native else 0, m=MASS, ieq=I_EQ, ipol=I_POLAR,
                     rb=R_BIG, eb=E_BIG, rs=R_SMALL, es=E_SMALL)
    return mujoco.MjModel.from_xml_string(xml)


def launch(m, d):
    """θ₀ about the world x axis, the big sphere touching the floor, ω₀ about e₃."""
    q = np.array([math.cos(THETA0 / 2), math.sin(THETA0 / 2), 0.0, 0.0])
    e3 = np.array([0.0, -math.sin(THETA0), math.cos(THETA0)])  # R(q)·ẑ
    g = np.array([0.0, 0.0, R_BIG]) - E_BIG * e3
    d.qpos[:] = np.concatenate([g, q])
    d.qvel[:] = [0, 0, 0, 0, 0, SPIN0]
    mujoco.mj_forward(m, d)


def probe(m, d):
    """θ, spin ω·e₃, energy, θ ≥ θ*."""
    rot = d.xmat[1].reshape(3, 3)
    e3 = rot[:, 2]
    theta = math.atan2(math.hypot(e3[0], e3[1]), e3[2])
    v = d.qvel[0:3]
    w = d.qvel[3:6]
    z = d.xpos[1][2]
    inertia = np.array([I_EQ, I_EQ, I_POLAR])
    h_big = R_BIG - d.geom_xpos[1][2]
    h_small = R_SMALL - d.geom_xpos[2][2]
    energy = (0.5 * MASS * v @ v + 0.5 * w @ (inertia * w) + MASS * G * z
              + hertz_energy(ESTAR, R_BIG, h_big) + hertz_energy(ESTAR, R_SMALL, h_small))
    return theta, float(w[2]), float(energy), theta >= THETA_STAR


def summary(name, t, theta, spin, energy, touch, wall, cpu=None):
    """One row: inverts?, t(θ = π/2), touch time, θ, spin, energy at the end, wall time."""
    t, theta = np.asarray(t), np.asarray(theta)
    up = np.flatnonzero(theta >= math.pi / 2)
    touched = np.flatnonzero(np.asarray(touch))
    return {
        "run": name,
        "inverts": bool(touch[-1]),
        "t_half": float(t[up[0]]) if up.size else None,
        "t_touch": float(t[touched[0]]) if touched.size else None,
        "theta": float(theta[-1]),
        "spin": float(spin[-1]),
        "energy": float(energy[-1]),
        "wall": wall,
        "cpu": cpu,
        "series": (t, theta),
    }


def simulate(name, m, end, floor=None):
    d = mujoco.MjData(m)
    if floor is not None:
        floor.install()
    try:
        launch(m, d)
        every = max(1, round(SAMPLE / m.opt.timestep))
        steps = round(end / m.opt.timestep)
        rows = [(0.0, *probe(m, d))]
        start, cpu0 = time.perf_counter(), time.process_time()
        for i in range(1, steps + 1):
            mujoco.mj_step(m, d)
            if i % every == 0:
                rows.append((d.time, *probe(m, d)))
                if not np.all(np.isfinite(d.qpos)):
                    break
        wall = time.perf_counter() - start
        cpu = time.process_time() - cpu0
    finally:
        if floor is not None:
            floor.uninstall()
    t, theta, spin, energy, touch = map(list, zip(*rows))
    return summary(name, t, theta, spin, energy, touch, wall, cpu)


def rust_scene(end):
    """The Rust scene's rows (its CSVs; `best` and `simplified`), None without cargo."""
    out = Path(tempfile.mkdtemp())
    cmd = ["cargo", "run", "--release", "--quiet", "--features", "scenes", "--example", "tippe_top", "--", str(out)]
    try:
        run = subprocess.run(cmd, cwd=REPO, capture_output=True, text=True, timeout=1800)
    except (OSError, subprocess.TimeoutExpired):
        return []
    if run.returncode != 0:
        print(run.stderr, file=sys.stderr)
        return []
    rows = []
    for law in ["best", "simplified"]:
        wall = re.search(rf"^{law}\s.*?([0-9.]+) s wall", run.stdout, re.M)
        with open(out / f"tippe_top_{law}.csv") as fh:
            data = [r for r in csv.DictReader(fh) if float(r["t"]) <= end + 1e-9]
        t = [float(r["t"]) for r in data]
        rows.append(summary(
            f"Rust scene, {law} (RK4 10 µs)", t, [float(r["theta"]) for r in data],
            [float(r["spin"]) for r in data], [float(r["energy"]) for r in data],
            [float(r["theta"]) >= THETA_STAR for r in data], float(wall.group(1)) if wall else float("nan")))
    return rows


def runs(end, rust=True, native=True):
    out = []
    if native:
        for condim in [3, 4, 6]:
            out.append(simulate(f"MuJoCo condim {condim}, defaults", model(condim), end))
        for condim in [3, 4, 6]:
            out.append(simulate(f"MuJoCo condim {condim}, stiff", model(condim, dt=1e-4, solref="0.0002 1"), end))
    for law in ["best", "simplified"]:
        m = model(dt=DT, integrator=INTEGRATOR, native=False)
        floor = SphereFloor(m, "top", ["big", "small"], ESTAR, CD, F, DELTA, law=law)
        out.append(simulate(f"MuJoCo + contensou, {law} ({INTEGRATOR} {DT * 1e6:g} µs)", m, end, floor))
    if rust:
        out.extend(rust_scene(end))
    return out


def fmt_time(x):
    return "—" if x is None else f"{x:.3f} s"


def table(rows, end):
    lines = [
        f"| run | inverts? | t(θ = π/2) | small sphere touches (θ ≥ θ*) | θ({end:g} s) | ω·e₃({end:g} s) | energy({end:g} s) | wall | CPU |",
        "|---|---|---:|---:|---:|---:|---:|---:|---:|",
    ]
    for r in rows:
        lines.append(
            f"| {r['run']} | {'yes' if r['inverts'] else 'no'} | {fmt_time(r['t_half'])} | {fmt_time(r['t_touch'])} "
            f"| {r['theta']:.3f} rad | {r['spin']:.1f} rad/s | {r['energy'] * 1e3:.3f} mJ | {r['wall']:.1f} s "
            f"| {'—' if r['cpu'] is None else format(r['cpu'], '.1f') + ' s'} |"
        )
    return "\n".join(lines)


def agreement(rows):
    """Relative differences of contensou-in-MuJoCo from the Rust scene, per law."""
    lines = []
    for law in ["best", "simplified"]:
        mj = next((r for r in rows if r["run"].startswith(f"MuJoCo + contensou, {law}")), None)
        rs = next((r for r in rows if r["run"].startswith(f"Rust scene, {law}")), None)
        if not (mj and rs) or None in (mj["t_half"], rs["t_half"], mj["t_touch"], rs["t_touch"]):
            continue
        d_half = mj["t_half"] / rs["t_half"] - 1
        d_touch = mj["t_touch"] / rs["t_touch"] - 1
        lines.append(f"{law}: t(θ = π/2) {d_half:+.2%}, touch {d_touch:+.2%}, "
                     f"θ(end) {mj['theta'] - rs['theta']:+.3f} rad, energy(end) {mj['energy'] / rs['energy'] - 1:+.2%}")
    return lines


def main():
    ap = argparse.ArgumentParser(description="tippe top: MuJoCo's contact vs contensou vs the Rust scene")
    ap.add_argument("--end", type=float, default=8.0, help="end time (s)")
    ap.add_argument("--no-rust", action="store_true", help="skip the Rust scene (cargo)")
    args = ap.parse_args()
    rows = runs(args.end, rust=not args.no_rust)
    print(table(rows, args.end))
    for line in agreement(rows):
        print(line)


if __name__ == "__main__":
    main()
