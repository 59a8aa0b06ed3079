#!/usr/bin/env python3
"""The user docs (README.md and the guide's chapters, docs/guide/src/*.md) as CI checks them.

    python3 tools/guide_blocks.py links            # every relative link and image resolves, and
                                                   # every file, example, bench and test a
                                                   # ```sh block names exists
    PY tools/guide_blocks.py run                   # every ```python block runs, every ```xml
                                                   # MuJoCo model loads and steps (PY: a venv with
                                                   # the contensou package, numpy and mujoco)

`links` needs the standard library only. A link is checked when it is relative (resolved from
the document's directory, anchors dropped) or points into this repository's web view
(https://github.com/contensou/contensou/blob/main/<path>, raw.githubusercontent.com/...): the
file must exist. So is each mdBook `{{#include PATH[:ANCHOR]}}`: PATH must exist and hold the
`ANCHOR: name` / `ANCHOR_END: name` pair. External links are not fetched. The ```sh blocks
(commands, run by CI elsewhere or too long for it) are checked for what they name: repository paths
(tools/…, capi/…, python/…, mujoco/…, firmware/…) and `--example/--bench/--test/--bin NAME`.

`run` executes each Python block as its own script from the repository root (the blocks use
repository paths such as mujoco/models/tippe_top.xml); blocks that load the MuJoCo plugin
need mujoco/build/libcontensou_mujoco.so (mujoco/build.sh). Each ```xml block that is a whole
model (`<mujoco`) is loaded with the plugin and stepped 100 times. The Rust blocks are
doc-tests (src/lib.rs) and the C blocks are compiled and run by capi/build.sh.
"""

import re
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs/guide/src").glob("*.md"))]
REPO_URLS = (
    "https://github.com/contensou/contensou/blob/main/",
    "https://github.com/contensou/contensou/tree/main/",
    "https://raw.githubusercontent.com/contensou/contensou/main/",
)
LINK = re.compile(r"!?\[[^\]]*\]\(([^)\s]+)\)")
INCLUDE = re.compile(r"\{\{#include\s+([^}:\s]+)(?::([\w-]+))?\s*\}\}")
FENCE = re.compile(r"^```(\w*)\s*$")


def blocks(text):
    """(language, first line number, code) of each fenced block."""
    out, lang, start, lines = [], None, 0, []
    for n, line in enumerate(text.splitlines(), 1):
        m = FENCE.match(line)
        if lang is None and m:
            lang, start, lines = m.group(1) or "text", n + 1, []
        elif lang is not None and line.strip() == "```":
            out.append((lang, start, "\n".join(lines) + "\n"))
            lang = None
        elif lang is not None:
            lines.append(line)
    return out


def prose(text):
    """The document without its fenced blocks (links inside code are not links)."""
    keep, inside = [], False
    for line in text.splitlines():
        if FENCE.match(line) or (inside and line.strip() == "```"):
            inside = not inside
            continue
        if not inside:
            keep.append(line)
    return "\n".join(keep)


def named_targets():
    """The --example/--bench/--test/--bin names Cargo.toml and the tree define."""
    names = {"example": set(), "bench": set(), "test": set(), "bin": {"contact_eval"}}
    for f in (ROOT / "examples").iterdir():
        names["example"].add(f.stem)
    for f in (ROOT / "benches").iterdir():
        names["bench"].add(f.stem)
    kind = None
    for line in (ROOT / "Cargo.toml").read_text().splitlines():
        m = re.match(r"^\[\[(test|bench|example|bin)\]\]", line)
        if m:
            kind = m.group(1)
        m = re.match(r'^name = "([^"]+)"', line)
        if m and kind:
            names[kind].add(m.group(1))
    return names


def check_commands(doc, names):
    """Broken names in the document's ```sh blocks."""
    bad = []
    for lang, line, code in blocks(doc.read_text()):
        if lang not in ("sh", "bash", "console"):
            continue
        for path in re.findall(r"(?<![\w./-])((?:tools|capi|python|mujoco|firmware)/[\w./-]*\w)", code):
            if not (ROOT / path).exists() and not path.startswith(("capi/target", "mujoco/build")):
                bad.append(f"{doc.relative_to(ROOT)}:{line}: {path}")
        for kind, name in re.findall(r"--(example|bench|test|bin) ([\w-]+)", code):
            if name not in names[kind]:
                bad.append(f"{doc.relative_to(ROOT)}:{line}: --{kind} {name}")
    return bad


def check_links():
    bad, count = [], 0
    names = named_targets()
    for doc in DOCS:
        for target in LINK.findall(prose(doc.read_text())):
            path = None
            for url in REPO_URLS:
                if target.startswith(url):
                    path = ROOT / target[len(url):]
            if path is None:
                if re.match(r"^[a-z]+:", target) or target.startswith("#"):
                    continue
                path = doc.parent / target
            path = Path(str(path).split("#")[0])
            count += 1
            if not path.exists():
                bad.append(f"{doc.relative_to(ROOT)}: {target}")
        for target, anchor in INCLUDE.findall(prose(doc.read_text())):
            path = doc.parent / target
            count += 1
            if not path.exists():
                bad.append(f"{doc.relative_to(ROOT)}: include {target}")
            elif anchor and not all(
                re.search(rf"{kind}:\s*{re.escape(anchor)}\b", path.read_text())
                for kind in ("ANCHOR", "ANCHOR_END")
            ):
                bad.append(f"{doc.relative_to(ROOT)}: include {target}:{anchor} (no such anchor pair)")
        bad += check_commands(doc, names)
    for b in bad:
        print(f"broken link: {b}", file=sys.stderr)
    print(f"guide links: {count} links and the sh blocks' names checked in {len(DOCS)} documents, {len(bad)} broken")
    return 1 if bad else 0


XML_CHECK = """
import sys, mujoco
mujoco.mj_loadPluginLibrary("mujoco/build/libcontensou_mujoco.so")
m = mujoco.MjModel.from_xml_path(sys.argv[1])
d = mujoco.MjData(m)
if m.nkey:
    mujoco.mj_resetDataKeyframe(m, d, 0)
mujoco.mj_step(m, d, 100)
"""


def run_blocks():
    failed, ran = 0, 0
    with tempfile.TemporaryDirectory() as tmp:
        for doc in DOCS:
            for lang, line, code in blocks(doc.read_text()):
                where = f"{doc.relative_to(ROOT)}:{line}"
                if lang == "python":
                    cmd = [sys.executable, "-c", code]
                elif lang == "xml" and code.lstrip().startswith("<mujoco"):
                    model = Path(tmp) / f"model{ran}.xml"
                    model.write_text(code)
                    cmd = [sys.executable, "-c", XML_CHECK, str(model)]
                else:
                    continue
                ran += 1
                r = subprocess.run(cmd, cwd=ROOT, capture_output=True, text=True, timeout=600)
                status = "ok" if r.returncode == 0 else f"FAILED (exit {r.returncode})"
                print(f"{where} ({lang}): {status}")
                if r.returncode:
                    failed += 1
                    sys.stderr.write(r.stdout + r.stderr)
    print(f"guide blocks: {ran} run, {failed} failed")
    return 1 if failed or not ran else 0


if __name__ == "__main__":
    if sys.argv[1:] == ["links"]:
        sys.exit(check_links())
    if sys.argv[1:] == ["run"]:
        sys.exit(run_blocks())
    print(__doc__, file=sys.stderr)
    sys.exit(2)
