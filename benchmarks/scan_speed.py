"""Scan speed: ns per step of a generated 10,000-step program, fast and monitored, vs the floor.

The floor is the same logic written as plain straight-line Python (one expression per network
over local bytearrays, then an if/else per coil), built directly from the logic description,
not through the compiler. Prints figures; asserts nothing.
"""

from __future__ import annotations

import random
import time
from collections.abc import Callable
from dataclasses import dataclass

from ladderworks.core.address import Area
from ladderworks.core.compiler import compile as compile_ladder
from ladderworks.core.il import parse
from ladderworks.core.plc.engine import ScanEngine

STEPS = 10_000
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


def best_ns(run: Callable[[], None], scans: int, repeats: int = 7) -> float:
    """Best time of `scans` calls, per call, in ns."""
    best = float("inf")
    for _ in range(repeats):
        start = time.perf_counter_ns()
        for _ in range(scans):
            run()
        best = min(best, (time.perf_counter_ns() - start) / scans)
    return best


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
    scans = 200
    floor_ns = best_ns(floor, scans)
    fast_ns = best_ns(engine.scan, scans)
    engine.monitored = True
    monitored_ns = best_ns(engine.scan, scans)
    print(f"program: {steps} steps in {len(networks)} networks")
    print(f"floor (hand-written Python): {floor_ns / steps:7.1f} ns/step  "
          f"({floor_ns / 1e6:.3f} ms/scan)")
    print(f"fast mode:                   {fast_ns / steps:7.1f} ns/step  "
          f"({fast_ns / 1e6:.3f} ms/scan)  {fast_ns / floor_ns:.2f}x floor")
    print(f"monitored mode:              {monitored_ns / steps:7.1f} ns/step  "
          f"({monitored_ns / 1e6:.3f} ms/scan)  {monitored_ns / fast_ns:.2f}x fast")


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
