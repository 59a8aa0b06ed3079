#!/usr/bin/env python3
"""Where a QEMU benchmark row's instructions go, by source line: a diagnosis for cost work.

Runs the firmware under QEMU's exec log (tools/cycle_model.py --profile: the same trace the
cycle model reads, checked against TIM2), takes each named row's executed instructions per call
by address, and maps every address to the innermost frame of the crate's own source
(`arm-none-eabi-addr2line -i`, the release build's debug info; with LTO and inlining a line is
where the instruction's code comes from, not a call) or, outside the crate, to the function
(libm's `logf`, core's arithmetic). Writes a Markdown table: per location the instructions per
call of each row, the lines sorted by how much more the last row spends than the first.

    tools/profile_row.py --md bench-results/rolling-wrench-profile.md \\
        rolling,wrench-axis,f32 rolling,wrench-skewed,f32 rolling,wrench-varying,f32

Needs what tools/qemu-bench.sh needs (rustup, qemu-system-arm, binutils-arm-none-eabi). Builds
the firmware (cargo build --release --locked in firmware/) first. ≈ 1 min.
"""
import argparse
import collections
import pathlib
import subprocess
import sys
import tempfile

root = pathlib.Path(__file__).resolve().parent.parent
fw = root / "firmware"


def runner():
    """The QEMU command of firmware/.cargo/config.toml without its `timeout` and `-kernel`."""
    for line in (fw / ".cargo/config.toml").read_text().splitlines():
        if line.strip().startswith("runner"):
            cmd = line.split("=", 1)[1].strip().strip('"').split()
            if cmd[0] == "timeout":
                cmd = cmd[2:]
            return [c for c in cmd if c != "-kernel"]
    sys.exit("profile_row: no runner in firmware/.cargo/config.toml")


def strip_generics(path):
    """A path's parts without its generic arguments and closures."""
    depth, plain = 0, ""
    for ch in path:
        depth += ch == "<"
        if depth == 0:
            plain += ch
        depth -= ch == ">" and depth > 0
    return [p for p in plain.split("::") if p and not p.startswith("{")]


def short(fn):
    """A demangled function, short: `module::Type::method`, `<f32 as Real>::max`, `module::fn`."""
    if fn.startswith("<"):
        depth = 0
        for k, ch in enumerate(fn):
            depth += (ch == "<") - (ch == ">")
            if depth == 0:
                break
        inner, method = fn[1:k], strip_generics(fn[k + 1:])
        if " as " in inner:
            ty, tr = inner.split(" as ", 1)
            head = f"<{'::'.join(strip_generics(ty)[-1:])} as {'::'.join(strip_generics(tr)[-1:])}>"
        else:
            head = "::".join(strip_generics(inner)[-2:])
        return "::".join([head] + method[-1:])
    return "::".join(strip_generics(fn)[-3:]) or fn[:60]


def locate(elf, addrs):
    """address → (line, function): the innermost frame in the crate's src/ (`src/path:line`, the
    function it lies in), libm's function for libm's code, else the innermost function."""
    out = subprocess.run(["arm-none-eabi-addr2line", "-e", str(elf), "-i", "-f", "-C", "-a"]
                         + [hex(a) for a in addrs], check=True, capture_output=True, text=True).stdout
    src = str(root / "src") + "/"
    chains, cur = {}, None
    lines = out.splitlines()
    k = 0
    while k < len(lines):
        if lines[k].startswith("0x"):
            cur = int(lines[k], 16)
            chains[cur] = []
            k += 1
            continue
        chains[cur].append((lines[k], lines[k + 1] if k + 1 < len(lines) else "?"))
        k += 2
    loc = {}
    for a, chain in chains.items():
        inner = chain[0] if chain else ("?", "?")
        mine = [(f, l.split(" ")[0]) for f, l in chain if l.startswith(src)]
        if "/libm-" in inner[1]:
            name = "libm::" + short(inner[0]).split("::")[-1]
            loc[a] = (name, name)
        elif mine:
            loc[a] = ("src/" + mine[0][1][len(src):], short(mine[0][0]))
        else:
            loc[a] = (short(inner[0]), short(inner[0]))
    return loc


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("rows", nargs="+", help="STAGE,METHOD,PRECISION as in bench-results/qemu.csv")
    ap.add_argument("--md", help="write the table here (default: standard output)")
    ap.add_argument("--top", type=int, default=30, help="functions and lines shown (default 30 each)")
    args = ap.parse_args()
    subprocess.run(["cargo", "build", "--release", "--locked", "--quiet"], cwd=fw, check=True)
    elf = fw / "target/thumbv7em-none-eabihf/release/contensou-firmware"
    with tempfile.TemporaryDirectory() as tmp:
        files = [pathlib.Path(tmp) / f"p{i}.csv" for i in range(len(args.rows))]
        cmd = [sys.executable, str(root / "tools/cycle_model.py"), "--elf", str(elf), "--csv", "/dev/null"]
        for r, f in zip(args.rows, files):
            cmd += ["--profile", f"{r}={f}"]
        subprocess.run(cmd + ["--"] + runner(), check=True, stdout=subprocess.DEVNULL)
        per = [{int(a, 16): float(c) for a, c in (l.split(",") for l in f.read_text().splitlines())}
               for f in files]
    loc = locate(elf, sorted(set().union(*per)))
    names = [r.split(",")[1] for r in args.rows]
    out = [f"# Where the instructions go: {', '.join(args.rows)}\n",
           f"`tools/profile_row.py {' '.join(args.rows)}` (M4F f32 under QEMU, instructions per call, from the "
           "traced run tools/cycle_model.py checks against TIM2). Each executed instruction is put where its code "
           "comes from after inlining: the innermost frame in the crate's src/ (its line, and the function that "
           "line is in), libm's function for libm's code. Sorted by how much more the last row spends than the "
           "first. A snapshot for cost work, not checked by CI: rerun it after a change.\n"]
    for title, which, top in (("By function", 1, args.top), ("By line", 0, args.top)):
        agg = [collections.Counter() for _ in per]
        for p, acc in zip(per, agg):
            for a, c in p.items():
                acc[loc.get(a, ("?", "?"))[which]] += c
        keys = sorted(set().union(*agg), key=lambda k: (-(agg[-1][k] - agg[0][k]), -agg[-1][k], k))
        out += [f"## {title}\n", "| " + " | ".join(names) + " | where |", "|" + "---:|" * len(names) + "---|",
                "| " + " | ".join(f"**{sum(p.values()):.0f}**" for p in per) + " | total |"]
        for k in keys[:top]:
            out.append("| " + " | ".join(f"{a[k]:.1f}" for a in agg) + f" | `{k}` |")
        rest = [sum(a[k] for k in keys[top:]) for a in agg]
        if len(keys) > top:
            out.append("| " + " | ".join(f"{r:.1f}" for r in rest) + f" | the other {len(keys) - top} |")
        out.append("")
    text = "\n".join(out)
    if args.md:
        pathlib.Path(args.md).write_text(text)
    print(text)


if __name__ == "__main__":
    main()
