"""`contensou.jacobian` and `contensou.step` against `contact_eval jacobian` and `contact_eval
step`: the same rows give the same bits for every law, form and precision (with and without
the optional columns); bad input is a ValueError naming the argument, the index and the
reason, at the row where the CLI stops."""

import subprocess
import zlib

import numpy as np
import pytest

import contensou
from rows import contract_rows, every_law_form_precision
from test_bit_identity import DTYPES, REPO, assert_same_bits, reference, reference_command, rolling_columns, text

J = list(contensou.JACOBIAN_OUTPUTS)
S = list(contensou.STEP_OUTPUTS)
STEP_COLUMNS = list(contensou.INPUTS) + list(contensou.STEP_INPUTS)
W_NAMES = list(contensou.STEP_INPUTS[1:])
UPPER = [(i, j) for i in range(4) for j in range(i, 4)]  # w_nn, w_nx, ..., w_ww


def inverse_masses(n, rng):
    """`n` inverse-mass matrices over u = (v_n, v_x, v_y, w): a ball of mass m and radius r on a
    fixed plane (rolling couples v_x, v_y to the spin of the ball), or a random positive
    definite matrix of the same scale; as the 10 upper-triangle columns."""
    m = 10.0 ** rng.uniform(-3, 1, n)
    r = 10.0 ** rng.uniform(-3, -1, n)
    inv_i = 1.0 / (0.4 * m * r * r)
    out = np.zeros((n, 4, 4))
    for k in range(n):
        if rng.random() < 0.5:
            out[k] = np.diag([1 / m[k], 1 / m[k] + r[k] ** 2 * inv_i[k], 1 / m[k] + r[k] ** 2 * inv_i[k], inv_i[k]])
        else:
            b = rng.normal(size=(4, 4))
            a = b @ b.T + 0.5 * np.eye(4)
            d = np.sqrt([1 / m[k], 1 / m[k], 1 / m[k], inv_i[k]])
            out[k] = a * np.outer(d, d)
    return {name: out[:, i, j] for name, (i, j) in zip(W_NAMES, UPPER)}


def step_rows(n, seed, dtype):
    """`n` rows of the step contract: the wrench's rows, a step from 10 µs to 10 ms, W, and the
    free end-of-step velocity near the start velocity."""
    rng = np.random.default_rng(seed)
    rows = contract_rows(n, seed=seed, dtype=np.float64)
    rows["dt"] = 10.0 ** rng.uniform(-5, -2, n)
    rows.update(inverse_masses(n, rng))
    start = {"un_free": -rows["hdot"], "ux_free": rows["vx"], "uy_free": rows["vy"], "uw_free": rows["omega"]}
    for name, u in start.items():
        rows[name] = u + rng.normal(0, 0.01, n) * (1 + np.abs(u))
    return {k: v.astype(dtype) for k, v in rows.items()}


@every_law_form_precision
def test_jacobian_matches_the_cli(law, form, precision):
    dtype = DTYPES[precision]
    rows = contract_rows(200, seed=zlib.crc32(f"jac/{law}/{form}".encode()), dtype=dtype)
    want = reference(rows, law, form, precision, sub="jacobian", outputs=J)
    got = contensou.jacobian(**rows, law=law, form=form, precision=precision)
    assert_same_bits(got, want, precision, J)
    # The Jacobian's wrench is the wrench, bit for bit.
    plain = contensou.wrench(**rows, law=law, form=form, precision=precision)
    assert_same_bits({c: got[c] for c in S}, {c: plain[c] for c in S}, precision, S)
    # With the rolling columns (the sliding laws ignore them).
    rows.update(rolling_columns(rows, seed=zlib.crc32(law.encode())))
    names = ("G", "nu", "vrx", "vry") if law != "table" else ("vry", "G")
    want = reference(rows, law, form, precision, names, sub="jacobian", outputs=J)
    got = contensou.jacobian(**{c: rows[c] for c in contensou.INPUTS + list(names)}, law=law, form=form,
                             precision=precision)
    assert_same_bits(got, want, precision, J)


@every_law_form_precision
def test_step_matches_the_cli(law, form, precision):
    dtype = DTYPES[precision]
    rows = step_rows(150, seed=zlib.crc32(f"step/{law}/{form}".encode()), dtype=dtype)
    base = {c: rows[c] for c in STEP_COLUMNS}
    for names in [(), ("un_free", "ux_free", "uy_free", "uw_free"), ("uw_free", "ux_free")]:
        want = reference(rows, law, form, precision, names, sub="step", inputs=STEP_COLUMNS, outputs=S)
        got = contensou.step(**base, **{c: rows[c] for c in names}, law=law, form=form, precision=precision)
        assert_same_bits(got, want, precision, S)
        assert np.all(np.isfinite(got["N"])) and np.all(got["N"] >= 0)
    if law in ("table", "fastsim-16"):
        rows.update(rolling_columns(rows, seed=3))
        names = ("G", "nu", "vrx", "vry", "ux_free")
        want = reference(rows, law, form, precision, names, sub="step", inputs=STEP_COLUMNS, outputs=S)
        got = contensou.step(**base, **{c: rows[c] for c in names}, law=law, form=form, precision=precision)
        assert_same_bits(got, want, precision, S)


def test_step_broadcasts_and_tends_to_the_wrench():
    """A scalar W and step against arrays of states; as dt -> 0 the step-aware wrench tends to
    the plain wrench (the start state's)."""
    spec = {"P": 50.0, "Q": 50.0, "estar": 1.15e11, "cd": 0.0, "f": 0.3, "delta": 1e-4}
    state = {"h": np.array([[1e-6], [2e-6]]), "hdot": 0.0, "vx": np.array([0.01, -0.02, 0.05]), "vy": 0.0,
             "omega": 5.0}
    w = dict(zip(W_NAMES, [33.0, 0, 0, 0, 115.0, 0, 0, 115.0, 0, 8.2e4]))
    got = contensou.step(**spec, **state, dt=1e-9, **w)
    assert all(np.shape(v) == (2, 3) for v in got.values())
    plain = contensou.wrench(**spec, **state)
    for c in S:
        assert np.allclose(got[c], plain[c], rtol=1e-3, atol=0), c
    one = contensou.step(**spec, **{**state, "h": 2e-6, "vx": -0.02}, dt=1e-9, **w)
    assert all(one[c].tobytes() == got[c][1, 1].tobytes() for c in S)


SPEC = {"P": 20.0, "Q": 50.0, "estar": 1.15e11, "cd": 0.0, "f": 0.3, "delta": 1e-4}
STATE = {"h": 1e-6, "hdot": 0.0, "vx": 0.01, "vy": -0.002, "omega": 30.0}
W_BALL = dict(zip(W_NAMES, [33.0, 0, 0, 0, 115.0, 0, 0, 115.0, 0, 8.2e4]))


def step_with(name, value, index=2, n=5):
    """Scalar columns but `name`: an array of `n` good values with `value` at `index`."""
    args = {**SPEC, **STATE, "dt": 1e-3, **W_BALL}
    column = np.full(n, float(args.get(name, 0.1)))
    column[index] = value
    args[name] = column
    return args


STEP_ERRORS = [
    # (argument, bad value, message start, reason fragment)
    ("dt", 0.0, "dt = 0 at index 2", "time step dt must be > 0"),
    ("dt", -1e-3, "dt = -0.001 at index 2", "time step dt must be > 0"),
    ("dt", np.nan, "dt = NaN at index 2", "must be finite"),
    ("dt", np.inf, "dt = inf at index 2", "must be finite"),
    ("w_xy", np.nan, "w_xy = NaN at index 2", "must be finite"),
    ("w_nn", -33.0, "W at index 2", "not positive semidefinite"),
    ("w_xy", 1e3, "W at index 2", "not positive semidefinite"),
    ("w_ww", np.inf, "w_ww = inf at index 2", "must be finite"),
    ("uw_free", np.nan, "uw_free = NaN at index 2", "must be finite"),
    ("h", np.nan, "h = NaN at index 2", "must be finite"),
    ("P", 60.0, "P = 60 at index 2", "P <= Q"),
]


@pytest.mark.parametrize("precision", ["f64", "f32"])
@pytest.mark.parametrize("name,value,start,reason", STEP_ERRORS)
def test_step_errors_name_argument_index_and_reason(name, value, start, reason, precision):
    with pytest.raises(ValueError) as e:
        contensou.step(**step_with(name, value), precision=precision)
    message = str(e.value)
    assert message.startswith(start) and reason in message, message
    # The CLI refuses the same row (row 3: it counts rows from 1) for the same column and reason.
    args = step_with(name, value)
    optional = ["uw_free"] if name == "uw_free" else []
    columns = STEP_COLUMNS + optional
    rows = [",".join(text(np.broadcast_to(args[c], 5)[i], precision) for c in columns) for i in range(5)]
    cmd = reference_command("step") + ["--precision", precision]
    run = subprocess.run(cmd, input="\n".join([",".join(columns)] + rows) + "\n", capture_output=True, text=True,
                         cwd=REPO)
    column = message.split(" ")[0]
    cli_reason = "not a number (NaN)" if np.isnan(value) else reason  # the CLI refuses NaN as it reads
    assert run.returncode == 1 and f"row 3: {column}" in run.stderr and cli_reason in run.stderr, run.stderr


def test_jacobian_errors():
    h = np.full((2, 3), 1e-6)
    h[1, 0] = np.nan
    with pytest.raises(ValueError, match=r"^h = NaN at index \(1, 0\): input must be finite"):
        contensou.jacobian(**SPEC, **{**STATE, "h": h})
    with pytest.raises(ValueError, match=r"^vry = inf at index \(\): input must be finite"):
        contensou.jacobian(**SPEC, **STATE, vry=np.inf, law="table")
    with pytest.raises(ValueError, match=r"^P = 60 at index \(\): .*P <= Q"):
        contensou.jacobian(**{**SPEC, "P": 60.0}, **STATE)
    with pytest.raises(ValueError, match=r"^law: unknown 'exact'"):
        contensou.jacobian(**SPEC, **STATE, law="exact")
    with pytest.raises(ValueError, match=r"shape mismatch"):
        contensou.jacobian(**SPEC, **{**STATE, "h": np.ones(3), "vx": np.ones(4)})


@pytest.mark.parametrize("precision", ["f64", "f32"])
@pytest.mark.parametrize("law,form", [("best", "fixed"), ("simplified", "varying"), ("table", "fixed")])
def test_contact_jacobian_is_the_per_row_function(law, form, precision):
    """Contact.jacobian on arrays of steps (and the rolling velocity) = contensou.jacobian on the
    same rows with the contact's columns repeated, bit for bit; its errors name the step column."""
    dtype = DTYPES[precision]
    steps = contract_rows(120, seed=5, dtype=dtype)
    roll = rolling_columns(steps, seed=6)
    step_cols = {c: steps[c] for c in contensou.INPUTS[6:]}
    contact = contensou.Contact(**SPEC, law=law, form=form, precision=precision)
    got = contact.jacobian(**step_cols, vrx=roll["vrx"], vry=roll["vry"])
    want = contensou.jacobian(**SPEC, **step_cols, vrx=roll["vrx"], vry=roll["vry"], law=law, form=form,
                              precision=precision)
    assert_same_bits(got, want, precision, J)
    one = contact.jacobian(*(c[7] for c in step_cols.values()))
    assert all(np.asarray(one[c]).tobytes() == np.asarray(contensou.jacobian(
        **SPEC, **{k: v[7] for k, v in step_cols.items()}, law=law, form=form, precision=precision)[c]).tobytes()
        for c in J)
    bad = dict(step_cols)
    bad["hdot"] = bad["hdot"].copy()
    bad["hdot"][9] = np.inf
    with pytest.raises(ValueError, match=r"^hdot = inf at index 9: input must be finite"):
        contact.jacobian(**bad)
