"""Delta's MPS / MRD / MPP branches drawn as ladder branches from one point, and read back
from the grid to the same instructions; what has no such picture stays a list."""

from __future__ import annotations

from dataclasses import replace

import pytest

from ladderworks.core.compiler import compile
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.ladder.model import Coil, Contact
from ladderworks.core.plc.engine import ScanEngine

from .conftest import bit_of, delta, get, put

DRAWN = [
    "LD X0\nMPS\nAND X1\nOUT Y0\nMRD\nAND X2\nOUT Y1\nMPP\nANI X3\nOUT Y2\nEND\n",
    "LD X0\nOR X5\nMPS\nAND X1\nOUT Y0\nOUT Y3\nMPP\nANI X2\nOUT Y2\nEND\n",
    "LD X0\nMPS\nLD X1\nOR X2\nANB\nOUT Y0\nMPP\nAND= D0 K1\nOUT Y2\nEND\n",
    "LD X0\nINV\nOUT Y0\nEND\n",  # INV: a contact inverting the power before it
]
LISTS = [
    "LD X0\nMPS\nAND X1\nOUT Y0\nEND\n",  # no MPP
    "LD X0\nLD X1\nINV\nORB\nOUT Y0\nEND\n",  # INV inside a block: inverts it alone
]


@pytest.mark.parametrize("text", DRAWN)
def test_branches_are_drawn_and_read_back(text: str) -> None:
    code = list(delta(text).networks[0].instructions)
    net = layout_network(code)
    assert net.listing is None and net.source is None
    coils = [cell for cell, e in net.elements() if isinstance(e, Coil)]
    assert len({row for row, _ in coils}) == len(coils)  # one row each, in the coil column
    back, diags = network_to_instructions(net, dialect="delta")
    assert not diags and back == code


@pytest.mark.parametrize("text", LISTS)
def test_no_picture_stays_a_list(text: str) -> None:
    code = delta(text).networks[0].instructions
    net = layout_network(code)
    assert net.listing == tuple(code)


def test_a_branch_drawing_is_not_pmc_ladder() -> None:
    net = layout_network(list(delta(DRAWN[0]).networks[0].instructions))
    code, diags = network_to_instructions(net)  # the PMC has no MPS: FANUC's coil-branch
    assert code is None and [d.code for d in diags] == ["coil-branch"]


def test_the_drawn_branches_run_as_written() -> None:
    program = delta(DRAWN[0])
    net = layout_network(list(program.networks[0].instructions))
    program.networks[0].instructions[:] = network_to_instructions(net, dialect="delta")[0] or []
    plc = ScanEngine(compile(program))
    for x0, x1, x2, x3 in ((1, 1, 0, 0), (1, 0, 1, 1), (0, 1, 1, 0)):
        for name, value in (("X0", x0), ("X1", x1), ("X2", x2), ("X3", x3)):
            put(plc, name, value)
        plc.scan()
        assert (get(plc, "Y0"), get(plc, "Y1"), get(plc, "Y2")) == (
            x0 & x1, x0 & x2, x0 & (1 - x3))


ON_THE_POINT = [
    "LD X0\nOR X5\nMPS\nAND X1\nOUT Y0\nMPP\nOUT Y2\nEND\n",
    "LD X0\nMPS\nOUT Y2\nMPP\nAND X1\nOUT Y0\nEND\n",
    "LD X0\nMPS\nAND X1\nOUT Y0\nMRD\nOUT Y3\nMPP\nANI X2\nOUT Y2\nEND\n",
]


@pytest.mark.parametrize("text", ON_THE_POINT)
def test_a_branch_without_contacts_is_drawn_and_kept(text: str) -> None:
    """Coils on the branch point itself: a branch of wire from the point (the same picture as
    an output chain, so the coding is kept in `source` and read back as branches)."""
    code = list(delta(text).networks[0].instructions)
    net = layout_network(code)
    assert net.listing is None and net.source == tuple(code)
    coils = [cell for cell, e in net.elements() if isinstance(e, Coil)]
    assert len({row for row, _ in coils}) == len(coils) == text.count("OUT")
    back, diags = network_to_instructions(net, dialect="delta")
    assert not diags and back == code


def test_an_edited_branch_network_keeps_its_branches() -> None:
    code = list(delta(ON_THE_POINT[0]).networks[0].instructions)
    net = layout_network(code)
    x1 = bit_of("X1")
    cell = next(c for c, e in net.elements() if isinstance(e, Contact) and e.address == x1)
    net.cells[cell] = replace(net.cells[cell], address=bit_of("X7"))  # type: ignore[arg-type]
    back, diags = network_to_instructions(net, dialect="delta")
    assert not diags and back is not None
    names = [i.name for i in back]
    assert names == [i.name for i in code]  # MPS … MPP, not an output chain
    assert back[3].operand == bit_of("X7")
    program = delta(ON_THE_POINT[0])
    program.networks[0].instructions[:] = back
    plc = ScanEngine(compile(program))
    put(plc, "X0", 1)
    put(plc, "X7", 1)
    plc.scan()
    assert (get(plc, "Y0"), get(plc, "Y2")) == (1, 1)
    put(plc, "X7", 0)
    plc.scan()
    assert (get(plc, "Y0"), get(plc, "Y2")) == (0, 1)


NESTED = [
    "LD X0\nMPS\nAND X1\nMPS\nAND X2\nOUT Y0\nMPP\nOUT Y1\nMPP\nOUT Y2\nEND\n",
    "LD X0\nMPS\nAND X1\nMPS\nAND X2\nOUT Y0\nMPP\nAND X3\nOUT Y1\nMPP\nAND X4\nOUT Y2\nEND\n",
    "LD X0\nMPS\nAND X1\nOUT Y5\nMPP\nAND X6\nMPS\nAND X2\nOUT Y0\nMRD\nOUT Y3\nMPP\n"
    "AND X3\nOUT Y1\nEND\n",
    "LD X0\nMPS\nAND X1\nMPS\nLD X2\nOR X7\nANB\nMPS\nAND X5\nOUT Y0\nMPP\nOUT Y6\nMPP\n"
    "AND X3\nOUT Y1\nMPP\nAND X4\nOUT Y2\nEND\n",
]


@pytest.mark.parametrize("text", NESTED)
def test_nested_branches_are_drawn_read_back_and_run(text: str) -> None:
    """An MPS inside a branch: that branch's own branches from the end of its block."""
    program = delta(text)
    code = list(program.networks[0].instructions)
    net = layout_network(code)
    assert net.listing is None
    coils = [cell for cell, e in net.elements() if isinstance(e, Coil)]
    assert len({row for row, _ in coils}) == len(coils) == text.count("OUT")
    back, diags = network_to_instructions(net, dialect="delta")
    assert not diags and back == code
    again = net.copy()  # the grid alone (no kept coding): the same meaning on every input
    again.source = None
    back, diags = network_to_instructions(again, dialect="delta")
    assert not diags and back is not None
    inputs = sorted({str(i.operand): i.operand for i in code
                     if i.operand is not None and i.operand.area.name == "X"}.values(), key=str)
    outputs = [i.operand for i in code if i.spec.is_coil]
    redrawn = delta(text)
    redrawn.networks[0].instructions[:] = back
    plcs = [ScanEngine(compile(program)), ScanEngine(compile(redrawn))]
    for mask in range(1 << len(inputs)):
        results = []
        for plc in plcs:
            for bit, address in enumerate(inputs):
                plc.memory.set_bit(address, (mask >> bit) & 1)
            plc.scan()
            results.append([plc.memory.bit(o) for o in outputs])
        assert results[0] == results[1], mask


def test_a_program_with_such_branches_saves_byte_for_byte() -> None:
    from ladderworks.core.il.printer import encode_program
    from ladderworks.core.il.reading import parse_bytes
    from ladderworks.core.ladder.convert import ladder_to_program, program_to_ladder

    data = ("".join(NESTED + ON_THE_POINT).replace("END\n", "")
            .replace("\n", "\r\n") + "END\r\n").encode("utf-8")
    result = parse_bytes(data, "delta")
    assert result.ok, result.diagnostics
    doc = program_to_ladder(result.program)
    assert all(net.listing is None for net in doc.networks[:-1])
    back, diags = ladder_to_program(doc)
    assert not diags and encode_program(back) == data
