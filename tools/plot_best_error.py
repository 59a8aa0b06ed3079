#!/usr/bin/env python3
"""Error maps of the `best` friction law (issue 5, item 5): |model - exact| over (u, psi) for
several e^2, as PNG images in bench-results/best-error-*.png, plus the max-error table on
stdout. Both columns come from the evaluator (`contact_eval friction --model best|exact`).
The table's maxima also cover a dense set on both sides of the ellipse boundary,
u = u_b(psi)(1 +- d) for d = 1e-9 ... 0.3 (the error peaks just outside it, where the slip's
instantaneous centre leaves the patch), so they are maxima, not the grid's.
Needs numpy and matplotlib (`--table`: numpy only, no images). Run from the repository root:
python3 tools/plot_best_error.py [--table]
"""
import io
import subprocess
import sys

import numpy as np

E2 = [0.0, 0.5, 0.9, 0.99, 0.999, 0.9999]
NU, NPSI = 241, 181


def run(model, rows, precision="f64"):
    text = "e2,psi,u\n" + "".join(f"{m!r},{p!r},{u!r}\n" for m, p, u in rows)
    cmd = ["cargo", "run", "--quiet", "--release", "--bin", "contact_eval", "--",
           "friction", "--model", model, "--precision", precision]
    out = subprocess.run(cmd, input=text, capture_output=True, text=True, check=True).stdout
    return np.loadtxt(io.StringIO(out), delimiter=",", skiprows=1)[:, 3:6]


def errors(rows, prec, ex):
    b = run("best", rows, prec)
    ef = np.maximum(abs(b[:, 0] - ex[:, 0]), abs(b[:, 1] - ex[:, 1]))
    return ef, abs(b[:, 2] - ex[:, 2])


def main():
    images = "--table" not in sys.argv[1:]
    if images:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    u = 10 ** np.linspace(-2, 2, NU)
    psi = np.linspace(0, np.pi / 2, NPSI)  # the symmetries cover the other quadrants
    d = 10 ** np.linspace(-9, np.log10(0.3), 160)
    print("model,precision,e2,max_force_error_fN,max_torque_error_fNa")
    for m in E2:
        rows = [(m, float(p), float(x)) for p in psi for x in u]
        ub = 1 / np.sqrt(np.sin(psi) ** 2 + np.cos(psi) ** 2 / (1 - m))
        edge = [(m, float(p), float(b * (1 + s * x))) for p, b in zip(psi, ub) for x in d for s in (-1, 1)]
        ex, ex_edge = run("exact", rows), run("exact", edge)
        for prec in ("f64", "f32"):
            ef, et = errors(rows, prec, ex)
            ef_edge, et_edge = errors(edge, prec, ex_edge)
            ef, et = ef.reshape(NPSI, NU), et.reshape(NPSI, NU)
            print(f"best,{prec},{m},{max(ef.max(), ef_edge.max()):.2e},{max(et.max(), et_edge.max()):.2e}")
            if prec != "f64" or not images:
                continue
            fig, axes = plt.subplots(1, 2, figsize=(11, 4), constrained_layout=True)
            for ax, e, name in ((axes[0], ef, "force error (fN)"),
                                (axes[1], et, "torque error (fNa)")):
                im = ax.pcolormesh(u, psi, np.log10(np.maximum(e, 1e-17)), shading="auto",
                                   vmin=-16, vmax=-4, cmap="viridis")
                ax.plot(ub, psi, "w--", lw=0.8, label="ellipse u_b(ψ)")
                ax.set_xscale("log")
                ax.set_xlabel("u = v/(aω)")
                ax.set_ylabel("ψ (rad)")
                ax.set_title(f"best, e² = {m}: log10 {name}")
                ax.legend(loc="lower right", fontsize=7)
                fig.colorbar(im, ax=ax)
            fig.savefig(f"bench-results/best-error-e2-{m}.png", dpi=80)
            plt.close(fig)


if __name__ == "__main__":
    main()
