"""Code-generation limits: deep JMP/COM nesting, huge networks, determinism."""

from __future__ import annotations

import random

from ladderworks.core.address import Address, Area
from ladderworks.core.compiler import compile, decode
from ladderworks.core.il import Instruction, Network, Program
from ladderworks.core.plc.codegen import CHUNK_OPS
from ladderworks.core.plc.engine import ScanEngine
from tests.core.plc.conftest import bit, engine_for, set_bit


def nested(opening: str, closing: str, depth: int) -> str:
    """`depth` nested ranges, each with a coil Y(k).0 inside, the innermost k = depth - 1."""
    lines = []
    for k in range(depth):
        lines += [f"RD X{k % 8}.{k % 8}", opening, "RD R9091.1", f"WRT R{100 + k}.0"]
    lines += [closing] * depth
    return "\n".join(lines)


def test_150_nested_jumps_run() -> None:
    engine = engine_for(nested("JMP 0", "JMPE", 150))
    engine.scan()
    assert all(bit(engine, f"R{100 + k}.0") for k in range(150))
    engine.memory.areas[Area.R][100:250] = bytes(150)
    set_bit(engine, "X3.3", 1)  # the jump of range 3 (and 11, 19, ... sharing X3.3) is taken
    engine.scan()
    assert [bit(engine, f"R{100 + k}.0") for k in range(5)] == [1, 1, 1, 0, 0]
    assert bit(engine, "R249.0") == 0


def test_150_nested_common_lines_run() -> None:
    engine = engine_for(nested("COM 0", "COME", 150))
    engine.memory.areas[Area.X][0:8] = b"\xff" * 8
    engine.scan()
    assert all(bit(engine, f"R{100 + k}.0") for k in range(150))
    set_bit(engine, "X3.3", 0)  # COM 3 (and 11, ...) off: its coils and every inner one get 0
    engine.scan()
    assert [bit(engine, f"R{100 + k}.0") for k in range(5)] == [1, 1, 1, 0, 0]


def test_a_70000_step_network_compiles_and_runs() -> None:
    steps = [Instruction("RD", Address(Area.X, 0, 0), line=1)]
    steps += [Instruction("AND.NOT" if k % 2 else "OR", Address(Area.R, k % 5000, k % 8),
                          line=2 + k) for k in range(70_000)]
    steps.append(Instruction("WRT", Address(Area.Y, 0, 0), line=70_002))
    binary = compile(Program([Network(steps)]))
    ops = decode(binary).ops
    assert (ops[-1].source.instruction, ops[-1].source.line) == (70_001, 70_002)
    engine = ScanEngine(binary)
    assert engine.source.count("def c") >= 70_000 // CHUNK_OPS  # cut into small functions
    engine.memory.set_bit(Address(Area.X, 0, 0), 1)
    engine.scan()
    assert engine.memory.bit(Address(Area.Y, 0, 0)) == 1  # every R bit is 0
    engine.memory.areas[Area.R][4999] = 0x80  # AND.NOT R4999.7 (k = 69 999) opens it
    engine.scan()
    assert engine.memory.bit(Address(Area.Y, 0, 0)) == 0


def test_same_program_same_inputs_same_memory_image() -> None:
    text = "\n".join(
        f"RD X{k % 4}.{k % 8}\nAND.NOT R{k % 7}.{k % 5}\nRD.STK R9091.5\nOR.STK\n"
        f"{'SET' if k % 3 == 0 else 'WRT'} R{10 + k}.{k % 8}\nRD R9091.1\nTMR {1 + k % 9}\n"
        f"WRT R{60 + k}.1" for k in range(40))
    images = []
    for _ in range(2):
        engine = engine_for(text)
        rng = random.Random(5)
        for _ in range(60):
            engine.memory.areas[Area.X][0:4] = bytes(rng.randrange(256) for _ in range(4))
            engine.scan()
        images.append(engine.memory.snapshot())
    assert images[0] == images[1]
