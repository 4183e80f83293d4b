"""Fatek `OUT L` (retentive coil) is a row of its own: read, drawn (L), coded back, run as an
output, copied and pasted, and written `OUT L` in a changed network (no value lost)."""

from __future__ import annotations

from dataclasses import replace

from ladderworks.core.dialects.fatek import DEVICES
from ladderworks.core.dialects.fatek.printer import network_lines
from ladderworks.core.il import Network
from ladderworks.core.ladder.art import draw_network
from ladderworks.core.ladder.clipboard import copy_text, network_from_text
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.ladder.model import Coil, LadderNetwork, flip

from .test_programs import engine, fatek, get, put

TEXT = "ORG      X0\nOUT L    Y10\nEND\n"


def _coil(text: str = TEXT) -> tuple[Coil, LadderNetwork]:
    net = layout_network(fatek(text).networks[0].instructions)
    coil = next(e for _, e in net.elements() if isinstance(e, Coil))
    return coil, net


def test_out_l_is_its_own_row_and_runs_as_an_output() -> None:
    program = fatek(TEXT)
    assert [i.name for i in program.networks[0].instructions] == ["RD", "FBS.OUTL"]
    for monitored in (False, True):
        plc = engine(TEXT, monitored)
        plc.scan()
        assert get(plc, "Y10") == 0
        put(plc, "X0", 1)
        plc.scan()
        assert get(plc, "Y10") == 1


def test_a_changed_out_l_network_is_written_out_l() -> None:
    coil, net = _coil()
    assert coil.row == "FBS.OUTL" and coil.address == DEVICES.bit("Y10")
    assert "(L)" in "".join(draw_network(net))
    net.cells[next(c for c, e in net.cells.items() if e is coil)] = replace(
        coil, address=DEVICES.bit("Y11"))
    code, diags = network_to_instructions(net, dialect="fatek")
    assert not diags and [i.name for i in code] == ["RD", "FBS.OUTL"]
    assert network_lines(Network(code), True) == ["ORG      X0", "OUT L    Y11"]


def test_copy_paste_keeps_out_l_and_not_makes_out_not() -> None:
    coil, net = _coil()
    pasted = network_from_text(copy_text(net))
    assert any(isinstance(e, Coil) and e.row == "FBS.OUTL" for e in pasted.cells.values())
    inverted = flip(coil)
    assert isinstance(inverted, Coil) and inverted.negated and inverted.row == ""
