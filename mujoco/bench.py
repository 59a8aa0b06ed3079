"""Speed of the contact inside MuJoCo, side by side in one run: wall and CPU time per simulated
second for the tippe top and the steel ball at the same step — MuJoCo's native contact (condim
3 and 6), the Python `mjcb_passive` callback (python/examples/floor_contact.py) and the
contensou.contact plugin (mujoco/build/libcontensou_mujoco.so).

    mujoco/build.sh && python mujoco/bench.py             # writes bench-results/mujoco.md (≈ 1 min)
    python mujoco/bench.py --sim 0.1 --repeat 1 --out -   # a smoke run to stdout

Each run steps from the scene's keyframe (the plugin model's keyframe 0; the native and callback
models are the Python examples' own at the same step and integrator) with
mujoco.mj_step(m, d, nstep) — one call, no Python per step except inside the callback — over
`--sim` simulated seconds, `--repeat` times; the table gives the fastest repeat (the machine is
shared) per simulated second. The runs alternate per repeat so that load drifts hit all alike.
"""

import argparse
import copy
import os
import platform
import sys
import time
from pathlib import Path

import mujoco

HERE = Path(__file__).resolve().parent
REPO = HERE.parent
sys.path.insert(0, str(HERE / "examples"))
sys.path.insert(0, str(REPO / "python" / "examples"))
import mujoco_ball as ball  # noqa: E402
import mujoco_tippe_top as top  # noqa: E402
import run_models  # noqa: E402
from floor_contact import SphereFloor  # noqa: E402


FLAG = '<flag contact="disable"/>'


def contact_flag(m, on):
    """A copy of model `m` with MuJoCo's contact pipeline on or off (mjDSBL_CONTACT)."""
    m = copy.deepcopy(m)
    if on:
        m.opt.disableflags &= ~int(mujoco.mjtDisableBit.mjDSBL_CONTACT)
    else:
        m.opt.disableflags |= int(mujoco.mjtDisableBit.mjDSBL_CONTACT)
    return m


PLUGIN_ROW = "contensou.contact plugin, step = explicit (the model file's contact flag off)"
CALLBACK_ROW = "Python callback (the example's model: contact flag on)"


def cases():
    """(scene, run, model, callback or None) for every row; every model of a scene at one dt."""
    out = []
    for scene, xml, module, geoms in (("tippe top", "tippe_top.xml", top, ["big", "small"]),
                                      ("ball", "ball.xml", ball, ["ball"])):
        # The plugin model at its small reference step with the plain contact (step = explicit):
        # the callback's arithmetic, every row at one step.
        pm = mujoco.MjModel.from_xml_string(run_models.explicit(xml[:-4]))
        dt = pm.opt.timestep
        native = (lambda c: top.model(c, dt=dt, integrator="Euler")) if module is top else (lambda c: ball.model(c, dt=dt))
        bare = top.model(dt=dt, integrator="Euler", native=False) if module is top else ball.model(dt=dt, native=False)
        for condim in (3, 6):
            out.append((scene, f"MuJoCo native, condim {condim}", native(condim), None))
        out.append((scene, "MuJoCo, no contact at all (contact flag off): the bare step", contact_flag(bare, False), None))
        body = "top" if module is top else "ball"
        for on, name in ((True, CALLBACK_ROW), (False, "Python callback, contact flag off")):
            cm = contact_flag(bare, on)
            out.append((scene, name, cm, SphereFloor(cm, body, geoms, module.ESTAR, module.CD, module.F, module.DELTA)))
        out.append((scene, "contensou.contact plugin, contact flag on", contact_flag(pm, True), None))
        out.append((scene, PLUGIN_ROW, pm, None))
    return out


STEP_AWARE_DT = 0.002  # MuJoCo's default step


def step_aware_rows():
    """(scene, run, model) at MuJoCo's default 2 ms against today's plugin at its small step:
    native condim 6 at 2 ms (Euler, the examples' integrator), the shipped plugin model (step =
    aware, implicitfast, 2 ms), the plugin with the plain contact (step = explicit) at its small
    reference step."""
    out = []
    for scene, xml, module in (("tippe top", "tippe_top.xml", top), ("ball", "ball.xml", ball)):
        am = mujoco.MjModel.from_xml_path(str(run_models.MODELS / xml))
        assert am.opt.timestep == STEP_AWARE_DT
        pm = mujoco.MjModel.from_xml_string(run_models.explicit(xml[:-4]))
        native = (top.model(6, dt=STEP_AWARE_DT, integrator="Euler") if module is top
                  else ball.model(6, dt=STEP_AWARE_DT))
        out.append((scene, "MuJoCo native, condim 6, 2 ms", native))
        out.append((scene, "contensou.contact plugin as shipped (step = aware, 2 ms)", am))
        out.append((scene, f"contensou.contact plugin, step = explicit ({pm.opt.timestep * 1e6:g} µs)", pm))
    return out


# The 2 ms rows simulate this many times `--sim` (each of their runs is 100–200× cheaper than a
# small-step one: 0.5 s at 2 ms is ≈ 1 ms of CPU, below the timer's resolution on a busy host).
STEP_AWARE_SIM = 8


def step_aware_section(starts, sim, repeat):
    rows = step_aware_rows()
    sim = sim * STEP_AWARE_SIM
    best = {}
    for _ in range(repeat):
        for scene, name, m in rows:
            _, c, _ = timed(m, None, *starts[scene], sim)
            best[(scene, name)] = min(c, best.get((scene, name), c))
    lines = ["", "## At MuJoCo's default 2 ms: the step-aware plugin", "",
             "The plugin models as shipped (`step = aware`, `timestep` 2 ms, implicitfast) against "
             "MuJoCo's native condim-6 contact at 2 ms and against the plugin with the plain contact (`step = "
             f"explicit`) at the small step it needs: CPU time per simulated second over {sim:g} s simulated "
             "(the 2 ms rows) from the scene's start, the fastest of the repeats.", "",
             "| scene | run | CPU / simulated s | vs native condim 6 at 2 ms |", "|---|---|---:|---:|"]
    for scene in ("tippe top", "ball"):
        c6 = best[(scene, "MuJoCo native, condim 6, 2 ms")]
        for s_, name, _ in rows:
            if s_ == scene:
                lines.append(f"| {scene} | {name} | {best[(scene, name)]:.4f} s | {best[(scene, name)] / c6:.2f}× |")
    return lines


def start_state(scene):
    """qpos, qvel of the scene's keyframe 0 (the plugin model's)."""
    m = mujoco.MjModel.from_xml_path(str(run_models.MODELS / ("tippe_top.xml" if scene == "tippe top" else "ball.xml")))
    return m.key_qpos[0].copy(), m.key_qvel[0].copy()


def timed(m, callback, qpos, qvel, sim):
    d = mujoco.MjData(m)
    d.qpos[:], d.qvel[:] = qpos, qvel
    mujoco.mj_forward(m, d)
    steps = round(sim / m.opt.timestep)
    if callback is not None:
        callback.install()
    try:
        wall, cpu = time.perf_counter(), time.process_time()
        mujoco.mj_step(m, d, steps)
        wall, cpu = time.perf_counter() - wall, time.process_time() - cpu
    finally:
        if callback is not None:
            callback.uninstall()
    return wall / d.time, cpu / d.time, steps


def cpu_name():
    try:
        for line in open("/proc/cpuinfo"):
            if line.startswith("model name"):
                return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or "unknown CPU"


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--sim", type=float, default=0.5, help="simulated seconds per run (default 0.5)")
    ap.add_argument("--repeat", type=int, default=3, help="repeats; the fastest counts (default 3)")
    ap.add_argument("--out", default=str(REPO / "bench-results" / "mujoco.md"), help="output file, - for stdout")
    ap.add_argument("--plugin", default=str(run_models.PLUGIN), help="the plugin library")
    args = ap.parse_args()
    run_models.load_plugin(args.plugin)
    rows = cases()
    starts = {scene: start_state(scene) for scene in {r[0] for r in rows}}
    best = {}
    for _ in range(args.repeat):
        for scene, name, m, callback in rows:
            w, c, steps = timed(m, callback, *starts[scene], args.sim)
            old = best.get((scene, name))
            best[(scene, name)] = (min(w, old[0]), min(c, old[1]), steps) if old else (w, c, steps)
    lines = [
        "# The contact inside MuJoCo: speed per simulated second",
        "",
        f"Regenerate: `mujoco/build.sh && python mujoco/bench.py` (`--sim {args.sim:g} --repeat {args.repeat}`). "
        f"MuJoCo {mujoco.__version__}, Python {platform.python_version()}, {cpu_name()}, {os.cpu_count()} "
        "logical CPUs shared with other jobs (wall includes waiting for a CPU; CPU is the process's CPU time). "
        f"Each run: {args.sim:g} s simulated from the scene's keyframe, `mj_step(m, d, nstep)` in one call; "
        f"the fastest of {args.repeat} repeats. Same step and integrator (Euler) for every run of a scene: "
        "MuJoCo's native contact (pyramidal cone, default solref/solimp, friction \"f 0.005 0.0001\"; condim 6 adds "
        "torsional and rolling friction), the Python `mjcb_passive` callback of `python/examples/floor_contact.py`, "
        "and the `contensou.contact` plugin (`mujoco/build/libcontensou_mujoco.so`, the same contact bit for bit).",
        "",
        "| scene | dt | run | wall / simulated s | CPU / simulated s | CPU per step | over the bare step | CPU vs plugin |",
        "|---|---:|---|---:|---:|---:|---:|---:|",
    ]
    for scene in ("tippe top", "ball"):
        plugin_cpu = best[(scene, PLUGIN_ROW)][1]
        bare = best[(scene, "MuJoCo, no contact at all (contact flag off): the bare step")][1]
        for s, name, m, _ in rows:
            if s != scene:
                continue
            w, c, steps = best[(scene, name)]
            per_step = c * args.sim / steps * 1e6
            extra = (c - bare) * args.sim / steps * 1e6
            lines.append(f"| {scene} | {m.opt.timestep * 1e6:g} µs | {name} | {w:.3f} s | {c:.3f} s | "
                         f"{per_step:.2f} µs | {extra:+.2f} µs | {c / plugin_cpu:.2f}× |")
    lines.append("")
    for scene in ("tippe top", "ball"):
        b = {name: best[(s, name)][1] for s, name, _, _ in rows if s == scene}
        bare = b["MuJoCo, no contact at all (contact flag off): the bare step"]
        cb_on, cb_off = b[CALLBACK_ROW], b["Python callback, contact flag off"]
        pl_on, pl_off = b["contensou.contact plugin, contact flag on"], b[PLUGIN_ROW]
        c6 = b["MuJoCo native, condim 6"]
        lines.append(
            f"- {scene}: the plugin is **{cb_on / pl_on:.1f}×** faster than the Python callback with the contact flag on "
            f"in both, **{cb_off / pl_off:.1f}×** with it off in both, **{cb_on / pl_off:.1f}×** the model file's flags against "
            f"the example's; the contact's own cost over the bare step: plugin {(pl_off - bare) / max(cb_off - bare, 1e-30):.3f}× "
            f"the callback's; the plugin model (step = explicit) takes **{pl_off / c6:.2f}×** the CPU time of MuJoCo's native "
            f"condim-6 contact ({pl_on / c6:.2f}× with the contact flag on).")
    lines += step_aware_section(starts, args.sim, args.repeat)
    text = "\n".join(lines) + "\n"
    if args.out == "-":
        print(text)
    else:
        Path(args.out).write_text(text)
        print(text)
        print(f"wrote {args.out}")


if __name__ == "__main__":
    main()
