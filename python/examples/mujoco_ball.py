"""A steel ball launched sliding and spinning on a steel floor, in MuJoCo: its own contact
against contensou's and the analytic spin decay.

    python python/examples/mujoco_ball.py              # 20 s, every run, the table
    python python/examples/mujoco_ball.py --end 0.5    # a smoke run (CI)

R = 10 mm, steel (ρ = 7850 kg/m³: m = 32.9 g, I = (2/5)mR²), E* = 115 GPa (E = 210 GPa,
ν = 0.3 on both sides), f = 0.1; launched at v₀ = 1 m/s along x without rolling and with
ω₀ = 100 rad/s about the vertical, resting on its static Hertz approach.

Analytic: sliding ends at t_roll = 2v₀/(7fg) (then v = 5v₀/7); while it slides the drilling
torque is that of u = v/(aω) ≫ 1 (≈ fNa/(5u), negligible); once it rolls the patch spins in
place and the Contensou torque is the pure-spin (3π/16)·f·N·a, so ω(t) = ω₀ − (3π/16)fNa/I·(t −
t_roll) with N = mg and the Hertz radius a = (3NR/(4E*))^(1/3).

Runs: MuJoCo's contact at the defaults (timestep 2 ms, solref "0.02 1"), friction
"0.1 0.005 0.0001", condim 3 (no torsional friction), 4 (torsional 0.005 m) and 6 (and rolling
friction 1e-4 m); condim 4 with the physical torsional coefficient (3π/16)·f·a = 1.6e-6 m
(MuJoCo raises it to its floor mjMINMU = 1e-5); contensou (floor_contact.py, best law,
δ = 1e-4 m/s, c_d = 1 s/m) with MuJoCo's Euler at 20 µs.
"""

import argparse
import math
import sys
import time
from pathlib import Path

import mujoco
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
from floor_contact import SphereFloor  # noqa: E402

R, RHO, ESTAR, F, G = 0.01, 7850.0, 210e9 / (2 * (1 - 0.3**2)), 0.1, 9.81
MASS = RHO * 4 / 3 * math.pi * R**3
INERTIA = 0.4 * MASS * R**2
V0, SPIN0 = 1.0, 100.0
CD, DELTA = 1.0, 1e-4
N_STATIC = MASS * G
A_STATIC = (3 * N_STATIC * R / (4 * ESTAR)) ** (1 / 3)
H_STATIC = A_STATIC**2 / R
TORSION = 3 * math.pi / 16 * F * A_STATIC  # the physical torsional coefficient (m)
SPIN_TIMES = [1.0, 5.0, 20.0]
ROLLING = 1e-3  # m/s: slip speed below which the ball rolls
SAMPLE = 0.01  # s: the ω_z(t) series

XML = """
<mujoco model="ball">
  <option timestep="{dt}" integrator="Euler" gravity="0 0 -{g}"/>
  <worldbody>
    <geom name="floor" type="plane" size="5 5 0.1" condim="{condim}" friction="{f} {torsion} 0.0001"
          contype="1" conaffinity="1"/>
    <body name="ball">
      <freejoint/>
      <inertial pos="0 0 0" mass="{m}" diaginertia="{i} {i} {i}"/>
      <geom name="ball" type="sphere" size="{r}" condim="{condim}" friction="{f} {torsion} 0.0001"
            contype="{native}" conaffinity="{native}"/>
    </body>
  </worldbody>
</mujoco>
"""


def model(condim=3, torsion=0.005, dt=2e-3, native=True):
    xml = XML.format(dt=dt, g=G, condim=condim, f=F, torsion=torsion, m=MASS, i=INERTIA, r=R,
                     native=1 if native else 0)
    return mujoco.MjModel.from_xml_string(xml)


def analytic():
    t_roll = 2 * V0 / (7 * F * G)
    rate = TORSION * N_STATIC / INERTIA
    spin = lambda t: SPIN0 - rate * max(t - t_roll, 0.0)  # noqa: E731
    ts = [0.0, t_roll, SPIN_TIMES[-1]]
    return {"run": f"analytic: t_roll = 2v₀/(7fg), dω/dt = (3π/16)fNa/I = {rate:.3f} rad/s²",
            "t_roll": t_roll, "spins": [spin(t) for t in SPIN_TIMES], "wall": None, "cpu": None,
            "series": (ts, [spin(t) for t in ts])}


def simulate(name, m, end, floor=None):
    d = mujoco.MjData(m)
    if floor is not None:
        floor.install()
    try:
        d.qpos[:] = [0, 0, R - (H_STATIC if floor is not None else 0.0), 1, 0, 0, 0]
        d.qvel[:] = [V0, 0, 0, 0, 0, SPIN0]
        mujoco.mj_forward(m, d)
        t_roll = None
        spins = {}
        steps = round(end / m.opt.timestep)
        marks = {round(t / m.opt.timestep): t for t in SPIN_TIMES}
        check = max(1, round(1e-3 / m.opt.timestep))
        every = max(1, round(SAMPLE / m.opt.timestep))
        series = ([0.0], [SPIN0])
        start, cpu0 = time.perf_counter(), time.process_time()
        for i in range(1, steps + 1):
            mujoco.mj_step(m, d)
            if t_roll is None and i % check == 0:
                w = d.xmat[1].reshape(3, 3) @ d.qvel[3:6]
                slip = d.qvel[0:3] + np.cross(w, [0.0, 0.0, -R])
                if math.hypot(slip[0], slip[1]) < ROLLING:
                    t_roll = d.time
            if i in marks or i % every == 0:
                spin = float((d.xmat[1].reshape(3, 3) @ d.qvel[3:6])[2])
                if i in marks:
                    spins[marks[i]] = spin
                if i % every == 0:
                    series[0].append(d.time)
                    series[1].append(spin)
        wall, cpu = time.perf_counter() - start, time.process_time() - cpu0
    finally:
        if floor is not None:
            floor.uninstall()
    return {"run": name, "t_roll": t_roll, "spins": [spins.get(t) for t in SPIN_TIMES], "wall": wall, "cpu": cpu,
            "series": series}


def runs(end):
    """Every run up to `end` (the analytic row is for the full 20 s)."""
    out = [analytic()]
    for condim in [3, 4, 6]:
        out.append(simulate(f"MuJoCo condim {condim}, defaults", model(condim), end))
    out.append(simulate(f"MuJoCo condim 4, torsional {TORSION:.1e} m (physical; floor 1e-5)",
                        model(4, torsion=TORSION), end))
    m = model(dt=2e-5, native=False)
    floor = SphereFloor(m, "ball", ["ball"], ESTAR, CD, F, DELTA, law="best")
    out.append(simulate("MuJoCo + contensou, best (Euler 20 µs)", m, end, floor))
    return out


def table(rows):
    head = " | ".join(f"ω_z({t:g} s)" for t in SPIN_TIMES)
    lines = [f"| run | time to pure rolling | {head} | wall | CPU |",
             "|---|---:|" + "---:|" * len(SPIN_TIMES) + "---:|---:|"]
    for r in rows:
        spins = " | ".join("—" if s is None else f"{s:.2f} rad/s" for s in r["spins"])
        t_roll = "never" if r["t_roll"] is None else f"{r['t_roll']:.3f} s"
        wall = "—" if r["wall"] is None else f"{r['wall']:.1f} s"
        cpu = "—" if r["cpu"] is None else f"{r['cpu']:.1f} s"
        lines.append(f"| {r['run']} | {t_roll} | {spins} | {wall} | {cpu} |")
    return "\n".join(lines)


def main():
    ap = argparse.ArgumentParser(description="steel ball: MuJoCo's contact vs contensou vs analytic")
    ap.add_argument("--end", type=float, default=20.0, help="end time (s)")
    args = ap.parse_args()
    print(f"m = {MASS * 1e3:.2f} g, N = {N_STATIC:.4f} N, a = {A_STATIC * 1e6:.2f} µm, "
          f"(3π/16)·f·a = {TORSION:.2e} m")
    print(table(runs(args.end)))


if __name__ == "__main__":
    main()
