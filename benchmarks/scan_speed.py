"""Scan speed: ns per step, fast and monitored, against the straight-line floor.

Three programs: (1) 35,000 steps of mixed basic logic, compared with the floor: the same logic
written as plain straight-line Python (one expression per network over local bytearrays, then
an if/else per coil), built from the logic description, not through the compiler; (2) the same
networks in the shape of a real FANUC program (level 1 + END1, level 2 with JMP 0/JMPE blocks
and CALLU of 100 subprograms, SP/SPE, END), which the generator cuts into per-unit chunk
functions; (3) the real X22 program (shared/real-programs/FANUC_STUDER_X22_P036.txt) when the
parser can read it. Timings are interleaved (floor, fast, monitored, repeated; best of each)
and in CPU time of the thread (time.thread_time_ns) because the machine is shared: 30 rounds
of 4 scans, the best round being the least disturbed. The monitored mode is timed twice: as it
runs (the power flow's bytes are made when a view reads them) and with the bytes read after
every scan (as it is with time travel on). Then the generated code alone (no engine around
it), before and after in one run: fast, monitored as before (`flow_by_op`: a store `M[op]`
into one list per op) and monitored now (256-op lists).
Prints figures; asserts nothing.
"""

from __future__ import annotations

import random
import time
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path

from ladderworks.core.address import Area
from ladderworks.core.compiler import compile as compile_ladder
from ladderworks.core.il import parse, parse_file
from ladderworks.core.plc.codegen import generate
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.functions import FunctionContext, load_all

STEPS = 35_000
_ROOT = Path(__file__).resolve().parents[1]
# <repo root>/../shared (the main checkout), or two levels up from a worktree in /work/wt/
X22 = next((base / "shared" / "real-programs" / "FANUC_STUDER_X22_P036.txt"
            for base in (_ROOT.parent, _ROOT.parent.parent)
            if (base / "shared" / "real-programs").is_dir()), _ROOT / "missing")
SEED = 2024


@dataclass(frozen=True)
class Contact:
    area: str
    byte: int
    bit: int
    inverted: bool

    def il(self) -> str:
        return f"{self.area}{self.byte}.{self.bit}"

    def python(self) -> str:
        byte = f"{'~' if self.inverted else ''}{self.area}[{self.byte}]"
        return f"({byte} >> {self.bit} & 1)" if self.bit else f"({byte} & 1)"


@dataclass
class Network:
    """A chain: first contact, then (operator, item) where item is a contact or a branch."""

    first: Contact
    chain: list[tuple[str, Contact | list[Contact]]]
    coils: list[tuple[int, int, bool]]  # R byte, bit, inverted


def contact(rng: random.Random) -> Contact:
    area = rng.choice("XRRRF")
    return Contact(area, rng.randrange(16) if area != "R" else rng.randrange(100, 200),
                   rng.randrange(8), rng.random() < 0.3)


def make_networks(rng: random.Random, steps: int) -> list[Network]:
    networks: list[Network] = []
    total = 0
    while total < steps:
        net = Network(contact(rng), [], [])
        total += 1
        for _ in range(rng.randint(2, 8)):
            if rng.random() < 0.15:
                branch = [contact(rng) for _ in range(rng.randint(1, 3))]
                net.chain.append((rng.choice(["&", "|"]), branch))
                total += len(branch) + 1
            else:
                net.chain.append((rng.choice(["&", "&", "|"]), contact(rng)))
                total += 1
        for _ in range(rng.choice([1, 1, 1, 2])):
            net.coils.append((rng.randrange(300, 400), rng.randrange(8), rng.random() < 0.2))
            total += 1
        networks.append(net)
    return networks


def to_il(networks: list[Network]) -> str:
    lines = ["%@3"]
    for net in networks:
        lines.append(("RD.NOT " if net.first.inverted else "RD ") + net.first.il())
        for operator, item in net.chain:
            word = "AND" if operator == "&" else "OR"
            if isinstance(item, Contact):
                lines.append(f"{word}{'.NOT' if item.inverted else ''} {item.il()}")
            else:
                head, *rest = item
                lines.append(f"RD{'.NOT' if head.inverted else ''}.STK {head.il()}")
                lines.extend(f"AND{'.NOT' if c.inverted else ''} {c.il()}" for c in rest)
                lines.append(f"{word}.STK")
        for byte, bit, inverted in net.coils:
            lines.append(f"WRT{'.NOT' if inverted else ''} R{byte}.{bit}")
    lines.append("%")
    return "\n".join(lines) + "\n"


def to_python(networks: list[Network]) -> str:
    """The floor: how one would write this logic by hand in Python."""
    body = ["def scan(X, F, R):"]
    for net in networks:
        expr = net.first.python()
        for operator, item in net.chain:
            term = (item.python() if isinstance(item, Contact)
                    else "(" + " & ".join(c.python() for c in item) + ")")
            expr = f"({expr}) {operator} {term}" if operator == "&" else f"{expr} | {term}"
        if len(net.coils) == 1:
            body.append(f"    if {expr}:")
        else:
            body.append(f"    v = {expr}")
            body.append("    if v:")
        for index, (byte, bit, inverted) in enumerate(net.coils):
            if index:
                body.append("    if v:")
            on, off = f"R[{byte}] |= {1 << bit}", f"R[{byte}] &= {0xFF ^ (1 << bit)}"
            if inverted:
                on, off = off, on
            body += [f"        {on}", "    else:", f"        {off}"]
    return "\n".join(body) + "\n"


def best_ns(runs: dict[str, Callable[[], None]], scans: int, rounds: int = 9) -> dict[str, float]:
    """Best time per call in ns of each of `runs`, measured interleaved round by round."""
    best = dict.fromkeys(runs, float("inf"))
    for _ in range(rounds):
        for name, run in runs.items():
            start = time.thread_time_ns()
            for _ in range(scans):
                run()
            best[name] = min(best[name], (time.thread_time_ns() - start) / scans)
    return best


def shaped(networks: list[Network]) -> str:
    """The networks as a FANUC-shaped program: levels, JMP blocks, 100 subprograms."""
    body = to_il(networks).splitlines()[1:-1]
    chunks: list[list[str]] = [[]]
    for line in body:  # one list per network (a network starts at RD)
        if line.startswith(("RD ", "RD.NOT ")) and chunks[-1]:
            chunks.append([])
        chunks[-1].append(line)
    level1, rest = chunks[:30], chunks[30:]
    cut = len(rest) * 6 // 10
    level2, subs = rest[:cut], rest[cut:]
    lines = [line for net in level1 for line in net] + ["END1"]
    per_sub = max(1, len(subs) // 100)
    count = (len(subs) + per_sub - 1) // per_sub
    for k, net in enumerate(level2):
        if k % 20 == 0:
            lines += [f"RD R{(k // 20) % 50 + 500}.0", "JMP 0"]
        lines += net
        if k % 20 == 19 or k == len(level2) - 1:
            lines.append("JMPE")
        if k % max(1, len(level2) // count) == 0 and k // max(1, len(level2) // count) < count:
            lines.append(f"CALLU P{k // max(1, len(level2) // count) + 1}")
    lines.append("END2")
    for k in range(count):
        lines.append(f"SP P{k + 1}")
        lines += [line for net in subs[k * per_sub:(k + 1) * per_sub] for line in net]
        lines.append("SPE")
    lines.append("END")
    return "\n".join(lines)


def engine_of(text: str) -> ScanEngine | None:
    """An engine for a program given as ladder lines (with `P` numbers, levels and SP/SPE)."""
    result = parse(f"%@3\n{text}\n%\n")
    return ScanEngine(compile_ladder(result.program)) if result.ok else None


def report(title: str, steps: int, figures: dict[str, float]) -> None:
    """Print ns/step of fast and monitored (and the floor when measured)."""
    print(f"{title}: {steps} steps")
    fast = figures["fast"]
    if "floor" in figures:
        floor = figures["floor"]
        print(f"  floor (hand-written Python): {floor / steps:7.1f} ns/step  "
              f"({floor / 1e6:.3f} ms/scan)")
        print(f"  fast mode:                   {fast / steps:7.1f} ns/step  "
              f"({fast / 1e6:.3f} ms/scan)  {fast / floor:.2f}x floor")
    else:
        print(f"  fast mode:                   {fast / steps:7.1f} ns/step  "
              f"({fast / 1e6:.3f} ms/scan)")
    monitored = figures["monitored"]
    copied = figures["copied"]
    print(f"  monitored, flow copied:      {copied / steps:7.1f} ns/step  "
          f"({copied / 1e6:.3f} ms/scan)  {copied / fast:.2f}x fast  (before: bytes every scan)")
    print(f"  monitored mode:              {monitored / steps:7.1f} ns/step  "
          f"({monitored / 1e6:.3f} ms/scan)  {monitored / fast:.2f}x fast  (bytes when read)")
    code_fast = figures["code fast"]
    print(f"  generated code alone: fast {code_fast / 1e6:.3f} ms/scan; monitored before "
          f"(M[op]) {figures['code before'] / 1e6:.3f} ms = "
          f"{figures['code before'] / code_fast:.2f}x fast; monitored now (256-op lists) "
          f"{figures['code now'] / 1e6:.3f} ms = {figures['code now'] / code_fast:.2f}x fast")


def measure(engine: ScanEngine, scans: int,
            floor: Callable[[], None] | None = None) -> dict[str, float]:
    """Fast and monitored timings of `engine` (and the floor), interleaved."""
    monitored = ScanEngine(engine.program, memory=engine.memory)
    monitored.monitored = True
    runs: dict[str, Callable[[], None]] = {}
    if floor is not None:
        runs["floor"] = floor
    runs["fast"] = engine.scan
    runs["monitored"] = monitored.scan
    copied = ScanEngine(engine.program, memory=engine.memory)
    copied.monitored = True

    def copy_every_scan() -> None:  # the monitored mode before: the bytes made in every scan
        copied.scan()
        _ = copied.power_flow

    runs["copied"] = copy_every_scan
    runs.update(code_alone(engine))
    return best_ns(runs, scans, rounds=30)


def code_alone(engine: ScanEngine) -> dict[str, Callable[[], None]]:
    """One scan of the generated code only, over `engine`'s memory: fast, monitored as before
    (`flow_by_op`, one list `M[op]`) and monitored now (the power flow in 256-op lists)."""
    ops, areas, registry = engine.program.ops, engine.memory.areas, load_all()
    ctx = FunctionContext(engine.memory, 0, engine.period_ms, dialect=engine.program.dialect)
    fast = generate(ops, areas, registry).scan
    before = generate(ops, areas, registry, monitored=True, flow_by_op=True).scan
    now = generate(ops, areas, registry, monitored=True).scan
    flat = [0] * len(ops)
    return {"code fast": lambda: fast(ctx, None, True),
            "code before": lambda: before(ctx, flat, True),
            "code now": lambda: now(ctx, None, True)}


def main() -> None:
    rng = random.Random(SEED)
    networks = make_networks(rng, STEPS)
    text = to_il(networks)
    program = parse(text).program
    steps = program.step_count()
    engine = ScanEngine(compile_ladder(program))
    memory = engine.memory
    for area in (Area.X, Area.F, Area.R):
        data = memory.areas[area]
        data[:] = bytes(rng.randrange(256) for _ in range(len(data)))
    namespace: dict[str, object] = {}
    exec(compile(to_python(networks), "<floor>", "exec"), namespace)
    floor_scan = namespace["scan"]
    areas = memory.areas
    x, f, r = areas[Area.X], areas[Area.F], areas[Area.R]

    def floor() -> None:
        floor_scan(x, f, r)  # type: ignore[operator]

    check_same_logic(engine, floor)
    report(f"basic logic, {len(networks)} networks", steps, measure(engine, 4, floor))
    shaped_text = shaped(networks)
    shaped_engine = engine_of(shaped_text)
    assert shaped_engine is not None
    shaped_engine.memory.areas[Area.X][:] = memory.areas[Area.X]
    shaped_steps = len(shaped_engine.program.ops)
    report("FANUC-shaped (levels, JMP blocks, 100 subprograms)", shaped_steps,
           measure(shaped_engine, 4))
    if X22.exists():
        result = parse_file(X22)
        if result.ok:
            real = ScanEngine(compile_ladder(result.program))
            report("X22 real program", result.program.step_count(), measure(real, 4))
        else:
            print(f"X22 real program: not measured, the parser does not read it yet "
                  f"({len(result.diagnostics)} diagnostics)")


def check_same_logic(engine: ScanEngine, floor: Callable[[], None]) -> None:
    """The floor and the engine must compute the same relays, or the comparison is void."""
    memory = engine.memory
    before = bytes(memory.areas[Area.R])
    engine.scan()
    by_engine = bytes(memory.areas[Area.R])
    memory.areas[Area.R][:] = before
    floor()
    by_floor = bytes(memory.areas[Area.R])
    by_engine = by_engine[:9000]  # R9000.. are system relays the engine sets
    if by_floor[:9000] != by_engine:
        raise SystemExit("the floor and the engine disagree: the benchmark is wrong")


if __name__ == "__main__":
    main()
