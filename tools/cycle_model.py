#!/usr/bin/env python3
"""Cortex-M4F cycle estimates from the executed instruction mix of every QEMU benchmark.

Runs one firmware ELF under QEMU with the rig's runner (tools/qemu-bench.sh passes it) plus

    -d exec,nochain -dfilter <.text range> -trace memory_region_ops_read -D <fifo>

reads the log from a FIFO while QEMU runs (nothing is written to disk), rebuilds the sequence of
executed instructions, cuts it at the TIM2->CNT reads the harness makes around every measured
call, and applies the timing model below to each measured region. The firmware's own output
(its stdout: OVERHEAD / BENCH / DETAIL lines) names the regions: the firmware prints a row
after measuring it (a semihosting BKPT in the trace), so a row's regions are the last `inputs=`
regions before a print, and their counts must give the row's DETAIL total, min and max.

Checks (exit status 1 if any fails): every region's traced instruction count equals the TIM2
difference minus the empty-region overhead, every row's traced total equals its DETAIL total,
and every executed block's successor is consistent with the disassembly.

Output, one line per BENCH row, in the firmware's order:
    stage,method,precision,insns,cycles_lo,cycles_mid,cycles_hi       (--csv, appended rows)
and the per-row executed mix (--mix); with --profile, one row's executed instructions per call by
address (a diagnosis: tools/profile_row.py maps them to source lines).

Executed instructions without plugins. QEMU 7.2's `-d exec,nochain` logs every translation block
(TB) it starts; `-singlestep` makes every TB one instruction (the brief's method: 7x more log
lines). By default the blocks are expanded from the disassembly instead: a TB runs from its
start to the first instruction that ends a TB (any write of the PC, BKPT/SVC/UDF, barriers,
ISB, MSR/CPS/VMSR), to a 1 KiB page end, to 512 instructions, or to the count in its cflags (set by
QEMU for icount-limited and I/O blocks). `cpu_io_recompile: rewound ... to X` means the block
ran up to X only; `Stopped execution of TB chain before` means the block logged just before it
did not run. `--singlestep` runs the one-instruction-per-TB way and gives the same result
(recorded in bench-results/cycles.md).

Timing model (ARM Cortex-M4 TRM, r0p1, table 3-1 and the FPU table 7-1; zero wait states):
  - data processing, MUL/MLA/MLS, long multiplies, CLZ, bit field, IT, NOP: 1
  - UDIV/SDIV: 2..12 (early termination, data dependent): lo 2, mid 7, hi 12
  - LDR*/STR* (single, incl. VLDR/VSTR): 2; 1 when the previous executed instruction was a
    single load/store (address and data phases pipeline), unless the previous was a load whose
    destination is this access's base or index register
  - LDRD/STRD 1+2; LDM/STM/PUSH/POP 1+N; VLDM/VSTM/VPUSH/VPOP 1+N, N = 32-bit words
  - taken branch B/BL/BX/BLX/CBZ/CBNZ 1+P; not-taken conditional 1; POP/LDM with PC 1+N+P;
    LDR PC 2+P; TBB/TBH 2+P; MOV/ADD PC 1+P;  P = 1 / 2 / 3 gives cycles_lo / _mid / _hi
  - VFP: VADD/VSUB/VMUL/VNMUL/VABS/VNEG/VCMP/VCVT/VMOV/VMRS/VMSR 1, VMOV of two core
    registers 2, VMLA/VMLS/VNMLA/VNMLS/VFMA/VFMS/VFNMA/VFNMS 3, VDIV.F32/VSQRT.F32 14.
Not modelled: flash wait states (an STM32F4 at 168 MHz has 5; the ART accelerator's prefetch
and 1 KiB instruction cache hide them in loops but not on cold or branchy code), bus contention,
the write buffer, integer instructions overlapping a VDIV/VSQRT, IT folding, and
condition-failed instructions (counted as executed).
"""

import argparse
import collections
import fcntl
import os
import re
import subprocess
import sys
import tempfile

CONDS = {"eq", "ne", "cs", "hs", "cc", "lo", "mi", "pl", "vs", "vc", "hi", "ls", "ge", "lt",
         "gt", "le", "al"}
PAGE = 1024
MAX_TB = 512
TIM2_CNT = 0x40000024

# Instruction classes of the mix (index, name).
CLASSES = ["int", "mul", "div", "ldst", "ldst_multi", "branch", "fp", "fp_mac", "fp_div",
           "fp_sqrt", "fp_ldst", "fp_multi"]
C = {name: i for i, name in enumerate(CLASSES)}

FP_MAC = {"vmla", "vmls", "vnmla", "vnmls", "vfma", "vfms", "vfnma", "vfnms"}
LD_SINGLE = {"ldr", "ldrb", "ldrh", "ldrsb", "ldrsh", "ldrt", "ldrbt", "ldrht", "ldrsbt",
             "ldrsht", "ldrex", "ldrexb", "ldrexh"}
ST_SINGLE = {"str", "strb", "strh", "strt", "strbt", "strht", "strex", "strexb", "strexh"}
MULS = {"mul", "muls", "mla", "mls", "umull", "smull", "umlal", "smlal", "umaal", "smulbb",
        "smulbt", "smultb", "smultt", "smmul", "smmla", "smlabb"}
TB_ENDERS = {"bkpt", "svc", "udf", "wfi", "wfe", "sev", "isb", "cpsid", "cpsie",
             "msr", "vmsr"}
REG = re.compile(r"\b(r1[0-5]|r[0-9]|sl|fp|ip|sp|lr|pc)\b")


class Insn:
    __slots__ = ("addr", "size", "mnem", "ops", "cls", "base", "ls", "is_ld", "dest",
                 "addr_regs", "cti", "cond", "target", "refill", "taken_extra", "ender")


def reglist_words(ops):
    """Number of 32-bit words moved by a {...} register list (d registers count 2)."""
    inner = ops[ops.index("{") + 1:ops.index("}")]
    words = 0
    for part in inner.split(","):
        part = part.strip()
        if "-" in part:
            a, b = part.split("-")
            n = int(b.strip()[1:]) - int(a.strip()[1:]) + 1
            words += n * (2 if a.strip()[0] == "d" else 1)
        else:
            words += 2 if part[0] == "d" else 1
    return words


def classify(ins, in_it):
    """Fills the timing fields of one decoded instruction."""
    m = ins.mnem
    for suf in (".n", ".w"):
        if m.endswith(suf):
            m = m[:-2]
    fp = m.startswith("v")
    if fp:
        m = m.split(".")[0]
    cond = in_it
    # Conditional suffix (objdump prints it inside IT blocks, and on b<cond>).
    base = m
    if m.startswith("b") and m[1:] in CONDS:
        base, cond = "b", True
    elif in_it and len(m) > 2 and m[-2:] in CONDS and m[:-2]:
        base = m[:-2]
    ops = ins.ops
    ins.cls, ins.base, ins.ls, ins.is_ld, ins.dest, ins.addr_regs = C["int"], 1, False, False, (), ()
    ins.cti, ins.cond, ins.target, ins.refill, ins.taken_extra = False, cond, None, False, 0
    ins.ender = base in TB_ENDERS
    dest_pc = ops.startswith("pc")

    def target():
        mt = re.match(r"([0-9a-f]+)\s*<", ops.split(",")[-1].strip())
        return int(mt.group(1), 16) if mt else None

    if base in ("b", "bl"):
        ins.cls, ins.cti, ins.target, ins.refill = C["branch"], True, target(), True
    elif base in ("bx", "blx"):
        ins.cls, ins.cti, ins.refill = C["branch"], True, True
        if base == "blx" and "<" in ops:
            ins.target = target()
    elif base in ("cbz", "cbnz"):
        ins.cls, ins.cti, ins.cond, ins.target, ins.refill = C["branch"], True, True, target(), True
    elif base in ("tbb", "tbh"):
        ins.cls, ins.cti, ins.base, ins.refill = C["branch"], True, 2, True
    elif fp:
        if base == "vdiv":
            ins.cls, ins.base = C["fp_div"], 14
        elif base == "vsqrt":
            ins.cls, ins.base = C["fp_sqrt"], 14
        elif base in FP_MAC:
            ins.cls, ins.base = C["fp_mac"], 3
        elif base in ("vldr", "vstr"):
            ins.cls, ins.base, ins.ls, ins.is_ld = C["fp_ldst"], 2, True, False
            ins.addr_regs = tuple(REG.findall(ops[ops.index("["):])) if "[" in ops else ()
        elif base in ("vpush", "vpop") or base.startswith("vldm") or base.startswith("vstm"):
            ins.cls, ins.base = C["fp_multi"], 1 + reglist_words(ops)
        elif base == "vmov":
            core = [r for r in (o.strip() for o in ops.split(",")) if REG.fullmatch(r)]
            ins.cls, ins.base = C["fp"], 2 if len(core) == 2 else 1
        else:
            ins.cls = C["fp"]
    elif base in LD_SINGLE or base in ST_SINGLE:
        ins.cls, ins.base, ins.ls = C["ldst"], 2, True
        ins.is_ld = base in LD_SINGLE
        if "[" in ops:
            ins.addr_regs = tuple(REG.findall(ops[ops.index("["):]))
        if ins.is_ld:
            ins.dest = (ops.split(",")[0].strip(),)
        if ins.is_ld and dest_pc:
            ins.cls, ins.ls, ins.cti, ins.refill = C["branch"], False, True, True
    elif base in ("ldrd", "strd"):
        ins.cls, ins.base = C["ldst_multi"], 3
    elif base in ("push", "pop") or base.startswith("ldm") or base.startswith("stm"):
        ins.cls, ins.base = C["ldst_multi"], 1 + reglist_words(ops)
        if base != "push" and not base.startswith("stm") and re.search(r"\bpc\b", ops):
            ins.cti, ins.refill = True, True
    elif base in ("udiv", "sdiv"):
        ins.cls, ins.base = C["div"], 2
    elif base in MULS:
        ins.cls = C["mul"]
    elif base in ("mov", "add") and dest_pc:
        ins.cls, ins.cti, ins.refill = C["branch"], True, True
    return ins


def disassemble(elf, objdump):
    """addr -> Insn for every instruction of the ELF's code."""
    out = subprocess.run([objdump, "-d", elf], check=True, capture_output=True, text=True).stdout
    line_re = re.compile(r"^\s*([0-9a-f]+):\t([0-9a-f]{4}(?: [0-9a-f]{4})?) *\t(\S+)(?:\t(.*))?$")
    insns = {}
    it_left = 0
    for line in out.splitlines():
        mt = line_re.match(line)
        if not mt:
            continue
        mnem = mt.group(3)
        if mnem.startswith("."):
            it_left = 0
            continue
        ins = Insn()
        ins.addr = int(mt.group(1), 16)
        ins.size = 4 if " " in mt.group(2) else 2
        ins.mnem = mnem
        ins.ops = (mt.group(4) or "").split("\t@")[0].split(";")[0].strip()
        in_it = it_left > 0
        if in_it:
            it_left -= 1
        classify(ins, in_it)
        if re.fullmatch(r"it[te]{0,3}", mnem):
            it_left = len(mnem) - 1
        insns[ins.addr] = ins
    return insns


class Block:
    """One executed TB expanded to instructions, with its static cost."""
    __slots__ = ("n", "base", "refills_static", "divs", "first_ls", "first_regs", "first_cls",
                 "last", "fall", "mix_n", "mix_c", "ok", "bkpt", "addrs")


def build_block(insns, start, count, end_at):
    seq = []
    a = start
    page_end = (start // PAGE + 1) * PAGE
    while True:
        if end_at is not None and a == end_at:
            break
        ins = insns.get(a)
        if ins is None:
            break
        seq.append(ins)
        a += ins.size
        if ins.cti or ins.ender or (count and len(seq) == count) or len(seq) >= MAX_TB:
            break
        if a >= page_end or (a + 2 >= page_end and insns.get(a) is not None
                             and insns[a].size == 4 and a + 4 > page_end):
            break
    blk = Block()
    blk.addrs = [ins.addr for ins in seq]
    blk.ok = bool(seq) or end_at == start
    blk.n = len(seq)
    blk.mix_n = [0] * len(CLASSES)
    blk.mix_c = [0] * len(CLASSES)
    base = divs = 0
    prev = None
    for ins in seq:
        c = ins.base
        if ins.ls and prev is not None and prev.ls and not (prev.is_ld and set(prev.dest) & set(ins.addr_regs)):
            c -= 1
        if ins.cls == C["div"]:
            divs += 1
        if ins.cti and not ins.cond:
            pass  # the refill is added per execution (taken)
        base += c
        blk.mix_n[ins.cls] += 1
        blk.mix_c[ins.cls] += c
        prev = ins
    blk.base, blk.divs = base, divs
    blk.first_ls = bool(seq) and seq[0].ls
    blk.first_regs = set(seq[0].addr_regs) if seq else set()
    blk.first_cls = seq[0].cls if seq else 0
    blk.last = seq[-1] if seq else None
    blk.fall = a
    blk.refills_static = 0
    blk.bkpt = bool(seq) and seq[-1].mnem == "bkpt"  # a semihosting call: the firmware prints
    return blk


def run_trace(args, insns, text_lo, text_hi, singlestep):
    """Runs QEMU with the exec log into a FIFO; returns (windows, reads, stdout, stats)."""
    tmp = tempfile.mkdtemp(prefix="cycles-")
    fifo = os.path.join(tmp, "exec.log")
    os.mkfifo(fifo)
    cmd = list(args.runner) + (["-singlestep"] if singlestep else []) + [
        "-d", "exec,nochain", "-dfilter", "0x%x..0x%x" % (text_lo, text_hi - 1),
        "-trace", "memory_region_ops_read", "-D", fifo, "-kernel", args.elf]
    outf = open(os.path.join(tmp, "stdout"), "w+b")
    proc = subprocess.Popen(cmd, stdout=outf, stderr=subprocess.PIPE)
    try:
        fd = os.open(fifo, os.O_RDONLY)
        try:
            fcntl.fcntl(fd, 1031, 1 << 20)  # F_SETPIPE_SZ: fewer wake-ups of QEMU
        except OSError:
            pass
        log = os.fdopen(fd, "rb", buffering=1 << 20)
        result = consume(log, insns)
        log.close()
    finally:
        err = proc.communicate()[1]
        os.unlink(fifo)
    if proc.returncode != 0:
        sys.stderr.buffer.write(err)
        sys.exit("cycle_model: QEMU exited with %d" % proc.returncode)
    outf.seek(0)
    stdout = outf.read().decode().replace("\r", "")
    outf.close()
    os.unlink(os.path.join(tmp, "stdout"))
    os.rmdir(tmp)
    return result, stdout


def consume(log, insns):
    cache = {}
    # Segment state: even segments lie between a pair of counter reads (measured regions).
    # per region: [insns, base, refills, divs, tb_counts{key: n}, taken, pipe_fix{cls: n}, group]
    windows = []
    group = 0  # regions between two semihosting calls (prints) form one group
    reads = []
    seg = -1  # before the first read
    cur = None
    pending = None  # (pc, count)
    prev_ls, prev_ld_dest = False, ()
    stats = collections.Counter()
    bad = []

    def note_bad(what):
        # Outside the measured regions an inconsistency only blurs the pipelining state; inside
        # one it is fatal.
        where = "in_region" if cur is not None else "outside"
        stats["bad_successor_" + where] += 1
        if len(bad) < 10:
            bad.append(where + ": " + what)

    def finalize(pc, count, end_at, next_pc):
        nonlocal prev_ls, prev_ld_dest, group
        key = (pc, count, end_at)
        blk = cache.get(key)
        if blk is None:
            blk = cache[key] = build_block(insns, pc, count, end_at)
        if not blk.ok:
            stats["unknown_pc"] += 1
            if len(bad) < 10:
                bad.append("no instruction at 0x%x" % pc)
            prev_ls = False
            return
        if blk.n == 0:
            return
        if blk.bkpt and windows and windows[-1][7] == group:
            group += 1
        cyc = blk.base
        pipe = False
        if blk.first_ls and prev_ls and not (set(prev_ld_dest) & blk.first_regs):
            cyc -= 1
            pipe = True
        last = blk.last
        taken = False
        if last.cti:
            if next_pc is None:
                taken = not last.cond
            else:
                taken = (not last.cond) or next_pc != blk.fall
                if taken and last.target is not None and next_pc != last.target:
                    note_bad("0x%x -> 0x%x, target 0x%x" % (last.addr, next_pc, last.target))
        elif next_pc is not None and next_pc != blk.fall:
            note_bad("block 0x%x ends 0x%x, next 0x%x" % (pc, blk.fall, next_pc))
        prev_ls = last.ls and not taken
        prev_ld_dest = last.dest if last.is_ld else ()
        if cur is not None:
            cur[0] += blk.n
            cur[1] += cyc
            cur[3] += blk.divs
            tbc = cur[4]
            tbc[key] = tbc.get(key, 0) + 1
            if taken:
                cur[2] += 1
                cur[5] += 1
            if pipe:
                cur[6][blk.first_cls] = cur[6].get(blk.first_cls, 0) + 1

    for raw in log:
        c0 = raw[:1]
        if c0 == b"T":  # Trace 0: 0x7f.. [cs_base/pc/flags/cflags] symbol
            b = raw.index(b"[")
            pc = int(raw[b + 10:b + 18], 16)
            count = int(raw[b + 28:b + 36], 16) & 0x1FF
            if pending is not None:
                finalize(pending[0], pending[1], None, pc)
            pending = (pc, count)
            stats["tb"] += 1
        elif c0 == b"m":  # memory_region_ops_read cpu 0 mr 0x.. addr 0x.. value 0x.. size 4 ...
            parts = raw.split()
            addr = int(parts[6], 16)
            if addr != TIM2_CNT:
                continue
            value = int(parts[8], 16)
            if pending is None or pending[1] != 1:
                sys.exit("cycle_model: counter read outside a one-instruction I/O block")
            # The read instruction itself belongs to no region.
            if cur is not None:
                windows.append(cur)
            pending = None
            prev_ls, prev_ld_dest = True, ()
            seg += 1
            reads.append(value)
            cur = [0, 0, 0, 0, {}, 0, {}, group] if seg % 2 == 0 else None
        elif c0 == b"c":  # cpu_io_recompile: rewound execution of TB to XXXXXXXX
            x = int(raw.split()[-1], 16)
            if pending is not None:
                finalize(pending[0], pending[1], x, x)
            pending = None
            stats["io_recompile"] += 1
        elif c0 == b"S":  # Stopped execution of TB chain before ...: pending did not run
            pending = None
            stats["stopped"] += 1
    if pending is not None:
        finalize(pending[0], pending[1], None, None)
    return windows, reads, stats, bad, cache


def parse_run(stdout):
    overhead = None
    rows = []
    expect = {}
    for line in stdout.splitlines():
        f = line.split()
        if not f:
            continue
        if f[0] == "OVERHEAD":
            overhead = int(f[-1].split("=")[1])  # "OVERHEAD [name] insns=N"
        elif f[0] == "BENCH":
            rows.append({"key": (f[1], f[2], f[3]), "insns": int(f[4].split("=")[1])})
        elif f[0] == "DETAIL":
            kv = dict(x.split("=") for x in f[4:])
            assert rows and rows[-1]["key"] == (f[1], f[2], f[3])
            rows[-1]["inputs"] = int(kv["inputs"])
            rows[-1]["total"] = int(kv["total"])
            rows[-1]["min"] = int(kv["min"])
            rows[-1]["max"] = int(kv["max"])
        elif f[0] == "EXPECT":  # EXPECT stage method precision lo mid hi (validation cases)
            expect[(f[1], f[2], f[3])] = [int(v) for v in f[4:7]]
    return overhead, rows, expect


def rounded_avg(total, n):
    return (total + n // 2) // n


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--elf", required=True)
    ap.add_argument("--objdump", default="arm-none-eabi-objdump")
    ap.add_argument("--csv", help="append stage,method,precision,insns,cycles_lo,_mid,_hi rows")
    ap.add_argument("--mix", help="append the per-row executed mix (per call) as CSV rows")
    ap.add_argument("--mix-header", action="store_true", help="write the mix header first")
    ap.add_argument("--stdout", help="write the firmware's output here")
    ap.add_argument("--check", help="validation: write EXPECT cases (cycles minus the stage's "
                    "`empty` row vs the stated values) as CSV here; fail on any difference")
    ap.add_argument("--profile", metavar="STAGE,METHOD,PRECISION=FILE", action="append", default=[],
                    help="diagnosis: write that row's executed instructions per call by address "
                         "(lines addr,count) to FILE (tools/profile_row.py reads them)")
    ap.add_argument("--singlestep", action="store_true", help="one instruction per TB (slow)")
    ap.add_argument("runner", nargs=argparse.REMAINDER, help="-- qemu-system-arm ... (no -kernel)")
    args = ap.parse_args()
    if args.runner and args.runner[0] == "--":
        args.runner = args.runner[1:]
    if not args.runner:
        ap.error("give the QEMU command after --")

    insns = disassemble(args.elf, args.objdump)
    hdr = subprocess.run(["arm-none-eabi-size", "-A", args.elf], check=True, capture_output=True,
                         text=True).stdout
    text = [l.split() for l in hdr.splitlines() if l.startswith(".text ")][0]
    text_lo, text_hi = int(text[2]), int(text[2]) + int(text[1])

    (windows, reads, stats, bad, cache), stdout = run_trace(args, insns, text_lo, text_hi,
                                                            args.singlestep)
    if args.stdout:
        with open(args.stdout, "w") as f:
            f.write(stdout)
    overhead, rows, expect = parse_run(stdout)
    fail = []
    if stats["bad_successor_outside"]:
        print("cycle_model: warning: %d inconsistent blocks outside the measured regions: %s"
              % (stats["bad_successor_outside"], bad[:3]), file=sys.stderr)
    if stats["bad_successor_in_region"] or stats["unknown_pc"]:
        fail.append("inconsistent trace: %s; first: %s" % (dict(stats), bad[:5]))
    # Each region: traced instructions == TIM2 difference - overhead.
    for i, w in enumerate(windows):
        delta = reads[2 * i + 1] - reads[2 * i]
        if w[0] != delta - overhead:
            fail.append("region %d: traced %d instructions, TIM2 says %d" % (i, w[0], delta - overhead))
            break
    # Regions → rows: the firmware prints a row after measuring it, so a row's regions are the
    # last `inputs` regions before a print; regions measured without printing (an input search)
    # share the group and are skipped. A group matches a row when those regions' counts give
    # the row's DETAIL total, min and max.
    groups = collections.defaultdict(list)
    for w in windows:
        groups[w[7]].append(w)
    groups = [groups[g] for g in sorted(groups)]
    gi, skipped = 0, 0
    assigned = []
    for r in rows:
        n = r["inputs"]
        while gi < len(groups):
            ws = groups[gi][-n:] if n else []
            gi += 1
            counts = [w[0] for w in ws]
            if len(ws) == n and sum(counts) == r["total"] and (
                    not counts or (min(counts), max(counts)) == (r["min"], r["max"])):
                assigned.append(ws)
                break
            skipped += 1
        else:
            fail.append("%s: no traced regions match its DETAIL line" % ",".join(r["key"]))
            assigned.append([])
    out_csv, out_mix = [], []
    exact = {}  # key -> (insns, [lo, mid, hi]) per call, unrounded
    for r, ws in zip(rows, assigned):
        n = max(r["inputs"], 1)
        tot = sum(w[0] for w in ws)
        if tot != r["total"]:
            fail.append("%s: traced %d instructions, DETAIL total %d" % (",".join(r["key"]), tot, r["total"]))
        base = sum(w[1] for w in ws)
        refills = sum(w[2] for w in ws)
        divs = sum(w[3] for w in ws)
        cyc = [base + p * refills + extra * divs for p, extra in ((1, 0), (2, 5), (3, 10))]
        avg = [rounded_avg(c, n) for c in cyc]
        exact[r["key"]] = (tot / n, [c / n for c in cyc])
        ins_avg = rounded_avg(tot, n)
        if ins_avg != r["insns"]:
            fail.append("%s: traced average %d, BENCH %d" % (",".join(r["key"]), ins_avg, r["insns"]))
        out_csv.append("%s,%d,%d,%d,%d" % (",".join(r["key"]), ins_avg, *avg))
        # Mix: per-class instructions and mid cycles per call.
        mix_n = [0] * len(CLASSES)
        mix_c = [0] * len(CLASSES)
        for w in ws:
            for key, k in w[4].items():
                blk = cache[key]
                for j in range(len(CLASSES)):
                    mix_n[j] += k * blk.mix_n[j]
                    mix_c[j] += k * blk.mix_c[j]
            for cls, k in w[6].items():
                mix_c[cls] -= k
        mix_c[C["branch"]] += 2 * refills
        mix_c[C["div"]] += 5 * divs
        taken = sum(w[5] for w in ws)
        out_mix.append("%s,%s,%s" % (",".join(r["key"]), "%.1f" % (taken / n),
                                     ",".join("%.1f,%.1f" % (mix_n[j] / n, mix_c[j] / n)
                                              for j in range(len(CLASSES)))))
    for spec in args.profile:
        row, path = spec.split("=", 1)
        key = tuple(row.split(","))
        per = collections.Counter()
        found = False
        for r, ws in zip(rows, assigned):
            if r["key"] != key:
                continue
            found = True
            n = max(r["inputs"], 1)
            for w in ws:
                for bkey, k in w[4].items():
                    for a in cache[bkey].addrs:
                        per[a] += k / n
        if not found:
            fail.append("--profile %s: no such row" % row)
        with open(path, "w") as f:
            f.write("".join("0x%x,%.4f\n" % (a, c) for a, c in sorted(per.items())))
    check = []
    for key, want in expect.items():
        floor = (key[0], "empty", key[2])
        if key not in exact or floor not in exact:
            fail.append("EXPECT %s: no such row or no `empty` row" % (key,))
            continue
        ins = exact[key][0] - exact[floor][0]
        got = [a - b for a, b in zip(exact[key][1], exact[floor][1])]
        ok = got == want
        check.append("%s,%g,%s,%s,%s" % (key[1], ins, ",".join("%g" % g for g in got),
                                         ",".join(map(str, want)), "ok" if ok else "DIFFERS"))
        if not ok:
            fail.append("EXPECT %s: model %s, stated %s" % (",".join(key), got, want))
    if args.check:
        with open(args.check, "w") as f:
            f.write("case,block_insns,cycles_lo,cycles_mid,cycles_hi,trm_lo,trm_mid,trm_hi,result\n")
            f.write("".join(l + "\n" for l in check))
    if fail:
        for f in fail:
            print("cycle_model: " + f, file=sys.stderr)
        sys.exit(1)
    if args.csv:
        with open(args.csv, "a") as f:
            f.write("".join(l + "\n" for l in out_csv))
    else:
        print("\n".join(out_csv))
    if args.mix:
        with open(args.mix, "a") as f:
            if args.mix_header:
                f.write("stage,method,precision,taken_branches,%s\n" % ",".join(
                    "%s_insns,%s_cycles" % (c, c) for c in CLASSES))
            f.write("".join(l + "\n" for l in out_mix))
    print("cycle_model: %s: %d regions (%d groups without a row), %d blocks logged (%d I/O "
          "rewinds, %d not run), 0 inconsistencies" % (
              os.path.basename(args.elf), len(windows), skipped, stats["tb"],
              stats["io_recompile"], stats["stopped"]), file=sys.stderr)


if __name__ == "__main__":
    main()
