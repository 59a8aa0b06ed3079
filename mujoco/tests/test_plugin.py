"""The contensou.contact MuJoCo plugin (mujoco/build/libcontensou_mujoco.so, built by
mujoco/build.sh): agreement with the Python-callback path, the scenes' reference figures,
the ellipsoid geometry against mpmath, two-body and capsule contacts, refusals at load.

    mujoco/build.sh && python -m pytest -q mujoco/tests

Needs the `mujoco` and `contensou` Python packages (the callback path: pip install ./python).
"""

import csv
import ctypes
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

    pm = mujoco.MjModel.from_xml_string(run_models.explicit("tippe_top"))  # step = explicit, 10 µs
    pm.opt.integrator = getattr(mujoco.mjtIntegrator, f"mjINT_{integrator.upper()}")
    cm = top.model(dt=pm.opt.timestep, integrator=integrator, native=False)
    floor = SphereFloor(cm, "top", ["big", "small"], top.ESTAR, top.CD, top.F, top.DELTA, law="best")
    worst, identical = lockstep(pm, cm, floor, steps)
    print(f"tippe top, {integrator}, {steps} steps: max relative difference {worst:.3g}, bit for bit: {identical}")
    assert worst <= 1e-12


def test_ball_equals_the_python_callback():
    import mujoco_ball as ball
    from floor_contact import SphereFloor

    pm = mujoco.MjModel.from_xml_string(run_models.explicit("ball"))  # step = explicit, 20 µs
    cm = ball.model(dt=pm.opt.timestep, native=False)
    floor = SphereFloor(cm, "ball", ["ball"], ball.ESTAR, ball.CD, ball.F, ball.DELTA, law="best")
    worst, identical = lockstep(pm, cm, floor, 3000)
    print(f"ball, Euler, 3000 steps: max relative difference {worst:.3g}, bit for bit: {identical}")
    assert worst <= 1e-12


# Steel on steel (E = 210 GPa, ν = 0.3): G = E/(2(1 + ν)), the rolling laws' elasticity of the
# ball and the tippe top in the rolling tests below.
STEEL_G, STEEL_NU = 210e9 / 2.6, 0.3


def with_rolling_law(name, law="table", shear=STEEL_G, nu=STEEL_NU):
    """Model `name` at its small step with step = explicit (run_models.explicit) with the
    plugin's law replaced by the rolling law `law` and the elasticity G, ν added (δ is not read
    by the rolling laws)."""
    text = run_models.explicit(name)
    assert 'key="law" value="best"' in text
    text = text.replace('<config key="law" value="best"/>',
                        f'<config key="law" value="{law}"/><config key="G" value="{shear!r}"/>'
                        f'<config key="nu" value="{nu!r}"/>')
    return mujoco.MjModel.from_xml_string(text)


@pytest.mark.parametrize("law", ["table", "blend"])
def test_ball_with_a_rolling_law_equals_the_python_callback(law):
    """The rolling velocity V = v_P − ½u_P of a sphere on the floor (v_P the centre's
    velocity): the plugin against the callback (floor_contact.py, Contact(..., law, G, nu).step
    with vrx, vry), bit for bit over the sliding start."""
    import mujoco_ball as ball
    from floor_contact import SphereFloor

    pm = with_rolling_law("ball", law)
    cm = ball.model(dt=pm.opt.timestep, native=False)
    floor = SphereFloor(cm, "ball", ["ball"], ball.ESTAR, ball.CD, ball.F, ball.DELTA, law=law, G=STEEL_G,
                        nu=STEEL_NU)
    worst, identical = lockstep(pm, cm, floor, 3000)
    print(f"ball, {law}, Euler, 3000 steps: max relative difference {worst:.3g}, bit for bit: {identical}")
    assert worst <= 1e-12


def test_tippe_top_with_the_rolling_law_equals_the_python_callback():
    """Two spheres off the centre of mass (v_P = the material velocity of each sphere's centre):
    law = "rolling" (the default rolling law, table) against the callback's table."""
    import mujoco_tippe_top as top
    from floor_contact import SphereFloor

    pm = with_rolling_law("tippe_top", "rolling")
    cm = top.model(dt=pm.opt.timestep, integrator="Euler", native=False)
    floor = SphereFloor(cm, "top", ["big", "small"], top.ESTAR, top.CD, top.F, top.DELTA, law="table",
                        G=STEEL_G, nu=STEEL_NU)
    worst, identical = lockstep(pm, cm, floor, 3000)
    print(f"tippe top, rolling (table), Euler, 3000 steps: max relative difference {worst:.3g}, "
          f"bit for bit: {identical}")
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
    # The guide (docs/guide/src/time-stepping.md, the slip scale δ): `best` at δ = 0.1 mm/s (the
    # scene's BEST_DELTA), ω₀ = −2 rad/s, RK4 20 µs: the stall at 0.8365 s, the δ → 0 limit (located
    # between the steps). Here RK4 20 µs, step = explicit, sampled every 1 ms: 0.837 s.
    run = run_models.run_rattleback(1.0, sample=1e-3)
    assert run["reversal"] is None
    assert run["stall"] == pytest.approx(0.8365, abs=2e-3)


# The Rust scene with the rolling law `table` (README, the rattleback rolling; RK4 0.1 ms, events
# located between the steps): ω₀ = −2 rad/s is braked to the stall at 1.1248 s (it then turns,
# by less than the event's threshold), ω₀ = +2 rad/s stalls at 1.3317 s (`cargo run --release
# --features scenes --example rattleback`, RATTLEBACK_LAWS=table → rattleback_summary.csv;
# committed: docs/rattleback_summary.csv).
RUST_RATTLEBACK_TABLE = {"launch": ("stall", 1.1248), "steady": ("stall", 1.3317)}


@pytest.mark.parametrize("key", ["launch", "steady"])
def test_rolling_rattleback_events_as_the_rust_scene(key):
    """The ellipsoid's rolling velocity (the support point's travel over the body, closed form)
    through the model rattleback_rolling.xml (table, G and ν of the Rust scene), at its small
    step with step = explicit (RK4 0.1 ms): the outcome per spin direction and its time, sampled every 1 ms, against
    the Rust scene's located events (measured: stall 1.125 s, stall 1.332 s; with `table`'s tables
    at a/b 0.2 … 5 only the launch reversed)."""
    event, t_rust = RUST_RATTLEBACK_TABLE[key]
    m = mujoco.MjModel.from_xml_path(str(run_models.MODELS / "rattleback_rolling.xml"))
    run = run_models.run_rattleback(t_rust + 0.05, sample=1e-3, name="rattleback_rolling", key=m.key(key).id)
    other = "stall" if event == "reversal" else "reversal"
    assert run[other] is None
    assert run[event] == pytest.approx(t_rust, abs=2e-3), run[event]


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
ESTAR_F = '<config key="estar" value="1e9"/><config key="f" value="0.3"/>'
CONFIG = ESTAR_F + '<config key="cd" value="1"/>'


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


ROLLING = CONFIG + '<config key="law" value="rolling"/>'


@pytest.mark.parametrize("config,bodies,message", [
    (CONFIG + '<config key="law" value="full-slip"/>', BALL, r"law = 'full-slip' is no law \(best, .*fastsim-16\)"),
    (CONFIG + '<config key="G" value="8e10"/>', BALL, r"G = '8e10' is read by the rolling laws only \(law = 'best'"),
    (CONFIG + '<config key="law" value="pade"/><config key="nu" value="0.3"/>', BALL,
     r"nu = '0.3' is read by the rolling laws only \(law = 'pade'"),
    (ROLLING + '<config key="G" value="-5"/>', BALL, r"G = -5: "),
    (ROLLING + '<config key="nu" value="0.7"/>', BALL, r"nu = 0\.7: "),
    (ROLLING + '<config key="G" value="soft"/>', BALL, r"G = 'soft' is not a finite number"),
    ('<config key="young1" value="2e11"/><config key="poisson1" value="0.3"/><config key="young2" value="2e11"/>'
     '<config key="poisson2" value="0.3"/><config key="f" value="0.3"/><config key="law" value="table"/>'
     '<config key="G" value="8e10"/>', BALL, r"give either G \(= '8e10'\) or young1"),
    ('<config key="young1" value="2e11"/><config key="poisson1" value="-0.2"/><config key="young2" value="2e11"/>'
     '<config key="poisson2" value="0.3"/><config key="f" value="0.3"/><config key="law" value="blend"/>', BALL,
     r"poisson1 = -0\.2: the rolling laws take Poisson's ratios in \[0, 0\.5\]"),
    (ESTAR_F + '<config key="law" value="stribeck"/>', BALL, r"law = 'stribeck' is no law"),
    ('<config key="estar" value="1e9"/><config key="f" value="-0.3"/>', BALL, r"f = -0\.3: .*friction"),
    ('<config key="estar" value="-5"/><config key="f" value="0.3"/>', BALL, r"estar = -5: "),
    (ESTAR_F + '<config key="delta" value="-1"/>', BALL, r"delta = -1: "),
    (ESTAR_F + '<config key="cd" value="fast"/>', BALL, r"cd = 'fast' is not a finite number"),
    (ESTAR_F + '<config key="form" value="rigid"/>', BALL, r"form = 'rigid' is no form"),
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


def test_materials_give_the_rolling_laws_kalkers_g_and_nu():
    """young1, poisson1, young2, poisson2 with a rolling law: G, ν by Kalker's rule for
    dissimilar bodies (Gᵢ = Eᵢ/(2(1 + νᵢ)), G = 2G₁G₂/(G₁ + G₂), ν = (G₂ν₁ + G₁ν₂)/(G₁ + G₂),
    written here in the textbook form) — the same motion as G, ν and E* given directly."""
    e1, n1, e2, n2 = 3e9, 0.35, 70e9, 0.22
    g1, g2 = e1 / (2 * (1 + n1)), e2 / (2 * (1 + n2))
    shear, nu = 2 * g1 * g2 / (g1 + g2), (g2 * n1 + g1 * n2) / (g1 + g2)
    estar = 1 / ((1 - n1 * n1) / e1 + (1 - n2 * n2) / e2)
    law = '<config key="f" value="0.3"/><config key="law" value="table"/>'
    materials = (f'<config key="young1" value="{e1!r}"/><config key="poisson1" value="{n1!r}"/>'
                 f'<config key="young2" value="{e2!r}"/><config key="poisson2" value="{n2!r}"/>' + law)
    direct = (f'<config key="estar" value="{estar!r}"/><config key="G" value="{shear!r}"/>'
              f'<config key="nu" value="{nu!r}"/>' + law)
    out = []
    for c in (materials, direct):
        m = mujoco.MjModel.from_xml_string(xml(BALL, config=c))
        d = mujoco.MjData(m)
        d.qpos[2] = 0.01 - 2e-6
        d.qvel[:] = [0.2, 0.0, 0.0, 0.0, 5.0, 3.0]  # rolling forward with some slip, spinning
        mujoco.mj_step(m, d, 200)
        out.append(run_models.contacts(m, d)[0].copy())
    assert out[0][0] > 0 and abs(out[0][1]) > 0 and abs(out[0][3]) > 0
    assert np.allclose(out[0], out[1], rtol=1e-9, atol=0)


def post_and_ball(radius):
    """A sphere of radius 0.01 welded to the world (the post) and a free ball of `radius` beside
    it, in both model orders: (post first, ball first)."""
    fixed = """<body name="post" pos="0 0 0.05"><plugin instance="c"/>
      <geom name="post" type="sphere" size="0.01" contype="0" conaffinity="0"/></body>"""
    moving = f"""<body name="ball" pos="-0.0199 0 0.05"><freejoint/><plugin instance="c"/>
      <geom name="ball" type="sphere" size="{radius!r}" mass="0.03" contype="0" conaffinity="0"/></body>"""
    return fixed + moving, moving + fixed


def test_rolling_spheres_move_the_same_whichever_is_body_a():
    """Sphere–sphere with a rolling law: V = v_P − ½(u_A + u_B) is symmetric in A and B, so
    the moving ball rolls over the fixed one the same way whichever comes first in the model
    (a V missing u_A, or v_P taken at the wrong centre, breaks the symmetry)."""
    out = []
    for bodies in post_and_ball(0.008):
        m = mujoco.MjModel.from_xml_string(xml(bodies, config=ROLLING, gravity="10 0 0", floor=""))
        d = mujoco.MjData(m)
        d.qpos[0] = -0.018 + 1e-6  # pressed onto the post by the "gravity" along x
        d.qvel[:] = [0.0, 0.05, 0.01, 0.0, 0.0, 4.0]
        mujoco.mj_forward(m, d)
        assert run_models.contacts(m, d)[0, 0] > 0
        mujoco.mj_step(m, d, 2000)
        assert run_models.contacts(m, d)[0, 0] > 0  # still in contact: rolled over the post
        out.append(np.concatenate([d.qpos, d.qvel]))
    assert np.abs(out[0][3:]).max() > 0.1
    assert np.allclose(out[1], out[0], rtol=1e-9, atol=1e-12)


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
    vx = []
    for bodies in post_and_ball(0.01):
        m = mujoco.MjModel.from_xml_string(xml(bodies, gravity="0 0 0", floor=""))
        d = mujoco.MjData(m)
        d.qvel[0] = 0.01
        mujoco.mj_forward(m, d)
        assert run_models.contacts(m, d)[0, 0] > 0
        mujoco.mj_step(m, d, 2000)
        vx.append(float(d.qvel[0]))
    assert vx[0] < 0  # bounced back
    assert vx[1] == pytest.approx(vx[0], rel=1e-12)


# ------------------------------------------------------- the contacts' inverse mass W from MuJoCo


class ShimContact(ctypes.Structure):
    _fields_ = [("pair", ctypes.c_int), ("body_a", ctypes.c_int), ("body_b", ctypes.c_int),
                ("point", ctypes.c_double * 3), ("n", ctypes.c_double * 3), ("x", ctypes.c_double * 3),
                ("y", ctypes.c_double * 3)]


def inverse_mass(m, d, cap=8):
    """The touching pairs and their W = J M⁻¹ Jᵀ (4K × 4K) as the plugin computes them
    (src/inverse_mass.c: mj_jac, mj_solveM), through build/libcontensou_mujoco_test.so."""
    path = REPO / "mujoco" / "build" / "libcontensou_mujoco_test.so"
    if not path.exists():
        pytest.skip(f"{path}: run mujoco/build.sh")
    lib = ctypes.CDLL(str(path))
    fn = lib.contensou_mujoco_test_inverse_mass
    fn.restype = ctypes.c_int
    fn.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_int, ctypes.POINTER(ShimContact),
                   ctypes.POINTER(ctypes.c_double), ctypes.c_int]
    contacts = (ShimContact * cap)()
    w = np.zeros((4 * cap) ** 2)
    k = fn(m._address, d._address, 0, contacts, w.ctypes.data_as(ctypes.POINTER(ctypes.c_double)), cap)
    assert k >= 0
    return list(contacts[:k]), w[: (4 * k) ** 2].reshape(4 * k, 4 * k)


def test_inverse_mass_of_a_free_sphere_on_a_plane_is_the_analytic_one():
    """W of a sphere (mass m, isotropic inertia I, centre at ρ = r − h above the patch centre P
    on the plane) in the contact frame (n, x, y, spin): diag(1/m, 1/m + ρ²/I, 1/m + ρ²/I, 1/I) —
    the slip at P is v − ρ ω × n, the spin ω·n."""
    mass, r, inertia, h = 0.03, 0.01, 2e-6, 1e-6
    rho = r - h
    body = f"""<body name="ball"><freejoint/><plugin instance="c"/>
      <inertial pos="0 0 0" mass="{mass}" diaginertia="{inertia} {inertia} {inertia}"/>
      <geom name="ball" type="sphere" size="{r}" contype="0" conaffinity="0"/></body>"""
    m = mujoco.MjModel.from_xml_string(xml(body))
    d = mujoco.MjData(m)
    d.qpos[:] = [0.1, -0.2, rho, 0.9, 0.1, -0.3, 0.2]  # turned: the frame is the plane's anyway
    d.qpos[3:] /= np.linalg.norm(d.qpos[3:])
    mujoco.mj_forward(m, d)
    contacts, w = inverse_mass(m, d)
    assert len(contacts) == 1
    expected = np.diag([1 / mass, 1 / mass + rho * rho / inertia, 1 / mass + rho * rho / inertia, 1 / inertia])
    assert np.abs(w - expected).max() <= 1e-12 * np.abs(expected).max()  # measured 8e-19 relative


def hand_inverse_mass(m, d, contacts):
    """W = J M⁻¹ Jᵀ built by hand for free bodies, in the coordinates (v_G, ω) of each body (G
    its centre of mass, ω world): M = diag(m I₃, R diag(I) Rᵀ), R the inertial frame (ximat);
    the contact rows of B are tᵀ(v_G + ω × (P − G)) = [tᵀ, ((P − G) × t)ᵀ] for t = n, x, y and
    [0, nᵀ] for the spin, minus the same for A — no MuJoCo Jacobian, no mj_solveM."""
    bodies = sorted({b for c in contacts for b in (c.body_a, c.body_b) if b > 0})
    col = {b: 6 * i for i, b in enumerate(bodies)}
    minv = np.zeros((6 * len(bodies), 6 * len(bodies)))
    for b in bodies:
        rot = d.ximat[b].reshape(3, 3)
        i = col[b]
        minv[i:i + 3, i:i + 3] = np.eye(3) / m.body_mass[b]
        minv[i + 3:i + 6, i + 3:i + 6] = np.linalg.inv(rot @ np.diag(m.body_inertia[b]) @ rot.T)
    jac = np.zeros((4 * len(contacts), 6 * len(bodies)))
    for k, c in enumerate(contacts):
        p, n, x, y = (np.array(v[:]) for v in (c.point, c.n, c.x, c.y))
        for b, sign in ((c.body_b, 1.0), (c.body_a, -1.0)):
            if b <= 0:
                continue
            arm = p - d.xipos[b]
            for row, t in enumerate((n, x, y)):
                jac[4 * k + row, col[b]:col[b] + 3] += sign * t
                jac[4 * k + row, col[b] + 3:col[b] + 6] += sign * np.cross(arm, t)
            jac[4 * k + 3, col[b] + 3:col[b] + 6] += sign * n
    return jac @ minv @ jac.T


def test_inverse_mass_with_cross_blocks_matches_a_hand_construction():
    """Three free bodies of one instance: a dumbbell (two spheres on one body, off-centre mass,
    turned principal axes) on the floor, and two balls touching each other, one of them on the
    floor — five contacts: W's cross blocks between the dumbbell's two contacts, between a ball's
    floor contact and the ball–ball contact, zero between contacts of different bodies."""
    bodies = """
    <body name="dumbbell" pos="0 0 0.0099995"><freejoint/><plugin instance="c"/>
      <inertial pos="0.004 0.001 0.002" quat="0.9 0.2 0.1 0.3" mass="0.05" diaginertia="2e-5 3e-5 4e-5"/>
      <geom name="left" type="sphere" size="0.01" pos="-0.03 0 0" contype="0" conaffinity="0"/>
      <geom name="right" type="sphere" size="0.01" pos="0.03 0 0" contype="0" conaffinity="0"/></body>
    <body name="ball1" pos="0.2 0 0.0099995"><freejoint/><plugin instance="c"/>
      <geom name="ball1" type="sphere" size="0.01" mass="0.03" contype="0" conaffinity="0"/></body>
    <body name="ball2" pos="0.2 0.012 0.0249"><freejoint/><plugin instance="c"/>
      <geom name="ball2" type="sphere" size="0.01" mass="0.02" contype="0" conaffinity="0"/></body>"""
    m = mujoco.MjModel.from_xml_string(xml(bodies))
    d = mujoco.MjData(m)
    mujoco.mj_forward(m, d)
    contacts, w = inverse_mass(m, d)
    assert [(c.body_a, c.body_b) for c in contacts] == [(0, 1), (0, 1), (0, 2), (2, 3)]
    expected = hand_inverse_mass(m, d, contacts)
    assert np.abs(w - expected).max() <= 1e-12 * np.abs(expected).max()  # measured 4e-19 relative
    assert np.abs(w[0:4, 4:8]).max() > 1.0  # the dumbbell's two contacts are coupled
    assert np.abs(w[8:12, 12:16]).max() > 1.0  # ball1's floor contact and ball1–ball2
    assert np.all(w[0:8, 8:16] == 0.0)  # no body in common
    assert np.all(w == w.T) and np.linalg.eigvalsh(w).min() > -1e-12 * np.abs(w).max()


def step_prepare(m, d, cap=8):
    """src/step_aware.c's step_prepare through the shim: the pairs taken, u, u_free, h_free, W."""
    path = REPO / "mujoco" / "build" / "libcontensou_mujoco_test.so"
    if not path.exists():
        pytest.skip(f"{path}: run mujoco/build.sh")
    fn = ctypes.CDLL(str(path)).contensou_mujoco_test_step_prepare
    fn.restype = ctypes.c_int
    dp = ctypes.POINTER(ctypes.c_double)
    fn.argtypes = [ctypes.c_void_p, ctypes.c_void_p, ctypes.c_int, ctypes.POINTER(ctypes.c_int), dp, dp, dp, dp,
                   ctypes.c_int]
    index = (ctypes.c_int * cap)()
    u, u_free, h_free, w = np.zeros(4 * cap), np.zeros(4 * cap), np.zeros(cap), np.zeros((4 * cap) ** 2)
    k = fn(m._address, d._address, 0, index, u.ctypes.data_as(dp), u_free.ctypes.data_as(dp),
           h_free.ctypes.data_as(dp), w.ctypes.data_as(dp), cap)
    assert k >= 0
    return (list(index[:k]), u[:4 * k].reshape(k, 4), u_free[:4 * k].reshape(k, 4), h_free[:k],
            w[:(4 * k) ** 2].reshape(4 * k, 4 * k))


def test_free_end_velocity_is_mujocos_euler_step_without_the_contact():
    """u_free = J q̇_free: a tumbling dumbbell (turned principal axes, off-centre mass: Coriolis
    terms) falling towards the floor, just apart (no contact force at the start state), pushed
    by qfrc_applied and xfrc_applied: after one MuJoCo Euler step of 1 ms, J (at the start pose)
    times the new q̇ equals the u_free computed before the step, and the approach at the pose the
    step reached equals h_free. The pairs close within the step, so they are taken though apart; u = J q̇ equals the velocity of B's material point at the
    patch centre P (below each sphere's centre on the floor) in (n, x, y) and ω·n."""
    bodies = """
    <body name="dumbbell" pos="0 0 0.01005"><freejoint/><plugin instance="c"/>
      <inertial pos="0.004 0.001 0.002" quat="0.9 0.2 0.1 0.3" mass="0.05" diaginertia="2e-5 3e-5 4e-5"/>
      <geom name="left" type="sphere" size="0.01" pos="-0.03 0 0" contype="0" conaffinity="0"/>
      <geom name="right" type="sphere" size="0.01" pos="0.03 0 0" contype="0" conaffinity="0"/></body>"""
    m = mujoco.MjModel.from_xml_string(xml(bodies))
    m.opt.timestep = 1e-3
    d = mujoco.MjData(m)
    d.qvel[:] = [0.05, -0.02, -0.2, 1.0, -2.0, 11.0]
    d.qfrc_applied[:] = [0.01, 0.0, -0.02, 1e-4, 0.0, -2e-4]
    d.xfrc_applied[1] = [0.0, 0.03, 0.0, 0.0, 5e-5, 0.0]
    mujoco.mj_forward(m, d)
    assert np.all(run_models.contacts(m, d)[:, 6] < 0)  # both spheres apart
    index, u, u_free, h_free, _ = step_prepare(m, d)
    assert index == [0, 1]  # both close within the step
    omega = d.xmat[1].reshape(3, 3) @ d.qvel[3:6]
    for k, g in enumerate((m.geom("left").id, m.geom("right").id)):
        p = d.geom_xpos[g] * [1, 1, 0]
        v = d.qvel[0:3] + np.cross(omega, p - d.xpos[1])
        assert u[k] == pytest.approx([v[2], v[0], v[1], omega[2]], rel=1e-13, abs=1e-15)
    qpos0 = d.qpos.copy()
    mujoco.mj_step(m, d)
    # h_free: the approach at the pose MuJoCo's step reached (no contact force: apart at the start)
    mujoco.mj_forward(m, d)
    assert np.all(h_free > 0)
    assert np.abs(run_models.contacts(m, d)[:, 6] - h_free).max() <= 1e-15  # m; h ≈ 1e-5 m
    d.qpos[:] = qpos0  # J at the start pose, q̇ after the step
    mujoco.mj_forward(m, d)
    _, u_end, _, _, _ = step_prepare(m, d)
    assert np.abs(u_end - u_free).max() <= 1e-12 * np.abs(u_free).max()  # measured: 0 (bit for bit)
    assert np.abs(u_free - u).max() > 1e-3  # the step changed u


def test_bad_step_modes_are_refused_and_explicit_is_the_default():
    with pytest.raises(ValueError, match=r"step = 'implicit' is no step mode \(explicit, aware\)"):
        mujoco.MjModel.from_xml_string(xml(BALL, config=CONFIG + '<config key="step" value="implicit"/>'))
    m = mujoco.MjModel.from_xml_string(xml(BALL, config=CONFIG + '<config key="step" value="explicit"/>'))
    assert m.nplugin == 1
    with pytest.raises(ValueError, match=r"step_point is read by step = 'aware' only"):
        mujoco.MjModel.from_xml_string(xml(BALL, config=CONFIG + '<config key="step_point" value="0.5"/>'))
    with pytest.raises(ValueError, match=r"step_point = 1.5 is not in \[0, 1\]"):
        mujoco.MjModel.from_xml_string(xml(BALL, config=CONFIG + '<config key="step_point" value="1.5"/>'))


# ---------------------------------------------------- step = aware at MuJoCo's own steps (issue targets)

# The shipped models (step = aware, implicitfast, step_point per model: run_models.STEP_POINT)
# with only `timestep` changed.
AWARE = {"step": "aware", "step_point": "0.25"}


def aware_run(name, dt, key=0):
    """step_sweep.run of the shipped model `name` at `dt` (only `timestep` changed)."""
    import step_sweep

    return step_sweep.run(name, dt, {}, key)


def test_shipped_models_are_step_aware_at_2ms():
    for name in run_models.FINE:
        m = mujoco.MjModel.from_xml_path(str(run_models.MODELS / f"{name}.xml"))
        assert m.opt.timestep == 0.002 and m.opt.integrator == mujoco.mjtIntegrator.mjINT_IMPLICITFAST
        e = mujoco.MjModel.from_xml_string(run_models.explicit(name))
        assert (e.opt.timestep, e.opt.integrator) == (run_models.FINE[name][0],
                                                      getattr(mujoco.mjtIntegrator, f"mjINT_{run_models.FINE[name][1].upper()}"))


@pytest.mark.parametrize("dt", [5e-4, 1e-3, 2e-3])
def test_step_aware_ball_rolls_and_spins_down_as_the_analytic_solution(dt):
    import mujoco_ball as ball

    run = aware_run("ball", dt)
    assert run["stable"] and run["energy_max_rise"] <= 1e-9
    assert run["roll"] == pytest.approx(2 * ball.V0 / (7 * ball.F * ball.G), rel=0.01)  # measured +0.26 %
    assert run["spin_rate"] == pytest.approx(ball.TORSION * ball.N_STATIC / ball.INERTIA, rel=0.02)  # 0.01 %


@pytest.mark.parametrize("dt,tolerance", [(5e-4, 0.03), (1e-3, 0.05), (2e-3, None)])
def test_step_aware_tippe_top_inverts(dt, tolerance):
    run = aware_run("tippe_top", dt)
    assert run["stable"] and run["half"] is not None
    if tolerance:  # measured +0.5 % at 0.5 ms, +1.1 % at 1 ms (−0.8 % at 2 ms)
        assert run["half"] == pytest.approx(RUST_T_HALF_BEST, rel=tolerance)


@pytest.mark.parametrize("dt", [5e-4, 1e-3, 2e-3])
def test_step_aware_rattleback_stalls_as_the_rust_scene(dt):
    run = aware_run("rattleback", dt)
    assert run["stable"]
    if dt <= 1e-3:  # δ = 0.1 mm/s, step_point 0.5: measured 0.835 s at 0.5 ms, 0.833 s at 1 ms (Rust 0.8365 s)
        assert run["reversal"] is None
        assert run["stall"] == pytest.approx(0.8365, rel=0.03)


@pytest.mark.parametrize("dt", [5e-4, 1e-3, 2e-3])
@pytest.mark.parametrize("key", ["launch", "steady"])
def test_step_aware_rolling_rattleback_keeps_the_rust_scenes_outcome(dt, key):
    """step_point 0.55, the friction passive at MuJoCo's end velocity: measured (2026-12-04)
    launch stall +2.5 % (0.5 ms), +2.4 % (1 ms), steady stall +0.5 %, −0.7 %; at 2 ms (stability
    only) the launch's turn after its stall passes the event's threshold, which the fine step's
    just misses (reversal 1.844 s), and the steady stall is −5.2 % (1.262 s)."""
    event, t_rust = RUST_RATTLEBACK_TABLE[key]
    m = mujoco.MjModel.from_xml_path(str(run_models.MODELS / "rattleback_rolling.xml"))
    run = aware_run("rattleback_rolling", dt, m.key(key).id)
    assert run["stable"]
    if dt <= 1e-3:
        assert run["stall" if event == "reversal" else "reversal"] is None
        assert run[event] == pytest.approx(t_rust, rel=0.02 if event == "reversal" else 0.10)


@pytest.mark.parametrize("dt,staggered,true,friction,vs_native,law", [
    (2e-3, 2.5e-4, 1.2e-3, 1e-7, 2.0, 2e-2), (1e-3, 1e-5, 2e-4, 1e-8, 0.6, 1.2e-3), (5e-4, 1e-6, 5e-5, 1e-8, 0.3, 1e-5)])
def test_step_aware_rattleback_keeps_semi_implicit_eulers_energy(dt, staggered, true, friction, vs_native, law):
    """The `best` rattleback over 3 s (energy_budget.py): MuJoCo's semi-implicit Euler keeps the
    staggered energy ½v_nᵀM(q_n)v_{n+1} + V + U, not T(v_n) + V + U, which swings by O(Δt)
    around it as the pose update sinks the 2 m bottom by ½(ρ − ℓ)(Δt·ω)² per step. Largest rise
    per step, relative to the start energy (δ = 0.1 mm/s): staggered 1.8e-4 at 2 ms, 3.4e-6 at
    1 ms, 3.1e-7 at 0.5 ms; T + V + U 9.9e-4, 1.5e-4 and 3.7e-5; friction's work per step
    ≤ 2.7e-8 (checked at MuJoCo's Euler end velocity; implicitfast takes the free body's
    gyroscopic force implicitly). MuJoCo's own condim-6 contact on the same body
    (energy_budget.native_budget) rises by 6.4e-4, 3.1e-4, 1.6e-4 per step (T + V + ½N·pen;
    staggered 5.8e-4, 3.0e-4, 1.6e-4): the plugin's T + V + U rise is 1.55×, 0.48×, 0.23× that,
    its staggered one 0.31×, 0.011×, 0.002×. Summed over the run, the normal law against the
    elastic energy (Σ law, ≤ 0 for an exact backward-Euler normal force) is +1.44e-2, +8.0e-4,
    −1.8e-5 of E0: at 2 ms the end approach the library predicts linearly misses the one MuJoCo's
    pose update produces, and the rattleback regains 1.3 % of E0 after its stall (mujoco/README.md;
    the end gap of branch energy-endgap takes it below 0 at a cost in the events)."""
    import energy_budget

    sums = {}
    m, peak, _, resid = energy_budget.budget("rattleback", dt, {}, 3.0, sums=sums)
    assert resid < 1e-5
    assert sums["law"] <= law
    assert peak["staggered"] <= staggered
    assert peak["true"] <= true
    assert peak["friction"] <= friction
    _, native = energy_budget.native_budget("rattleback", dt, 3.0)
    assert native["true"] > 0.0  # the native contact gains over some steps too
    assert peak["true"] <= vs_native * native["true"]
    assert peak["staggered"] <= 0.4 * native["staggered"]


# The rattleback's small rocking oscillations lose their energy at these rates (s⁻¹; roll,
# pitch) with the plain contact at its reference step (20 µs RK4; energy_budget.rocking_decay
# with step = explicit, measured): the contact's own damping (Hunt–Crossley, micro-slip).
RATTLEBACK_ROCKING_DECAY = (0.0053, 0.0089)


@pytest.mark.parametrize("dt", [2e-3, 1e-3])
def test_step_aware_rattleback_rocks_without_numerical_damping(dt):
    """The per-step rise of T + V + U that the test above bounds is mostly the swing of
    semi-implicit Euler around its staggered energy: the step-aware contact neither pumps nor
    damps a small rocking oscillation. A small roll and pitch oscillation (0.2 rad/s kick from rest) decays at
    the fine-step rate within 0.02 s⁻¹ (measured: roll 0.013, pitch 0.007 at 2 ms; 0.007, 0.010
    at 1 ms). A contact that keeps T + V + U from rising over every step (the normal force
    applied at the mid-step contact point: measured ≤ 2.5e-9 of E0 per step) damps them at
    ≈ ½·Δt·Ω²: roll 1.2 and pitch 8.6 s⁻¹ at 2 ms, and the rattleback stalls 28 % late."""
    import energy_budget

    for axis, reference in enumerate(RATTLEBACK_ROCKING_DECAY):
        assert energy_budget.rocking_decay("rattleback", dt, axis) == pytest.approx(reference, abs=0.02)


def test_step_aware_normal_force_matches_the_end_gap():
    """The rolling rattleback spun at +2 rad/s, 1 ms, 3 s (energy_budget.py): where the library's
    N is not the normal law's value at the end approach its wrench gives (W's normal–tangential
    coupling: the friction moves that approach), the plugin re-solves N to that value (step_aware.c, step_normal). Without it
    the largest rise over a step is 6.8e-4 of E0 (staggered energy 5.2e-4; with θ = 0.6 and
    before the friction check, one step at 0.277 s returned N = 4.2 N for an end approach whose
    Hertz force is 65 N: 1.4e-3); with it 3.5e-5 (staggered 1.2e-8), the stall 1.741 → 1.744 s
    (fine step 1.920 s)."""
    import energy_budget

    m = mujoco.MjModel.from_xml_path(str(run_models.MODELS / "rattleback_rolling.xml"))
    _, peak, _, resid = energy_budget.budget("rattleback_rolling", 1e-3, {}, 3.0, m.key("steady").id)
    assert resid < 1e-5
    assert peak["true"] <= 2e-4
    assert peak["staggered"] <= 1e-5


TWO_BALLS = """
    <body name="a" pos="0 0 0"><freejoint/><plugin instance="c"/>
      <geom name="ga" type="sphere" size="0.01" mass="0.01" contype="0" conaffinity="0"/></body>
    <body name="b" pos="0.0201 0.006 0"><freejoint/><plugin instance="c"/>
      <geom name="gb" type="sphere" size="0.01" mass="0.02" contype="0" conaffinity="0"/></body>"""


@pytest.mark.parametrize("point", ["0", "0.25"])
def test_step_aware_spinning_spheres_collide_passively_at_2ms(point):
    """Two free spinning spheres (a body–body pair, no floor, no gravity) meet obliquely at
    0.75 m/s with step = aware at 2 ms (implicitfast): linear momentum kept to rounding (the pair's
    wrench acts on both bodies, opposite), the mechanical energy plus the exact elastic energy
    (2/5)·N_el(h)·h never rises over a step. The impact lasts two steps: backward Euler keeps
    0.226 of the start energy where the fine explicit step (1 µs) keeps 0.480 (the rebound is
    nearly plastic at 2 ms)."""
    config = CONFIG + f'<config key="step" value="aware"/><config key="step_point" value="{point}"/>'
    m = mujoco.MjModel.from_xml_string(xml(TWO_BALLS, config=config, gravity="0 0 0", floor=""))
    m.opt.timestep = 2e-3
    m.opt.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    m.opt.enableflags |= mujoco.mjtEnableBit.mjENBL_ENERGY
    plain = mujoco.MjModel.from_xml_string(xml(TWO_BALLS, gravity="0 0 0", floor=""))
    dp = mujoco.MjData(plain)
    d = mujoco.MjData(m)
    d.qvel[:] = [0.5, 0, 0, 0, 0, 30, -0.25, 0, 0, 5, 0, -20]

    def energy():
        dp.qpos[:] = d.qpos
        dp.qvel[:] = 0
        mujoco.mj_forward(plain, dp)
        elastic = run_models.contacts(plain, dp)
        mujoco.mj_forward(m, d)
        return float(d.energy[1]) + 0.4 * float(np.sum(elastic[:, 0] * np.maximum(elastic[:, 6], 0.0)))

    def momentum():
        return m.body_mass[1] * d.qvel[0:3] + m.body_mass[2] * d.qvel[6:9]

    e0, p0, touching, rise = energy(), momentum(), 0, -np.inf
    for _ in range(50):
        before = energy()
        mujoco.mj_step(m, d)
        rise = max(rise, energy() - before)
        touching += run_models.contacts(m, d)[0, 0] > 0
    assert touching >= 1 and np.isfinite(d.qvel).all()
    assert np.abs(momentum() - p0).max() < 1e-15  # measured 5e-20
    assert rise <= 1e-12 * e0  # measured: never rises (0.0)
    assert energy() < 0.5 * e0  # the impact took energy (0.226 of e0)


@pytest.mark.parametrize("dt", [5e-4, 1e-3, 2e-3])
def test_step_aware_ball_stack_rests(dt):
    """A 10 g ball resting on a 100 g ball on the floor (two bodies, three pairs: the balls on the
    floor and on each other, the upper one's floor pair apart) with step = aware: the floor
    carries both weights, the balls each other's upper weight, at rest. The floor's impulse lifts
    the lower ball into the upper one within the step, which the library's choice of the active
    contacts (each from its own predicted gap) does not see: without the plugin's re-solve of such
    an idle pair (plugin.c, reactivate) the upper contact carried nothing and twice the weight on
    alternate steps at 1 and 2 ms (the upper ball's vertical velocity ±g·Δt/2)."""
    bodies = """
    <body name="low" pos="0 0 0.02"><freejoint/><plugin instance="c"/>
      <geom name="gl" type="sphere" size="0.02" mass="0.1" contype="0" conaffinity="0"/></body>
    <body name="top" pos="0 0 0.05"><freejoint/><plugin instance="c"/>
      <geom name="gt" type="sphere" size="0.01" mass="0.01" contype="0" conaffinity="0"/></body>"""
    m = mujoco.MjModel.from_xml_string(xml(bodies, config=CONFIG + '<config key="step" value="aware"/>'))
    m.opt.timestep = dt
    m.opt.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    d = mujoco.MjData(m)
    mujoco.mj_step(m, d, round(1.0 / dt))
    # The contacts' elastic forces at the rest gaps (the plain contact, q̇ = 0): the step's N is
    # the law's there (measured: upper exact, floor 8e-4 at 2 ms; 32 % off on the upper one
    # without the plugin's normal re-solve).
    plain = mujoco.MjModel.from_xml_string(xml(bodies))
    dp = mujoco.MjData(plain)
    dp.qpos[:] = d.qpos
    mujoco.mj_forward(plain, dp)
    elastic = run_models.contacts(plain, dp)[:, 0]
    assert elastic[0] == pytest.approx(0.11 * 9.81, rel=2e-3)
    assert elastic[2] == pytest.approx(0.01 * 9.81, rel=2e-3)
    for _ in range(2):  # two consecutive steps: no alternation
        mujoco.mj_step(m, d)
        rows = run_models.contacts(m, d)
        assert rows.shape == (3, 7) and rows[1, 0] == 0.0  # the upper ball's floor pair is apart
        assert rows[0, 0] == pytest.approx(0.11 * 9.81, rel=1e-8)
        assert rows[2, 0] == pytest.approx(0.01 * 9.81, rel=1e-8)
        assert np.abs(d.qvel).max() < 1e-9


@pytest.mark.parametrize("nfeet,rest", [(6, 1e-9), (10, 1e-3)])
def test_step_aware_feet_share_the_weight_at_2ms(nfeet, rest):
    """A plate on n spheres (one body: n contacts with W's cross blocks) resting on the floor with
    step = aware at 2 ms: the normal forces add up to the weight, every foot carries its share by
    symmetry, no friction, the plate at rest. Six feet: one solve (up to 8 contacts per call);
    ten: two parts of 8 and 2, block Gauss–Seidel over them — approximate: the weight is carried
    (to 1e-8) but the shares are uneven (0.30–0.87 N for 0.59 N each), balanced friction forces
    stay locked in between the feet (up to 0.07 N) and the plate keeps a
    residual drift (|q̇| 2.8e-7 to 6.4e-5 after 1 s, depending on the library's version);
    without the sweeps the parts each carried the whole weight and the plate hopped at 0.28 m/s."""
    feet = "".join(f'<geom name="f{i}" type="sphere" size="0.01" pos="{0.05 * math.cos(2 * i * math.pi / nfeet)!r} '
                   f'{0.05 * math.sin(2 * i * math.pi / nfeet)!r} 0" contype="0" conaffinity="0"/>'
                   for i in range(nfeet))
    body = f"""<body name="plate" pos="0 0 0.0099999"><freejoint/><plugin instance="c"/>
      <inertial pos="0 0 0" mass="0.6" diaginertia="4e-4 4e-4 8e-4"/>{feet}</body>"""
    config = CONFIG + "".join(f'<config key="{k}" value="{v}"/>' for k, v in AWARE.items())
    m = mujoco.MjModel.from_xml_string(xml(body, config=config))
    m.opt.timestep = 2e-3
    m.opt.integrator = mujoco.mjtIntegrator.mjINT_IMPLICITFAST
    d = mujoco.MjData(m)
    mujoco.mj_step(m, d, 500)  # 1 s
    rows = run_models.contacts(m, d)
    assert rows.shape == (nfeet, 7)
    assert rows[:, 0].sum() == pytest.approx(0.6 * 9.81, rel=1e-8)
    if nfeet <= 8:
        assert rows[:, 0] == pytest.approx([0.6 * 9.81 / nfeet] * nfeet, rel=1e-3)
        assert np.abs(rows[:, 1:4]).max() < 1e-6
    else:  # locked-in friction between the parts (up to 0.07 N per foot), balanced
        assert np.abs(rows[:, 1:3].sum(axis=0)).max() < 1e-6
    assert np.abs(d.qvel).max() < rest
