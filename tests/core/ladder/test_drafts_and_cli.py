"""Nothing drawn is lost on save; the text-art drawing; the `ladder` and `mnemonic` commands."""

from __future__ import annotations

import random

import pytest

from ladderworks.cli import main
from ladderworks.core.address import parse_address
from ladderworks.core.il import parse, parse_file, print_program
from ladderworks.core.ladder import WIRE, Coil, Contact, FunctionBox, LadderNetwork
from ladderworks.core.ladder.art import draw_document, draw_network
from ladderworks.core.ladder.convert import ladder_to_program, program_to_ladder
from ladderworks.core.ladder.decompose import network_to_instructions
from tests.core.ladder.strategies import EXAMPLES
from tests.core.ladder.test_power_flow import _random_grid


def _save_and_reopen(doc):
    program, _ = ladder_to_program(doc)
    text = print_program(program)
    result = parse(text)
    assert result.ok, result.diagnostics
    return program_to_ladder(result.program), text


def _half_drawn() -> LadderNetwork:
    network = LadderNetwork(4, 2, comments=["yarım kaldı"])
    network.cells[(0, 0)] = Contact(parse_address("X1.0"), comment="başla // bekle")
    network.cells[(0, 2)] = Coil(None)
    network.cells[(1, 1)] = FunctionBox.new("CTR", (3,))
    network.links.add((0, 1))
    return network


def test_a_network_still_being_drawn_is_saved_and_reopened_as_drawn() -> None:
    doc = program_to_ladder(parse_file(EXAMPLES / "rising_edge.LAD").program)
    doc.networks.insert(1, _half_drawn())
    doc.networks.append(_half_drawn())
    reopened, text = _save_and_reopen(doc)
    assert "//@grid " in text
    assert len(reopened.networks) == len(doc.networks)
    for old, new in zip(doc.networks, reopened.networks, strict=True):
        assert new == old
    assert network_to_instructions(reopened.networks[0])[0] is not None


def test_random_unfinished_networks_survive_saving() -> None:
    rnd = random.Random(3)
    saved = 0
    for _ in range(400):
        network = _random_grid(rnd)
        network.comments = ["not", "done"]
        if network_to_instructions(network)[0] is not None:
            continue
        saved += 1
        reopened, _ = _save_and_reopen(program_to_ladder(parse("%@3\n%\n").program).__class__(
            networks=[network]))
        assert reopened.networks == [network]
    assert saved > 200


def test_a_damaged_draft_stays_as_comment_lines() -> None:
    text = "%@3\n//@grid LADDERWORKS-GRID 1 {oops\n//@grid {}\nRD X0.0\nWRT Y0.0\n%\n"
    doc = program_to_ladder(parse(text).program)
    assert len(doc.networks) == 1
    assert doc.networks[0].comments == ["@grid LADDERWORKS-GRID 1 {oops", "@grid {}"]


def test_text_art_shows_addresses_contacts_coils_links_and_comments() -> None:
    doc = program_to_ladder(parse_file(EXAMPLES / "or_double.LAD").program)
    lines = draw_network(doc.networks[0])
    art = "\n".join(lines)
    assert lines[0] == "//  2- İKİLİ OR UYGULAMASI"
    assert "F9.4" in lines[1] and "|/|" in lines[2] and "( )" in lines[2]
    assert "+" in lines[2] and "|" in lines[3]  # the parallel branch is joined
    assert "R1.4" in lines[3] and "|/|" in lines[4]
    assert "M30 KOD ÇÖZÜCÜ SİNYALİ" in art


def test_text_art_shows_a_box_with_its_inputs_and_parameters() -> None:
    network = LadderNetwork(4, 1)
    network.cells.update({(0, 0): Contact(parse_address("X0.0")), (0, 1): WIRE,
                          (0, 2): FunctionBox.new("TMRB", (3, 96)),
                          (0, 4): Coil(parse_address("R1.0"))})
    art = "\n".join(draw_network(network))
    assert "TMRB" in art and "ACT" in art and "96" in art and "W1" in art


def test_listing_networks_are_printed_as_instructions() -> None:
    doc = program_to_ladder(parse("%@3\nRD X0.0\nWRT Y0.0\nOR X0.1\nWRT Y0.1\n%\n").program)
    art = draw_document(doc)
    assert "kept as instruction list" in art and "OR X0.1" in art


@pytest.mark.parametrize("name", ["or_triple_and.LAD", "all_functions.LAD"])
def test_cli_ladder_prints_every_network(name: str, capsys: pytest.CaptureFixture[str]) -> None:
    path = EXAMPLES / name
    assert main(["ladder", str(path)]) == 0
    out = capsys.readouterr().out
    program = parse_file(path).program
    assert out.count("== network ") == len(program.networks)
    for ins in program.instructions():
        if ins.operand is not None:
            assert str(ins.operand) in out


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.LAD")), ids=lambda p: p.name)
def test_cli_mnemonic_prints_the_program_back(path, capsys: pytest.CaptureFixture[str]) -> None:
    assert main(["mnemonic", str(path)]) == 0
    assert capsys.readouterr().out == print_program(parse_file(path).program)


def test_cli_reports_a_broken_file(tmp_path, capsys: pytest.CaptureFixture[str]) -> None:
    bad = tmp_path / "bad.LAD"
    bad.write_text("%@3\nRD Q1.0\n%\n", encoding="utf-8")
    assert main(["mnemonic", str(bad)]) == 1
    assert "unknown-area" in capsys.readouterr().err
