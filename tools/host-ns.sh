#!/usr/bin/env bash
# Host nanoseconds per call for the report: runs the criterion benches elliptic, hertz, friction,
# wrench and rolling with short measurement times, then reads target/criterion/<id>/new/sample.json and
# keeps the fastest sample (time/iterations; on a shared, loaded machine the minimum is far more
# repeatable than the mean), divided by the calls per iteration, and writes
#   bench-results/host-ns.csv    stage,method,precision,ns   (keys as in bench-results/qemu.csv)
#
#   tools/host-ns.sh            # run the benches, then collect
#   tools/host-ns.sh --collect  # only collect from the last criterion run
#
# `cargo bench --bench friction` also re-measures its accuracy grid and rewrites
# bench-results/friction.csv.
set -euo pipefail
cd "$(dirname "$0")/.."
if [[ "${1:-}" != "--collect" ]]; then
    args=(--warm-up-time 0.2 --measurement-time 0.6)
    # the optional micromath backend's twins get their own rows (`*_micromath_f32` ids)
    features=()
    grep -q '^micromath *=' Cargo.toml && features=(--features micromath)
    for b in elliptic hertz friction wrench rolling; do
        cargo bench "${features[@]}" --bench "$b" -- "${args[@]}" >&2
    done
fi
python3 - <<'PY'
import json, os
def fastest(cid, calls):
    path = f"target/criterion/{cid}/new/sample.json"
    if not os.path.exists(path):
        return None
    with open(path) as f:
        d = json.load(f)
    return min(t / n for t, n in zip(d["times"], d["iters"])) / calls
rows = []
for p in ("f32", "f64"):
    # benches/elliptic.rs: group kebd (K, E, B, D all used, as the QEMU stage), 64 m per iteration
    for m in ("agm", "theta", "table"):
        rows.append(("elliptic", m, p, fastest(f"kebd_{m}_{p}", 64)))
    # benches/hertz.rs: one call per iteration
    for m in ("per_step", "table_each_step", "fitted_each_step", "volumetric", "shape_table", "shape_linear",
              "shape_hamrock-dowson", "shape_newton"):
        rows.append(("hertz", m, p, fastest(f"hertz_{m}_{p}", 1)))
    # benches/friction.rs: the 64-state mixed set per iteration; `best-contact` is BestContact
    # (QEMU `best`), the law `Best` re-deriving its constants per call is QEMU `best-varying`
    for cid, m in (("simplified", "simplified"), ("pade", "pade"), ("ellipsoid", "ellipsoid"),
                   ("coulomb", "coulomb"), ("exact", "exact"), ("best-contact", "best"),
                   ("best", "best-varying")):
        rows.append(("friction", m, p, fastest(f"friction_{cid}-{p}", 64)))
    # benches/wrench.rs: one step per iteration
    for g in ("fixed", "table_each_step"):
        for law, suffix in (("simplified", ""), ("best", "-best")):
            rows.append(("wrench", g + suffix, p, fastest(f"wrench_{g}_{law}_{p}", 1)))
    # benches/rolling.rs: RollingContact::wrench over the 64 states of the QEMU stage `rolling`
    for m in ("table", "blend", "fastsim", "fastsim-16", "full-slip"):
        rows.append(("rolling", m, p, fastest(f"rolling_{m}-{p}", 64)))
    # the per-step wrench (contact::Rolling, `table`) over the same 64 states: V along the major
    # axis, at 30° from it, and a varying contact (the QEMU stage's wrench-* rows)
    for m in ("wrench-axis", "wrench-skewed", "wrench-varying"):
        rows.append(("rolling", m, p, fastest(f"rolling_{m}-{p}", 64)))
# the micromath twins (f32 only; present when the benches ran with --features micromath)
rows.append(("elliptic", "theta-micromath", "f32", fastest("kebd_theta_micromath_f32", 64)))
for m in ("per_step", "shape_hamrock-dowson"):
    rows.append(("hertz", f"{m}-micromath", "f32", fastest(f"hertz_{m}_micromath_f32", 1)))
for m in ("simplified", "ellipsoid", "coulomb", "best"):
    rows.append(("friction", f"{m}-micromath", "f32", fastest(f"friction_{m}_micromath_f32", 64)))
with open("bench-results/host-ns.csv", "w") as f:
    f.write("stage,method,precision,ns\n")
    for s, m, p, ns in rows:
        if ns is not None:
            f.write(f"{s},{m},{p},{ns:.2f}\n")
print("wrote bench-results/host-ns.csv")
PY
