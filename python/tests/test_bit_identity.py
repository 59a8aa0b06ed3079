"""Bit identity with `contact_eval wrench`: the same rows through the CLI (shortest round-trip
floats, parsed back exactly) and through `contensou.wrench` / `Contact.wrench` give the same
bits, for every law, form and precision.

The reference command: $CONTENSOU_WRENCH_CMD if set, else
`cargo run --release --bin contact_eval -- wrench` in this repository. Other subcommands
(`jacobian`, `step`: test_jacobian_step.py): $CONTENSOU_EVAL_CMD (contact_eval without a
subcommand) if set, else the same cargo run."""

import os
import shlex
import shutil
import subprocess
import zlib
from pathlib import Path

import numpy as np
import pytest

import contensou
from rows import contract_rows, every_law_form_precision

REPO = Path(__file__).resolve().parents[2]
DTYPES = {"f32": np.float32, "f64": np.float64}
UINTS = {"f32": np.uint32, "f64": np.uint64}


def reference_command(sub="wrench"):
    if sub == "wrench" and os.environ.get("CONTENSOU_WRENCH_CMD"):
        return shlex.split(os.environ["CONTENSOU_WRENCH_CMD"])
    if os.environ.get("CONTENSOU_EVAL_CMD"):
        return shlex.split(os.environ["CONTENSOU_EVAL_CMD"]) + [sub]
    if shutil.which("cargo") is None:
        pytest.skip("cargo not on PATH: no reference command")
    return ["cargo", "run", "--release", "--quiet", "--manifest-path", str(REPO / "Cargo.toml"),
            "--bin", "contact_eval", "--", sub]


def text(x, precision):
    """Shortest round-trip decimal of x in its precision (numpy's and Python's str)."""
    return str(np.float32(x)) if precision == "f32" else repr(float(x))


def reference(rows, law, form, precision, optional=(), sub="wrench", inputs=None, outputs=None):
    """The CLI's outputs on `rows` (the 11 columns — or `inputs` — then the optional columns
    named), through the subcommand `sub` whose output columns are `outputs`."""
    inputs = list(contensou.INPUTS) if inputs is None else list(inputs)
    outputs = list(contensou.OUTPUTS) if outputs is None else list(outputs)
    n = len(rows["P"])
    columns = inputs + list(optional)
    lines = [",".join(columns)]
    lines += [",".join(text(rows[c][i], precision) for c in columns) for i in range(n)]
    cmd = reference_command(sub) + ["--law", law, "--form", form, "--precision", precision]
    run = subprocess.run(cmd, input="\n".join(lines) + "\n", capture_output=True, text=True, cwd=REPO)
    assert run.returncode == 0, run.stderr
    out = run.stdout.strip().split("\n")
    header = out[0].split(",")
    assert header == columns + outputs
    table = np.array([[float(x) for x in line.split(",")] for line in out[1:]])
    assert table.shape == (n, len(header))
    dtype = DTYPES[precision]
    # The echoed inputs are the bits we sent (the decimal form round-trips).
    for k, c in enumerate(columns):
        assert np.array_equal(table[:, k].astype(dtype).view(UINTS[precision]), rows[c].view(UINTS[precision])), c
    return {c: table[:, len(columns) + k].astype(dtype) for k, c in enumerate(outputs)}


def assert_same_bits(got, want, precision, outputs=None):
    for c in contensou.OUTPUTS if outputs is None else outputs:
        g, w = np.asarray(got[c]), np.asarray(want[c])
        assert g.dtype == DTYPES[precision], c
        bad = np.flatnonzero(g.view(UINTS[precision]) != w.view(UINTS[precision]))
        assert bad.size == 0, f"{c}: {bad.size} rows differ, first {bad[:3]}: {g[bad[:3]]} vs {w[bad[:3]]}"


@every_law_form_precision
def test_wrench_matches_the_cli(law, form, precision):
    rows = contract_rows(400, seed=zlib.crc32(f"{law}/{form}".encode()), dtype=DTYPES[precision])
    want = reference(rows, law, form, precision)
    got = contensou.wrench(**rows, law=law, form=form, precision=precision)
    assert_same_bits(got, want, precision)
    assert np.all(got["N"] >= 0) and np.any(got["N"] > 0)
    assert np.any(got["Tz"] != 0) == (law != "coulomb")  # a point contact has no drilling torque


@pytest.mark.parametrize("precision", ["f64", "f32"])
@pytest.mark.parametrize("form", contensou.FORMS)
def test_contact_matches_the_cli(form, precision):
    """One contact (fixed columns), 300 steps: Contact.wrench on the array, one call per scalar
    step, and the CLI on the same rows."""
    dtype = DTYPES[precision]
    steps = contract_rows(300, seed=7, dtype=dtype)
    spec = {"P": 20.0, "Q": 50.0, "estar": 1.15e11, "cd": 0.3, "f": 0.3, "delta": 1e-4}
    rows = {**steps, **{k: np.full(300, v, dtype=dtype) for k, v in spec.items()}}
    want = reference(rows, "best", form, precision)
    contact = contensou.Contact(**spec, law="best", form=form, precision=precision)
    step_cols = [steps[c] for c in contensou.INPUTS[6:]]
    assert_same_bits(contact.wrench(*step_cols), want, precision)
    one = [contact.wrench(*(c[i] for c in step_cols)) for i in range(300)]
    assert_same_bits({c: np.array([o[c] for o in one], dtype=dtype) for c in contensou.OUTPUTS}, want, precision)


def rolling_columns(rows, seed):
    """The optional rolling columns for `rows`: G from 0.1 to 1 E*, nu in [0, 0.5] (both ends
    too), a rolling velocity from 0 to well past the slip, some rows with V = 0."""
    rng = np.random.default_rng(seed)
    n = len(rows["P"])
    dtype = rows["P"].dtype
    extra = {
        "G": rows["estar"].astype(np.float64) * 10.0 ** rng.uniform(-1, 0, n),
        "nu": np.where(rng.random(n) < 0.2, rng.choice([0.0, 0.5], n), rng.uniform(0, 0.5, n)),
        "vrx": np.where(rng.random(n) < 0.1, 0.0, rng.normal(0, 1, n) * 10.0 ** rng.uniform(-3, 1, n)),
        "vry": np.where(rng.random(n) < 0.3, 0.0, rng.normal(0, 1, n) * 10.0 ** rng.uniform(-3, 1, n)),
    }
    return {k: v.astype(dtype) for k, v in extra.items()}


@every_law_form_precision
def test_rolling_columns_match_the_cli(law, form, precision):
    """The optional columns G, nu, vrx, vry through contensou.wrench and the CLI: every law (the
    sliding laws ignore them: the bits of the plain call), and subsets (defaults)."""
    dtype = DTYPES[precision]
    rows = contract_rows(200, seed=zlib.crc32(f"roll/{law}/{form}".encode()), dtype=dtype)
    rows.update(rolling_columns(rows, seed=zlib.crc32(law.encode())))
    subsets = [("G", "nu", "vrx", "vry")]
    if law == "table":
        subsets += [("vrx", "vry"), ("vry", "nu"), ("G",)]
    for names in subsets:
        want = reference(rows, law, form, precision, names)
        got = contensou.wrench(**{c: rows[c] for c in contensou.INPUTS}, **{c: rows[c] for c in names},
                               law=law, form=form, precision=precision)
        assert_same_bits(got, want, precision)
    if law in ("best", "simplified", "pade", "ellipsoid", "coulomb"):
        plain = contensou.wrench(**{c: rows[c] for c in contensou.INPUTS}, law=law, form=form, precision=precision)
        assert_same_bits(got, plain, precision)


@pytest.mark.parametrize("precision", ["f64", "f32"])
@pytest.mark.parametrize("law", ["table", "fastsim-16"])
def test_rolling_contact_matches_the_cli(law, precision):
    """Contact(..., G=, nu=) built once, .wrench(..., vrx=, vry=) on arrays and .step per row."""
    dtype = DTYPES[precision]
    steps = contract_rows(150, seed=11, dtype=dtype)
    spec = {"P": 20.0, "Q": 50.0, "estar": 1.15e11, "cd": 0.3, "f": 0.3, "delta": 1e-4}
    roll = rolling_columns(steps, seed=12)
    rows = {**steps, **{k: np.full(150, v, dtype=dtype) for k, v in spec.items()},
            "G": np.full(150, 7e10, dtype=dtype), "nu": np.full(150, 0.27, dtype=dtype),
            "vrx": roll["vrx"], "vry": roll["vry"]}
    want = reference(rows, law, "fixed", precision, ("G", "nu", "vrx", "vry"))
    contact = contensou.Contact(**spec, law=law, precision=precision, G=7e10, nu=0.27)
    step_cols = [steps[c] for c in contensou.INPUTS[6:]]
    assert_same_bits(contact.wrench(*step_cols, vrx=roll["vrx"], vry=roll["vry"]), want, precision)
    one = [contact.step(*(float(c[i]) for c in step_cols), vrx=float(roll["vrx"][i]), vry=float(roll["vry"][i]))
           for i in range(150)]
    got = {c: np.array([o[k] for o in one], dtype=dtype) for k, c in enumerate(contensou.OUTPUTS)}
    assert_same_bits(got, want, precision)
