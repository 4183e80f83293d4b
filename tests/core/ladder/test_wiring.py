"""Rungs that wire themselves: placement rules, automatic wires, and the open-circuit marks."""

from __future__ import annotations

import random
from dataclasses import replace
from pathlib import Path

import pytest
from hypothesis import given, settings

from ladderworks.core.address import parse_address
from ladderworks.core.il import parse, parse_file
from ladderworks.core.ladder import (
    WIRE,
    Coil,
    Contact,
    FunctionBox,
    LadderNetwork,
    OpenEnd,
    Wire,
    add_parallel,
    delete,
    open_cells,
    open_ends,
    place,
    place_wired,
    target_cell,
)
from ladderworks.core.ladder.convert import program_to_ladder
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.ladder.logic import code_rung
from tests.core.ladder.strategies import EXAMPLES, rungs
from tests.hypothesis_profiles import examples
from tests.real_programs import fragment_names, real_bytes


def _c(text: str, negated: bool = False) -> Contact:
    return Contact(parse_address(text), negated)


def _coil(text: str) -> Coil:
    return Coil(parse_address(text))


def _code(network: LadderNetwork) -> list[str]:
    code, problems = network_to_instructions(network)
    assert problems == [], problems
    return [f"{i.name} {i.operand or ''}".strip() for i in code or []]


def _wires(network: LadderNetwork, row: int) -> list[int]:
    return sorted(c for (r, c), e in network.cells.items() if r == row and isinstance(e, Wire))


def test_a_coil_clicked_anywhere_goes_to_the_coil_column_and_is_wired_to_the_contact() -> None:
    net = LadderNetwork()
    place_wired(net, 0, 0, _c("X0.0"))
    assert target_cell(net, 0, 3, _coil("Y0.0")) == (0, net.coil_column)
    place_wired(net, 0, 3, _coil("Y0.0"))
    assert net.cells[(0, net.coil_column)] == _coil("Y0.0")
    assert (0, 3) not in net.cells or net.cells[(0, 3)] is WIRE
    assert _wires(net, 0) == list(range(1, net.columns))
    assert _code(net) == ["RD X0.0", "WRT Y0.0"]
    assert open_ends(net) == []


def test_series_contacts_are_wired_to_each_other_and_to_the_coil() -> None:
    net = LadderNetwork()
    place_wired(net, 0, 0, _c("X0.0"))
    place_wired(net, 0, 9, _coil("Y0.0"))
    place_wired(net, 0, 4, _c("X0.1", negated=True))  # dropped on the wire
    place_wired(net, 0, 6, _c("X0.2"))
    assert _wires(net, 0) == [1, 2, 3, 5, 7, 8, 9]
    assert _code(net) == ["RD X0.0", "AND.NOT X0.1", "AND X0.2", "WRT Y0.0"]
    assert open_cells(net) == set()


def test_a_coil_placed_first_waits_for_its_logic_and_the_gap_is_marked() -> None:
    net = LadderNetwork()
    place_wired(net, 0, 5, _coil("Y0.0"))
    assert _wires(net, 0) == []  # a coil is never wired straight to the rail
    assert open_ends(net) == [OpenEnd((0, net.columns - 1), "gap")]
    place_wired(net, 0, 2, _c("X0.0"))
    assert _wires(net, 0) == [0, 1, 3, 4, 5, 6, 7, 8, 9]
    assert _code(net) == ["RD X0.0", "WRT Y0.0"]
    assert open_ends(net) == []


def test_a_contact_alone_is_marked_open_on_the_cell_after_it() -> None:
    net = LadderNetwork()
    place_wired(net, 0, 0, _c("X0.0"))
    assert open_ends(net) == [OpenEnd((0, 1), "gap")]
    place_wired(net, 0, 1, _c("X0.1"))
    assert open_ends(net) == [OpenEnd((0, 2), "gap")]  # the chain is marked once


def test_a_deleted_series_contact_leaves_a_marked_gap() -> None:
    net = LadderNetwork()
    for col, element in ((0, _c("X0.0")), (1, _c("X0.1")), (9, _coil("Y0.0"))):
        place_wired(net, 0, col, element)
    delete(net, 0, 1)
    assert open_ends(net) == [OpenEnd((0, 1), "gap")]  # one mark, though both sides are open
    place_wired(net, 0, 1, _c("X0.2"))
    assert open_cells(net) == set()


def test_a_contact_on_a_lower_row_alone_is_marked_on_both_sides() -> None:
    net = LadderNetwork()
    for col, element in ((0, _c("X0.0")), (9, _coil("Y0.0"))):
        place_wired(net, 0, col, element)
    place_wired(net, 1, 3, _c("X0.1"))
    assert _wires(net, 1) == []  # a lower row is not wired to the rail on its own
    assert open_ends(net) == [OpenEnd((1, 2), "gap"), OpenEnd((1, 4), "gap")]


def test_an_element_end_is_marked_when_the_next_cell_is_taken() -> None:
    net = LadderNetwork()
    net.cells[(0, 0)] = _c("X0.0")
    net.cells[(0, 1)] = replace(FunctionBox.new("TMR", (1,)), height=2)  # a taller box
    net.rows = 2
    net.cells[(1, 0)] = _c("X0.1")  # runs into the box's body, where there is no pin
    assert OpenEnd((1, 0), "right") in open_ends(net)


def test_the_or_tool_draws_its_verticals_and_a_contact_after_the_branch_lengthens_it() -> None:
    net = LadderNetwork()
    for col, element in ((0, _c("X0.0")), (9, _coil("Y0.0"))):
        place_wired(net, 0, col, element)
    add_parallel(net, 0, 0, _c("X0.1"))
    assert {(0, 0), (0, 1)} <= net.links
    assert open_cells(net) == set()
    place_wired(net, 1, 1, _c("X0.2"))
    assert (0, 1) not in net.links and (0, 2) in net.links
    assert _code(net) == ["RD X0.0", "RD.STK X0.1", "AND X0.2", "OR.STK", "WRT Y0.0"]
    assert open_cells(net) == set()


def test_a_branch_row_is_wired_to_the_verticals_it_meets() -> None:
    net = LadderNetwork()
    for col, element in ((0, _c("X0.0")), (1, _c("X0.1")), (9, _coil("Y0.0"))):
        place_wired(net, 0, col, element)
    net.links |= {(0, 3)}  # the user drew the closing vertical first
    place_wired(net, 1, 0, _c("X0.2"))
    assert _wires(net, 1) == [1, 2]
    assert _code(net) == ["RD X0.0", "AND X0.1", "OR X0.2", "WRT Y0.0"]


def test_a_box_goes_right_aligned_and_its_input_and_w1_coil_are_wired() -> None:
    net = LadderNetwork()
    place_wired(net, 0, 0, _c("R1.4"))
    box = FunctionBox.new("TMR", (1,))
    assert target_cell(net, 0, 1, box) == (0, net.columns - 2)
    place_wired(net, 0, 1, box)
    assert net.cells[(0, 8)] == box
    assert _wires(net, 0) == list(range(1, 8))
    place_wired(net, 0, 0, _coil("R1.7"))
    assert _code(net) == ["RD R1.4", "TMR", "WRT R1.7"]  # operands are params
    assert open_ends(net) == []


def test_a_box_without_control_inputs_sits_on_the_rail() -> None:
    net = LadderNetwork()
    box = FunctionBox.new("END1")
    place_wired(net, 0, 5, box)
    assert net.cells == {(0, 0): box}
    assert open_ends(net) == []


def test_wiring_fills_only_empty_cells_and_its_edit_undoes_exactly() -> None:
    rng = random.Random(18)
    for _ in range(200):
        net = LadderNetwork(6, 3)
        for _ in range(rng.randrange(1, 8)):
            row, col = rng.randrange(3), rng.randrange(6)
            element = rng.choice([_c("X0.0"), _c("X0.1", True), _coil("Y0.0"),
                                  FunctionBox.new("TMR", (1,))])
            before = net.copy()
            target = target_cell(net, row, col, element)
            undo = place_wired(net, row, col, element)
            covered = set(net.footprint(target, element))
            for cell, old in before.cells.items():
                if not set(before.footprint(cell, old)) & covered:  # not replaced: kept
                    assert net.cells[cell] == old
            for cell, new in net.cells.items():
                if cell not in before.cells and cell != target:
                    assert new is WIRE
            after = net.copy()
            redo = undo.apply(net)
            assert net == before
            redo.apply(net)
            assert net == after


def test_a_network_from_text_has_no_marks_and_a_listing_none() -> None:
    program = parse("%@3\nRD X0.0\nOR X0.1\nAND.NOT X0.2\nWRT Y0.0\n%\n").program
    net = program_to_ladder(program).networks[0]
    assert open_ends(net) == []
    listing = layout_network(parse("%@3\nRD X0.0\nOR X0.1\n%\n").program.instructions())
    assert listing.listing is not None and open_ends(listing) == []


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.LAD")), ids=lambda p: p.name)
def test_no_example_network_is_marked_open(path: Path) -> None:
    for net in program_to_ladder(parse_file(path).program).networks:
        assert open_ends(net) == [], net


@pytest.mark.parametrize("name", fragment_names())
def test_no_real_fragment_network_is_marked_open(name: str) -> None:
    program = parse(real_bytes(name).decode("utf-8", "surrogateescape"), "fanuc").program
    for net in program_to_ladder(program).networks:
        code, problems = network_to_instructions(net, None, "fanuc")
        if code is not None and not problems:
            assert open_ends(net) == [], net


@settings(max_examples=examples(300), deadline=None)
@given(rungs())
def test_every_drawn_rung_is_closed(rung) -> None:
    net = layout_network(code_rung(rung))
    assert open_ends(net) == []


def test_a_placed_contact_replaces_nothing_but_its_own_cell() -> None:
    net = LadderNetwork()
    place(net, 0, 3, _c("X0.0"))
    place_wired(net, 0, 3, _c("X0.1"))
    assert net.cells[(0, 3)] == _c("X0.1")
