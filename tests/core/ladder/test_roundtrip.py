"""Program → grid → program gives the same program (comments included)."""

from __future__ import annotations

import random
from pathlib import Path

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from ladderworks.core.address import parse_address
from ladderworks.core.il import parse, parse_file, print_program
from ladderworks.core.il.program import Instruction, Network, Program
from ladderworks.core.ladder.convert import ladder_to_program, program_to_ladder
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.ladder.layout import layout_network
from tests.core.ladder.reference import run
from tests.core.ladder.strategies import EXAMPLES, programs, rungs, stack_code
from tests.hypothesis_profiles import examples

EXAMPLE_FILES = sorted(EXAMPLES.glob("*.LAD"))


def _drawn_only(program: Program) -> Program:
    """Program → grid → program using only what is drawn (original codings forgotten)."""
    doc = program_to_ladder(program)
    for network in doc.networks:
        assert network.listing is None
        network.source = None
    back, diagnostics = ladder_to_program(doc)
    assert diagnostics == []
    return back


def test_there_are_examples() -> None:
    assert len(EXAMPLE_FILES) >= 9


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: p.name)
def test_every_example_round_trips_through_the_picture(path: Path) -> None:
    program = parse_file(path).program
    assert _drawn_only(program) == program


@pytest.mark.parametrize("path", EXAMPLE_FILES, ids=lambda p: p.name)
def test_example_mnemonic_text_is_the_canonical_text(path: Path) -> None:
    program = parse_file(path).program
    back, _ = ladder_to_program(program_to_ladder(program))
    assert print_program(back) == print_program(program)


@settings(max_examples=examples(500), deadline=None)
@given(programs())
def test_generated_programs_round_trip_through_the_picture(program: Program) -> None:
    assert _drawn_only(program) == program


@settings(max_examples=examples(200), deadline=None)
@given(programs())
def test_generated_programs_round_trip_as_text(program: Program) -> None:
    back, _ = ladder_to_program(program_to_ladder(program))
    text = print_program(back)
    assert text == print_program(program)
    assert parse(text).program == program


@settings(max_examples=examples(400), deadline=None)
@given(rungs())
def test_layout_then_decomposition_gives_the_standard_coding(rung) -> None:
    from ladderworks.core.ladder.logic import code_rung

    code = code_rung(rung)
    grid = layout_network(code)
    assert grid.source is None and grid.listing is None
    assert network_to_instructions(grid) == (code, [])


@settings(max_examples=examples(400), deadline=None)
@given(stack_code(), st.randoms(use_true_random=False))
def test_any_stack_coding_round_trips_and_its_picture_means_the_same(
        code: list[Instruction], rnd: random.Random) -> None:
    grid = layout_network(code)
    assert grid.listing is None
    assert network_to_instructions(grid)[0] == code  # original coding kept while unedited
    grid.source = None
    drawn, problems = network_to_instructions(grid)  # what the picture alone says
    assert problems == [] and drawn is not None
    addresses = {ins.operand for ins in code if ins.operand is not None}
    for _ in range(8):
        values = {address: rnd.random() < 0.5 for address in addresses}
        assert run(drawn, values.__getitem__).writes == run(code, values.__getitem__).writes


def _ins(text: str) -> list[Instruction]:
    result = parse("%@3\n" + text + "\n%\n")
    assert result.ok
    return result.program.instructions()


UNDRAWABLE = [
    "RD X0.0\nWRT Y0.0\nOR X0.1\nWRT Y0.1",  # OR onto a result already written
    "RD X0.0\nWRT Y0.0\nAND X0.1",  # logic after the last coil
    "RD X0.0\nRD.STK X0.1\nWRT Y0.0",  # two values left on the stack
    "RD X0.0\nCTR 1\nWRT Y0.0",  # CTR without its four control inputs
    "RD X0.0\nTMR 1\nAND X0.2\nWRT Y0.0",  # logic after a function's W1
    "RD X0.0\nRD X0.1\nWRT Y0.0",  # RD overwrites ST0
    "RD X0.0\nMOVOR R1 R2 R3\nWRT Y0.0",  # a coil after a function without W1
]


@pytest.mark.parametrize("text", UNDRAWABLE)
def test_code_without_a_picture_is_kept_as_a_listing(text: str) -> None:
    code = _ins(text)
    grid = layout_network(code, ["kept"])
    assert grid.listing == tuple(code)
    assert grid.cells == {}
    assert network_to_instructions(grid) == (code, [])


def test_unusual_code_in_a_file_round_trips_and_is_still_drawn() -> None:
    text = ("%@3\n// net\nRD X0.0\nRD.STK X0.1  // b\nAND.STK  // joined\nWRT Y0.0\n\n"
            "RD X1.0\nWRT Y1.0\nOR X1.1\nWRT Y1.1\n%\n")
    program = parse(text).program
    doc = program_to_ladder(program)
    first = doc.networks[0]
    assert first.listing is None and len(first.cells) == 2 + 8 + 1  # 2 contacts, wires, coil
    assert doc.networks[1].listing is not None
    back, diagnostics = ladder_to_program(doc)
    assert diagnostics == [] and back == program


def test_editing_an_unusual_network_gives_the_standard_coding() -> None:
    from ladderworks.core.ladder.edits import set_address

    program = parse("%@3\nRD X0.0\nRD.STK X0.1\nAND.STK\nWRT Y0.0\n%\n").program
    doc = program_to_ladder(program)
    set_address(doc.networks[0], 0, 1, "X0.2")
    back, _ = ladder_to_program(doc)
    assert back.networks[0].instructions == _ins("RD X0.0\nAND X0.2\nWRT Y0.0")


def test_a_network_and_its_comment_lines_keep_their_order() -> None:
    program = Program([Network(_ins("RD X0.0\nWRT Y0.0"), ["a", "b"]),
                       Network(_ins("RD.NOT X0.1\nWRT.NOT Y0.1  // out"), ["c"])],
                      header=["h"], trailer=["t"])
    assert _drawn_only(program) == program
    assert parse_address("Y0.1") == program.networks[1].instructions[-1].operand


def test_output_chain_is_drawn_below_its_first_coil_and_read_back() -> None:
    code = _ins("RD X0.0\nOR X0.1\nWRT Y0.0\nAND X0.2\nWRT Y0.1\nWRT Y0.2\n"
                "RD.STK X0.3\nOR X0.4\nAND.STK\nWRT Y0.3")
    grid = layout_network(code)
    assert grid.listing is None and grid.source is None
    where = {str(e.address): cell for cell, e in grid.elements() if hasattr(e, "address")}
    assert where["Y0.0"] == (0, 10) and where["X0.2"] == (2, 1)
    assert where["Y0.1"] == (2, 10) and where["Y0.2"] == (3, 10)
    assert where["X0.3"] == (4, 2) and where["Y0.3"] == (4, 10)
    assert (1, 1) in grid.links and (3, 2) in grid.links  # each segment hangs from the last
    assert network_to_instructions(grid) == (code, [])
