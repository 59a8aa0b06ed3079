"""`contensou.rolling` (Kalker's rolling contact) against `contact_eval rolling`: the
same rows (shortest round-trip floats) give the same bits for every rolling law and precision;
bad input is a ValueError naming the argument, its value, the index and the reason.

The reference command: $CONTENSOU_ROLLING_CMD if set, else
`cargo run --release --bin contact_eval -- rolling` in this repository."""

import os
import shlex
import shutil
import subprocess
import zlib
from pathlib import Path

import numpy as np
import pytest

import contensou
from rows import with_bad

REPO = Path(__file__).resolve().parents[2]
DTYPES = {"f32": np.float32, "f64": np.float64}
UINTS = {"f32": np.uint32, "f64": np.uint64}
INPUTS = contensou.ROLLING_EVAL_INPUTS
OUTPUTS = contensou.ROLLING_EVAL_OUTPUTS


def reference_command():
    if os.environ.get("CONTENSOU_ROLLING_CMD"):
        return shlex.split(os.environ["CONTENSOU_ROLLING_CMD"])
    if shutil.which("cargo") is None:
        pytest.skip("cargo not on PATH: no reference command")
    return ["cargo", "run", "--release", "--quiet", "--manifest-path", str(REPO / "Cargo.toml"),
            "--bin", "contact_eval", "--", "rolling"]


def text(x, precision):
    return str(np.float32(x)) if precision == "f32" else repr(float(x))


def rolling_rows(n, seed, dtype):
    """Valid rows: shapes a/b from 0.02 to 50, creepages from 1e-3 of saturation to far past
    it, pure and combined, V of both signs and 0, N <= 0, f = 0, nu at both ends."""
    rng = np.random.default_rng(seed)
    u = rng.uniform
    c = 10.0 ** u(-4, -2, n)
    ratio = 10.0 ** u(-1.7, 1.7, n)
    g = 10.0 ** u(6, 11, n)
    f = np.where(rng.random(n) < 0.05, 0.0, u(0.05, 1.0, n))
    N = np.where(rng.random(n) < 0.05, np.where(rng.random(n) < 0.5, 0.0, -1.0), 10.0 ** u(-1, 6, n))
    sat = np.maximum(f, 0.05) * np.abs(N).clip(1.0) / (g * c * c)
    mag = sat * 10.0 ** u(-3, 2, n)

    def creep(p_zero):
        return np.where(rng.random(n) < p_zero, 0.0, rng.normal(0, 1, n) * mag)

    rows = {
        "a": c * np.sqrt(ratio),
        "b": c / np.sqrt(ratio),
        "G": g,
        "nu": np.where(rng.random(n) < 0.1, 0.0, np.where(rng.random(n) < 0.1, 0.5, u(0, 0.5, n))),
        "f": f,
        "N": N,
        "V": np.where(rng.random(n) < 0.1, 0.0, rng.normal(0, 10, n)),
        "xi": creep(0.3),
        "eta": creep(0.3),
        "phi": creep(0.3) / c,
    }
    return {k: v.astype(dtype) for k, v in rows.items()}


def reference(rows, law, precision):
    n = len(rows["a"])
    lines = [",".join(INPUTS)]
    lines += [",".join(text(rows[c][i], precision) for c in INPUTS) for i in range(n)]
    cmd = reference_command() + ["--law", law, "--precision", precision]
    run = subprocess.run(cmd, input="\n".join(lines) + "\n", capture_output=True, text=True, cwd=REPO)
    assert run.returncode == 0, run.stderr
    out = run.stdout.strip().split("\n")
    assert out[0].split(",") == list(INPUTS) + list(OUTPUTS)
    table = np.array([[float(x) for x in line.split(",")] for line in out[1:]])
    assert table.shape == (n, len(INPUTS) + len(OUTPUTS))
    dtype, uint = DTYPES[precision], UINTS[precision]
    for k, c in enumerate(INPUTS):
        assert np.array_equal(table[:, k].astype(dtype).view(uint), rows[c].view(uint)), c
    return {c: table[:, len(INPUTS) + k].astype(dtype) for k, c in enumerate(OUTPUTS)}


@pytest.mark.parametrize("precision", ["f64", "f32"])
@pytest.mark.parametrize("law", contensou.ROLLING_LAWS)
def test_rolling_matches_the_cli(law, precision):
    rows = rolling_rows(300, seed=zlib.crc32(law.encode()), dtype=DTYPES[precision])
    want = reference(rows, law, precision)
    got = contensou.rolling(**rows, law=law, precision=precision)
    uint = UINTS[precision]
    for c in OUTPUTS:
        g = np.asarray(got[c])
        assert g.dtype == DTYPES[precision], c
        bad = np.flatnonzero(g.view(uint) != want[c].view(uint))
        assert bad.size == 0, f"{c}: {bad.size} rows differ, first {bad[:3]}: {g[bad[:3]]} vs {want[c][bad[:3]]}"
    # no contact (N <= 0) or f = 0: zero; otherwise |F| <= fN (the traction bound)
    fn = rows["f"].astype(np.float64) * np.clip(rows["N"].astype(np.float64), 0, None)
    force = np.hypot(got["Fx"].astype(np.float64), got["Fy"].astype(np.float64))
    if law != "linear":  # the unsaturated linear theory is a reference, not bounded
        assert np.all(force <= fn * (1 + 1e-5) + 1e-30)
    assert np.all(force[fn == 0] == 0)


def test_scalars_broadcast_and_defaults():
    w = contensou.rolling(6e-3, 4e-3, 8e10, 0.28, 0.3, 8e4, 30.0, 1e-3, 0.0, 0.0)
    assert set(w) == set(OUTPUTS) and np.ndim(w["Fx"]) == 0 and w["Fx"] < 0
    table = contensou.rolling(6e-3, 4e-3, 8e10, 0.28, 0.3, 8e4, 30.0, 1e-3, 0.0, 0.0, law="table")
    assert table["Fx"] == w["Fx"]  # table is the default
    xi = np.array([[1e-5], [1e-4], [1e-3]])
    phi = np.array([0.0, 1.0, 10.0, 100.0])
    w = contensou.rolling(6e-3, 4e-3, 8e10, 0.28, 0.3, 8e4, 30.0, xi, 0.0, phi, precision="f32")
    assert w["Mz"].shape == (3, 4) and w["Mz"].dtype == np.float32
    one = contensou.rolling(6e-3, 4e-3, 8e10, 0.28, 0.3, 8e4, 30.0, 1e-4, 0.0, 10.0, precision="f32")
    assert w["Mz"][1, 2] == one["Mz"]
    assert np.all(np.diff(w["Fx"][:, 0]) < 0)  # more creepage, more (negative) force


BAD = [
    # (argument, value, index, shape, message start, reason fragment)
    ("G", -1.0, 2, (5,), "G = -1 at index 2", "shear modulus"),
    ("G", np.inf, (1, 0), (2, 3), "G = inf at index (1, 0)", "finite"),
    ("nu", 0.6, 4, (5,), "nu = 0.6 at index 4", "Poisson"),
    ("nu", -0.1, 0, (5,), "nu = -0.1 at index 0", "Poisson"),
    ("a", 0.0, 1, (5,), "a = 0 at index 1", "length must be positive"),
    ("b", np.nan, 3, (5,), "b = NaN at index 3", "finite"),
    ("a", 1.0, 2, (5,), "a/b = 2", "at index 2: semi-axis ratio"),  # 250 (f32: 249.99998)
    ("f", -0.3, 1, (5,), "f = -0.3 at index 1", "friction coefficient is negative"),
    ("N", np.inf, 1, (5,), "N = inf at index 1", "finite"),
    ("V", -np.inf, 0, (5,), "V = -inf at index 0", "finite"),
    ("xi", np.nan, (0, 2), (2, 3), "xi = NaN at index (0, 2)", "finite"),
    ("eta", np.inf, 2, (5,), "eta = inf at index 2", "finite"),
    ("phi", -np.inf, None, None, "phi = -inf at index ()", "finite"),
]
GOOD = {"a": 6e-3, "b": 4e-3, "G": 8e10, "nu": 0.28, "f": 0.3, "N": 8e4, "V": 30.0, "xi": 1e-3, "eta": 0.0, "phi": 1.0}


@pytest.mark.parametrize("precision", ["f64", "f32"])
@pytest.mark.parametrize("name,value,index,shape,start,reason", BAD)
def test_bad_value_names_argument_index_and_reason(name, value, index, shape, start, reason, precision):
    with pytest.raises(ValueError) as e:
        contensou.rolling(**with_bad(GOOD, name, value, index, shape), precision=precision)
    assert str(e.value).startswith(start), str(e.value)
    assert reason in str(e.value), str(e.value)


def test_bad_options():
    with pytest.raises(ValueError, match="law: unknown 'best'; expected one of table, blend"):
        contensou.rolling(**GOOD, law="best")
    with pytest.raises(ValueError, match="shape mismatch"):
        contensou.rolling(**{**GOOD, "xi": np.zeros(3), "eta": np.zeros(4)})


@pytest.mark.parametrize("precision", ["f64", "f32"])
@pytest.mark.parametrize("law", contensou.ROLLING_LAWS)
def test_rolling_contact_is_the_per_row_function(law, precision):
    """RollingContact(a/b, G, nu) built once, wrench(a, b, f, N, V, xi, eta, phi) on arrays: the
    bits of contensou.rolling on the same rows (whose a/b is the contact's)."""
    dtype = DTYPES[precision]
    rows = rolling_rows(200, seed=5, dtype=dtype)
    ratio, g, nu = 1.7, 7e10, 0.27
    rows["a"] = (rows["b"] * dtype(ratio)).astype(dtype)
    keep = rows["a"] / rows["b"] == dtype(ratio)  # the rows whose a / b rounds to the contact's
    rows = {k: v[keep] for k, v in rows.items()}
    assert len(rows["a"]) > 100
    rows["G"] = np.full(len(rows["a"]), g, dtype=dtype)
    rows["nu"] = np.full(len(rows["a"]), nu, dtype=dtype)
    want = contensou.rolling(**rows, law=law, precision=precision)
    contact = contensou.RollingContact(ratio, g, nu, law=law, precision=precision)
    assert contact.law == law and contact.precision == precision
    got = contact.wrench(*(rows[k] for k in ("a", "b", "f", "N", "V", "xi", "eta", "phi")))
    uint = UINTS[precision]
    for k in OUTPUTS:
        assert np.array_equal(np.asarray(got[k]).view(uint), want[k].view(uint)), k
    one = contact.wrench(rows["a"][3], rows["b"][3], rows["f"][3], rows["N"][3], rows["V"][3],
                         rows["xi"][3], rows["eta"][3], rows["phi"][3])
    assert np.ndim(one["Mz"]) == 0 and one["Mz"] == want["Mz"][3]


def test_rolling_contact_errors():
    with pytest.raises(ValueError, match=r"^nu = 0.6: .*Poisson"):
        contensou.RollingContact(1.0, 8e10, 0.6)
    with pytest.raises(ValueError, match=r"^G = 0: shear modulus"):
        contensou.RollingContact(1.0, 0.0, 0.3)
    with pytest.raises(ValueError, match=r"^a_over_b = 200: .*ratio"):
        contensou.RollingContact(200.0, 8e10, 0.3)
    with pytest.raises(ValueError, match="law: unknown 'best'"):
        contensou.RollingContact(1.0, 8e10, 0.3, law="best")
    contact = contensou.RollingContact(1.5, 8e10, 0.28)
    with pytest.raises(ValueError, match=r"^phi = inf at index 1: .*finite"):
        contact.wrench(6e-3, 4e-3, 0.3, 8e4, 30.0, 1e-3, 0.0, np.array([0.0, np.inf]))
    with pytest.raises(ValueError, match=r"^b = -0.004 at index \(\): length must be positive"):
        contact.wrench(6e-3, -4e-3, 0.3, 8e4, 30.0, 1e-3, 0.0, 0.0)


def test_rolling_names_the_default_rolling_law():
    """`law="rolling"` is the default rolling law (the library resolves the alias), bit for bit."""
    default = contensou.ROLLING_LAWS[0]
    args = (6e-3, 4e-3, 8e10, 0.28, 0.3, 8e4, 30.0, 1e-3, -2e-4, np.array([0.0, 0.5, 50.0]))
    alias, named = (contensou.rolling(*args, law=law) for law in ("rolling", default))
    for k in OUTPUTS:
        assert np.array_equal(alias[k].view(np.uint64), named[k].view(np.uint64)), k
    assert contensou.RollingContact(1.5, 8e10, 0.28, law="rolling").law == default
    spec = {"P": 20.0, "Q": 50.0, "estar": 1.15e11, "cd": 0.0, "f": 0.3, "delta": 1e-4}
    step = {"h": 1e-6, "hdot": 0.0, "vx": 0.01, "vy": -0.002, "omega": 30.0, "vrx": 1.5, "vry": 0.5}
    by_alias, by_name = (contensou.wrench(**spec, **step, G=8e10, law=law) for law in ("rolling", default))
    for k in by_alias:
        assert np.array_equal(by_alias[k], by_name[k]), k
    assert contensou.Contact(**spec, law="rolling", G=8e10).law == default
