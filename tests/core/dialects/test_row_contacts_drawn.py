"""Delta's and Fatek's edge and comparison contacts drawn as contacts in the ladder grid:
laid out (not kept as lists), coded back to the same instructions, saved byte for byte."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from ladderworks.core.il import parse_file
from ladderworks.core.il.printer import encode_program
from ladderworks.core.instructions import Operation
from ladderworks.core.ladder import EditRefused, invert, set_address
from ladderworks.core.ladder.clipboard import copy_text, network_from_text
from ladderworks.core.ladder.convert import ladder_to_program, program_to_ladder
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.ladder.logic import has_bare_branch, stack_depth
from ladderworks.core.ladder.model import Contact, FunctionBox, LadderNetwork
from ladderworks.core.ladder.reading import read_rung
from ladderworks.core.ladder.row_contacts import ALWAYS_ON, contact_combine, mark
from tests.core.dialects.fatek.test_programs import fatek as fatek_program

from .conftest import delta

ROOT = Path(__file__).resolve().parents[3] / "resources" / "examples"
PROGRAMS = sorted((ROOT / "delta").glob("*.txt")) + sorted((ROOT / "fatek").glob("*.lst"))


def _row_contacts(net: LadderNetwork) -> list[Contact]:
    return [e for _, e in net.elements() if isinstance(e, Contact) and e.function]


@pytest.mark.parametrize("path", PROGRAMS, ids=lambda p: p.name)
def test_examples_draw_their_row_contacts_and_round_trip(path: Path) -> None:
    program = parse_file(path).program
    doc = program_to_ladder(program)
    for network, net in zip(program.networks, doc.networks, strict=True):
        has_row_contact = any(contact_combine(ins.spec) is not None
                              for ins in network.instructions)
        if has_row_contact:
            assert net.listing is None, [ins.name for ins in network.instructions]
            assert _row_contacts(net)
            # the drawing's standard coding is the text's; coils on a branch point itself
            # (a Fatek TR branch `LD TR 0 / OUT Y3`) keep their coding, as Delta's MPP / OUT
            assert net.source is None or has_bare_branch(read_rung(network.instructions).branches)
        code, diags = network_to_instructions(net, dialect=program.dialect)
        assert not diags and code == list(network.instructions)
    back, diags = ladder_to_program(doc)
    assert not diags
    assert encode_program(back) == path.read_bytes()


def test_delta_comparison_mid_rung_is_a_contact_with_its_operands() -> None:
    program = delta("LD X1\nLD< C1 C2\nOR> C2 K10\nANB\nAND= D0 K5\nOUT Y1\nEND\n")
    net = layout_network(program.networks[0].instructions)
    assert net.listing is None
    contacts = _row_contacts(net)
    assert [mark(c.function) for c in contacts] == ["<", "=", ">"]  # row 0, then OR> below
    assert all(len(c.params) == 2 and c.address is None for c in contacts)
    code, diags = network_to_instructions(net, dialect="delta")
    assert not diags and code == list(program.networks[0].instructions)


def test_delta_edges_in_series_and_parallel() -> None:
    program = delta("LDP X0\nORF X1\nANDP M0\nOUT Y0\nEND\n")
    net = layout_network(program.networks[0].instructions)
    assert [mark(c.function) for c in _row_contacts(net)] == ["↑", "↑", "↓"]  # X0, M0; X1
    assert network_to_instructions(net, dialect="delta")[0] == list(
        program.networks[0].instructions)


def test_fatek_conveyor_counter_is_ladder() -> None:
    program = parse_file(ROOT / "fatek" / "conveyor.lst").program
    doc = program_to_ladder(program)
    counter = next(net for net in doc.networks
                   if any(isinstance(e, FunctionBox) and len(e.pins) == 2
                          for e in net.cells.values()))
    assert counter.listing is None
    (edge,) = _row_contacts(counter)
    assert mark(edge.function) == "↑"


def test_a_fatek_edge_contact_starts_the_rung_without_a_short_contact() -> None:
    """`ORG TU X2` is drawn as one contact on the rail (its READ row, issue 38), `OR TU` as a
    contact in parallel; both code back to the same instructions."""
    program = fatek_program("ORG TU X2\nOR TU X3\nAND X4\nOUT Y0\n"
                            "ORG X0\nLD TD X1\nORF 170 (=)\n Sa: R0\n Sb: 5\nANDLD\nOUT Y1\n")
    for network in program.networks:
        net = layout_network(list(network.instructions))
        assert net.listing is None
        assert not [e for e in net.cells.values()
                    if isinstance(e, Contact) and e.address == ALWAYS_ON]  # no SHORT drawn
        again = replace(net, source=None)
        assert network_to_instructions(again, dialect="fatek")[0] == list(network.instructions)
    first = layout_network(list(program.networks[0].instructions))
    assert [mark(c.function) for c in _row_contacts(first)] == ["↑", "↑"]


def test_edits_on_a_row_contact() -> None:
    program = delta("LD X1\nAND= D0 K5\nOUT Y1\nEND\n")
    net = layout_network(program.networks[0].instructions)
    with pytest.raises(EditRefused) as refused:
        invert(net, 0, 1)
    assert refused.value.diagnostic.code == "edit-row-contact"
    set_address(net, 0, 1, "X2.0")
    assert net.cells[(0, 1)] == Contact(net.cells[(0, 1)].address)  # a plain contact now
    assert network_to_instructions(net)[0] is not None


def test_clipboard_keeps_a_row_contact() -> None:
    program = delta("LD X1\nAND= D0 K5\nOUT Y1\nEND\n")
    net = layout_network(program.networks[0].instructions)
    assert network_from_text(copy_text(net)) == net


def test_stack_depth_counts_a_pushing_comparison() -> None:
    code = list(delta("LD X1\nLD= D0 K5\nOR X2\nANB\nOUT Y1\nEND\n").networks[0].instructions)
    assert stack_depth(code) == 1


def test_fatek_rows_say_their_operation() -> None:
    from ladderworks.core.dialects.fatek.rows import ROWS
    tests = {spec.mnemonic: spec.operation for spec in ROWS if spec.inputs == ("IN",)}
    assert tests == {"TU": Operation.RISING, "TD": Operation.FALLING, "(=)": Operation.EQUAL,
                     "(>)": Operation.GREATER, "(<)": Operation.LESS,
                     "(<>)": Operation.NOT_EQUAL, "(>=)": Operation.GREATER_EQUAL,
                     "(<=)": Operation.LESS_EQUAL}
