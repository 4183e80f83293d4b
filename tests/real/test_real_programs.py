"""The three public FANUC 31i-A programs (read from ../shared/real-programs, never copied):
they pass check, draw, compile and run 10,000 scans deterministically."""

from __future__ import annotations

import hashlib

import pytest

from ladderworks.core.address import Address, Area
from ladderworks.core.compiler import compile_program
from ladderworks.core.diagnostics import has_errors
from ladderworks.core.il import parse_file
from ladderworks.core.il.printer import encode_program
from ladderworks.core.ladder.art import draw_document
from ladderworks.core.ladder.convert import ladder_to_program, program_to_ladder
from ladderworks.core.plc.engine import ScanEngine
from tests.real import PROGRAMS, real_program

SCANS = 10_000
CHECKED = 2_000  # the S41 programs: the second run repeats the first 2,000 scans (CI time)


@pytest.fixture(scope="module", params=PROGRAMS)
def compiled(request: pytest.FixtureRequest) -> tuple[str, bytes]:
    """(name, binary) of each real program, compiled once per module."""
    name = request.param
    result = parse_file(real_program(name))
    errors = [d for d in result.diagnostics if d.is_error]
    assert not errors, [d.located(name) for d in errors[:10]]
    compiled = compile_program(result.program)
    assert compiled.binary is not None, [d.located(name) for d in compiled.diagnostics
                                          if d.is_error][:10]
    return name, compiled.binary


def _image(engine: ScanEngine) -> str:
    """A digest of every area of the memory image."""
    digest = hashlib.sha256()
    for area, data in sorted(engine.memory.snapshot().items()):
        digest.update(area.value.encode())
        digest.update(data)
    return digest.hexdigest()


def test_check_passes_with_warnings_at_most(compiled: tuple[str, bytes]) -> None:
    name, binary = compiled
    assert len(binary) > 100_000, name


def test_the_ladder_draws(compiled: tuple[str, bytes]) -> None:
    name, _ = compiled
    result = parse_file(real_program(name))
    document = program_to_ladder(result.program)
    art = draw_document(document)
    assert len(document.networks) > 4000
    assert art.count("\n") > 50_000


def test_runs_10000_scans_deterministically(compiled: tuple[str, bytes]) -> None:
    name, binary = compiled
    again = SCANS if name == PROGRAMS[0] else CHECKED
    engine = ScanEngine(binary)  # skipping the scans of a repeating state (docs/engine.md)
    assert engine.advance(again * engine.period_ms) == again
    first = _image(engine)
    engine.advance(SCANS * engine.period_ms)
    assert engine.now_ms == SCANS * engine.period_ms and engine.scan_count == SCANS
    assert engine.memory.bit(Address(Area.R, 9091, 1)) == 1, name
    assert engine.memory.bit(Address(Area.R, 9091, 0)) == 0, name
    repeat = ScanEngine(binary)
    repeat.run_scans(again)  # every scan run
    assert _image(repeat) == first, name  # the same memory image after the same scans


def test_no_error_diagnostics_from_check(compiled: tuple[str, bytes]) -> None:
    name, _ = compiled
    result = parse_file(real_program(name))
    from ladderworks.core.compiler import check

    assert not has_errors(check(result.program)), name


def test_through_the_ladder_grid_and_back_byte_for_byte(compiled: tuple[str, bytes]) -> None:
    name, _ = compiled
    path = real_program(name)
    document = program_to_ladder(parse_file(path).program)
    program, diagnostics = ladder_to_program(document)
    assert diagnostics == []  # FANUC boxes checked with the 30i ranges (TMRB 245 is valid)
    assert encode_program(program) == path.read_bytes()
