"""A real machine's WPLSoft export (a lathe, ../shared/real-programs/delta) opens as found, is
drawn as ladder, runs, and saves byte for byte; read from ../shared, never copied."""

from __future__ import annotations

import pytest

from ladderworks.core.compiler import compile
from ladderworks.core.il.printer import encode_program
from ladderworks.core.il.reading import parse_file
from ladderworks.core.ladder.convert import program_to_ladder
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.session import PlcRun
from tests.real_programs import real_programs_dir

from .conftest import put

NAME = "METALURGICA_c91257f_proejto_clp.csv"


@pytest.fixture(scope="module")
def path():
    return real_programs_dir() / "delta" / NAME


def test_it_opens_with_warnings_only_and_saves_byte_for_byte(path) -> None:
    result = parse_file(path)
    assert result.ok and result.program.dialect == "delta"
    assert len(result.program.networks) == 71
    assert encode_program(result.program) == path.read_bytes()


def test_every_network_is_drawn_as_ladder_and_reads_back_as_written(path) -> None:
    program = parse_file(path).program
    doc = program_to_ladder(program)
    listed = [n for n, net in enumerate(doc.networks) if net.listing is not None]
    assert listed == []  # 71 of 71 drawn as ladder
    for n, (network, net) in enumerate(zip(program.networks, doc.networks, strict=True)):
        code, diagnostics = network_to_instructions(net, n, "delta")
        assert not diagnostics and code == list(network.instructions), n


def test_it_runs_and_names_the_instructions_it_passes_by(path) -> None:
    program = parse_file(path).program
    plc = PlcRun()
    result = plc.load_program(program)
    assert result.binary is not None
    # every instruction of the lathe program is simulated now (32-bit forms, ZRST, FROM/TO)
    assert [d.code for d in result.diagnostics] == []
    assert plc.skipped == []
    plc.start()
    plc.advance(plc.engine.now_ms + 500)  # type: ignore[union-attr]
    assert plc.engine is not None and plc.engine.scan_count >= 50


@pytest.mark.parametrize("monitored", [False, True])
def test_the_skipping_engine_equals_every_scan(path, monitored: bool) -> None:
    binary = compile(parse_file(path).program)
    memories = []
    for every in (True, False):
        plc = ScanEngine(binary, period_ms=10)
        plc.monitored, plc.every_scan = monitored, every
        for x in ("X2", "X3", "X20"):
            put(plc, x, 1)
        plc.step(3000)
        put(plc, "X3", 0)
        plc.step(3000)
        memories.append({area: bytes(data) for area, data in plc.memory.areas.items()})
    assert memories[0] == memories[1]
