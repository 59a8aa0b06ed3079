"""contensou as MuJoCo's floor contact (examples/floor_contact.py): short runs with bounds from
the analytic solution. Skipped without the `mujoco` package."""

import sys
from pathlib import Path

import numpy as np
import pytest

mujoco = pytest.importorskip("mujoco")
sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "examples"))
import mujoco_ball as ball  # noqa: E402
import mujoco_tippe_top as top  # noqa: E402
from floor_contact import SphereFloor  # noqa: E402


def test_ball_rolls_at_the_analytic_time_and_keeps_its_spin():
    m = ball.model(dt=2e-5, native=False)
    floor = SphereFloor(m, "ball", ["ball"], ball.ESTAR, ball.CD, ball.F, ball.DELTA)
    run = ball.simulate("contensou", m, 0.5, floor)
    t_roll = 2 * ball.V0 / (7 * ball.F * ball.G)
    assert run["t_roll"] == pytest.approx(t_roll, rel=0.02)
    # While it slides the drilling torque is small (u = v/(aω) >> 1); after 0.5 s the spin is
    # within 0.05 rad/s of the analytic ω₀ − (3π/16)fNa/I·(t − t_roll).
    t, spin = run["series"]
    expected = ball.SPIN0 - ball.TORSION * ball.N_STATIC / ball.INERTIA * (t[-1] - t_roll)
    assert abs(spin[-1] - expected) < 0.05
    assert mujoco.get_mjcb_passive() is None  # the callback is removed afterwards


def test_tippe_top_dissipates_and_spins_down():
    m = top.model(dt=1e-5, integrator="Euler", native=False)
    floor = SphereFloor(m, "top", ["big", "small"], top.ESTAR, top.CD, top.F, top.DELTA)
    run = top.simulate("contensou", m, 0.3, floor)
    t, theta = run["series"]
    assert np.all(np.isfinite(theta))
    # Friction and damping only dissipate: energy below the launch energy, spin slowing.
    e0 = top.MASS * top.G * (top.R_BIG - top.E_BIG * np.cos(top.THETA0)) + 0.5 * top.I_POLAR * top.SPIN0**2
    assert run["energy"] < e0
    assert 0 < run["spin"] < top.SPIN0
