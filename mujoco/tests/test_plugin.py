"""The contensou.contact MuJoCo plugin (mujoco/build/libcontensou_mujoco.so, built by
mujoco/build.sh): agreement with the Python-callback path, the scenes' reference figures,
the ellipsoid geometry against mpmath, two-body and capsule contacts, refusals at load.

    mujoco/build.sh && python -m pytest -q mujoco/tests

Needs the `mujoco` and `contensou` Python packages (the callback path: pip install ./python).
"""

import csv
import math
import re
import sys
from pathlib import Path

import numpy as np
import pytest

mujoco = pytest.importorskip("mujoco")
REPO = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(REPO / "mujoco" / "examples"))
sys.path.insert(0, str(REPO / "mujoco" / "models"))
sys.path.insert(0, str(REPO / "python" / "examples"))
import run_models  # noqa: E402

# The Rust scene's t(θ = π/2) with the `best` law (src/scenes/tippe_top.rs, RK4 10 µs, f64),
# located between the RK4 steps (src/scenes/event.rs):
# `cargo run --release --features scenes --example tippe_top` prints "θ = π/2 at 1.113694 s"
# (its 2 ms CSV, θ interpolated linearly: 1.1137478; docs/mujoco.md: 1.114 s).
RUST_T_HALF_BEST = 1.113694


@pytest.fixture(scope="module", autouse=True)
def plugin():
    run_models.load_plugin()


def test_models_are_what_the_generator_writes():
    import generate

    for name, make in generate.MODELS.items():
        assert generate.same((REPO / "mujoco" / "models" / name).read_text(), make()), \
            f"{name}: run mujoco/models/generate.py"


# ---------------------------------------------------------------------- the Python-callback path


def lockstep(plugin_model, callback_model, floor, steps):
    """Steps both from the plugin model's keyframe 0, one step each in turn (the callback is
    global: installed around its own steps only); the largest relative difference of (qpos,
    qvel) over every step, and whether every step was bit for bit."""
    pytest.importorskip("contensou")  # the callback's contact
    dp, dc = mujoco.MjData(plugin_model), mujoco.MjData(callback_model)
    mujoco.mj_resetDataKeyframe(plugin_model, dp, 0)
    dc.qpos[:], dc.qvel[:] = dp.qpos, dp.qvel
    worst, identical = 0.0, True
    for _ in range(steps):
        mujoco.mj_step(plugin_model, dp)
        floor.install()
        try:
            mujoco.mj_step(callback_model, dc)
        finally:
            floor.uninstall()
        a = np.concatenate([dp.qpos, dp.qvel])
        b = np.concatenate([dc.qpos, dc.qvel])
        identical &= bool(np.array_equal(a, b))
        worst = max(worst, float(np.max(np.abs(a - b) / np.where(b == 0, 1.0, np.abs(b)))))
    assert dp.time > 0 and np.all(np.isfinite(dp.qpos))
    return worst, identical


@pytest.mark.parametrize("integrator,steps", [("Euler", 3000), ("RK4", 500)])
def test_tippe_top_equals_the_python_callback(integrator, steps):
    import mujoco_tippe_top as top
    from floor_contact import SphereFloor

    pm = mujoco.MjModel.from_xml_path(str(run_models.MODELS / "tippe_top.xml"))
    pm.opt.integrator = getattr(mujoco.mjtIntegrator, f"mjINT_{integrator.upper()}")
    cm = top.model(dt=pm.opt.timestep, integrator=integrator, native=False)
    floor = SphereFloor(cm, "top", ["big", "small"], top.ESTAR, top.CD, top.F, top.DELTA, law="best")
    worst, identical = lockstep(pm, cm, floor, steps)
    print(f"tippe top, {integrator}, {steps} steps: max relative difference {worst:.3g}, bit for bit: {identical}")
    assert worst <= 1e-12


def test_ball_equals_the_python_callback():
    import mujoco_ball as ball
    from floor_contact import SphereFloor

    pm = mujoco.MjModel.from_xml_path(str(run_models.MODELS / "ball.xml"))
    cm = ball.model(dt=pm.opt.timestep, native=False)
    floor = SphereFloor(cm, "ball", ["ball"], ball.ESTAR, ball.CD, ball.F, ball.DELTA, law="best")
    worst, identical = lockstep(pm, cm, floor, 3000)
    print(f"ball, Euler, 3000 steps: max relative difference {worst:.3g}, bit for bit: {identical}")
    assert worst <= 1e-12


# ------------------------------------------------------------------------ the scenes' figures


def test_tippe_top_inverts_at_the_rust_scenes_time():
    run = run_models.run_tippe_top(1.2, sample=1e-4)
    assert run["t_half"] is not None
    assert abs(run["t_half"] - RUST_T_HALF_BEST) < 1e-3, run["t_half"]


def test_ball_rolls_and_spins_down_as_the_analytic_solution():
    import mujoco_ball as ball

    run = run_models.run_ball(1.5)
    t_roll = 2 * ball.V0 / (7 * ball.F * ball.G)
    rate = ball.TORSION * ball.N_STATIC / ball.INERTIA  # (3π/16) f N a / I
    assert run["t_roll"] == pytest.approx(t_roll, rel=0.01)
    assert -run_models.spin_rate(run, 0.5, 1.5) == pytest.approx(rate, rel=0.01)


def test_rattleback_stalls_as_the_rust_scene():
    # The guide (docs/guide/src/rattleback.md): `Best`, ω₀ = −2 rad/s, RK4 0.1 ms: the first 10 ms sample past
    # the stall threshold is 0.87 s, as compared here (same sampling); located between the
    # steps, the stall is at 0.8436 s (the spin's first dip, between samples).
    run = run_models.run_rattleback(1.0)
    assert run["reversal"] is None
    assert run["stall"] == pytest.approx(0.87, abs=0.02)


def test_ellipsoid_approach_matches_mpmath():
    """h of the closed-form support point against tools/data/rattleback_geometry.csv (mpmath,
    numerical minimisation of the height), at the committed attitudes."""
    import generate

    m = mujoco.MjModel.from_xml_path(str(run_models.MODELS / "rattleback.xml"))
    d = mujoco.MjData(m)
    # The data's q maps the principal (inertia) frame to the world; the body frame here is the
    # curvature frame, turned by −δ from it.
    half = -generate.RB_SKEW / 2
    rows = list(csv.DictReader(open(REPO / "tools" / "data" / "rattleback_geometry.csv")))
    assert rows
    for r in rows:
        q = generate.quat_mul([float(r[k]) for k in ("qw", "qx", "qy", "qz")], [math.cos(half), 0, 0, math.sin(half)])
        d.qpos[:] = [0.0, 0.0, float(r["zG"]), *q]
        d.qvel[:] = 0.0
        mujoco.mj_forward(m, d)
        h = run_models.contacts(m, d)[0, 6]
        assert h == pytest.approx(float(r["h"]), rel=1e-11)  # measured 3.1e-13


# ----------------------------------------------------------------- two bodies, capsules, sensor


PLUGIN_HEAD = """
<mujoco>
  <extension><plugin plugin="contensou.contact"><instance name="c">{config}</instance></plugin></extension>
  <option timestep="1e-5" integrator="Euler" gravity="{gravity}"/>
  <worldbody>
    {floor}
    {bodies}
  </worldbody>
  <sensor><plugin name="contacts" instance="c"/></sensor>
</mujoco>
"""
CONFIG = '<config key="estar" value="1e9"/><config key="f" value="0.3"/><config key="cd" value="1"/>'


def xml(bodies, config=CONFIG, gravity="0 0 -9.81", floor='<geom name="floor" type="plane" size="1 1 .1"/>'):
    return PLUGIN_HEAD.format(config=config, gravity=gravity, floor=floor, bodies=bodies)


def test_two_spheres_exchange_equal_and_opposite_loads():
    bodies = """
    <body name="a" pos="0 0 0"><freejoint/><plugin instance="c"/>
      <geom name="ga" type="sphere" size="0.01" mass="0.01" contype="0" conaffinity="0"/></body>
    <body name="b" pos="0.0199 0.001 0"><freejoint/><plugin instance="c"/>
      <geom name="gb" type="sphere" size="0.01" mass="0.02" contype="0" conaffinity="0"/></body>"""
    m = mujoco.MjModel.from_xml_string(xml(bodies, gravity="0 0 0", floor=""))
    d = mujoco.MjData(m)
    d.qvel[:] = [0.1, 0, 0, 0, 0, 30, -0.05, 0, 0, 5, 0, -20]
    mujoco.mj_forward(m, d)
    rows = run_models.contacts(m, d)
    assert rows.shape == (1, 7) and rows[0, 0] > 0  # one pair, touching
    # Linear momentum and the angular momentum about the origin are conserved by the contact.
    def momenta():
        p, l = np.zeros(3), np.zeros(3)
        for b in (1, 2):
            v, w = d.qvel[6 * (b - 1): 6 * (b - 1) + 3], d.xmat[b].reshape(3, 3) @ d.qvel[6 * (b - 1) + 3: 6 * b]
            mass = m.body_mass[b]
            inertia = d.xmat[b].reshape(3, 3) @ np.diag(m.body_inertia[b]) @ d.xmat[b].reshape(3, 3).T
            p += mass * v
            l += mass * np.cross(d.xpos[b], v) + inertia @ w
        return p, l
    p0, l0 = momenta()
    mujoco.mj_step(m, d, 200)
    p1, l1 = momenta()
    assert np.allclose(p1, p0, rtol=0, atol=1e-12)
    assert np.allclose(l1, l0, rtol=0, atol=1e-13)


def test_capsule_on_the_floor_carries_its_weight_on_both_ends():
    # Lying on the floor at the static Hertz approach of each end sphere, mg/2 = (4/3)E*√r·h^1.5.
    r, mass, estar = 0.01, 0.2, 1e9
    h0 = (0.5 * mass * 9.81 / (4 / 3 * estar * math.sqrt(r))) ** (2 / 3)
    bodies = f"""
    <body name="rod" pos="0 0 {r - h0!r}" euler="0 90 0"><freejoint/><plugin instance="c"/>
      <geom name="rod" type="capsule" size="{r} 0.05" mass="{mass}" contype="0" conaffinity="0"/></body>"""
    m = mujoco.MjModel.from_xml_string(xml(bodies))
    d = mujoco.MjData(m)
    mujoco.mj_step(m, d, 1000)
    rows = run_models.contacts(m, d)
    assert rows.shape == (2, 7)
    assert rows[:, 0] == pytest.approx([0.5 * mass * 9.81] * 2, rel=1e-3)
    assert rows[:, 6] == pytest.approx([h0] * 2, rel=1e-3)


# -------------------------------------------------------------------------------- refusals


BALL = """<body name="ball"><freejoint/><plugin instance="c"/>
  <geom name="ball" type="sphere" size="0.01" mass="0.03" contype="0" conaffinity="0"/></body>"""


@pytest.mark.parametrize("config,bodies,message", [
    ('<config key="estar" value="1e9"/><config key="f" value="0.3"/><config key="law" value="stribeck"/>', BALL,
     r"law = 'stribeck' is no law"),
    ('<config key="estar" value="1e9"/><config key="f" value="-0.3"/>', BALL, r"f = -0\.3: .*friction"),
    ('<config key="estar" value="-5"/><config key="f" value="0.3"/>', BALL, r"estar = -5: "),
    ('<config key="estar" value="1e9"/><config key="f" value="0.3"/><config key="delta" value="-1"/>', BALL,
     r"delta = -1: "),
    ('<config key="estar" value="1e9"/><config key="f" value="0.3"/><config key="cd" value="fast"/>', BALL,
     r"cd = 'fast' is not a finite number"),
    ('<config key="estar" value="1e9"/><config key="f" value="0.3"/><config key="form" value="rigid"/>', BALL,
     r"form = 'rigid' is no form"),
    ('<config key="f" value="0.3"/>', BALL, r"'estar' .* is required"),
    ('<config key="estar" value="1e9"/>', BALL, r"attribute 'f' is required"),
    ('<config key="estar" value="1e9"/><config key="young1" value="2e11"/><config key="f" value="0.3"/>', BALL,
     r"either estar"),
    ('<config key="young1" value="2e11"/><config key="poisson1" value="0.7"/><config key="young2" value="2e11"/>'
     '<config key="poisson2" value="0.3"/><config key="f" value="0.3"/>', BALL, r"poisson1 = 0\.7"),
    (CONFIG, BALL.replace('type="sphere" size="0.01"', 'type="box" size="0.01 0.01 0.01"'),
     r"geom 'ball' of body 'ball' is a box: unsupported geom type"),
    (CONFIG, BALL.replace(' contype="0" conaffinity="0"', ''), r"geom 'ball' would also collide natively with 'floor'"),
    (CONFIG + '<config key="mu" value="1"/>', BALL, r"unrecognized attribute 'plugin:mu'"),
])
def test_bad_configuration_is_refused_at_load_naming_attribute_and_value(config, bodies, message):
    with pytest.raises(ValueError, match=message):
        mujoco.MjModel.from_xml_string(xml(bodies, config=config))


def test_young_and_poisson_give_estar():
    cfg = ('<config key="young1" value="210e9"/><config key="poisson1" value="0.3"/><config key="young2" value="210e9"/>'
           '<config key="poisson2" value="0.3"/><config key="f" value="0.1"/>')
    est = '<config key="estar" value="{}"/><config key="f" value="0.1"/>'.format(repr(210e9 / (2 * (1 - 0.09))))
    out = []
    for c in (cfg, est):
        m = mujoco.MjModel.from_xml_string(xml(BALL.replace('pos', 'x'), config=c))
        d = mujoco.MjData(m)
        d.qpos[2] = 0.01 - 1e-6
        mujoco.mj_forward(m, d)
        out.append(run_models.contacts(m, d)[0, 0])
    assert out[0] > 0 and out[0] == pytest.approx(out[1], rel=1e-12)


def test_sensor_reports_hertz_force_of_a_resting_sphere():
    # Sphere on a plane: N = (4/3) E* sqrt(R) h^1.5, a = sqrt(R h) (model notes §1).
    m = mujoco.MjModel.from_xml_string(xml(BALL))
    d = mujoco.MjData(m)
    h = 2e-6
    d.qpos[2] = 0.01 - h
    mujoco.mj_forward(m, d)
    n, fx, fy, tz, a, b, hh = run_models.contacts(m, d)[0]
    assert hh == pytest.approx(h, rel=1e-9)
    assert n == pytest.approx(4 / 3 * 1e9 * math.sqrt(0.01) * h**1.5, rel=1e-12)
    assert a == pytest.approx(math.sqrt(0.01 * h), rel=1e-12) and b == pytest.approx(a, rel=1e-12)
    assert fx == fy == tz == 0.0


def test_error_messages_are_readable():
    with pytest.raises(ValueError) as e:
        mujoco.MjModel.from_xml_string(xml(BALL, config='<config key="estar" value="1e9"/><config key="f" value="-1"/>'))
    assert re.search(r"contensou\.contact: f = -1", str(e.value))


def test_a_body_without_free_joint_moves_as_the_free_one():
    """The general path (mj_objectVelocity, mj_applyFT through slide + ball joints) against the
    free-joint path: the same ball, launched sliding and spinning, the same motion."""
    free = BALL
    joints = BALL.replace("<freejoint/>", '<joint type="slide" axis="1 0 0"/><joint type="slide" axis="0 1 0"/>'
                                          '<joint type="slide" axis="0 0 1"/><joint type="ball"/>')
    out = []
    for body in (free, joints):
        m = mujoco.MjModel.from_xml_string(xml(body))
        d = mujoco.MjData(m)
        d.qpos[2] = 0.01 - 5e-7
        d.qvel[:] = [0.3, -0.1, 0.0, 2.0, -1.0, 40.0]  # v (world), ω (body = world at q = 1)
        mujoco.mj_step(m, d, 5000)  # 0.05 s, sliding
        out.append((d.xpos[1].copy(), d.xmat[1].reshape(3, 3) @ d.qvel[3:6], run_models.contacts(m, d)[0].copy()))
    (x0, w0, c0), (x1, w1, c1) = out
    assert c0[0] > 0
    assert np.allclose(x1, x0, rtol=0, atol=1e-12)
    assert np.allclose(w1, w0, rtol=1e-9, atol=0)
    assert np.allclose(c1[:4], c0[:4], rtol=1e-6, atol=1e-12)


def test_ellipsoid_patch_matches_mpmath_hertz():
    """a, b of the rattleback's patch at the mpmath attitudes of tools/data/rattleback_geometry.csv
    against exact Hertz from that file's P, Q and h (mpmath: G(c) = P/Q solved for c = e²,
    a² = h·D/(P·K), D = (K − E)/c, b² = (1 − c)·a²; model notes §1)."""
    mp = pytest.importorskip("mpmath")
    import generate

    mp.mp.dps = 30
    m = mujoco.MjModel.from_xml_path(str(run_models.MODELS / "rattleback.xml"))
    d = mujoco.MjData(m)
    half = -generate.RB_SKEW / 2
    for r in csv.DictReader(open(REPO / "tools" / "data" / "rattleback_geometry.csv")):
        q = generate.quat_mul([float(r[k]) for k in ("qw", "qx", "qy", "qz")], [math.cos(half), 0, 0, math.sin(half)])
        d.qpos[:] = [0.0, 0.0, float(r["zG"]), *q]
        d.qvel[:] = 0.0
        mujoco.mj_forward(m, d)
        _, _, _, _, a, b, h = run_models.contacts(m, d)[0]
        p, qq, hh = mp.mpf(r["P"]), mp.mpf(r["Q"]), mp.mpf(r["h"])
        if hh <= 0:  # apart: no patch
            assert a == b == 0.0 and h < 0
            continue
        g = lambda c: (1 - c) * (mp.ellipk(c) - mp.ellipe(c)) / (mp.ellipe(c) - (1 - c) * mp.ellipk(c)) - p / qq  # noqa: E731
        lo, hi = mp.mpf("1e-9"), 1 - mp.mpf("1e-20")  # g decreases from 1 − P/Q to −P/Q
        for _ in range(100):
            mid = (lo + hi) / 2
            lo, hi = (mid, hi) if g(mid) > 0 else (lo, mid)
        c = (lo + hi) / 2
        k, e = mp.ellipk(c), mp.ellipe(c)
        a_ref = mp.sqrt(hh * (k - e) / c / (p * k))
        b_ref = mp.sqrt(1 - c) * a_ref
        assert a == pytest.approx(float(a_ref), rel=1e-11)  # measured 1.8e-13 (the shape table: ≤ 5e-12)
        assert b == pytest.approx(float(b_ref), rel=1e-11)  # measured 1.5e-13


def test_a_fixed_sphere_pushes_a_moving_one_whichever_comes_first():
    """Sphere–sphere with one body welded to the world, as body A or as body B (model order):
    the moving ball is stopped by it the same way; the fixed one takes no load."""
    fixed = """<body name="post" pos="0 0 0.05"><plugin instance="c"/>
      <geom name="post" type="sphere" size="0.01" contype="0" conaffinity="0"/></body>"""
    moving = """<body name="ball" pos="-0.0199 0 0.05"><freejoint/><plugin instance="c"/>
      <geom name="ball" type="sphere" size="0.01" mass="0.03" contype="0" conaffinity="0"/></body>"""
    vx = []
    for bodies in (fixed + moving, moving + fixed):
        m = mujoco.MjModel.from_xml_string(xml(bodies, gravity="0 0 0", floor=""))
        d = mujoco.MjData(m)
        d.qvel[0] = 0.01
        mujoco.mj_forward(m, d)
        assert run_models.contacts(m, d)[0, 0] > 0
        mujoco.mj_step(m, d, 2000)
        vx.append(float(d.qvel[0]))
    assert vx[0] < 0  # bounced back
    assert vx[1] == pytest.approx(vx[0], rel=1e-12)
