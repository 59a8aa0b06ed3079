"""Where a shipped model's energy goes over one MuJoCo step with the step-aware contact: the
change of the mechanical energy split into the work of each generalized force as MuJoCo
integrates it, and the contact's elastic energy counted two ways.

    mujoco/build.sh
    python mujoco/examples/energy_budget.py                                  # the four models, 2 ms
    python mujoco/examples/energy_budget.py --models rattleback --dt 0.001
    python mujoco/examples/energy_budget.py --models rattleback --config step_point=0
    python mujoco/examples/energy_budget.py --native --dt 0.002      # MuJoCo's own condim-6 contact instead

MuJoCo's update (implicitfast without damping or actuators; Euler the same here) is
semi-implicit Euler: M(q)·Δv = Δt·(f_c − bias), q⁺ = q ⊕ Δt·v⁺, with f_c the plugin's
generalized contact force (qfrc_passive) and bias = gravity + Coriolis/gyroscopic (mj_rne).
Hence, exactly,

    ΔT = Δt·v⁺·f_N + Δt·v⁺·f_F − Δt·v⁺·bias_g − Δt·v⁺·bias_c − ½ΔvᵀMΔv + ½v⁺ᵀ(M(q⁺) − M(q))v⁺

with f_N the normal force N·n applied at the patch centre (mj_applyFT) and f_F = f_c − f_N the
friction force and drilling torque. Columns (per step, relative to the start energy E₀ of
step_sweep.py: kinetic + gravitational + (2/5)N·h):

- `normal` Δt·v⁺·f_N + ΔU (the normal force's work plus the change of the exact elastic energy
  U(h) = (2/5)·N_el(h)·h, N_el the Hertz force at the same pose and approach with zero
  velocity: the plugin with step = explicit on a copy of the state with q̇ = 0), split into
  `law` ΔU − N·Δh (the normal law against the elastic energy, with the change of U with the
  pose at a fixed h) and `pose` N·(Δh + Δt·n·v_P⁺) (the gap change of MuJoCo's pose update
  beyond the contact point's normal velocity: ½(ρ − ℓ)(Δt·ω)² for a body rocking on a bottom
  of curvature radius ρ about a contact ℓ below its centre of mass);
- `friction` Δt·v⁺·f_F (≤ 0 if the friction takes energy in the update MuJoCo makes);
- `rigid` −Δt·v⁺·bias_c − ½ΔvᵀMΔv + the ΔM term: the rigid-body update's own energy error
  (the explicit gyroscopic term of semi-implicit Euler);
- `true` ΔT + ΔV + ΔU (the sum of the above, the gravity cancelling exactly), and
  `reported` the rise step_sweep.py reports, with (2/5)·N·h taken from the step-aware N;
- `staggered` the rise of semi-implicit Euler's staggered energy ½v_nᵀM(q_n)v_{n+1} + V(q_n) +
  U(q_n) (the kinetic energy of the velocities either side of the pose q_n: for a force of
  the pose alone, symplectic Euler keeps this one, not T(v_n) + V(q_n), free of the O(Δt)
  swing; for a linear spring exactly).

Per model: the largest per-step value of each column and of `true`/`reported`, and the column
values at the step where `true` peaks. `--sums`: instead, each column summed over the run (from
`--since` s on): a swing sums to about nothing, a drift does not — the backward-Euler normal
force must take energy, Σ `law` ≤ 0.

`--native` (native_budget): the same bodies with MuJoCo's own soft contact instead of the plugin
(the plugin removed, the geoms colliding natively, condim 6, friction "f 0.005 0.0001": the
model's f, MuJoCo's default torsional and rolling coefficients): the largest per-step rise of
T + V (mjData.energy) and of T + V + U with U = ½·Σ N·(−dist) over the active contacts (a soft
constraint stores no elastic energy; this is a linear spring's at the contact's penetration and
normal force, mj_contactForce), and of the staggered energy, relative to the start T + V + U.
"""

import argparse
import re
import sys
from pathlib import Path

import mujoco
import numpy as np

sys.path.insert(0, str(Path(__file__).resolve().parent))
import run_models  # noqa: E402
import step_sweep  # noqa: E402


def support_points(m, d, body, normal):
    """Per sphere/ellipsoid geom of `body` (model order, the plugin's pair order against one
    plane): the point of the geom deepest along −normal."""
    sphere, ellipsoid = int(mujoco.mjtGeom.mjGEOM_SPHERE), int(mujoco.mjtGeom.mjGEOM_ELLIPSOID)
    out = []
    for g in range(m.body_geomadr[body], m.body_geomadr[body] + m.body_geomnum[body]):
        if int(m.geom_type[g]) not in (sphere, ellipsoid):
            continue
        a = m.geom_size[g] if int(m.geom_type[g]) == ellipsoid else np.full(3, m.geom_size[g][0])
        r = d.geom_xmat[g].reshape(3, 3)
        u = r.T @ (-normal)
        s = np.sqrt(np.sum(a**2 * u**2))
        out.append(d.geom_xpos[g] + r @ (a**2 * u / s))
    return out


def budget(name, dt, config, end, key=0, sums=None, since=0.0):
    m = step_sweep.load(name, dt, config)
    # The same model with the plain contact: the elastic force N_el(h) at a pose (q̇ = 0).
    plain = {k: x for k, x in config.items() if k != "step_point"}
    me = step_sweep.load(name, dt, {**plain, "step": "explicit"})
    de = mujoco.MjData(me)
    d = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, d, key)
    nv, body, h = m.nv, 1, m.opt.timestep
    normal = np.array([0.0, 0.0, 1.0])
    g_save = m.opt.gravity.copy()

    def state():
        """Energies and forces at d's state (after mj_forward)."""
        rows = run_models.contacts(m, d).copy()
        de.qpos[:] = d.qpos
        de.qvel[:] = 0
        mujoco.mj_forward(me, de)
        rows_el = run_models.contacts(me, de)
        hp = np.maximum(rows[:, 6], 0.0)
        return {
            "T": float(d.energy[1]), "V": float(d.energy[0]),
            "U_rep": 0.4 * float(np.sum(rows[:, 0] * hp)),
            "U": 0.4 * float(np.sum(rows_el[:, 0] * hp)),
            "rows": rows,
        }

    mujoco.mj_forward(m, d)
    s = state()
    e0 = s["T"] + s["V"] + s["U_rep"]
    cols = ("normal", "law", "pose", "friction", "gyro", "true", "reported", "accounting", "staggered")
    peak = {c: -np.inf for c in cols}
    at_true = None
    resid = 0.0
    stag_prev = None
    for _ in range(round(end / h)):
        mujoco.mj_forward(m, d)
        s = state()
        M = np.zeros((nv, nv))
        mujoco.mj_fullM(m, d, M)
        v = d.qvel.copy()
        fc = d.qfrc_passive.copy()
        bias = d.qfrc_bias.copy()
        m.opt.gravity[:] = 0
        coriolis = np.zeros(nv)
        mujoco.mj_rne(m, d, 0, coriolis)
        m.opt.gravity[:] = g_save
        fN = np.zeros(nv)
        points = support_points(m, d, body, normal)
        assert len(points) == len(s["rows"]), "one pair per sphere/ellipsoid geom against one plane"
        for p, row in zip(points, s["rows"]):
            if row[0] != 0.0:
                mujoco.mj_applyFT(m, d, row[0] * normal, np.zeros(3), p, body, fN)
        mujoco.mj_step(m, d)
        vp = d.qvel.copy()
        dv = vp - v
        resid = max(resid, float(np.max(np.abs(M @ dv - h * (fc - bias)))))
        mujoco.mj_forward(m, d)
        M1 = np.zeros((nv, nv))
        mujoco.mj_fullM(m, d, M1)
        s1 = state()
        wN = h * vp @ fN
        wF = h * vp @ (fc - fN)
        gyro = -h * vp @ coriolis - 0.5 * dv @ M @ dv + 0.5 * vp @ (M1 - M) @ vp
        true = (s1["T"] + s1["V"] + s1["U"]) - (s["T"] + s["V"] + s["U"])
        rep = (s1["T"] + s1["V"] + s1["U_rep"]) - (s["T"] + s["V"] + s["U_rep"])
        dh = s1["rows"][:, 6] - s["rows"][:, 6]
        n_dh = float(np.sum(s["rows"][:, 0] * dh))
        # The staggered energy of semi-implicit Euler at the start of this step: ½ v_nᵀM(q_n)v_{n+1} + V + U
        # (its kinetic part pairs the velocities either side of q_n); its rise over the previous step.
        stag = 0.5 * v @ M @ vp + s["V"] + s["U"]
        row = {"normal": wN + s1["U"] - s["U"], "law": s1["U"] - s["U"] - n_dh, "pose": n_dh + wN, "friction": wF, "gyro": gyro, "true": true, "reported": rep,
               "accounting": rep - true, "staggered": -np.inf if stag_prev is None else stag - stag_prev}
        stag_prev = stag
        row = {k: x / abs(e0) for k, x in row.items()}
        for c in cols:
            peak[c] = max(peak[c], row[c])
            if sums is not None and d.time > since and np.isfinite(row[c]):
                sums[c] = sums.get(c, 0.0) + row[c]
        if at_true is None or row["true"] >= max(at_true["true"], -np.inf):
            at_true = {**row, "t": d.time}
    return m, peak, at_true, resid


NATIVE_FRICTION = "0.005 0.0001"  # MuJoCo's default torsional and rolling coefficients (m)


def native_model(name, dt, integrator=None):
    """Model `name` with MuJoCo's own condim-6 contact on the plugin's bodies (module docs)."""
    text = (run_models.MODELS / f"{name}.xml").read_text()
    f = re.search(r'<config key="f" value="([^"]+)"/>', text).group(1)
    friction = f'condim="6" friction="{f} {NATIVE_FRICTION}"'
    for block in ("extension", "sensor"):
        text = re.sub(rf"<{block}>.*?</{block}>", "", text, flags=re.S)
    text = text.replace('<plugin instance="contact"/>', "").replace('<flag contact="disable"/>', "")
    text = text.replace('contype="0" conaffinity="0"', friction)
    text = re.sub(r'(<geom name="floor" type="plane"[^/]*)/>', rf"\1 {friction}/>", text)
    return step_sweep.model_from(text, dt, integrator)


def native_budget(name, dt, end, key=0, integrator=None):
    """Largest per-step rises relative to the start energy with MuJoCo's native contact:
    {"TV": T + V, "true": T + V + U, "staggered": ½v_nᵀM v_{n+1} + V + U} (module docs)."""
    m = native_model(name, dt, integrator)
    d = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, d, key)
    force = np.zeros(6)
    M = np.zeros((m.nv, m.nv))

    def elastic():
        u = 0.0
        for i in range(d.ncon):
            mujoco.mj_contactForce(m, d, i, force)
            u += 0.5 * force[0] * max(-d.contact[i].dist, 0.0)
        return u

    mujoco.mj_forward(m, d)
    e0 = abs(float(d.energy.sum()) + elastic())
    peak = {"TV": -np.inf, "true": -np.inf, "staggered": -np.inf}
    stag_prev = None
    for _ in range(round(end / m.opt.timestep)):
        mujoco.mj_forward(m, d)
        tv, u = float(d.energy.sum()), elastic()
        mujoco.mj_fullM(m, d, M)
        v = d.qvel.copy()
        mujoco.mj_step(m, d)
        stag = 0.5 * v @ M @ d.qvel + float(d.energy[0]) + u
        if stag_prev is not None:
            peak["staggered"] = max(peak["staggered"], (stag - stag_prev) / e0)
        stag_prev = stag
        mujoco.mj_forward(m, d)
        tv1 = float(d.energy.sum())
        peak["TV"] = max(peak["TV"], (tv1 - tv) / e0)
        peak["true"] = max(peak["true"], (tv1 + elastic() - tv - u) / e0)
    return m, peak


def rocking_decay(name, dt, axis, kick=0.2, settle=0.5, end=1.0, config=None):
    """How fast a small rocking oscillation of a rattleback model loses its energy over the
    step's integration (s⁻¹): the body set upright (its body frame is the bottom's curvature
    frame, origin at G; the approach from the settled state), settled for `settle` s without
    spin, then its ω about the body axis `axis` (0: roll about the long axis x, 1: pitch about
    y) raised by `kick` rad/s; the rocking energy e = T + V + U − (the settled one) over the
    first and last 0.2 s of `end` s gives ln(ē₀/ē₁)/(end − 0.2). A scheme that keeps T + V + U
    from rising over every step damps such a mode at about ½·Δt·Ω² (the normal force applied at
    the mid-step contact point, measured: 8.6, 5.7, 2.9 s⁻¹ for the pitch, Ω ≈ 107 rad/s, at 2,
    1, 0.5 ms; 1.2, 0.58, 0.29 for the roll, Ω ≈ 34 rad/s). (MuJoCo's native soft contact has no
    such measure: its penetration, and with it V, follows the rocking by tens of µm.) `config`:
    plugin config keys, as step_sweep.load (step=explicit: the plain contact at its small step)."""
    m = step_sweep.load(name, dt, config or {})
    d = mujoco.MjData(m)

    def energy():
        rows = run_models.contacts(m, d)
        return float(d.energy.sum()) + 0.4 * float(np.sum(rows[:, 0] * np.maximum(rows[:, 6], 0.0)))

    g = next(i for i in range(m.ngeom) if int(m.geom_type[i]) == int(mujoco.mjtGeom.mjGEOM_ELLIPSOID))
    d.qpos[:] = [0.0, 0.0, m.geom_size[g][2] - m.geom_pos[g][2], 1.0, 0.0, 0.0, 0.0]
    mujoco.mj_forward(m, d)
    mujoco.mj_step(m, d, round(settle / m.opt.timestep))
    mujoco.mj_forward(m, d)
    rest = energy()
    d.qvel[3 + axis] += kick
    mujoco.mj_forward(m, d)
    ts, es = [], []
    for _ in range(round(end / m.opt.timestep)):
        mujoco.mj_step(m, d)
        mujoco.mj_forward(m, d)
        ts.append(d.time)
        es.append(energy() - rest)
    ts, es = np.array(ts), np.array(es)
    first, last = es[ts < ts[0] + 0.2].mean(), es[ts > ts[-1] - 0.2].mean()
    return float(np.log(first / last) / (ts[-1] - ts[0] - 0.2)) if first > 0 and last > 0 else float("inf")


def pose_check(name, dt, config, end, key=0):
    """The `pose` term of an ellipsoid body (the rattlebacks: body frame = the geom's axes, the
    bottom at −a_z) against ½·N·Δt²·((ρ_x − ℓ)ω_y² + (ρ_y − ℓ)ω_x²), ρ = a²/a_z the bottom's
    curvature radii, ℓ = a_z − the geom's height over the centre of mass, ω in the body frame:
    (correlation, median ratio where the estimate exceeds a tenth of its peak, peak pose (J),
    the estimate there (J))."""
    m = step_sweep.load(name, dt, config)
    d = mujoco.MjData(m)
    mujoco.mj_resetDataKeyframe(m, d, key)
    g = next(i for i in range(m.ngeom) if int(m.geom_type[i]) == int(mujoco.mjtGeom.mjGEOM_ELLIPSOID))
    a, h = m.geom_size[g], m.opt.timestep
    rho_x, rho_y, ell = a[0] ** 2 / a[2], a[1] ** 2 / a[2], a[2] - m.geom_pos[g][2]
    normal = np.array([0.0, 0.0, 1.0])
    pose, est = [], []
    jp, jr = np.zeros((3, m.nv)), np.zeros((3, m.nv))
    for _ in range(round(end / h)):
        mujoco.mj_forward(m, d)
        r0 = run_models.contacts(m, d).copy()
        mujoco.mj_jac(m, d, jp, jr, support_points(m, d, m.geom_bodyid[g], normal)[0], m.geom_bodyid[g])
        mujoco.mj_step(m, d)
        mujoco.mj_forward(m, d)
        r1 = run_models.contacts(m, d)
        n = r0[0, 0]
        pose.append(n * (r1[0, 6] - r0[0, 6] + h * (jp @ d.qvel)[2]))
        w = d.qvel[3:6]
        est.append(0.5 * n * h * h * ((rho_x - ell) * w[1] ** 2 + (rho_y - ell) * w[0] ** 2))
    pose, est = np.array(pose), np.array(est)
    k, big = int(np.argmax(pose)), est > 0.1 * est.max()
    return float(np.corrcoef(pose, est)[0, 1]), float(np.median(pose[big] / est[big])), pose[k], est[k]


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--models", default="ball,tippe_top,rattleback,rattleback_rolling")
    ap.add_argument("--dt", type=float, default=None, help="step (s; default as shipped, 2 ms)")
    ap.add_argument("--config", action="append", default=[], help="plugin config key=value (repeatable)")
    ap.add_argument("--end", type=float, default=None, help="simulated time (s; default per model)")
    ap.add_argument("--sums", action="store_true", help="each column summed over the run instead of its peak")
    ap.add_argument("--since", type=float, default=0.0, help="--sums: from this time on (s)")
    ap.add_argument("--native", action="store_true",
                    help="MuJoCo's native condim-6 contact on the same bodies instead (native_budget)")
    ap.add_argument("--integrator", default=None, help="--native: Euler, implicitfast, … (default: as shipped)")
    ap.add_argument("--rocking", action="store_true",
                    help="the decay rate of a small roll and pitch oscillation of the rattleback (rocking_decay)")
    ap.add_argument("--pose-check", action="store_true",
                    help="the rattlebacks' `pose` term against ½N·Δt²·Σ(ρ − ℓ)ω² (pose_check) instead")
    args = ap.parse_args()
    run_models.load_plugin()
    config = dict(c.split("=", 1) for c in args.config)
    if args.native:
        print("| model | step | native condim 6, max rise per step: T + V | T + V + ½N·pen | staggered |")
        print("|---|---|---|---|---|")
        for name in args.models.split(","):
            for key in step_sweep.keys(name):
                m, peak = native_budget(name, args.dt, args.end or step_sweep.ENDS[name], key, args.integrator)
                label = name + ("" if key == 0 else f" {m.key(key).name}")
                print(f"| {label} | {m.opt.timestep * 1e3:g} ms | {peak['TV']:.1e} | {peak['true']:.1e} | "
                      f"{peak['staggered']:.1e} |", flush=True)
        return
    if args.rocking:
        print("| step | roll decay (1/s) | pitch decay (1/s) |")
        print("|---|---|---|")
        for dt in (args.dt,) if args.dt else (0.002, 0.001, 0.0005):
            rates = [rocking_decay("rattleback", dt, axis) for axis in (0, 1)]
            print(f"| {dt * 1e3:g} ms | " + " | ".join(f"{r:.3f}" for r in rates) + " |", flush=True)
        return
    if args.pose_check:
        for name in ("rattleback", "rattleback_rolling"):
            c, ratio, p, e = pose_check(name, args.dt, config, args.end or step_sweep.ENDS[name])
            print(f"{name}: pose vs ½N·Δt²·Σ(ρ − ℓ)ω²: correlation {c:.4f}, median ratio {ratio:.3f}, "
                  f"at the peak {p:.4e} J against {e:.4e} J")
        return
    print("| model | step | max per step: normal (law + pose) | law | pose | friction | rigid | true | reported "
          "| reported − true | staggered | at the true peak (t): law, pose, friction, rigid |")
    print("|---|---|---|---|---|---|---|---|---|---|---|---|")
    for name in args.models.split(","):
        for key in step_sweep.keys(name):
            sums = {} if args.sums else None
            m, peak, at, resid = budget(name, args.dt, config, args.end or step_sweep.ENDS[name], key, sums, args.since)
            label = name + ("" if key == 0 else f" {m.key(key).name}")
            assert resid < 1e-5, f"MuJoCo's update is not M·Δv = Δt·(f − bias) here (residual {resid:.1e})"
            if args.sums:
                print(f"| {label} | {m.opt.timestep * 1e3:g} ms | sums from {args.since:g} s: "
                      + ", ".join(f"{c} {sums.get(c, 0.0):+.2e}" for c in ("law", "pose", "friction", "gyro", "true"))
                      + " |", flush=True)
                continue
            print(f"| {label} | {m.opt.timestep * 1e3:g} ms | {peak['normal']:.1e} | {peak['law']:.1e} | "
                  f"{peak['pose']:.1e} | {peak['friction']:.1e} | {peak['gyro']:.1e} | {peak['true']:.1e} | "
                  f"{peak['reported']:.1e} | {peak['accounting']:.1e} | {peak['staggered']:.1e} | {at['t']:.3f} s: {at['law']:.1e}, "
                  f"{at['pose']:.1e}, {at['friction']:.1e}, {at['gyro']:.1e} |", flush=True)


if __name__ == "__main__":
    main()
