"""A TR point as a rung's branch point (`OUT TR n` … `LD TR n` after each branch's outputs):
one network drawn as WinProladder draws it, coded back to the same instructions, printed in
Fatek's form, running as the TR relay lowering did (DIALECTS.md §2.5, docs/dialects.md)."""

from __future__ import annotations

import itertools
from pathlib import Path

import pytest

from ladderworks.cli import main
from ladderworks.core.compiler import compile
from ladderworks.core.dialects.fatek import networks
from ladderworks.core.dialects.fatek.printer import network_lines
from ladderworks.core.il.printer import encode_program
from ladderworks.core.il.program import Program
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.ladder.convert import ladder_to_program, program_to_ladder
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.ladder.model import Coil, Contact, LadderNetwork
from ladderworks.core.plc.engine import ScanEngine
from tests.core.dialects.fatek.test_programs import fatek, get, put

TWO = "ORG X0\nOUT TR 0\nAND X1\nOUT Y0\nLD TR 0\nAND X2\nOUT Y1\n"
THREE = ("ORG X0\nOR X4\nOUT TR 3\nAND X1\nOUT Y0\nLD TR 3\nAND X2\nOUT Y1\nOUT M1\n"
         "LD TR 3\nAND NOT X3\nOUT Y2\n")
NESTED = ("ORG X0\nOUT TR 0\nAND X1\nOUT TR 1\nAND X2\nOUT Y0\nLD TR 1\nOUT Y1\nLD TR 0\n"
          "AND X3\nOUT Y2\n")


def _relays(text: str, monkeypatch: pytest.MonkeyPatch) -> Program:
    """The program as the lowering before branch points read it (TR relays, one network per
    branch)."""
    with monkeypatch.context() as patch:
        patch.setattr(networks, "branch_points", lambda network: {})
        return fatek(text)


def _cells(net: LadderNetwork) -> dict[tuple[int, int], str]:
    """The drawn contacts and coils by cell, as `X1` / `Y0` (NOT: `/X3`)."""
    from ladderworks.core.dialects.fatek.printer import device_text
    out = {}
    for cell, element in net.cells.items():
        if isinstance(element, Contact | Coil):
            out[cell] = ("/" if element.negated else "") + device_text(element.address)
    return out


def test_two_branches_are_one_network_drawn_from_the_branch_point() -> None:
    program = fatek(TWO)
    assert len(program.networks) == 1
    net = layout_network(program.networks[0].instructions)
    assert net.listing is None and net.source is None
    end = net.columns
    assert _cells(net) == {(0, 0): "X0", (0, 1): "X1", (0, end): "Y0",
                           (1, 1): "X2", (1, end): "Y1"}
    assert net.links == {(0, 1)}  # the branch point after X0


def test_three_branches_with_two_coils_on_the_second() -> None:
    program = fatek(THREE)
    assert len(program.networks) == 1
    net = layout_network(program.networks[0].instructions)
    end = net.columns
    cells = _cells(net)
    assert cells[(0, 0)] == "X0" and cells[(1, 0)] == "X4"
    assert {cell: text for cell, text in cells.items() if cell[1] > 0} == {
        (0, 1): "X1", (0, end): "Y0", (1, 1): "X2", (1, end): "Y1", (2, end): "M1",
        (3, 1): "/X3", (3, end): "Y2"}
    assert {(0, 1), (1, 1), (2, 1)} <= net.links  # the point's line down to the third branch


@pytest.mark.parametrize("text", [TWO, THREE, NESTED], ids=["two", "three", "nested"])
def test_coded_back_printed_back_and_read_again_equal(text: str) -> None:
    program = fatek(text)
    network = program.networks[0]
    net = layout_network(network.instructions)
    assert net.listing is None
    code, diags = network_to_instructions(net, 0, "fatek")
    assert code == network.instructions, diags
    printed = "\n".join(network_lines(network, True)) + "\n"
    assert printed.count("OUT TR") == text.count("OUT TR")
    assert printed.count("LD TR") == text.count("LD TR")
    assert [line.split() for line in printed.splitlines()] == \
        [line.split() for line in text.splitlines()]
    assert fatek(printed).networks[0].instructions == network.instructions


@pytest.mark.parametrize("text, inputs, outputs", [
    (TWO, ("X0", "X1", "X2"), ("Y0", "Y1")),
    (THREE, ("X0", "X1", "X2", "X3", "X4"), ("Y0", "Y1", "Y2", "M1")),
    (NESTED, ("X0", "X1", "X2", "X3"), ("Y0", "Y1", "Y2")),
], ids=["two", "three", "nested"])
def test_runs_as_the_tr_relay_lowering_on_every_input(text: str, inputs: tuple[str, ...],
                                                      outputs: tuple[str, ...],
                                                      monkeypatch: pytest.MonkeyPatch) -> None:
    relays = _relays(text, monkeypatch)
    assert len(relays.networks) > 1  # the lowering before: a network per branch
    plcs = [ScanEngine(compile(program), period_ms=10) for program in (fatek(text), relays)]
    for values in itertools.product((0, 1), repeat=len(inputs)):
        seen = []
        for plc in plcs:
            for name, value in zip(inputs, values, strict=True):
                put(plc, name, value)
            plc.scan()
            seen.append([get(plc, name) for name in outputs])
        assert seen[0] == seen[1], values


def test_unchanged_saves_byte_for_byte_a_changed_coil_prints_out_tr_and_ld_tr() -> None:
    data = ("; branches\r\n" + THREE.replace("\n", "\r\n")).encode()
    program = parse_bytes(data, "fatek").program
    kept: list = []
    doc = program_to_ladder(program, kept)
    saved, diags = ladder_to_program(doc, kept)
    assert not diags and encode_program(saved) == data
    net = doc.networks[0]
    cell = next(c for c, e in net.cells.items() if isinstance(e, Coil) and c[0] == 0)
    net.cells[cell] = Coil(fatek("ORG X0\nOUT Y7\n").networks[0].instructions[1].operand)
    changed, diags = ladder_to_program(doc, kept)
    assert not diags
    text = encode_program(changed).decode()
    assert "OUT TR   3\r\nAND      X1\r\nOUT      Y7\r\nLD TR    3\r\n" in text
    assert text.count("LD TR    3") == 2
    again = fatek(text)
    assert len(again.networks) == 1
    assert again.networks[0].instructions == changed.networks[0].instructions


def test_a_branch_drawn_anew_is_coded_with_a_tr_point() -> None:
    net = layout_network(fatek(TWO).networks[0].instructions)
    net.source = None
    grown = net.copy()
    end = grown.columns
    grown.cells[(2, 1)] = Contact(fatek("ORG X5\nOUT Y2\n").networks[0].instructions[0].operand)
    for col in range(2, end):
        grown.cells[(2, col)] = net.cells[(1, col)]
    grown.cells[(2, end)] = Coil(fatek("ORG X5\nOUT Y2\n").networks[0].instructions[1].operand)
    grown.links = {(0, 1), (1, 1)}
    grown.rows = 3
    code, diags = network_to_instructions(grown, 0, "fatek")
    assert code is not None, diags
    from ladderworks.core.il.program import Network
    text = "\n".join(network_lines(Network(code), True))
    assert [line.split() for line in text.splitlines()] == [
        ["ORG", "X0"], ["OUT", "TR", "0"], ["AND", "X1"], ["OUT", "Y0"], ["LD", "TR", "0"],
        ["AND", "X2"], ["OUT", "Y1"], ["LD", "TR", "0"], ["AND", "X5"], ["OUT", "Y2"]]


@pytest.mark.parametrize("text", [
    "ORG X0\nOUT TR 0\nAND X1\nOUT Y0\nLD TR 0\nAND TR0\nOUT Y1\n",  # TR 0 read as a contact
    "ORG X0\nOUT TR 0\nAND X1\nOUT Y0\nLD X2\nLD TR 0\nANDLD\nOUT Y1\n",  # pushed, joined
], ids=["contact", "block"])
def test_a_tr_point_read_otherwise_stays_a_relay(text: str,
                                                 monkeypatch: pytest.MonkeyPatch) -> None:
    assert fatek(text).networks == _relays(text, monkeypatch).networks


def test_the_binary_keeps_the_tr_numbers_and_disasm_prints_them(
        tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    source = tmp_path / "three.lst"
    source.write_text(THREE + NESTED.replace("X", "X1"))
    binary = tmp_path / "three.bin"
    assert main(["compile", str(source), "--dialect", "fatek", "-o", str(binary)]) == 0
    capsys.readouterr()
    assert main(["disasm", str(binary)]) == 0
    lines = [line.split() for line in capsys.readouterr().out.splitlines()]
    assert [line[-1] for line in lines if line[:2] in (["OUT", "TR"], ["LD", "TR"])] == \
        ["3", "3", "3", "0", "1", "1", "0"]
