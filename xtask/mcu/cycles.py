#!/usr/bin/env python3
"""Static cycle ESTIMATE from an icount-plugin histogram (PC, exec count, disassembly).

usage: cycles.py HIST.tsv {m0plus|m4|rv32} [PIXELS] [NM.txt]

Costs are per ARM's Cortex-M0+ / Cortex-M4 TRM instruction timing tables, assuming
zero-wait-state memory (code and data), the M0+ single-cycle multiplier, and a
pipeline refill P=2 on the M4 for taken branches. rv32 is a generic single-issue in-order
5-stage core (SiFive E31-like): ALU/MUL 1, load 2 (a load-use bubble assumed every time),
store 1, DIV/REM 33, taken branch or jump 3, not-taken branch 1.
With NM.txt (`llvm-nm -n -S -C ELF`) it also prints where the instructions go, per function
(inlined code counts in the function it was inlined into). Not a simulator: real parts add flash
wait states (unless code runs from RAM/cache) and bus contention. Use it to compare
code variants, not as an absolute frame rate.
"""
import re
import sys

COND = "eq ne cs hs cc lo mi pl vs vc hi ls ge lt gt le".split()


def parse(path):
    rows = []
    for line in open(path):
        va, cnt, dis = line.rstrip("\n").split("\t", 2)
        dis = dis.strip()
        # QEMU's RISC-V disassembler prefixes the raw instruction word in hex.
        head, _, rest = dis.partition(" ")
        if rest and len(head) in (4, 8) and all(ch in "0123456789abcdef" for ch in head):
            dis = rest.strip()
        rows.append((int(va, 16), int(cnt), dis))
    rows.sort()
    return rows


def nregs(ops):
    m = re.search(r"\{([^}]*)\}", ops)
    if not m:
        return 1
    n = 0
    for part in m.group(1).split(","):
        part = part.strip()
        if "-" in part:  # r4-r7 style
            a, b = part.split("-")
            n += int(b.strip()[1:]) - int(a.strip()[1:]) + 1
        elif part:
            n += 1
    return n


def classify(mn):
    base = mn.split(".")[0]
    if base.startswith("c."):
        base = base[2:]
    if base in ("b",):
        return "b"
    if base in ("bl", "blx", "bx"):
        return base
    if base in ("cbz", "cbnz"):
        return "bcond"
    if base.startswith("b") and base[1:] in COND:
        return "bcond"
    if base.startswith("it"):
        return "it"
    if base in ("push", "pop", "stm", "ldm", "stmdb", "ldmia", "stmia", "ldmdb", "stmea", "ldmfd"):
        return "multi"
    if base in ("ldrd", "strd"):
        return "dual"
    if base.startswith("ldr") or base.startswith("str"):
        return "ls"
    if base in ("mul", "muls", "mla", "mls", "smull", "umull", "smlal", "umlal") or base.startswith("smla") or base.startswith("smul"):
        return "mul"
    if base in ("sdiv", "udiv"):
        return "div"
    if base.startswith("v"):
        return "vfp"
    return "alu"


RV_BRANCH = ("beq", "bne", "blt", "bge", "bltu", "bgeu", "beqz", "bnez", "blez", "bgez", "bltz", "bgtz", "bgt", "ble", "bgtu", "bleu")


def classify_rv(mn):
    base = mn[2:] if mn.startswith("c.") else mn
    if base in RV_BRANCH:
        return "bcond"
    if base in ("j", "jal", "jalr", "jr", "ret", "call", "tail"):
        return "b"
    if base in ("lw", "lh", "lhu", "lb", "lbu", "lwsp"):
        return "ld"
    if base in ("sw", "sh", "sb", "swsp"):
        return "st"
    if base in ("mul", "mulh", "mulhu", "mulhsu"):
        return "mul"
    if base in ("div", "divu", "rem", "remu"):
        return "div"
    return "alu"


def estimate(rows, core):
    P = 2  # M4 pipeline refill for taken branches (TRM: 1..3)
    counts = {va: c for va, c, _ in rows}
    addrs = [va for va, _, _ in rows]
    total_cyc = 0
    total_ins = 0
    mix = {}
    prev_ls = False
    for i, (va, c, dis) in enumerate(rows):
        if c == 0:
            continue
        mn, _, ops = dis.partition(" ")
        k = classify_rv(mn) if core == "rv32" else classify(mn)
        nxt = addrs[i + 1] if i + 1 < len(addrs) else None
        fall = counts.get(nxt, 0) if nxt is not None and nxt - va <= 4 else 0
        taken = max(c - fall, 0) if k == "bcond" else c
        if core == "rv32":
            cyc = {"alu": 1, "mul": 1, "ld": 2, "st": 1, "div": 33, "b": 3}.get(k)
            if k == "bcond":
                total_cyc += taken * 3 + (c - taken) * 1
                cyc = None
        elif core == "m0plus":
            cyc = {"alu": 1, "mul": 1, "ls": 2, "dual": 3, "div": 1, "vfp": 1, "it": 1}.get(k)
            if k == "multi":
                n = nregs(ops)
                cyc = 1 + n + (2 if mn.startswith("pop") and "pc" in ops else 0)
            elif k == "b":
                cyc = 2
            elif k == "bcond":
                total_cyc += taken * 2 + (c - taken) * 1
                cyc = None
            elif k in ("bl",):
                cyc = 3
            elif k in ("bx", "blx"):
                cyc = 2
        else:  # m4
            cyc = {"alu": 1, "mul": 1, "dual": 3, "div": 7, "it": 1}.get(k)
            if k == "ls":
                # neighbouring loads/stores pipeline: N+1 for N in a row
                cyc = 1 if prev_ls else 2
            elif k == "multi":
                n = nregs(ops)
                cyc = 1 + n + (P if mn.startswith("pop") and "pc" in ops else 0)
            elif k == "vfp":
                cyc = 14 if mn.startswith(("vdiv", "vsqrt")) else (3 if mn.startswith(("vmla", "vmls", "vfma", "vfms")) else (2 if mn.startswith(("vldr", "vstr")) else 1))
            elif k in ("b", "bl", "bx", "blx"):
                cyc = 1 + P
            elif k == "bcond":
                total_cyc += taken * (1 + P) + (c - taken) * 1
                cyc = None
        prev_ls = k == "ls"
        if cyc is not None:
            total_cyc += cyc * c
        total_ins += c
        mix[k] = mix.get(k, 0) + c
    return total_ins, total_cyc, mix


def profile(rows, nm_path, pixels, top=8):
    syms = []
    for line in open(nm_path):
        f = line.split(None, 3)
        if len(f) == 4 and f[2] in "tTwW":
            syms.append((int(f[0], 16), int(f[1], 16), f[3].strip()))
    syms.sort()
    per = {}
    for va, c, _ in rows:
        name = "?"
        for a, sz, n in syms:
            if a <= va < a + max(sz, 2):
                name = n
                break
        per[name] = per.get(name, 0) + c
    total = sum(per.values()) or 1
    for n, c in sorted(per.items(), key=lambda kv: -kv[1])[:top]:
        short = n if len(n) < 70 else n[:67] + "..."
        print(f"  profile: {c / pixels:8.2f} insns/px {100 * c / total:5.1f}%  {short}")


def main():
    path, core = sys.argv[1], sys.argv[2]
    pixels = int(sys.argv[3]) if len(sys.argv) > 3 else 320 * 240
    rows = parse(path)
    ins, cyc, mix = estimate(rows, core)
    print(f"core={core} insns={ins} est_cycles={cyc} insns/px={ins/pixels:.2f} "
          f"est_cycles/px={cyc/pixels:.2f} CPI={cyc/ins:.2f}")
    print("mix: " + " ".join(f"{k}={v/pixels:.2f}/px" for k, v in sorted(mix.items(), key=lambda kv: -kv[1])))
    if len(sys.argv) > 4:
        profile(rows, sys.argv[4], pixels)


if __name__ == "__main__":
    main()
