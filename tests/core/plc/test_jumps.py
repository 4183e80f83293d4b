"""JMP n / JMPE: the jump range by coil count or up to JMPE, in the text, checks and scan."""

from __future__ import annotations

import random

from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.address import Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.il import parse, print_program
from ladderworks.core.plc.engine import ScanEngine
from tests.core.plc.conftest import (
    assert_matches_reference,
    at,
    bit,
    engine_for,
    set_bit,
    stack_step,
)
from tests.hypothesis_profiles import examples


def ladder(text: str) -> str:
    """`text` as a file with one ladder section."""
    return "%@3\n" + text.strip() + "\n%\n"


def outputs(engine: ScanEngine, count: int) -> list[int]:
    """Y0.1 … Y0.count."""
    return [bit(engine, f"Y0.{n}") for n in range(1, count + 1)]


# -- text and checks -------------------------------------------------------------------------

def test_fanuc_sub_10_form_is_jmp_with_its_coil_count() -> None:
    fanuc = parse(ladder("RD X0.0\nSUB 10\n0002\nRD X0.1\nWRT Y0.1"))
    one_line = parse(ladder("RD X0.0\nJMP 2\nRD X0.1\nWRT Y0.1"))
    assert fanuc.ok and one_line.ok
    jmp = fanuc.program.networks[0].instructions[1]
    assert (jmp.name, jmp.params) == ("JMP", (2,))
    assert print_program(fanuc.program) == print_program(one_line.program)


def test_jmp_needs_its_coil_count() -> None:
    for text, code in (("JMP", "param-count"), ("SUB 10", "param-count"),
                       ("JMP 10000", "param-range"), ("JMP -1", "param-range")):
        result = parse(ladder(f"RD X0.0\n{text}\nRD X0.1\nWRT Y0.1"))
        assert [(d.code, d.line) for d in result.diagnostics] == [(code, 3)], text


def test_jmp_n_compiles_without_jmpe_and_jmp_0_does_not() -> None:
    counted = compile_program(parse(ladder("RD X0.0\nJMP 1\nRD X0.1\nWRT Y0.1")).program)
    assert counted.binary is not None and not counted.diagnostics
    open_ended = compile_program(parse(ladder("RD X0.0\nJMP 0\nRD X0.1\nWRT Y0.1")).program)
    assert open_ended.binary is None
    assert [d.code for d in open_ended.diagnostics] == ["jmp-without-jmpe"]


# -- the scan --------------------------------------------------------------------------------

def test_jmp_0_skips_to_jmpe_and_the_coils_keep_their_state() -> None:
    engine = engine_for("RD X0.0\nJMP 0\nRD X0.1\nWRT Y0.1\nRD X0.1\nWRT Y0.2\nJMPE\n"
                        "RD X0.1\nWRT Y0.3")
    set_bit(engine, "X0.1", 1)
    engine.scan()
    assert outputs(engine, 3) == [1, 1, 1]
    set_bit(engine, "X0.0", 1)
    set_bit(engine, "X0.1", 0)
    engine.scan()
    assert outputs(engine, 3) == [1, 1, 0]


JMP_2 = """
RD X0.0
JMP 2
RD X0.1
WRT Y0.1
RD X0.1
WRT.NOT Y0.2
RD X0.1
WRT Y0.3
"""


def test_jmp_2_skips_exactly_the_next_two_coils() -> None:
    engine = engine_for(JMP_2)
    set_bit(engine, "X0.1", 1)
    engine.scan()
    assert outputs(engine, 3) == [1, 0, 1]
    set_bit(engine, "X0.0", 1)  # jump: Y0.1 and Y0.2 (a WRT.NOT) are frozen, Y0.3 runs
    set_bit(engine, "X0.1", 0)
    engine.scan()
    assert outputs(engine, 3) == [1, 0, 0]
    set_bit(engine, "X0.0", 0)
    engine.scan()
    assert outputs(engine, 3) == [0, 1, 0]


def test_the_range_of_jmp_n_takes_in_the_functions_up_to_the_nth_coil() -> None:
    engine = engine_for("""
RD X0.0
JMP 1
RD X0.1
NUMEB 1 7 R10
RD X0.1
WRT Y0.1
RD X0.1
NUMEB 1 9 R11
""")
    set_bit(engine, "X0.0", 1)
    set_bit(engine, "X0.1", 1)
    engine.scan()
    assert engine.memory.areas[Area.R][10:12] == bytes([0, 9])
    assert bit(engine, "Y0.1") == 0
    set_bit(engine, "X0.0", 0)
    engine.scan()
    assert engine.memory.areas[Area.R][10:12] == bytes([7, 9])
    assert bit(engine, "Y0.1") == 1


def test_a_range_ending_inside_a_network_leaves_the_rest_of_it_reading_0() -> None:
    engine = engine_for("RD X0.0\nJMP 1\nRD X0.1\nWRT Y0.1\nWRT Y0.2\nOR X0.2\nWRT Y0.3")
    set_bit(engine, "X0.1", 1)
    engine.scan()
    assert outputs(engine, 3) == [1, 1, 1]
    set_bit(engine, "X0.0", 1)  # Y0.1 frozen; Y0.2 is written with the skipped logic's 0
    engine.scan()
    assert outputs(engine, 3) == [1, 0, 0]
    set_bit(engine, "X0.2", 1)
    engine.scan()
    assert outputs(engine, 3) == [1, 0, 1]


def test_jmp_n_with_fewer_coils_after_it_skips_to_the_end() -> None:
    engine = engine_for("RD X0.0\nJMP 5\nRD X0.1\nWRT Y0.1")
    set_bit(engine, "X0.0", 1)
    set_bit(engine, "X0.1", 1)
    engine.scan()
    assert bit(engine, "Y0.1") == 0


def test_jmpe_ends_a_jmp_n_opened_inside_its_range() -> None:
    engine = engine_for("""
RD X0.0
JMP 0
RD X0.1
JMP 3
RD X0.2
WRT Y0.1
JMPE
RD X0.2
WRT Y0.2
""")
    set_bit(engine, "X0.1", 1)  # the inner JMP 3 jumps; its range stops at the JMPE
    set_bit(engine, "X0.2", 1)
    engine.scan()
    assert outputs(engine, 2) == [0, 1]


def test_a_coil_counts_only_for_the_innermost_range() -> None:
    engine = engine_for("""
RD X0.0
JMP 1
RD X0.1
JMP 1
RD X0.2
WRT Y0.1
RD X0.2
WRT Y0.2
RD X0.2
WRT Y0.3
""")
    set_bit(engine, "X0.0", 1)  # outer JMP 1: Y0.1 counts for the inner range, Y0.2 for it
    set_bit(engine, "X0.2", 1)
    engine.scan()
    assert outputs(engine, 3) == [0, 0, 1]
    set_bit(engine, "X0.0", 0)
    set_bit(engine, "X0.1", 1)  # only the inner one jumps
    engine.scan()
    assert outputs(engine, 3) == [0, 1, 1]


def test_disabled_coil_still_counts_in_a_jmp_range() -> None:
    engine = engine_for("RD X0.0\nJMP 1\nRD X0.1\nWRT Y0.1\nRD X0.1\nWRT Y0.2")
    engine.disable(3)
    set_bit(engine, "X0.0", 1)
    set_bit(engine, "X0.1", 1)
    engine.scan()
    assert (bit(engine, "Y0.1"), bit(engine, "Y0.2")) == (0, 1)


def test_disabled_jmp_n_never_jumps() -> None:
    engine = engine_for(JMP_2)
    engine.disable(1)
    set_bit(engine, "X0.0", 1)
    set_bit(engine, "X0.1", 1)
    engine.scan()
    assert outputs(engine, 3) == [1, 0, 1]


def test_power_flow_of_a_jmp_n_taken() -> None:
    engine = engine_for("RD X0.0\nJMP 1\nRD X0.1\nWRT Y0.1\nRD X0.1\nWRT Y0.2")
    engine.monitored = True
    set_bit(engine, "X0.0", 1)
    set_bit(engine, "X0.1", 1)
    engine.scan()
    assert list(engine.power_flow) == [1, 1, 0, 0, 1, 1]


# -- the generated code against a reference interpreter with jumps ------------------------------

Op = tuple[str, str | None, int]  # name, operand, JMP coil count


def reference_scan(program: list[Op], engine: ScanEngine) -> None:
    """The program run op by op: an explicit stack and a list of open jump ranges."""
    memory = engine.memory
    stack = [0]
    ranges: list[list[int]] = []  # [coils left (0: up to JMPE), taken]
    for name, operand, coils in program:
        skipping = any(taken for _, taken in ranges)
        if name == "JMPE":
            while ranges[-1][0]:
                ranges.pop()
            ranges.pop()
            continue
        if name == "JMP":
            ranges.append([coils, 0 if skipping else stack[-1]])
            stack[-1] = 0
            continue
        if name.startswith("WRT"):
            if not skipping:
                memory.set_bit(at(operand or ""), stack[-1] ^ (name == "WRT.NOT"))
            if ranges and ranges[-1][0]:
                ranges[-1][0] -= 1
                if not ranges[-1][0]:
                    ranges.pop()
                    if skipping and not any(taken for _, taken in ranges):
                        stack = [0] * len(stack)  # the skipped logic was not evaluated
            continue
        if skipping:  # the stack keeps its depth (the network may go on after the range)
            if name.endswith(".STK"):
                stack = [*stack, 0] if name.startswith("RD") else stack[:-1]
            continue
        stack_step(stack, name, memory.bit(at(operand)) if operand else 0)


def random_program(rng: random.Random, networks: int) -> list[Op]:
    """Random networks (several coils each, some mid-network) with JMP n / JMP 0 … JMPE."""
    bits = [f"R{b}.{k}" for b in range(3) for k in range(8)]
    ops: list[Op] = []
    open_jumps = 0
    for _ in range(networks):
        roll = rng.random()
        if roll < 0.25:
            coils = rng.choice([0, 1, 1, 2, 3])
            ops += [(rng.choice(["RD", "RD.NOT"]), rng.choice(bits), 0), ("JMP", None, coils)]
            open_jumps += coils == 0
            continue
        if roll < 0.35 and open_jumps:
            ops.append(("JMPE", None, 0))
            open_jumps -= 1
            continue
        ops.append((rng.choice(["RD", "RD.NOT"]), rng.choice(bits), 0))
        depth = 0
        for _ in range(rng.randint(0, 8)):
            step = rng.random()
            if step < 0.2 and depth < 8:
                ops.append((rng.choice(["RD.STK", "RD.NOT.STK"]), rng.choice(bits), 0))
                depth += 1
            elif step < 0.35 and depth:
                ops.append((rng.choice(["AND.STK", "OR.STK"]), None, 0))
                depth -= 1
            elif step < 0.55:
                ops.append((rng.choice(["WRT", "WRT.NOT"]), rng.choice(bits), 0))
            else:
                ops.append((rng.choice(["AND", "AND.NOT", "OR", "OR.NOT"]), rng.choice(bits), 0))
        ops += [("OR.STK", None, 0)] * depth
        ops.append((rng.choice(["WRT", "WRT.NOT"]), rng.choice(bits), 0))
    ops += [("JMPE", None, 0)] * open_jumps
    return ops


def text_of(program: list[Op]) -> str:
    """The program as ladder lines."""
    return "\n".join(f"JMP {coils}" if name == "JMP" else name if operand is None
                     else f"{name} {operand}" for name, operand, coils in program)


@settings(max_examples=examples(80), deadline=None)
@given(seed=st.integers(0, 10**6), monitored=st.booleans())
def test_generated_jumps_match_the_reference_interpreter(seed: int, monitored: bool) -> None:
    rng = random.Random(seed)
    program = random_program(rng, rng.randint(1, 10))
    assert_matches_reference(text_of(program), lambda engine: reference_scan(program, engine),
                             rng, monitored)
