"""docs/mujoco.md: both MuJoCo examples' tables and charts (θ(t) of the tippe top, ω_z(t) of
the ball).

    python python/examples/mujoco_report.py      # full runs (8 s top, 20 s ball; ≈ 10–20 min on a loaded 2-core machine)

Needs `pip install ./python mujoco matplotlib` and cargo (for the Rust scene's rows).
"""

import argparse
import platform
import sys
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import mujoco  # noqa: E402

sys.path.insert(0, str(Path(__file__).resolve().parent))
import mujoco_ball as ball  # noqa: E402
import mujoco_tippe_top as top  # noqa: E402

DOCS = Path(__file__).resolve().parents[2] / "docs"

# The native plugin (mujoco/): a fixed section, its figures live in mujoco/README.md.
PLUGIN_SECTION = """
## Natively: the `contensou.contact` engine plugin (`mujoco/`)

The same contact without callback code: a MuJoCo engine plugin in C over the C API, declared in
the model file (`<extension><plugin plugin="contensou.contact">`, `<body><plugin instance=…/>`),
built by `mujoco/build.sh` against the `mujoco` Python package, loaded by
`mujoco.mj_loadPluginLibrary`, `mj_loadPluginLibrary` from C, or `simulate`'s `mujoco_plugin/`
directory. Sphere, capsule and ellipsoid geoms against planes, sphere–sphere between plugin
bodies; a sensor with N, F_x, F_y, T_z, a, b, h per contact; bad configurations refused at load
naming the attribute and value. Its trajectory equals this page's callback path bit for bit
(tippe top Euler and RK4, ball); models `mujoco/models/{tippe_top,ball,rattleback}.xml`
(keyframe 0 = the scene's start). Use, geometry, refusals, MuJoCo's limits (explicit contact
forces: the step must respect the library's `stable_step`) and figures:
[`mujoco/README.md`](../mujoco/README.md); speed (`python mujoco/bench.py`):
[`bench-results/mujoco.md`](../bench-results/mujoco.md).
"""


def chart_top(rows, path):
    fig, ax = plt.subplots(figsize=(9, 4.5))
    for r in rows:
        t, theta = r["series"]
        style = "--" if r["run"].startswith("Rust") else "-"
        ax.plot(t, theta, style, lw=1.2 if "contensou" in r["run"] or "Rust" in r["run"] else 0.8, label=r["run"])
    ax.axhline(3.14159, color="k", lw=0.5)
    ax.axhline(2.448, color="grey", lw=0.5, ls=":")
    ax.set_xlabel("t (s)")
    ax.set_ylabel("θ (rad)")
    ax.set_title("Tippe top in MuJoCo: θ(t) (grey: both spheres touch, θ* = 2.448)")
    ax.legend(fontsize=7, loc="center right")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def chart_ball(rows, path):
    fig, ax = plt.subplots(figsize=(9, 4.5))
    for r in rows:
        t, spin = r["series"]
        style = "k:" if r["run"].startswith("analytic") else "-"
        ax.plot(t, spin, style, lw=1.2, label=r["run"])
    ax.set_xlabel("t (s)")
    ax.set_ylabel("ω_z (rad/s)")
    ax.set_ylim(-5, 105)
    ax.set_title("Steel ball, R = 10 mm, f = 0.1: spin about the vertical")
    ax.legend(fontsize=7, loc="center right")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--top-end", type=float, default=8.0)
    ap.add_argument("--ball-end", type=float, default=20.0)
    ap.add_argument("--out", type=Path, default=DOCS / "mujoco.md")
    args = ap.parse_args()
    out_dir = args.out.parent
    top_rows = top.runs(args.top_end)
    print(top.table(top_rows, args.top_end), file=sys.stderr)
    ball_rows = ball.runs(args.ball_end)
    print(ball.table(ball_rows), file=sys.stderr)
    chart_top(top_rows, out_dir / "mujoco_tippe_top.png")
    chart_ball(ball_rows, out_dir / "mujoco_ball.png")
    import contensou

    text = f"""# The library's contact inside MuJoCo

Regenerate: `python python/examples/mujoco_report.py` (a venv with `pip install ./python mujoco
matplotlib`, cargo on PATH for the Rust scene). MuJoCo {mujoco.__version__}, contensou
{contensou.__version__}, Python {platform.python_version()}. Wall and CPU times are of this run on a
shared 2-core machine (CPU: the process's CPU seconds).

The floor contact by contensou (`python/examples/floor_contact.py`): MuJoCo's contact disabled for
the body's geoms (contype = conaffinity = 0); in `mjcb_passive`, for each sphere geom, the approach
h = radius − centre height, ḣ and the slip of the material point at the patch centre from the free
joint's velocity, `Contact.step` (the `contensou::dynamic` wrench), and the force at the patch
centre plus the drilling torque summed about G into `qfrc_passive` (`mj_applyFT`).

## Tippe top (`python/examples/mujoco_tippe_top.py`)

The paper's top (src/scenes/tippe_top.rs): m = 6 g, I = 8e-7 / 7e-7 kg·m², R = 15 mm, r = 5 mm,
ε_R = 3 mm, ε_r = 16 mm, E* = 5 GPa, c_d = 5 s/m, f = 0.3, θ₀ = 0.1 rad, ω₀ = 180 rad/s, to
{args.top_end:g} s.

{top.table(top_rows, args.top_end)}

Agreement of MuJoCo + contensou with the Rust scene (same law, same contact; MuJoCo's
semi-implicit Euler against the scene's RK4, both at 10 µs):

{chr(10).join("- " + line for line in top.agreement(top_rows)) or "- (no Rust rows)"}

Reading: MuJoCo's own contact is a soft constraint with a pyramidal friction cone and, for
condim ≥ 4, a torsional friction torque bounded by μ_torsion·N (a length, default 5 mm): at the
defaults that torque eats the spin (condim 4, 6: a few rad/s left at 8 s) and the top never rises; with
condim 3 (no torsion) it rises but, lacking the drilling torque, does not stay on its head; the
stiff solref changes the timing, not the story. With contensou's Hertz + Contensou–Erismann
contact in the callback, MuJoCo inverts the top as the library's own scene does.

![θ(t)](mujoco_tippe_top.png)

## Steel ball (`python/examples/mujoco_ball.py`)

R = 10 mm steel on steel (E* = 115 GPa), f = 0.1, launched sliding at 1 m/s with 100 rad/s about
the vertical: m = {ball.MASS * 1e3:.2f} g, N = {ball.N_STATIC:.4f} N, Hertz radius
a = {ball.A_STATIC * 1e6:.2f} µm, so the physical torsional coefficient (3π/16)·f·a =
{ball.TORSION:.2e} m, below MuJoCo's floor mjMINMU = 1e-5 m. Pure rolling: the slip speed at the
contact below 1 mm/s. To {args.ball_end:g} s.

{ball.table(ball_rows)}

Reading: condim 3 has no torsional friction, so the spin never decays; condim 4 and 6 at
MuJoCo's default torsional coefficient (5 mm, ≈ 3,000 times the physical (3π/16)·f·a) stop it
within the sliding phase (condim 6's rolling friction also slows the rolling ball, so the
"pure rolling" criterion is met late); even set to the physical value the coefficient is raised
to MuJoCo's floor 1e-5 m and the spin decays about six times too fast (why that run's slip
stays above 1 mm/s until 9.4 s we have not investigated). With contensou the ball
rolls at the analytic 2v₀/(7fg) and its spin follows the analytic pure-spin decay.

![ω_z(t)](mujoco_ball.png)
"""
    text += PLUGIN_SECTION
    args.out.write_text(text)
    print(f"wrote {args.out}", file=sys.stderr)


if __name__ == "__main__":
    main()
