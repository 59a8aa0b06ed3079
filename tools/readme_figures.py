#!/usr/bin/env python3
"""The README's headline figures against the recorded benchmarks: every M4F instruction count,
µs at 168 MHz and M4F real-time factor in the two headline tables of README.md must be what
bench-results/qemu.csv and bench-results/cycles.csv (the cycle model's mid estimate) give now,
to the digits the README shows. The front door's figures are hand-written; this keeps them from
going stale when the rigs are re-run (`tools/qemu-bench.sh` rewrites both CSVs).

    python3 tools/readme_figures.py          # print each figure: README, recorded, ok
    python3 tools/readme_figures.py --check  # fail on the first figure that differs

Rows are found by the start of their first cell; a row the README no longer has is an error
(rename it here too).
"""
import csv, math, pathlib, re, sys

root = pathlib.Path(__file__).resolve().parent.parent
MHZ = 168.0

# headline table: row label → qemu.csv keys (stage, method), one per figure in the cell ("a / b")
HEADLINE = {
    "full wrench, fixed geometry (`Contact`)": [("wrench", "fixed-best")],
    "full wrench, geometry per step (`VaryingContact`)": [("wrench", "table_each_step-best")],
    "the paper's law, fixed geometry": [("wrench", "fixed")],
    "rolling creep (`RollingContact`)": [("rolling", "table")],
    "rolling wrench, V along an axis": [("rolling", "wrench-axis")],
    "rolling wrench, V skewed to the patch / varying contact": [("rolling", "wrench-skewed"),
                                                                ("rolling", "wrench-varying")],
}
# scenes table, M4F rows: row label → (cycles.csv key, simulated seconds per counted call)
SCENES = {
    "tippe top, `Simplified`": (("scene", "tippe_top_8s"), 8.0),
    "rattleback, `Best` (stalls": (("scene", "rattleback_step"), 20e-6),
    "rattleback, creep `table` (": (("scene", "rattleback_rolling_step"), 1e-4),
    "ball sliding into rolling, `best`, step-aware": (("scene-step", "ball"), 5e-3),
    "tippe top, `best`, step-aware, both spheres": (("scene-step", "tippe-top-two-contacts"), 2e-3),
    "rattleback, `best`, step-aware": (("scene-step", "rattleback"), 2e-3),
    "rattleback, creep `table`, step-aware": (("scene-step", "rattleback-table"), 1e-3),
    "ball bearing 209, creep `table`, step-aware": (("scene-step", "bearing"), 40e-6),
}


def recorded():
    insns, cycles = {}, {}
    for row in csv.DictReader((root / "bench-results/qemu.csv").open()):
        if row["precision"] == "f32":
            insns[(row["stage"], row["method"])] = int(row["insns"])
    for row in csv.DictReader((root / "bench-results/cycles.csv").open()):
        if row["precision"] == "f32":
            cycles[(row["stage"], row["method"])] = float(row["cycles_mid"])
    return insns, cycles


def rows(text):
    """{first cell: [cells]} of every table row of the README."""
    out = {}
    for line in text.splitlines():
        if line.startswith("| ") and not line.startswith("|---"):
            cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
            out[cells[0]] = cells
    return out


def find(table, label):
    hits = [k for k in table if k.startswith(label)]
    if len(hits) != 1:
        sys.exit(f"README.md: {len(hits)} headline rows start with {label!r} (rename it in {__file__})")
    return table[hits[0]]


def shown(cell):
    """The numbers of a cell ("1,593 / 2,094", "**0.29** (8 s in …)", "2.41"), as written."""
    return re.findall(r"\d[\d,]*(?:\.\d+)?", cell.replace("**", ""))


def same(text, value):
    """Whether `value` rounds to the README's `text` (its own number of decimals)."""
    digits = len(text.split(".")[1]) if "." in text else 0
    return abs(float(text.replace(",", "")) - value) <= 0.5 * 10 ** -digits + 1e-12


def main():
    insns, cycles = recorded()
    table = rows((root / "README.md").read_text())
    checks = []
    for label, keys in HEADLINE.items():
        cells = find(table, label)
        counts = shown(cells[3])
        if len(counts) != len(keys):
            sys.exit(f"README.md {label!r}: {len(keys)} instruction counts expected, found {cells[3]!r}")
        for text, key in zip(counts, keys):
            checks.append((f"{label} — M4F instructions", text, insns[key]))
        if cells[4] != "—":
            for text, key in zip(shown(cells[4]), keys):
                checks.append((f"{label} — µs at 168 MHz", text, cycles[key] / MHZ))
    for label, (key, seconds) in SCENES.items():
        cells = find(table, label)
        factor = shown(cells[-1])[0]
        checks.append((f"{label} — M4F real-time factor", factor, cycles[key] / (MHZ * 1e6) / seconds))
    bad = [c for c in checks if not same(c[1], c[2])]
    for name, text, value in checks:
        if "--check" not in sys.argv:
            print(f"{'ok ' if same(text, value) else 'BAD'} {name}: README {text}, recorded {value:.6g}")
    if bad and "--check" in sys.argv:
        sys.exit("README.md headline figures differ from bench-results: " +
                 "; ".join(f"{n}: README {t}, recorded {v:.4g}" for n, t, v in bad))
    if "--check" in sys.argv:
        print(f"readme-figures: {len(checks)} figures as recorded")


if __name__ == "__main__":
    main()
