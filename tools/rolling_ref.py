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
