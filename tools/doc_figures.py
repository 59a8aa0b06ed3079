#!/usr/bin/env python3
"""The docs' MCU figures against the recorded benchmarks, to the digits the docs show:

- README.md's two headline tables and the guide's "defaults at a glance" (model.md): every M4F
  instruction count, µs at 168 MHz and M4F real-time factor (rows found by the start of their
  first cell; a row the docs no longer have is an error: rename it here too);
- the guide's MCU table (docs/guide/src/mcu.md, the rows with a `stage,method` key): the
  instructions, the cycle model's mid (lo–hi), µs at 168 MHz and flash bytes.

Recorded: bench-results/qemu.csv, cycles.csv (the cycle model's mid estimate, `tools/qemu-bench.sh`
rewrites both), flash.csv (`tools/flash-bench.sh`) and, for the README's host ns column,
host-ns.csv (`tools/host-ns.sh`; CI checks the committed one: host times are not re-measured there). The docs' figures are hand-written; this
keeps them from going stale when the rigs are re-run.

    python3 tools/doc_figures.py          # print each figure: docs, recorded, ok
    python3 tools/doc_figures.py --check  # fail listing every figure that differs
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
# the guide's model chapter, "the defaults at a glance"
MODEL = {
    "K, E, B, D": [("elliptic", "table")],
    "patch a, b, N per step, geometry fixed": [("hertz", "per_step")],
    "patch per step from P/Q": [("hertz", "table_each_step")],
    "friction, per contact": [("friction", "best")],
    "full wrench, geometry fixed": [("wrench", "fixed-best")],
    "full wrench, geometry per step": [("wrench", "table_each_step-best")],
    "rolling creep, along an axis": [("rolling", "table")],
    "rolling wrench, V along an axis": [("rolling", "wrench-axis")],
    "rolling wrench, V skewed / varying contact": [("rolling", "wrench-skewed"), ("rolling", "wrench-varying")],
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
    insns, cycles, flash = {}, {}, {}
    for row in csv.DictReader((root / "bench-results/qemu.csv").open()):
        if row["precision"] == "f32":
            insns[(row["stage"], row["method"])] = int(row["insns"])
    for row in csv.DictReader((root / "bench-results/cycles.csv").open()):
        if row["precision"] == "f32":
            cycles[(row["stage"], row["method"])] = tuple(
                float(row[k]) for k in ("cycles_mid", "cycles_lo", "cycles_hi"))
    for row in csv.DictReader((root / "bench-results/flash.csv").open()):
        if row["precision"] == "f32":
            flash[(row["stage"], row["method"])] = int(row["bytes"])
    host = {}
    for row in csv.DictReader((root / "bench-results/host-ns.csv").open()):
        if row["precision"] == "f32":
            host[(row["stage"], row["method"])] = float(row["ns"])
    return insns, cycles, flash, host


def rows(text):
    """{first cell: [cells]} of every table row of a markdown text, and its tables' header rows."""
    out, heads = {}, []
    lines = text.splitlines()
    for k, line in enumerate(lines):
        if line.startswith("| ") and not line.startswith("|---"):
            cells = [c.strip() for c in line.strip().strip("|").split(" | ")]
            if k + 1 < len(lines) and lines[k + 1].startswith("|---"):
                heads.append(cells)
            else:
                out[cells[0]] = cells
    return out, heads


def find(table, label, where):
    hits = [k for k in table if k.startswith(label)]
    if len(hits) != 1:
        sys.exit(f"{where}: {len(hits)} rows start with {label!r} (rename it in {__file__})")
    return table[hits[0]]


def labelled(where, mapping, insns, cycles, host=None):
    """Checks of a table whose rows are found by label: its `instructions` column (one count per
    key, "a / b"), its `µs at 168 MHz` column and, given `host`, its `host ns` column (f32, the
    fastest criterion sample of bench-results/host-ns.csv) (each unless —)."""
    table, heads = rows((root / where).read_text())
    head = next(h for h in heads if any("instructions" in c for c in h))
    ci = next(i for i, c in enumerate(head) if "instructions" in c)
    cu = next(i for i, c in enumerate(head) if c.startswith("µs at 168 MHz"))
    out = []
    for label, keys in mapping.items():
        cells = find(table, label, where)
        counts = shown(cells[ci])
        if len(counts) != len(keys):
            sys.exit(f"{where} {label!r}: {len(keys)} instruction counts expected, found {cells[ci]!r}")
        for text, key in zip(counts, keys):
            out.append((f"{where} {label} — M4F instructions", text, insns[key]))
        if cells[cu] != "—":
            for text, key in zip(shown(cells[cu]), keys):
                out.append((f"{where} {label} — µs at 168 MHz", text, cycles[key][0] / MHZ))
        ch = next((i for i, c in enumerate(head) if c == "host ns"), None)
        if host is not None and ch is not None and cells[ch] != "—":
            for text, key in zip(shown(cells[ch]), keys):
                out.append((f"{where} {label} — host ns", text, host[key]))
    return out


def shown(cell):
    """The numbers of a cell ("1,593 / 2,094", "**0.29** (8 s in …)", "2.41"), as written."""
    return re.findall(r"\d[\d,]*(?:\.\d+)?", cell.replace("**", ""))


def same(text, value):
    """Whether `value` rounds to the README's `text` (its own number of decimals)."""
    digits = len(text.split(".")[1]) if "." in text else 0
    return abs(float(text.replace(",", "")) - value) <= 0.5 * 10 ** -digits + 1e-12


def mcu_table(insns, cycles, flash):
    """The checks of the guide's MCU table: per `stage,method` row, instructions, cycles mid
    (lo–hi), µs (to the digits shown) and flash bytes (— where the probe has no key)."""
    out = []
    for line in (root / "docs/guide/src/mcu.md").read_text().splitlines():
        m = re.match(r"\| ([^|]+) \| `([a-z0-9_-]+),([a-z0-9_-]+)` \| ([^|]+) \| ([^|]+) \| ([^|]+) \| ([^|]+) \|$", line)
        if not m:
            continue
        what, key = m.group(1), (m.group(2), m.group(3))
        ins, cyc, us, fl = (m.group(k).strip() for k in range(4, 8))
        name = f"mcu.md {','.join(key)}"
        out.append((f"{name} — instructions", ins, insns[key]))
        mid, lo, hi = shown(cyc)
        out += [(f"{name} — cycles mid", mid, cycles[key][0]), (f"{name} — cycles lo", lo, cycles[key][1]),
                (f"{name} — cycles hi", hi, cycles[key][2])]
        # µs: to the significant digits shown (3: 0.393, 11.3, 115)
        out.append((f"{name} — µs at 168 MHz", us, cycles[key][0] / MHZ))
        if fl != "—":
            out.append((f"{name} — flash bytes", fl, flash[key]))
    if not out:
        sys.exit("docs/guide/src/mcu.md: no `stage,method` rows found")
    return out


def main():
    insns, cycles, flash, host = recorded()
    checks = labelled("README.md", HEADLINE, insns, cycles, host) + labelled("docs/guide/src/model.md", MODEL, insns, cycles)
    table, _ = rows((root / "README.md").read_text())
    for label, (key, seconds) in SCENES.items():
        cells = find(table, label, "README.md")
        factor = shown(cells[-1])[0]
        checks.append((f"{label} — M4F real-time factor", factor, cycles[key][0] / (MHZ * 1e6) / seconds))
    checks += mcu_table(insns, cycles, flash)
    bad = [c for c in checks if not same(c[1], c[2])]
    for name, text, value in checks:
        if "--check" not in sys.argv:
            print(f"{'ok ' if same(text, value) else 'BAD'} {name}: docs {text}, recorded {value:.6g}")
    if bad and "--check" in sys.argv:
        sys.exit("doc figures differ from bench-results: " +
                 "; ".join(f"{n}: docs {t}, recorded {v:.4g}" for n, t, v in bad))
    if "--check" in sys.argv:
        print(f"doc-figures: {len(checks)} figures as recorded")


if __name__ == "__main__":
    main()
