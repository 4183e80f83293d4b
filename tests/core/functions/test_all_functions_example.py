"""resources/examples/all_functions.LAD through the compiler and the engine: every functional
instruction, 10,000 scans, the 12-station turret and the ring counter of the seed manual."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.cli import main
from ladderworks.core import instructions as it
from ladderworks.core.address import parse_address
from ladderworks.core.compiler import compile_program
from ladderworks.core.il import parse_file
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.functions.counters import counter_value_address, write_counter_preset
from tests.core.functions.conftest import at

EXAMPLE = Path(__file__).resolve().parents[3] / "resources" / "examples" / "all_functions.LAD"


@pytest.fixture(scope="module")
def binary() -> bytes:
    """The compiled example."""
    parsed = parse_file(EXAMPLE)
    assert parsed.ok, [str(d) for d in parsed.diagnostics]
    compiled = compile_program(parsed.program)
    assert compiled.binary is not None, [str(d) for d in compiled.diagnostics]
    assert not compiled.diagnostics
    return compiled.binary


def test_uses_every_functional_instruction() -> None:
    parsed = parse_file(EXAMPLE)
    used = {ins.name for ins in parsed.program.instructions()}
    assert {spec.name for spec in it.SEED_FUNCTIONS} <= used


def test_runs_ten_thousand_scans(binary: bytes) -> None:
    engine = ScanEngine(binary)
    engine.run_scans(10_000)
    assert engine.scan_count == 10_000
    memory = engine.memory
    seconds = engine.now_ms // 1000
    # ADD counts the 1 s clock in BCD and starts again after 99
    assert memory.read_bcd(at("R80"), 1) in (seconds % 100, (seconds - 1) % 100)
    assert memory.read(at("D200"), 2) == 10_000  # ADDB once a scan
    assert memory.read(at("R9002"), 2) == 10_000 % 7  # DIVB's remainder, the last binary op
    assert memory.read(at("R100"), 2) in {1 << k for k in range(16)}  # SFT walks one bit
    assert memory.read(at("R12"), 2) == 0x0027  # COD row 0, 4 digits
    assert memory.read(at("D8"), 2) == 1000  # CODB row 0


def _turret_scan(engine: ScanEngine, current: int, target: int) -> None:
    memory = engine.memory
    memory.write_bcd(at("X41"), current, 1)
    memory.write_bcd(at("F26"), target, 1)
    memory.set_bit(at("F7.3"), 1)  # TF
    engine.scan()


def test_turret_every_pair(binary: bytes) -> None:
    engine = ScanEngine(binary)
    memory = engine.memory
    for current in range(1, 13):
        for target in range(1, 13):
            _turret_scan(engine, current, target)
            forward = (target - current) % 12
            backward = (current - target) % 12
            reverse = backward < forward
            steps = backward if reverse else forward
            before = (target + (1 if reverse else -1) - 1) % 12 + 1
            assert memory.bit(at("R231.0")) == reverse, (current, target)
            assert memory.read_bcd(at("R230"), 1) == before, (current, target)
            assert memory.read_bcd(at("R232"), 1) == steps, (current, target)
            assert memory.bit(at("R233.0")) == (current == target)


def test_turret_slow_down_one_before(binary: bytes) -> None:
    engine = ScanEngine(binary)
    _turret_scan(engine, 2, 11)
    assert engine.memory.read_bcd(at("R230"), 1) == 12
    _turret_scan(engine, 12, 11)  # the turret reaches the slow-down station
    assert engine.memory.bit(at("R233.1")) == 1


def test_ring_counter_counts_stations_1_to_12(binary: bytes) -> None:
    engine = ScanEngine(binary)
    memory = engine.memory
    write_counter_preset(memory, 2, 12)
    pulse = parse_address("X36.0")
    seen, at_twelve = [], []
    for _ in range(24):
        memory.set_bit(pulse, 1)
        engine.scan()
        seen.append(memory.read(counter_value_address(2), 2))
        at_twelve.append(memory.bit(at("R200.0")))
        memory.set_bit(pulse, 0)
        engine.scan()
        assert memory.read(counter_value_address(2), 2) == seen[-1]  # no count on the fall
    assert seen == list(range(1, 13)) * 2
    assert at_twelve == ([0] * 11 + [1]) * 2


def test_cli_runs_ten_thousand_scans(capsys: pytest.CaptureFixture[str]) -> None:
    code = main(["run", str(EXAMPLE), "--scans", "10000", "--set", "X41=2",
                 "--set", f"F26={0x11}", "--set", "F7.3=1",
                 "--print", "D200:2,R230,R232,R231.0"])
    assert code == 0
    lines = capsys.readouterr().out.splitlines()
    assert "D200:2 = 10000" in lines
    assert f"R230 = {0x12}" in lines  # BCD 12: slow down one station before 11
    assert f"R232 = {0x03}" in lines  # 3 steps
    assert "R231.0 = 1" in lines  # the short way from 2 to 11 is reverse
