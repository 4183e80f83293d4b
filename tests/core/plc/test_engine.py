"""The scan engine: clock, stop/cold start, forcing, disabling, power flow, trace, JMP and COM."""

from __future__ import annotations

import random

from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.address import Area
from ladderworks.core.compiler import SourcePosition
from ladderworks.core.plc.codegen import compiled
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.functions.timers import write_timer_preset
from tests.core.plc.conftest import (
    assert_matches_reference,
    at,
    bit,
    engine_for,
    stack_step,
)
from tests.hypothesis_profiles import examples

SELF_HOLD = """
RD X0.0
OR Y0.0
AND.NOT X0.1
WRT Y0.0
"""


def test_clock_advances_one_period_per_scan() -> None:
    engine = engine_for(SELF_HOLD, period_ms=4)
    assert engine.step(10) == 3  # scans at 0, 4, 8
    assert engine.now_ms == 12
    engine.run_scans(2)
    assert (engine.now_ms, engine.scan_count) == (20, 5)


def test_stop_clears_outputs_and_keeps_keep_relays_and_data() -> None:
    engine = engine_for(SELF_HOLD + "\nRD X0.0\nWRT K1.0\nRD X0.0\nWRT R5.0")
    engine.memory.set_bit(at("X0.0"), 1)
    engine.memory.write(at("D7"), 99)
    engine.scan()
    engine.stop()
    assert engine.memory.read(at("Y0")) == 0
    assert (bit(engine, "K1.0"), engine.memory.read(at("D7")), bit(engine, "R5.0")) == (1, 99, 1)


def test_cold_start_clears_relays_and_timer_states_but_keeps_k_d_t_c() -> None:
    engine = engine_for("RD X0.0\nTMR 9\nWRT R0.1\nRD X0.0\nWRT K0.0")
    write_timer_preset(engine.memory, 9, 80)
    engine.memory.write(at("D3"), 7)
    engine.memory.set_bit(at("X0.0"), 1)
    engine.step(64)
    engine.cold_start()
    assert (bit(engine, "R0.1"), bit(engine, "K0.0")) == (0, 1)
    assert engine.memory.read(at("T32"), 4) == 80 and engine.memory.read(at("D3")) == 7
    engine.step(72)  # the timer starts again from zero
    assert bit(engine, "R0.1") == 0
    engine.step(16)
    assert bit(engine, "R0.1") == 1


def test_force_holds_an_input_against_the_machine() -> None:
    engine = engine_for(SELF_HOLD)
    engine.force(at("X0.1"), 1)
    engine.memory.set_bit(at("X0.0"), 1)
    engine.memory.set_bit(at("X0.1"), 0)  # the machine says 0 ...
    engine.scan()
    assert bit(engine, "Y0.0") == 0  # ... the forced 1 wins
    assert engine.release(at("X0.1"))
    engine.memory.set_bit(at("X0.1"), 0)
    engine.scan()
    assert bit(engine, "Y0.0") == 1


def test_force_holds_an_output_against_the_logic() -> None:
    engine = engine_for(SELF_HOLD)
    engine.force(at("Y0.0"), 1)
    engine.scan()
    assert bit(engine, "Y0.0") == 1
    engine.force(at("Y0.0"), 0)
    engine.memory.set_bit(at("X0.0"), 1)
    engine.scan()
    assert bit(engine, "Y0.0") == 0


def test_disabled_contact_is_open() -> None:
    engine = engine_for(SELF_HOLD)
    engine.memory.set_bit(at("X0.0"), 1)
    engine.disable(0)  # RD X0.0
    engine.scan()
    assert bit(engine, "Y0.0") == 0
    engine.enable(0)
    engine.scan()
    assert bit(engine, "Y0.0") == 1


def test_disabled_or_contact_and_inverted_contact_are_open() -> None:
    engine = engine_for("RD X0.0\nOR.NOT X0.1\nWRT Y0.0")
    engine.disable(1)
    engine.scan()
    assert bit(engine, "Y0.0") == 0  # OR.NOT X0.1 would have closed
    engine.enable(1)
    engine.scan()
    assert bit(engine, "Y0.0") == 1


def test_disabled_coil_is_not_written_and_keeps_its_value() -> None:
    engine = engine_for(SELF_HOLD)
    engine.memory.set_bit(at("X0.0"), 1)
    engine.scan()
    index = engine.disable(SourcePosition(0, 3, 0, 0))
    assert index == 3
    engine.memory.set_bit(at("X0.1"), 1)
    engine.scan()
    assert bit(engine, "Y0.0") == 1


def test_disabled_function_is_not_executed() -> None:
    engine = engine_for("RD X0.0\nTMR 9\nWRT R0.1")
    engine.memory.set_bit(at("X0.0"), 1)
    engine.disable((0, 1))
    engine.step(80)
    assert bit(engine, "R0.1") == 0
    engine.enable((0, 1))
    engine.scan()
    assert bit(engine, "R0.1") == 1  # preset 0: on in the first executed scan


def test_forces_are_listed_in_one_place() -> None:
    engine = engine_for(SELF_HOLD)
    engine.force(at("X0.1"), 0)
    engine.force(at("Y0.0"), 1)
    engine.disable(2)
    line = engine.program.ops[2].source.line
    assert [str(entry) for entry in engine.forces()] == [
        "force X0.1 = 0", "force Y0.0 = 1", f"disable op 2 (line {line})"]
    engine.release_all()
    assert engine.forces() == []


def test_monitored_scan_records_the_power_flow_of_every_op() -> None:
    engine = engine_for("RD X0.0\nAND X0.1\nRD.STK X0.2\nAND.NOT X0.3\nOR.STK\nWRT Y0.0")
    engine.monitored = True
    engine.memory.set_bit(at("X0.0"), 1)
    engine.memory.set_bit(at("X0.2"), 1)
    engine.scan()
    assert list(engine.power_flow) == [1, 0, 1, 1, 1, 1]
    flow = engine.power_flow_map()
    assert [(position.line, on) for position, on in flow] == [
        (2, True), (3, False), (4, True), (5, True), (6, True), (7, True)]


def test_monitored_mode_keeps_timer_state_when_switched_on() -> None:
    engine = engine_for("RD X0.0\nTMR 9\nWRT R0.1")
    write_timer_preset(engine.memory, 9, 40)
    engine.memory.set_bit(at("X0.0"), 1)
    engine.step(32)
    engine.monitored = True
    engine.scan()
    assert bit(engine, "R0.1") == 0
    engine.scan()
    assert bit(engine, "R0.1") == 1
    assert list(engine.power_flow) == [1, 1, 1]


def test_trace_samples_every_period_without_loss() -> None:
    engine = engine_for(SELF_HOLD)
    trace = engine.start_trace([at("X0.0"), at("Y0.0"), at("Y0")], 16)
    for scan in range(40):
        engine.memory.set_bit(at("X0.0"), scan == 5)
        engine.memory.set_bit(at("X0.1"), scan == 30)
        engine.scan()
    samples = trace.take()
    assert [s.time_ms for s in samples] == list(range(0, 320, 16))
    assert [s.seq for s in samples] == list(range(20))
    assert samples[2].values == (0, 0, 0)
    assert samples[3].values == (0, 1, 1)  # at 48 ms: X0.0 went back to 0, Y0.0 held
    assert samples[15].values == (0, 0, 0)
    assert trace.take() == []
    assert trace.dropped == 0


def test_trace_ring_buffer_counts_what_it_overwrites() -> None:
    engine = engine_for(SELF_HOLD)
    trace = engine.start_trace([at("Y0.0")], 8, capacity=5)
    engine.run_scans(12)
    samples = trace.take()
    assert [s.seq for s in samples] == [7, 8, 9, 10, 11]
    assert trace.dropped == 7


def test_jmp_skips_to_jmpe_and_skipped_coils_keep_their_state() -> None:
    engine = engine_for("""
RD X0.0
JMP 0
RD X0.1
WRT Y0.1
RD X0.1
TMR 9
WRT Y0.2
JMPE
RD X0.1
WRT Y0.3
""")
    engine.memory.set_bit(at("X0.1"), 1)
    engine.scan()
    assert [bit(engine, f"Y0.{n}") for n in (1, 2, 3)] == [1, 1, 1]
    engine.memory.set_bit(at("X0.0"), 1)  # jump: Y0.1 and Y0.2 are frozen
    engine.memory.set_bit(at("X0.1"), 0)
    engine.scan()
    assert [bit(engine, f"Y0.{n}") for n in (1, 2, 3)] == [1, 1, 0]
    engine.memory.set_bit(at("X0.0"), 0)
    engine.scan()
    assert [bit(engine, f"Y0.{n}") for n in (1, 2, 3)] == [0, 0, 0]


def test_com_off_writes_zero_to_the_coils_up_to_come() -> None:
    engine = engine_for("""
RD X0.0
COM 0
RD X0.1
WRT Y0.1
RD X0.1
WRT.NOT Y0.2
COME
RD X0.1
WRT Y0.3
""")
    engine.memory.set_bit(at("X0.0"), 1)
    engine.memory.set_bit(at("X0.1"), 1)
    engine.scan()
    assert [bit(engine, f"Y0.{n}") for n in (1, 2, 3)] == [1, 0, 1]
    engine.memory.set_bit(at("X0.1"), 0)
    engine.scan()
    assert [bit(engine, f"Y0.{n}") for n in (1, 2, 3)] == [0, 1, 0]
    engine.memory.set_bit(at("X0.0"), 0)  # COM off: both coils in the range are 0
    engine.scan()
    assert [bit(engine, f"Y0.{n}") for n in (1, 2, 3)] == [0, 0, 0]
    engine.memory.set_bit(at("X0.1"), 1)
    engine.scan()
    assert [bit(engine, f"Y0.{n}") for n in (1, 2, 3)] == [0, 0, 1]


def test_com_with_a_coil_count_covers_that_many_coils() -> None:
    engine = engine_for("RD X0.0\nCOM 1\nRD X0.1\nWRT Y0.1\nRD X0.1\nWRT Y0.2")
    engine.memory.set_bit(at("X0.1"), 1)
    engine.scan()
    assert (bit(engine, "Y0.1"), bit(engine, "Y0.2")) == (0, 1)


def test_system_relay_clocks() -> None:
    engine = engine_for(SELF_HOLD)
    ones, clock = [], []
    for _ in range(50):  # 400 ms
        engine.scan()
        ones.append(bit(engine, "R9091.1") - bit(engine, "R9091.0"))
        clock.append(bit(engine, "R9091.5"))
    assert set(ones) == {1}
    assert clock[:26] == [1] * 13 + [0] * 12 + [1]  # 104 ms on, 96 ms off


# -- the generated code against a straightforward reference interpreter ----------------------

CONTACTS = ["RD", "RD.NOT", "AND", "AND.NOT", "OR", "OR.NOT"]


def reference_scan(program: list[tuple[str, str | None]], engine: ScanEngine) -> None:
    """The program run op by op with an explicit stack list, on the engine's memory."""
    memory = engine.memory
    stack = [0]
    for name, operand in program:
        if name == "WRT":
            memory.set_bit(at(operand or ""), stack[-1])
        elif name == "WRT.NOT":
            memory.set_bit(at(operand or ""), stack[-1] ^ 1)
        else:
            stack_step(stack, name, memory.bit(at(operand)) if operand else 0)


def random_program(rng: random.Random, networks: int) -> list[tuple[str, str | None]]:
    bits = [f"R{b}.{k}" for b in range(3) for k in range(8)]
    ops: list[tuple[str, str | None]] = []
    for _ in range(networks):
        ops.append((rng.choice(["RD", "RD.NOT"]), rng.choice(bits)))
        depth = 0
        for _ in range(rng.randint(0, 12)):
            roll = rng.random()
            if roll < 0.2 and depth < 8:
                ops.append((rng.choice(["RD.STK", "RD.NOT.STK"]), rng.choice(bits)))
                depth += 1
            elif roll < 0.35 and depth:
                ops.append((rng.choice(["AND.STK", "OR.STK"]), None))
                depth -= 1
            elif roll < 0.45:
                ops.append((rng.choice(["WRT", "WRT.NOT"]), rng.choice(bits)))
            else:
                ops.append((rng.choice(CONTACTS[2:]), rng.choice(bits)))
        ops.extend([("OR.STK", None)] * depth)
        ops.append((rng.choice(["WRT", "WRT.NOT"]), rng.choice(bits)))
    return ops


@settings(max_examples=examples(60), deadline=None)
@given(seed=st.integers(0, 10**6), monitored=st.booleans())
def test_generated_scan_matches_the_reference_interpreter(seed: int, monitored: bool) -> None:
    rng = random.Random(seed)
    program = random_program(rng, rng.randint(1, 6))
    text = "\n".join(name if operand is None else f"{name} {operand}" for name, operand in program)
    assert_matches_reference(text, lambda engine: reference_scan(program, engine), rng, monitored)


def test_very_long_and_alternating_networks_compile_and_run() -> None:
    series = "\n".join(f"AND.NOT R{k // 8}.{k % 8}" for k in range(3000))
    alternating = "\n".join(f"{'AND' if k % 2 else 'OR'} R{k // 8}.{k % 8}" for k in range(500))
    engine = engine_for(f"RD X0.0\n{series}\nWRT Y0.0\nRD X0.0\n{alternating}\nWRT Y0.1")
    engine.memory.set_bit(at("X0.0"), 1)
    engine.scan()
    assert bit(engine, "Y0.0") == 1  # every R bit is 0, so every AND.NOT passes
    # (((X0.0 OR R0.0) AND R0.1) OR R0.2) ...: ends with AND R62.3 = 0
    assert bit(engine, "Y0.1") == 0
    engine.memory.areas[Area.R][62] = 0b1100  # OR R62.2 then AND R62.3
    engine.scan()
    assert bit(engine, "Y0.1") == 1


def test_disabled_coil_still_counts_in_a_com_range() -> None:
    engine = engine_for("RD X0.0\nCOM 1\nRD X0.1\nWRT Y0.1\nRD X0.1\nWRT Y0.2")
    engine.disable(3)
    engine.memory.set_bit(at("X0.1"), 1)
    engine.scan()
    assert (bit(engine, "Y0.1"), bit(engine, "Y0.2")) == (0, 1)


def test_power_flow_shows_a_jump_taken_and_the_skipped_ops_off() -> None:
    engine = engine_for("RD X0.0\nJMP 0\nRD X0.1\nWRT Y0.1\nJMPE\nRD X0.1\nWRT Y0.2")
    engine.monitored = True
    engine.memory.set_bit(at("X0.1"), 1)
    engine.scan()
    assert list(engine.power_flow) == [0, 0, 1, 1, 0, 1, 1]
    engine.memory.set_bit(at("X0.0"), 1)
    engine.scan()
    assert list(engine.power_flow) == [1, 1, 0, 0, 0, 1, 1]


def test_engines_of_one_program_share_compiled_code_but_not_memory_or_state() -> None:
    program = "RD X0.0\nTMR 9\nWRT R0.1\nRD X0.1\nOR Y0.0\nWRT Y0.0"
    first, second = engine_for(program), engine_for(program)
    assert first.source == second.source
    assert compiled.cache_info().hits > 0  # the second engine's code came from the cache
    for engine in (first, second):
        write_timer_preset(engine.memory, 9, 40)
    first.memory.set_bit(at("X0.0"), 1)
    first.memory.set_bit(at("X0.1"), 1)
    first.step(48)
    assert (bit(first, "R0.1"), bit(first, "Y0.0")) == (1, 1)
    assert (bit(second, "R0.1"), bit(second, "Y0.0")) == (0, 0)
    second.memory.set_bit(at("X0.0"), 1)
    second.step(32)  # its own timer started at its own first scan: not yet 40 ms
    assert bit(second, "R0.1") == 0
    second.step(16)
    assert bit(second, "R0.1") == 1
