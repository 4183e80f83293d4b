"""The monitored scan's power flow in 256-op lists equals the flat list's (M[op]), scan by scan."""

from __future__ import annotations

import random
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.address import Area
from ladderworks.core.compiler import compile as compile_ladder
from ladderworks.core.compiler.binary import Op
from ladderworks.core.il import parse_file
from ladderworks.core.plc.codegen import generate
from ladderworks.core.plc.codegen_flow import FLOW_BLOCK, flow_blocks, zero_lines
from ladderworks.core.plc.engine import load_binary
from ladderworks.core.plc.functions import FunctionContext, load_all
from ladderworks.core.plc.memory import Memory
from tests.core.plc.conftest import EXAMPLES, engine_for, set_bit
from tests.core.plc.test_jumps import random_program, text_of
from tests.hypothesis_profiles import examples
from tests.real import real_program


def assert_same_flow(ops: tuple[Op, ...], scans: int, rng: random.Random,
                     dialect: str = "seed") -> int:
    """Run the block variant and the `M[op]` variant side by side on random inputs (some
    scans level 1 only): the same memory and the same power flow after every scan; returns
    how many ops had power at some scan."""
    registry = load_all()
    memories = Memory(), Memory()
    contexts = [FunctionContext(memory, 0, 8, dialect=dialect) for memory in memories]
    blocks = generate(ops, memories[0].areas, registry, monitored=True)
    by_op = generate(ops, memories[1].areas, registry, monitored=True, flow_by_op=True)
    flat = [0] * len(ops)
    flowed = bytearray(len(ops))
    for scan in range(scans):
        if scan % 5 == 0:
            for area in (Area.X, Area.F, Area.R):
                data = bytes(rng.randrange(256) for _ in range(32))
                for memory in memories:
                    memory.areas[area][:32] = data
        for memory in memories:
            memory.areas[Area.R][9091] = 0b10  # R9091.1: always 1 (the engine sets it)
        full = scan % 4 != 3
        blocks.scan(contexts[0], None, full)
        by_op.scan(contexts[1], flat, full)
        assert memories[0].snapshot() == memories[1].snapshot(), scan
        flow = blocks.flow()
        assert flow == bytes(flat), scan
        flowed = bytearray(a | b for a, b in zip(flowed, flow, strict=True))
        for context in contexts:
            context.now_ms += 8
            context.scan_ms = 8
    return sum(flowed)


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.LAD")), ids=lambda p: p.name)
def test_every_example_records_the_same_flow_both_ways(path: Path) -> None:
    binary = load_binary(compile_ladder(parse_file(path).program))
    assert assert_same_flow(binary.ops, 60, random.Random(path.name), binary.dialect) >= \
        len(binary.ops) // 3


@pytest.mark.parametrize("name", ["FANUC_STUDER_X22_P036", "FANUC_STUDER_S41_F036"])
def test_a_real_program_records_the_same_flow_both_ways(name: str) -> None:
    binary = load_binary(compile_ladder(parse_file(real_program(name)).program))
    assert len(binary.ops) > 20 * FLOW_BLOCK
    assert assert_same_flow(binary.ops, 12, random.Random(name), binary.dialect) > 1000


@settings(max_examples=examples(60), deadline=None)
@given(seed=st.integers(0, 10**6))
def test_jumps_and_their_skipped_ops_record_the_same_flow_both_ways(seed: int) -> None:
    rng = random.Random(seed)
    ops = engine_for(text_of(random_program(rng, rng.randint(1, 10)))).program.ops
    assert_same_flow(ops, 6, rng)


@settings(max_examples=examples(200), deadline=None)
@given(count=st.integers(1, 5 * FLOW_BLOCK), data=st.data())
def test_zero_lines_clear_exactly_their_ops(count: int, data: st.DataObject) -> None:
    start = data.draw(st.integers(0, count))
    end = data.draw(st.integers(start, count))
    blocks = flow_blocks(count)
    for block in blocks:
        block[:] = [1] * len(block)
    namespace = {"FB": blocks, "Z": [0] * FLOW_BLOCK}
    exec("\n".join(["def run():", *zero_lines(start, end, "    "), "    pass"]), namespace)
    namespace["run"]()  # type: ignore[operator]
    flat = [value for block in blocks for value in block]
    assert len(flat) >= count and all(len(block) == FLOW_BLOCK for block in blocks)
    assert flat == [1] * start + [0] * (end - start) + [1] * (len(flat) - end)


def test_the_engine_reads_the_blocks_and_a_cold_start_clears_them() -> None:
    engine = engine_for("RD X0.0\nWRT Y0.0\nRD X0.1\nWRT Y0.1", monitored=True)
    set_bit(engine, "X0.0", 1)
    engine.scan()
    assert list(engine.power_flow) == [1, 1, 0, 0]
    set_bit(engine, "X0.1", 1)
    engine.scan()
    assert list(engine.power_flow) == [1, 1, 1, 1]
    engine.cold_start()
    assert list(engine.power_flow) == [0, 0, 0, 0]
    engine.monitored = False
    engine.scan()  # a fast scan leaves the last monitored scan's flow as it was
    assert list(engine.power_flow) == [0, 0, 0, 0]
    engine.monitored = True
    engine.scan()
    assert list(engine.power_flow) == [1, 1, 1, 1]


def test_the_scan_engine_power_flow_equals_the_flat_list_of_a_long_program() -> None:
    text = "\n".join(f"RD X{n % 16}.{n % 8}\nAND.NOT X{(n + 3) % 16}.{n % 5}\nWRT R{n}.0"
                     for n in range(300))
    engine = engine_for(text, monitored=True)
    ops = engine.program.ops
    memory = Memory()
    by_op = generate(ops, memory.areas, load_all(), monitored=True, flow_by_op=True)
    flat = [0] * len(ops)
    rng = random.Random(3)
    for _ in range(5):
        data = bytes(rng.randrange(256) for _ in range(16))
        engine.memory.areas[Area.X][:16] = data
        memory.areas[Area.X][:16] = data
        engine.scan()
        by_op.scan(FunctionContext(memory), flat, True)
        assert bytes(engine.power_flow) == bytes(flat)
    assert len(ops) > 3 * FLOW_BLOCK
