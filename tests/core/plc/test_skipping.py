"""Skipped scans are exact: after every run of scans, memory and every state equal every-scan mode.

Each program runs on two engines, one running every scan (`every_scan`) and one skipping the
scans of a repeating state (core/plc/skipping.py), with the same changes written between runs
(X and F bytes, R bytes written from outside as the GUI does, forced and released bits,
disabled elements, cold starts) and runs of 1 to 80 scans (`advance`); after every run all
areas, the clock, the scan count, every call site's state, the edge memories, the A-area log
and (monitored) the power flow must be equal. Programs: every example (PMC, Delta, Fatek),
the three real programs and random programs (hypothesis) with levels, JMP/COM ranges,
subprograms called twice, timers, edges shared by number, R9091 clocks, result-register
readers and bits written by several networks.
"""

from __future__ import annotations

import random
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.address import Address, Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.compiler.binary import BinaryProgram, decode
from ladderworks.core.il import parse, parse_file
from ladderworks.core.plc.engine import ScanEngine
from tests.hypothesis_profiles import examples
from tests.real_programs import real_programs_dir

EXAMPLES = Path(__file__).resolve().parents[3] / "resources" / "examples"


def binary_of(text: str) -> BinaryProgram:
    """The compiled binary of a program text (it must compile)."""
    result = compile_program(parse(text).program)
    assert result.binary is not None, [d.message() for d in result.diagnostics][:3]
    return decode(result.binary)


def pair(binary: BinaryProgram, divisions: int = 1,
         monitored: bool = False) -> tuple[ScanEngine, ScanEngine]:
    """An every-scan engine and a skipping one of the same program."""
    full = ScanEngine(binary, divisions=divisions, monitored=monitored)
    fast = ScanEngine(binary, divisions=divisions, monitored=monitored)
    full.every_scan = True
    assert not fast.every_scan
    return full, fast


def differences(full: ScanEngine, fast: ScanEngine) -> list[str]:
    """What differs between the two engines (at most 5 things)."""
    found = []
    for area in Area:
        a, b = full.memory.areas[area], fast.memory.areas[area]
        if a != b:
            found += [f"{area.value}{i}: {a[i]} != {b[i]}" for i in range(len(a)) if a[i] != b[i]]
    for name in ("now_ms", "scan_count"):
        if getattr(full, name) != getattr(fast, name):
            found.append(f"{name}: {getattr(full, name)} != {getattr(fast, name)}")
    states = [i for i, (a, b) in enumerate(zip(full._states, fast._states, strict=True))
              if a != b]
    found += [f"op {i}: {full._states[i]} != {fast._states[i]}" for i in states]
    if full._ctx.edges != fast._ctx.edges:
        found.append(f"edges: {full._ctx.edges} != {fast._ctx.edges}")
    if full.take_alarm_changes() != fast.take_alarm_changes():
        found.append("the A-area logs differ")
    if full.monitored and full.power_flow != fast.power_flow:
        found.append("the power flows differ")
    return found[:5]


class Driver:
    """Writes the same changes into both engines between scans."""

    def __init__(self, engines: tuple[ScanEngine, ScanEngine], rng: random.Random,
                 inputs: list[Address], outside: list[Address], force: list[Address]) -> None:
        self.engines = engines
        self.rng = rng
        self.inputs, self.outside, self.force_bits = inputs, outside, force

    def change(self, rate: float = 0.1) -> None:
        """Maybe change some inputs (each kind with its own probability)."""
        rng = self.rng
        if self.inputs and rng.random() < rate:
            address = rng.choice(self.inputs)
            value = rng.randrange(256) if rng.random() < 0.5 else 1 << rng.randrange(8)
            for engine in self.engines:
                engine.memory.areas[address.area][address.byte] = value
        if self.outside and rng.random() < rate / 4:
            address = rng.choice(self.outside)
            value = rng.randrange(256)
            for engine in self.engines:
                engine.memory.write(address, value)
        if self.force_bits and rng.random() < rate / 4:
            address = rng.choice(self.force_bits)
            forced = rng.random() < 0.6
            value = rng.random() < 0.5
            for engine in self.engines:
                if forced:
                    engine.force(address, value)
                else:
                    engine.release(address)

    def run(self, scans: int, rate: float = 0.1, longest: int = 80) -> int:
        """Run both engines for about `scans` scans in runs of 1..`longest`, changing inputs
        between runs; compare after every run. The scans the skipping engine skipped."""
        full, fast = self.engines
        skipped = fast.skipped
        end = full.now_ms + scans * full.period_ms
        while full.now_ms < end:
            self.change(rate)
            limit = full.now_ms + self.rng.randint(1, longest) * full.period_ms
            assert full.advance(limit) == fast.advance(limit)
            found = differences(full, fast)
            assert not found, (full.now_ms, found)
        return fast.skipped - skipped


def bytes_of(area: Area, count: int) -> list[Address]:
    """The first `count` bytes of an area."""
    return [Address(area, byte) for byte in range(count)]


def program_inputs(binary: BinaryProgram) -> tuple[list[Address], list[Address], list[Address]]:
    """A program's input bytes (X, F it reads), R/D bytes it uses, and bits it writes."""
    inputs: set[Address] = set()
    used: set[Address] = set()
    coils: set[Address] = set()
    for op in binary.ops:
        operand = op.operand
        if operand is None:
            continue
        byte = Address(operand.area, operand.byte)
        if operand.area in (Area.X, Area.F):
            inputs.add(byte)
        elif operand.area in (Area.R, Area.D) and operand.byte < 9000:
            used.add(byte)
        if op.spec.is_coil and operand.area is not Area.A:
            coils.add(operand)
    return sorted(inputs), sorted(used), sorted(coils)


# -- the examples ------------------------------------------------------------------------------

EXAMPLE_FILES = sorted([*EXAMPLES.glob("*.LAD"), *(EXAMPLES / "delta").glob("*.txt"),
                        *(EXAMPLES / "fatek").glob("*.txt"), *(EXAMPLES / "fatek").glob("*.lst"),
                        *(EXAMPLES / "s7").glob("*/*.s7dcl")])


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: f"{p.parent.name}/{p.stem}")
def test_every_example_runs_the_same_skipping_scans(path: Path) -> None:
    result = parse_file(path)
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    binary = decode(compiled.binary)
    engines = pair(binary)
    inputs, used, coils = program_inputs(binary)
    driver = Driver(engines, random.Random(path.stem), inputs or bytes_of(Area.X, 4),
                    used, (inputs and [Address(a.area, a.byte, 0) for a in inputs[:2]]) + coils[:4])
    driver.run(3000, rate=0.05)
    for engine in engines:
        engine.cold_start()
    driver.run(400, rate=0.2)


# -- random programs --------------------------------------------------------------------------

BITS = [f"R{byte}.{bit}" for byte in range(4) for bit in range(8)]
INPUTS = [f"X{byte}.{bit}" for byte in range(2) for bit in range(8)]


def contacts(rng: random.Random) -> list[str]:
    """A random series/parallel condition over inputs and relays."""
    lines = [f"{rng.choice(['RD', 'RD.NOT'])} {rng.choice(INPUTS + BITS)}"]
    depth = 0
    for _ in range(rng.randint(0, 5)):
        roll = rng.random()
        if roll < 0.15 and depth < 3:
            lines.append(f"{rng.choice(['RD.STK', 'RD.NOT.STK'])} {rng.choice(INPUTS + BITS)}")
            depth += 1
        elif roll < 0.3 and depth:
            lines.append(rng.choice(["AND.STK", "OR.STK"]))
            depth -= 1
        else:
            word = rng.choice(["AND", "AND.NOT", "OR", "OR.NOT"])
            source = rng.choice(INPUTS + BITS + ["R9091.5", "R9091.6", "R9000.0", "R9000.1"])
            lines.append(f"{word} {source}")
    lines += ["OR.STK"] * depth
    return lines


def network(rng: random.Random) -> list[str]:
    """One random network: coils, or a functional instruction."""
    lines = contacts(rng)
    roll = rng.random()
    target = rng.choice(BITS)
    if roll < 0.45:
        for _ in range(rng.randint(1, 2)):
            lines.append(f"{rng.choice(['WRT', 'WRT.NOT', 'SET', 'RST'])} {rng.choice(BITS)}")
    elif roll < 0.55:
        timer = rng.choice([f"TMRB {rng.randint(1, 3)}", f"TMRBF {rng.randint(4, 5)}"])
        lines += [f"{timer} {rng.choice([0, 16, 40, 96, 400, 1000])}", f"WRT {target}"]
    elif roll < 0.65:
        lines += [f"{rng.choice(['DIFU', 'DIFD'])} {rng.randint(1, 2)}", f"WRT {target}"]
    elif roll < 0.75:
        lines += [f"MOVB R{rng.randrange(4)} R{rng.randrange(4, 6)}"]
    elif roll < 0.85:
        lines += [f"NUMEB 1 {rng.randrange(4)} R{rng.randrange(4, 6)}"]
    elif roll < 0.95:
        lines += [f"COMPB 1001 R{rng.randrange(4, 6)} R{rng.randrange(4)}",
                  f"RD R9000.{rng.randrange(2)}", f"WRT {target}"]
    else:
        lines += [f"ADDB 1 R{rng.randrange(4, 6)} 1 R{rng.randrange(4, 6)}"]
    return lines


def block(rng: random.Random, count: int, calls: int) -> list[str]:
    """Networks with JMP 0 / JMP n / COM ranges and calls of P1..P`calls`."""
    lines: list[str] = []
    open_jumps = open_commons = 0
    for _ in range(count):
        roll = rng.random()
        if roll < 0.1:
            lines += [f"RD {rng.choice(INPUTS + BITS)}", f"JMP {rng.choice([0, 0, 1, 2])}"]
            open_jumps += lines[-1] == "JMP 0"
        elif roll < 0.15 and open_jumps:
            lines.append("JMPE")
            open_jumps -= 1
        elif roll < 0.2:
            lines += [f"RD {rng.choice(INPUTS + BITS)}", "COM 0"]
            open_commons += 1
        elif roll < 0.25 and open_commons:
            lines.append("COME")
            open_commons -= 1
        elif roll < 0.35 and calls:
            number = rng.randint(1, calls)
            lines += [f"RD {rng.choice(INPUTS + BITS)}", f"CALL P{number}"] \
                if rng.random() < 0.5 else [f"CALLU P{number}"]
        else:
            lines += network(rng)
    return lines + ["COME"] * open_commons + ["JMPE"] * open_jumps


def random_program(rng: random.Random) -> str:
    """A random program: plain, or FANUC-shaped with levels and subprograms."""
    if rng.random() < 0.3:
        body = block(rng, rng.randint(1, 12), 0)
    else:
        subprograms = rng.randint(0, 3)
        body = [*block(rng, rng.randint(1, 5), 0), "END1"]
        body += block(rng, rng.randint(1, 10), subprograms)
        body += [f"CALLU P{n}" for n in range(1, subprograms + 1)] + ["END2"]
        for number in range(1, subprograms + 1):
            body += [f"SP P{number}", *block(rng, rng.randint(1, 6), number - 1), "SPE"]
        body.append("END")
    return "%@3\n" + "\n".join(body) + "\n%\n"


@settings(max_examples=examples(200), deadline=None)
@given(seed=st.integers(0, 10**9), divisions=st.sampled_from([1, 1, 2]),
       monitored=st.booleans())
def test_random_programs_run_the_same_skipping_scans(seed: int, divisions: int,
                                                     monitored: bool) -> None:
    rng = random.Random(seed)
    text = random_program(rng)
    result = compile_program(parse(text).program)
    if result.binary is None:  # a range the generator left open across a level end
        return
    engines = pair(decode(result.binary), divisions, monitored)
    inputs = bytes_of(Area.X, 2)
    driver = Driver(engines, rng, inputs, bytes_of(Area.R, 6),
                    [Address(Area.X, 0, 1), Address(Area.R, 1, 2), Address(Area.R, 0, 0),
                     Address(Area.R, 9091, 5)])
    driver.run(400, rate=0.2)
    driver.run(3000, rate=0.02, longest=600)  # runs of more than two rounds of the clocks
    for op in rng.sample(range(len(engines[0].program.ops)), k=1):
        for engine in engines:
            engine.disable(op)
    driver.run(100, rate=0.2)
    for engine in engines:
        engine.release_all()
        engine.cold_start()
    driver.run(100, rate=0.2)


def test_a_quiet_program_skips_to_the_timer_and_the_end() -> None:
    text = "%@3\nRD X0.0\nTMRB 1 800\nWRT R0.1\nRD X0.1\nWRT R0.2\n%\n"
    full, fast = pair(binary_of(text))
    driver = Driver((full, fast), random.Random(1), [], [], [])
    for engine in (full, fast):
        engine.memory.set_bit(Address(Area.X, 0, 0), 1)
        assert engine.advance(792) == 99  # the timer reaches 800 ms in the scan at 800
        assert engine.memory.bit(Address(Area.R, 0, 1)) == 0
        engine.advance(801)
        assert engine.memory.bit(Address(Area.R, 0, 1)) == 1
    assert fast.skipped > 80 and full.skipped == 0
    assert driver.run(10_000, rate=0.0, longest=2000) > 9_000  # nothing changes: skipped
    assert not differences(full, fast)


def test_a_scan_toggling_bit_is_a_cycle_of_two() -> None:
    text = "%@3\nRD.NOT R0.0\nWRT R0.0\nRD R0.0\nAND X0.0\nWRT R0.1\n%\n"
    full, fast = pair(binary_of(text))
    driver = Driver((full, fast), random.Random(2), bytes_of(Area.X, 1), [], [])
    assert driver.run(5_000, rate=0.02) > 4_000


def test_a_clock_the_program_reads_ends_each_skip_or_whole_rounds_are_skipped() -> None:
    text = "%@3\nRD.NOT R0.0\nWRT R0.0\nRD R9091.5\nWRT R0.1\nRD R9091.6\nWRT R0.2\n%\n"
    full, fast = pair(binary_of(text))
    driver = Driver((full, fast), random.Random(2), [], [], [])
    # runs shorter than two rounds (1 s: the clocks' common period): skips end at the edges
    skipped = driver.run(5_000, rate=0.0, longest=100)
    assert 2_000 < skipped < 4_500  # R9091.5 changes every 96-104 ms (12-13 scans)
    # long runs: the state at a round's start comes back, whole rounds are skipped
    assert driver.run(50_000, rate=0.0, longest=5_000) > 48_000


def test_no_scan_is_skipped_while_a_trace_samples() -> None:
    text = "%@3\nRD.NOT R0.0\nWRT R0.0\n%\n"
    engine = ScanEngine(binary_of(text))
    engine.start_trace([Address(Area.R, 0)], 8)
    engine.advance(8000)
    assert engine.skipped == 0 and len(engine.trace.take()) == 1000  # type: ignore[union-attr]
    engine.stop_trace()
    engine.advance(16_000)
    assert engine.skipped > 990  # of 1000: R9091's clocks are not read


def test_waitfor_stops_at_the_scan_a_skipped_run_would_reach() -> None:
    text = "%@3\nRD X0.0\nTMRB 1 400\nWRT R0.1\n%\n"
    full, fast = pair(binary_of(text))
    seen = []
    for engine in (full, fast):
        engine.memory.set_bit(Address(Area.X, 0, 0), 1)
        engine.advance(5000, lambda e=engine: e.memory.bit(Address(Area.R, 0, 1)) == 1)
        seen.append(engine.now_ms)
    assert seen == [408, 408] and fast.skipped > 0


# -- the real programs ----------------------------------------------------------------------


def real_pair(name: str) -> tuple[tuple[ScanEngine, ScanEngine], BinaryProgram]:
    """Both engines of a real program, from a cold start."""
    result = parse_file(real_programs_dir() / f"{name}.txt")
    compiled = compile_program(result.program)
    assert compiled.binary is not None
    binary = decode(compiled.binary)
    return pair(binary), binary


def run_real(name: str, scans: int) -> None:
    """Run a real program in both modes with its inputs changing."""
    engines, binary = real_pair(name)
    inputs, used, coils = program_inputs(binary)
    rng = random.Random(name)
    driver = Driver(engines, rng, inputs, used[:200], coils[:20])
    assert driver.run(scans, rate=0.1) > 0
    assert driver.run(scans, rate=0.01, longest=400) > 0  # more than two rounds of the clocks


@pytest.mark.parametrize("name", ["FANUC_STUDER_X22_P036", "FANUC_STUDER_S41_F036",
                                  "FANUC_STUDER_S41_F034"])
def test_real_programs_run_the_same_skipping_scans(name: str) -> None:
    run_real(name, 800)


# -- the command line --------------------------------------------------------------------------


def test_cli_test_and_run_take_every_scan(capsys: pytest.CaptureFixture[str]) -> None:
    from ladderworks.cli import main

    program = str(EXAMPLES / "timer_relay.LAD")
    scenario = str(EXAMPLES / "timer_relay.scenario.csv")
    outputs = []
    for extra in ([], ["--every-scan"]):
        assert main(["test", program, scenario, *extra]) == 0
        outputs.append(capsys.readouterr().out.split(": passed")[0])
        assert main(["run", program, "--ms", "2000", "--set", "R1.4=1", "--print", "R1.7",
                     *extra]) == 0
        outputs.append(capsys.readouterr().out)
    assert outputs[0] == outputs[2] and outputs[1] == outputs[3]  # the same results
    assert "R1.7 = 1" in outputs[3]


def test_a_clock_is_read_by_a_contact_on_it_or_a_parameter_over_its_byte() -> None:
    from ladderworks.core.plc.engine import SYSTEM_CLOCKS
    from ladderworks.core.plc.skipping import clocks_read

    fast, slow = SYSTEM_CLOCKS
    for text, read in (("RD R9091.5\nWRT R0.0", (fast,)), ("RD R9091.1\nWRT R0.0", ()),
                       ("RD R0.0\nMOVB R9091 R1", (fast, slow)),
                       ("RD R0.0\nMOVW R9090 R2", (fast, slow)),
                       ("RD R0.0\nMOVW R9092 R2", ())):
        binary = binary_of(f"%@3\n{text}\n%\n")
        assert clocks_read(binary.ops, SYSTEM_CLOCKS, binary.dialect) == read, text
