"""Random valid rows of the wrench contract, shared by the tests and the bench."""

import numpy as np


def contract_rows(n, seed=0, dtype=np.float64):
    """`n` rows of valid inputs (dict of the 11 columns), covering e^2 from 0 to ~1, undamped and
    damped, delta = 0 and > 0, contact loss (h <= 0), zero slip and zero spin."""
    rng = np.random.default_rng(seed)
    u = rng.uniform
    q = 10.0 ** u(0, 3, n)
    g = np.where(rng.random(n) < 0.2, 1.0, 10.0 ** u(-3.9, 0, n))
    rows = {
        "P": g * q,
        "Q": q,
        "estar": 10.0 ** u(9, 11.5, n),
        "cd": np.where(rng.random(n) < 0.5, 0.0, 10.0 ** u(-2, 0, n)),
        "f": np.where(rng.random(n) < 0.1, 0.0, u(0, 1, n)),
        "delta": np.where(rng.random(n) < 0.3, 0.0, 10.0 ** u(-6, -2, n)),
        "h": np.where(rng.random(n) < 0.1, -(10.0 ** u(-9, -5, n)), 10.0 ** u(-9, -4, n)),
        "hdot": rng.normal(0, 0.1, n),
        "vx": np.where(rng.random(n) < 0.1, 0.0, rng.normal(0, 1, n) * 10.0 ** u(-4, 0, n)),
        "vy": np.where(rng.random(n) < 0.1, 0.0, rng.normal(0, 1, n) * 10.0 ** u(-4, 0, n)),
        "omega": np.where(rng.random(n) < 0.1, 0.0, rng.normal(0, 1, n) * 10.0 ** u(-1, 2, n)),
    }
    rows["h"][rng.random(n) < 0.02] = 0.0
    out = {k: v.astype(dtype) for k, v in rows.items()}
    # Rounding to f32 must keep P <= Q.
    out["P"] = np.minimum(out["P"], out["Q"])
    return out


def with_bad(good, name, value, index=None, shape=(5,)):
    """The arguments `good` with `name` made bad: `value` itself (index None), or an array of
    `shape` holding good's value everywhere but `value` at `index`."""
    args = dict(good)
    if index is None:
        args[name] = value
    else:
        column = np.full(shape, args[name])
        column[index] = value
        args[name] = column
    return args


def every_law_form_precision(test):
    """`test(law, form, precision)` run for every law, form and precision (pytest parameters)."""
    import pytest

    import contensou

    for name, values in [("law", contensou.LAWS), ("form", contensou.FORMS), ("precision", ["f64", "f32"])]:
        test = pytest.mark.parametrize(name, values)(test)
    return test
