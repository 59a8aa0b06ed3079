"""Shared by tools/fit_rolling_blend.py and tools/fit_rolling_table.py: the exact rolling
reference's CSV rows (format: tools/rolling_exact/README.md) and the library's rolling laws
through `contact_eval rolling` (build it first: cargo build --release --bin contact_eval)."""
import math, pathlib, subprocess

root = pathlib.Path(__file__).resolve().parent.parent
exe = root / "target/release/contact_eval"


def read(path):
    """The rows of a reference CSV: (family, a_over_b, nu, nl, xi, eta, phi_c, fx, fy, mz, …)."""
    rows = []
    for line in pathlib.Path(path).read_text().splitlines():
        if not line or line.startswith("#") or line.startswith("family"):
            continue
        f = line.split(",")
        rows.append((f[0],) + tuple(float(x) for x in f[1:]))
    return rows


def evaluate(law, inputs, binary=None):
    """Fx, Fy, Mz of `contact_eval rolling --law LAW` for rows (a, b, G, nu, f, N, V, xi, eta, phi)
    (`binary`: another contact_eval, e.g. an older build, instead of target/release's)."""
    text = "a,b,G,nu,f,N,V,xi,eta,phi\n" + "\n".join(",".join(repr(x) for x in r) for r in inputs) + "\n"
    out = subprocess.run([str(binary or exe), "rolling", "--law", law], input=text, capture_output=True,
                         text=True, check=True).stdout
    return [tuple(float(x) for x in l.split(",")[10:]) for l in out.splitlines()[1:]]


def patch(aob):
    """Semi-axes (a, b) with c = √(ab) = 1 for a/b = aob."""
    s = math.sqrt(aob)
    return s, 1 / s


def law_inputs(rows):
    """The `contact_eval rolling` rows of reference rows: (a, b) of c = 1, G = 1, f = 1, N = nl,
    V = 1 and the row's creepages (ξ, η, cφ)."""
    inputs = []
    for fam, aob, nu, nl, xi, eta, phic, *_ in rows:
        a, b = patch(aob)
        inputs.append((a, b, 1, nu, 1, nl, 1, xi, eta, phic))
    return inputs


def normalised(law, rows):
    """Fx, Fy, Mz of `contact_eval rolling --law LAW` on reference rows, each over the row's nl
    (the reference's normalisation)."""
    return [tuple(v / r[3] for v in w) for w, r in zip(evaluate(law, law_inputs(rows)), rows)]


def creep_coefficients(shapes):
    """Kalker's (C11, C22, C23, C33) per (a/b, ν) of `shapes`, from the library's linear law at
    unit creepages (c = 1, G = 1, N = 1)."""
    unit = []
    for aob, nu in shapes:
        a, b = patch(aob)
        unit += [(a, b, 1, nu, 1, 1, 1, 1, 0, 0), (a, b, 1, nu, 1, 1, 1, 0, 1, 0), (a, b, 1, nu, 1, 1, 1, 0, 0, 1)]
    lin = evaluate("linear", unit)
    coef = {}
    for k, key in enumerate(shapes):
        x, y, p = lin[3 * k: 3 * k + 3]
        coef[key] = (-x[0], -y[1], -p[1], -p[2])
    return coef
