"""Bad input: a ValueError naming the argument, the index into the broadcast shape and the
reason; never a crash, never NaN out."""

import numpy as np
import pytest

import contensou
import rows

SPEC = {"P": 20.0, "Q": 50.0, "estar": 1.15e11, "cd": 0.0, "f": 0.3, "delta": 1e-4}
STEP = {"h": 1e-6, "hdot": 0.0, "vx": 0.01, "vy": -0.002, "omega": 30.0}


def with_bad(name, value, index=None, shape=(5,)):
    """Every column a scalar but `name` (rows.with_bad)."""
    return rows.with_bad({**SPEC, **STEP}, name, value, index, shape)


CASES = [
    # (argument, bad value, index, shape, expected message start, reason fragment)
    ("P", np.nan, 2, (5,), "P = NaN at index 2", "finite"),
    ("P", 60.0, (1, 0), (2, 3), "P = 60 at index (1, 0)", "P <= Q"),
    ("P", -1.0, 4, (5,), "P = -1 at index 4", "curvature must be positive"),
    ("Q", np.inf, (0, 2), (2, 3), "Q = inf at index (0, 2)", "finite"),
    ("P", 1e-5, 0, (5,), "P = 0.00001 at index 0", "ratio"),
    ("estar", -2.0, 1, (5,), "estar = -2 at index 1", "modulus must be positive"),
    ("cd", -0.5, 3, (5,), "cd = -0.5 at index 3", "damping coefficient is negative"),
    ("f", -0.1, (1, 1, 1), (2, 2, 2), "f = -0.1 at index (1, 1, 1)", "friction coefficient is negative"),
    ("delta", -1e-4, 0, (5,), "delta = -0.0001 at index 0", "delta must be >= 0"),
    ("h", np.nan, 3, (5,), "h = NaN at index 3", "finite"),
    ("hdot", -np.inf, 1, (5,), "hdot = -inf at index 1", "finite"),
    ("omega", np.nan, (1, 2), (2, 3), "omega = NaN at index (1, 2)", "finite"),
    ("vy", np.nan, None, None, "vy = NaN at index ()", "finite"),
]


@pytest.mark.parametrize("precision", ["f64", "f32"])
@pytest.mark.parametrize("name,value,index,shape,start,reason", CASES)
def test_bad_value_names_argument_index_and_reason(name, value, index, shape, start, reason, precision):
    with pytest.raises(ValueError) as e:
        contensou.wrench(**with_bad(name, value, index, shape), precision=precision)
    message = str(e.value)
    assert message.startswith(start), message
    assert reason in message, message


@pytest.mark.parametrize("name,value,index,shape,start,reason", [c for c in CASES if c[0] in STEP])
def test_contact_step_errors(name, value, index, shape, start, reason):
    contact = contensou.Contact(**SPEC)
    args = with_bad(name, value, index, shape)
    with pytest.raises(ValueError) as e:
        contact.wrench(**{k: args[k] for k in STEP})
    assert str(e.value).startswith(start) and reason in str(e.value)


@pytest.mark.parametrize("name,value,reason", [
    ("P", 60.0, "P <= Q"), ("Q", np.nan, "finite"), ("estar", 0.0, "modulus"),
    ("f", -1.0, "friction coefficient"), ("delta", -1.0, "delta"), ("cd", -1.0, "damping"),
])
def test_contact_construction_errors(name, value, reason):
    with pytest.raises(ValueError) as e:
        contensou.Contact(**{**SPEC, name: value})
    assert str(e.value).startswith(f"{name} = ") and reason in str(e.value)


def test_contact_columns_must_be_scalars():
    with pytest.raises(ValueError, match=r"^P: .*scalars, got shape \(2,\)"):
        contensou.Contact(**{**SPEC, "P": [1.0, 2.0]})


def test_f32_overflow_is_not_finite():
    with np.errstate(over="ignore"), pytest.raises(ValueError, match=r"^estar = inf at index \(\): input must be finite"):
        contensou.wrench(**{**SPEC, "estar": 1e39}, **STEP, precision="f32")


def test_shape_mismatch_names_both_arguments():
    with pytest.raises(ValueError, match=r"shape mismatch: vx has shape \(4,\) and h has shape \(3,\)"):
        contensou.wrench(**SPEC, **{**STEP, "h": np.ones(3), "vx": np.ones(4)})
    contact = contensou.Contact(**SPEC)
    with pytest.raises(ValueError, match=r"omega has shape \(2, 5\) and vy has shape \(3, 1\)"):
        contact.wrench(1e-6, 0.0, 0.0, np.ones((3, 1)), np.ones((2, 5)))


@pytest.mark.parametrize("option,value", [("law", "fast"), ("precision", "f16"), ("form", "rigid")])
def test_unknown_options(option, value):
    with pytest.raises(ValueError, match=rf"^{option}: unknown '{value}'; expected one of"):
        contensou.wrench(**SPEC, **STEP, **{option: value})
    with pytest.raises(ValueError, match=rf"^{option}: unknown"):
        contensou.Contact(**SPEC, **{option: value})


def test_not_a_number_names_the_argument():
    with pytest.raises(ValueError, match=r"^omega: not convertible"):
        contensou.wrench(**SPEC, **{**STEP, "omega": "fast"})


def test_set_curvatures_error_leaves_contact_unchanged():
    contact = contensou.Contact(**SPEC, form="varying")
    before = contact.wrench(**STEP)
    with pytest.raises(ValueError, match=r"^P = 60: .*P <= Q"):
        contact.set_curvatures(60.0, 50.0)
    after = contact.wrench(**STEP)
    assert contact.spec["P"] == 20.0 and all(before[c] == after[c] for c in contensou.OUTPUTS)


def test_first_bad_row_reported_and_no_output():
    """Several bad rows: the first in C order is reported."""
    h = np.full((3, 3), 1e-6)
    h[2, 0] = np.nan
    h[1, 2] = np.nan
    with pytest.raises(ValueError, match=r"^h = NaN at index \(1, 2\)"):
        contensou.wrench(**SPEC, **{**STEP, "h": h})


def test_step_errors():
    contact = contensou.Contact(**SPEC)
    with pytest.raises(ValueError, match=r"^omega = NaN: input must be finite"):
        contact.step(1e-6, 0.0, 0.0, 0.0, float("nan"))
    with pytest.raises(ValueError, match=r"^h = inf: input must be finite"):
        contact.step(float("inf"), 0.0, 0.0, 0.0, 0.0)
    with pytest.raises(TypeError):
        contact.step("x", 0.0, 0.0, 0.0, 0.0)


ROLLING_CASES = [
    # (argument, bad value, index, shape, message start, reason fragment) through law="table"
    ("G", -1.0, 2, (5,), "G = -1 at index 2", "shear modulus"),
    ("G", np.inf, 0, (5,), "G = inf at index 0", "finite"),
    ("nu", 0.6, (1, 1), (2, 3), "nu = 0.6 at index (1, 1)", "Poisson"),
    ("nu", np.nan, 4, (5,), "nu = NaN at index 4", "finite"),
    ("vrx", np.inf, 3, (5,), "vrx = inf at index 3", "finite"),
    ("vry", np.nan, (0, 2), (2, 3), "vry = NaN at index (0, 2)", "finite"),
]
ROLLING = {"G": 8e10, "nu": 0.28, "vrx": 2.0, "vry": 0.0}


@pytest.mark.parametrize("precision", ["f64", "f32"])
@pytest.mark.parametrize("name,value,index,shape,start,reason", ROLLING_CASES)
def test_rolling_columns_name_argument_index_and_reason(name, value, index, shape, start, reason, precision):
    args = {**SPEC, **STEP, **ROLLING}
    column = np.full(shape, args[name])
    column[index] = value
    args[name] = column
    with pytest.raises(ValueError) as e:
        contensou.wrench(**args, law="table", precision=precision)
    assert str(e.value).startswith(start), str(e.value)
    assert reason in str(e.value), str(e.value)
    # the sliding laws neither read nor validate them
    contensou.wrench(**args, law="best", precision=precision)


def test_rolling_contact_errors():
    with pytest.raises(ValueError, match=r"^nu = 0.7: .*Poisson"):
        contensou.Contact(**SPEC, law="table", nu=0.7)
    with pytest.raises(ValueError, match=r"^G = 0: shear modulus"):
        contensou.Contact(**SPEC, law="blend", G=0.0)
    contact = contensou.Contact(**SPEC, law="table", G=8e10)
    with pytest.raises(ValueError, match=r"^vry = NaN: .*finite"):
        contact.step(**STEP, vrx=1.0, vry=float("nan"))
    with pytest.raises(ValueError, match=r"^vrx = inf at index 1: .*finite"):
        contact.wrench(**STEP, vrx=np.array([0.0, np.inf]))
