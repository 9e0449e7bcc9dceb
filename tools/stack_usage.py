#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Worst-case stack depth of an ECU image, per entry point.

Inputs:
  - the linked ELF: the functions that are really in the image, the calls
    between them from the disassembly (bl = call, b/b.w to another
    function's first instruction = tail call), indirect calls (blx/bx reg
    other than lr), and the vector table (which handlers are entry points);
  - the compiler's per-function frame sizes: GCC's -fstack-usage (.su) files,
    and its -fcallgraph-info=su (.ci) graphs for the call sites the compiler
    itself marks as indirect.
Functions without a .su entry (libgcc helpers, hand-written assembly) get
their frame from their prologue (push/stmdb/strd/str with write-back, sub sp,
vpush) and are listed as estimated. Recursion and indirect calls cannot be
bounded this way: they are reported, never silently dropped.

Entry points: Reset_Handler (-> main loop) and every distinct handler of the
vector table. Exception entry stacks 32 bytes (8 words), 104 with the FPU's
lazy context (hard-float images). The nesting total assumes the HAL's
priorities: faults over SysTick over the CAN interrupts over thread mode.

Prints one line per entry point, then "STACK main=N isr_max=N total=N
reserve=N"; exits 1 if the total exceeds the linker's __stack_reserve, 2 if
the depth cannot be bounded (indirect calls, recursion, dynamic frames).
"""
import glob
import os
import re
import struct
import subprocess
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import helptext  # noqa: E402


def run(cmd):
    return subprocess.run(cmd, check=True, capture_output=True, text=True).stdout


def load_su(build_dir):
    """name -> (bytes, qualifier); static functions by plain name (max)."""
    frames = {}
    for path in glob.glob(os.path.join(build_dir, "**", "*.su"), recursive=True):
        with open(path) as f:
            for line in f:
                parts = line.rstrip("\n").split("\t")
                if len(parts) != 3:
                    continue
                name = parts[0].rsplit(":", 1)[-1]
                size = int(parts[1])
                qual = parts[2]
                old = frames.get(name)
                if old is None or size > old[0]:
                    frames[name] = (size, qual)
    return frames


def pushed_bytes(args):
    """Bytes a push/stmdb/vpush of the register list in args stores: 4 per
    core or single register (r4, lr, s16), 8 per double (d8); ranges such as
    r4-r7 or d8-d15 count each register."""
    regs = re.search(r"\{([^}]*)\}", args)
    if not regs:
        return 0
    n = 0
    for r in regs.group(1).split(","):
        r = r.strip()
        rng = re.match(r"[rsd](\d+)-[rsd](\d+)", r)
        width = 8 if r.startswith("d") else 4
        n += (int(rng.group(2)) - int(rng.group(1)) + 1) * width if rng else width
    return n


def load_ci_indirect(build_dir):
    """functions the compiler says make an indirect call"""
    callers = set()
    for path in glob.glob(os.path.join(build_dir, "**", "*.ci"), recursive=True):
        with open(path) as f:
            for m in re.finditer(r'sourcename: "([^"]+)" targetname: "__indirect_call"', f.read()):
                callers.add(m.group(1).rsplit(":", 1)[-1])
    return callers


def parse_elf(prefix, elf):
    syms = {}   # addr (thumb bit cleared) -> name
    sizes = {}
    for line in run([prefix + "nm", "-S", "--defined-only", elf]).splitlines():
        p = line.split()
        if len(p) == 4 and p[2] in "tTwW":
            addr = int(p[0], 16) & ~1
            syms.setdefault(addr, p[3])
            sizes[p[3]] = int(p[1], 16)
    calls = {}      # name -> set(callee)
    indirect = set()
    prologue = {}   # name -> estimated frame bytes
    cur = None
    insn_no = 0
    for line in run([prefix + "objdump", "-d", "--no-show-raw-insn", elf]).splitlines():
        m = re.match(r"^([0-9a-f]+) <([^>]+)>:$", line)
        if m:
            cur = m.group(2)
            calls.setdefault(cur, set())
            prologue[cur] = 0
            insn_no = 0
            continue
        m = re.match(r"^\s+([0-9a-f]+):\s+(\S+)\s*(.*)$", line)
        if not m or cur is None:
            continue
        op, args = m.group(2), m.group(3)
        insn_no += 1
        t = re.search(r"\b([0-9a-f]+) <([^>+]+)>", args)
        if op in ("bl", "blx") and t:
            calls[cur].add(t.group(2))
        elif op == "blx" or (op == "bx" and "lr" not in args):
            indirect.add(cur)
        elif re.match(r"^b(\.w|\.n)?$", op) and t and int(t.group(1), 16) in syms \
                and t.group(2) != cur:
            calls[cur].add(t.group(2))  # tail call
        if insn_no <= 8:  # prologue
            if op in ("push", "push.w", "stmdb", "stmdb.w") and ("sp!" in args or op.startswith("push")) \
                    or op.startswith("vpush"):
                prologue[cur] += pushed_bytes(args)
            elif op.startswith("sub") and args.startswith("sp, sp, #") or \
                    (op.startswith("sub") and re.match(r"sp, #", args)):
                prologue[cur] += int(re.search(r"#(\d+)", args).group(1))
            elif op.startswith(("str", "strd")) and re.search(r"\[sp, #-(\d+)\]!", args):
                prologue[cur] += int(re.search(r"\[sp, #-(\d+)\]!", args).group(1))
    return syms, calls, indirect, prologue


def vector_handlers(prefix, elf, syms):
    raw = subprocess.run([prefix + "objcopy", "-O", "binary", "--only-section=.isr_vector",
                          elf, "/dev/stdout"], check=True, capture_output=True).stdout
    handlers = []
    for i in range(1, len(raw) // 4):
        addr = struct.unpack_from("<I", raw, 4 * i)[0]
        if addr == 0:
            continue
        name = syms.get(addr & ~1)
        if name and name not in handlers:
            handlers.append(name)
    return handlers


def main():
    ap = helptext.parser(__doc__, "tools/stack_usage.py")
    ap.add_argument("elf", metavar="IMAGE.elf", help="the linked ECU image")
    ap.add_argument("build_dir", metavar="BUILD_DIR", help="where its objects and their .su/.ci files are")
    ap.add_argument("--prefix", default="arm-none-eabi-", metavar="PREFIX",
                    help="binutils prefix of objdump/nm (default arm-none-eabi-)")
    a = ap.parse_args()
    for path, kind in ((a.elf, os.path.isfile), (a.build_dir, os.path.isdir)):
        if not kind(path):
            sys.exit("stack_usage.py: %s: no such %s" % (path, "file" if kind is os.path.isfile else "folder"))
    try:
        return report(a)
    except FileNotFoundError as e:
        sys.exit("stack_usage.py: %s not found (Debian's binutils-arm-none-eabi)" % e.filename)
    except subprocess.CalledProcessError as e:
        sys.exit("stack_usage.py: %s failed: %s" % (" ".join(e.cmd), "; ".join((e.stderr or "").strip().splitlines()[-1:])))


def report(a):
    su = load_su(a.build_dir)
    ci_indirect = load_ci_indirect(a.build_dir)
    syms, calls, indirect, prologue = parse_elf(a.prefix, a.elf)
    indirect |= {f for f in ci_indirect if f in calls}
    hard_float = "Tag_ABI_VFP_args: VFP registers" in run([a.prefix + "readelf", "-A", a.elf])
    estimated = set()
    dynamic = set()

    def frame(fn):
        key = fn if fn in su else re.sub(r"\.\d+$", "", fn)  # GCC clone "f.isra.0" is "f.isra" in .su
        if key in su:
            size, qual = su[key]
            if "dynamic" in qual and "bounded" not in qual:
                dynamic.add(fn)
            return size
        estimated.add(fn)
        return prologue.get(fn, 0)

    memo = {}
    recursive = set()

    def worst(fn, stack):
        if fn in memo:
            return memo[fn]
        if fn in stack:
            recursive.add(fn)
            return 0, [fn + " (recursion)"]
        best, path = 0, []
        for callee in sorted(calls.get(fn, ())):
            d, p = worst(callee, stack | {fn})
            if d > best:
                best, path = d, p
        res = (frame(fn) + best, [fn] + path)
        memo[fn] = res
        return res

    exc_frame = 104 if hard_float else 32
    handlers = vector_handlers(a.prefix, a.elf, syms)
    results = {}
    print("worst-case stack per entry point (%s, exception frame %d bytes):" % (a.elf, exc_frame))
    for h in handlers:
        d, p = worst(h, frozenset())
        results[h] = d
        print("  %-24s %5d bytes  %s" % (h, d, " > ".join(p)))
    main_depth = results.get("Reset_Handler", 0)
    # bxCAN's CAN1_TX_IRQHandler ..., FDCAN's FDCAN1_IT0_IRQHandler ...
    can_isr = max([v for k, v in results.items() if k.startswith(("CAN", "FDCAN"))] or [0])
    systick = results.get("SysTick_Handler", 0)
    # the G4's NMI_Handler runs its ECC check, then the fault handler
    fault = max(results.get("Fault_Handler", 0), results.get("Default_Handler", 0),
                results.get("NMI_Handler", 0))
    total = main_depth + 3 * exc_frame + can_isr + systick + fault + exc_frame
    print("  nesting: main %d + CAN ISR %d + SysTick %d + fault %d + 4 exception frames = %d bytes"
          % (main_depth, can_isr, systick, fault, total))
    if estimated:
        print("  frames estimated from the prologue (no .su): " + ", ".join(sorted(estimated)))
    if indirect:
        print("  INDIRECT calls (not bounded here): " + ", ".join(sorted(indirect)))
    else:
        print("  indirect calls: none")
    if recursive:
        print("  RECURSION (not bounded): " + ", ".join(sorted(recursive)))
    else:
        print("  recursion: none")
    if dynamic:
        print("  DYNAMIC frames (alloca/VLA, unbounded): " + ", ".join(sorted(dynamic)))
    reserve = None
    for line in run([a.prefix + "nm", a.elf]).splitlines():
        p = line.split()
        if len(p) == 3 and p[2] == "__stack_reserve":
            reserve = int(p[0], 16)
    print("STACK main=%d isr_max=%d total=%d reserve=%s" % (main_depth, max(can_isr, systick, fault),
                                                        total, reserve if reserve is not None else "?"))
    if indirect or recursive or dynamic:
        print("stack depth NOT bounded (see above)")
        return 2
    if reserve is not None and total > reserve:
        print("worst case %d bytes EXCEEDS the linker's stack reserve of %d bytes" % (total, reserve))
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
