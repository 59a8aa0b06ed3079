"""Broadcasting, dtypes, the object API and the per-row function agreeing bit for bit."""

import threading

import numpy as np
import pytest

import contensou
from rows import contract_rows, every_law_form_precision

SPEC = {"P": 20.0, "Q": 50.0, "estar": 1.15e11, "cd": 0.0, "f": 0.3, "delta": 1e-4}
STEP = {"h": 1e-6, "hdot": 0.0, "vx": 0.01, "vy": -0.002, "omega": 30.0}


def test_scalars_give_numpy_scalars():
    w = contensou.wrench(**SPEC, **STEP)
    assert set(w) == set(contensou.OUTPUTS)
    for v in w.values():
        assert isinstance(v, np.float64) and np.ndim(v) == 0
    assert w["N"] > 0 and w["Fx"] < 0 and w["Fy"] > 0 and w["Tz"] < 0
    assert w["a"] > w["b"] > 0 and 0 < w["e2"] < 1


def test_f32_arrays():
    w = contensou.wrench(**SPEC, **{**STEP, "h": [1e-6, 2e-6]}, precision="f32")
    for v in w.values():
        assert v.dtype == np.float32 and v.shape == (2,)


def test_broadcast_shape_and_values():
    h = np.array([[1e-6], [2e-6], [0.0]])  # (3, 1)
    omega = np.linspace(-50, 50, 4)  # (4,)
    w = contensou.wrench(**SPEC, **{**STEP, "h": h, "omega": omega})
    assert all(v.shape == (3, 4) for v in w.values())
    for i in range(3):
        for j in range(4):
            one = contensou.wrench(**SPEC, **{**STEP, "h": h[i, 0], "omega": omega[j]})
            for c in contensou.OUTPUTS:
                assert w[c][i, j].tobytes() == one[c].tobytes()
    assert np.all(w["N"][2] == 0)  # h = 0: no contact


def test_non_contiguous_and_fortran_inputs():
    rows = contract_rows(64, seed=3)
    want = contensou.wrench(**rows)
    grid = {k: np.asfortranarray(v.reshape(8, 8)) for k, v in rows.items()}
    got = contensou.wrench(**grid)
    strided = {k: np.repeat(v, 2)[::2] for k, v in rows.items()}
    got2 = contensou.wrench(**strided)
    for c in contensou.OUTPUTS:
        assert np.array_equal(got[c].ravel().view(np.uint64), want[c].view(np.uint64))
        assert np.array_equal(got2[c].view(np.uint64), want[c].view(np.uint64))


def test_lists_and_ints_are_converted():
    w = contensou.wrench(20, 50, 115000000000, 0, 0.3, 0, [1e-6, 2e-6], 0, 0, 0, 1)
    assert w["N"].shape == (2,) and np.all(w["N"] > 0)


def test_empty_arrays():
    w = contensou.wrench(**SPEC, **{**STEP, "h": np.zeros((0, 3))})
    assert all(v.shape == (0, 3) for v in w.values())


@every_law_form_precision
def test_contact_equals_per_row(law, form, precision):
    dtype = np.float32 if precision == "f32" else np.float64
    steps = contract_rows(200, seed=11, dtype=dtype)
    step_cols = {c: steps[c] for c in contensou.INPUTS[6:]}
    contact = contensou.Contact(**SPEC, law=law, form=form, precision=precision)
    got = contact.wrench(**step_cols)
    want = contensou.wrench(**SPEC, **step_cols, law=law, form=form, precision=precision)
    for c in contensou.OUTPUTS:
        assert got[c].tobytes() == want[c].tobytes(), c
    assert contact.law == law and contact.form == form and contact.precision == precision


@pytest.mark.parametrize("form", contensou.FORMS)
def test_set_curvatures(form):
    contact = contensou.Contact(**SPEC, form=form)
    contact.set_curvatures(30.0, 40.0)
    assert contact.spec["P"] == 30.0 and contact.spec["Q"] == 40.0
    got = contact.wrench(**STEP)
    want = contensou.wrench(**{**SPEC, "P": 30.0, "Q": 40.0}, **STEP, form=form)
    assert all(got[c] == want[c] for c in contensou.OUTPUTS)


def test_threads_share_a_contact():
    contact = contensou.Contact(**SPEC)
    steps = contract_rows(100_000, seed=5)
    step_cols = [steps[c] for c in contensou.INPUTS[6:]]
    want = contact.wrench(*step_cols)
    results = [None] * 4

    def work(k):
        results[k] = contact.wrench(*step_cols)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for r in results:
        assert all(r[c].tobytes() == want[c].tobytes() for c in contensou.OUTPUTS)


def test_friction_dissipates():
    """The friction power F·v + T_z·ω is never positive (rows of every law)."""
    rows = contract_rows(20_000, seed=9)
    for law in contensou.LAWS:
        w = contensou.wrench(**rows, law=law)
        power = w["Fx"] * rows["vx"] + w["Fy"] * rows["vy"] + w["Tz"] * rows["omega"]
        assert np.all(power <= 0), law


@pytest.mark.parametrize("precision", ["f64", "f32"])
@pytest.mark.parametrize("law", contensou.LAWS)
def test_step_equals_wrench(law, precision):
    """Contact.step (Python floats) gives the values of Contact.wrench, bit for bit."""
    dtype = np.float32 if precision == "f32" else np.float64
    steps = contract_rows(100, seed=13, dtype=dtype)
    contact = contensou.Contact(**SPEC, law=law, precision=precision)
    want = contact.wrench(*(steps[c] for c in contensou.INPUTS[6:]))
    for i in range(100):
        got = contact.step(*(float(steps[c][i]) for c in contensou.INPUTS[6:]))
        assert isinstance(got, tuple) and len(got) == 7 and all(type(x) is float for x in got)
        for c, x in zip(contensou.OUTPUTS, got):
            assert dtype(x).tobytes() == want[c][i].tobytes() and x == float(want[c][i]), (c, i)
