"""S7 networks drawn as TIA draws LAD from the graph kept with the Program, and read back.

Every example (SD and SimaticML XML) draws one network per S7 network, alike in both forms, with
named pins and operands as written; the drawing read back as a graph lowers to the same engine
program; an edit lowers again and runs."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from ladderworks.core.compiler import compile_program
from ladderworks.core.dialects.s7 import palette, reader, xml_open
from ladderworks.core.dialects.s7.from_grid import network_from_grid, operand_from_text
from ladderworks.core.dialects.s7.graph import OperandKind
from ladderworks.core.dialects.s7.source import S7Model
from ladderworks.core.il.program import Program
from ladderworks.core.ladder.art import draw_document
from ladderworks.core.ladder.clipboard import copy_text, network_from_text
from ladderworks.core.ladder.convert import ladder_to_program, program_to_ladder
from ladderworks.core.ladder.model import Coil, Contact, FunctionBox, LadderNetwork, Wire
from ladderworks.core.plc.engine import DEFAULT_PERIOD_MS
from ladderworks.core.plc.scenario import read_scenario, run_scenario
from ladderworks.core.plc.session import PlcRun

ROOT = Path(__file__).resolve().parents[4] / "resources" / "examples"
NAMES = ("calls", "compare", "counters", "jump_list", "jumps", "switch", "timers")


def _open(form: str, name: str) -> Program:
    module = reader if form == "s7" else xml_open
    program, diagnostics, _encoding = module.open_path(ROOT / form / name, None)
    assert not [d for d in diagnostics if d.severity.name == "ERROR"]
    return program


def _model(program: Program) -> S7Model:
    assert isinstance(program.model, S7Model)
    return program.model


@pytest.mark.parametrize("name", NAMES)
def test_every_example_draws_one_network_per_s7_network_alike_in_sd_and_xml(name: str) -> None:
    sd, xml = _open("s7", name), _open("s7-xml", name)
    drawn = program_to_ladder(sd).networks
    assert len(drawn) == len(_model(sd).entry.networks)
    assert all(n.listing is None for n in drawn), "kept as instruction list"
    assert draw_document(program_to_ladder(sd)) == draw_document(program_to_ladder(xml))
    assert [_shown(n) for n in drawn] == [_shown(n) for n in program_to_ladder(xml).networks]


def _shown(network: LadderNetwork) -> object:
    """What is drawn (a box's `origin` keeps what its form says beyond that: an XML call's
    block kind)."""
    return [(cell, replace(e, origin=()) if isinstance(e, FunctionBox) else e)
            for cell, e in network.elements()], network.links, network.label


def _boxes(network: LadderNetwork) -> list[FunctionBox]:
    return [e for _c, e in network.elements() if isinstance(e, FunctionBox)]


def test_the_ton_box_has_its_pins_its_instance_and_its_operands_as_written() -> None:
    first, second = program_to_ladder(_open("s7", "timers")).networks
    assert first.comments == ["TON 10 s on the start input"]
    start = first.cells[(0, 0)]
    assert isinstance(start, Contact) and start.texts == ('"Start"',)
    assert start.address is not None  # the tag's engine address: power flow reads it
    (ton,) = _boxes(first)
    assert (ton.title, ton.type_name, ton.instance) == ("TON", "Time", '"IEC_Timer_0_DB"')
    pins = {(p.name, p.row, p.output): p.text for p in ton.named}
    assert pins == {("IN", 0, False): "", ("PT", 1, False): "T#10s",
                    ("Q", 0, True): "", ("ET", 1, True): '"Geçen Süre"'}
    assert ton.name == "S7.TON" and ton.inputs == ("IN",) and ton.has_output
    coil = first.cells[(0, first.columns)]
    assert isinstance(coil, Coil) and coil.texts == ('"Lamba 1"',)
    compare = second.cells[(0, 0)]
    assert isinstance(compare, Contact) and compare.texts == ('"Geçen Süre"', "T#5s")
    assert compare.mark == ">=\nTime"


def test_counters_calls_jumps_and_ranges_are_drawn_with_their_pins() -> None:
    counters = program_to_ladder(_open("s7", "counters")).networks
    ctud = _boxes(counters[2])[0]
    assert [p.name for p in ctud.named if not p.output] == ["CU", "CD", "R", "LD", "PV"]
    assert [p.name for p in ctud.named if p.output] == ["QU", "QD", "CV"]
    calls = program_to_ladder(_open("s7", "calls")).networks
    fb = _boxes(calls[1])[0]
    assert (fb.title, fb.instance) == ("Gecikme", '"Gecikme_DB"')
    assert {p.name: p.text for p in fb.named}.items() >= {
        "giris": '"Motor"', "sure": "T#3s", "cikis": '"Fan"'}.items()
    jumps = program_to_ladder(_open("s7", "jumps")).networks
    jump = jumps[0].cells[(0, jumps[0].columns)]
    assert isinstance(jump, Coil) and (jump.mark, jump.texts) == ("JMP", ("AA_1",))
    assert jumps[2].label == "AA_1"
    compare = program_to_ladder(_open("s7", "compare")).networks
    in_range = _boxes(compare[0])[0]
    assert [p.name for p in in_range.named if p.text] == ["MIN", "VAL", "MAX"]
    switch = _boxes(program_to_ladder(_open("s7", "switch")).networks[0])[0]
    assert [p.text for p in switch.named if p.name.startswith(("DEST", "ELSE"))] == [
        "Kucuk", "Esit", "Buyuk", "Tanimsiz"]


@pytest.mark.parametrize(("form", "name"), [(f, n) for f in ("s7", "s7-xml") for n in NAMES])
def test_the_drawing_read_back_lowers_to_the_same_program(form: str, name: str) -> None:
    program = _open(form, name)
    model = _model(program)
    nets = model.draw()
    changed = [net.copy() for net in nets]
    for net in changed:  # each drawn network counts as changed: read back from its grid
        net.comments = [*net.comments, "edited"]
    rebuilt, found = model.rebuild(changed)
    assert not found
    assert [n.instructions for n in rebuilt.networks] == \
        [n.instructions for n in program.networks]
    graph = [network_from_grid(net, model.entry) for net in nets]
    assert [len(g.parts) for g in graph] == [len(n.parts) for n in model.entry.networks]


def _scenario(name: str) -> Path:
    return ROOT / "s7" / name / "Main.scenario.csv"


@pytest.mark.parametrize("name", ["timers", "counters", "jumps", "switch"])
def test_the_rebuilt_program_passes_the_example_scenario(name: str) -> None:
    program = _open("s7", name)
    doc = program_to_ladder(program)
    for net in doc.networks:
        net.comments = [*net.comments, "changed"]
    rebuilt, found = ladder_to_program(doc)
    assert not found
    compiled = compile_program(rebuilt)
    assert compiled.binary is not None
    plc = PlcRun(period_ms=DEFAULT_PERIOD_MS)
    assert not plc.load(compiled.binary)
    scenario = read_scenario(str(_scenario(name)), rebuilt.symbols, "s7")
    result = run_scenario(plc, scenario)
    assert result.passed, [c for c in result.checks if not c.passed] or result


def test_an_edit_lowers_again_and_runs() -> None:
    """A contact added in series before the TON: the timer runs only with both inputs."""
    program = _open("s7", "timers")
    doc = program_to_ladder(program)
    first = doc.networks[0]
    first.cells[(1, 0)] = Contact(texts=('"Geçen Süre"',))  # any operand: replaced below
    del first.cells[(1, 0)]
    ton_anchor = next(c for c, e in first.cells.items() if isinstance(e, FunctionBox))
    assert first.cells[(0, 1)] == Wire()
    first.cells[(0, 1)] = Contact(texts=("%I0.7",), negated=True)
    rebuilt, found = ladder_to_program(doc)
    assert not found
    model = _model(rebuilt)
    parts = [p.name for p in model.entry.networks[0].parts]
    assert parts.count("Contact") == 2 and "TON" in parts
    assert rebuilt.networks != program.networks
    redrawn = program_to_ladder(rebuilt).networks[0]
    assert isinstance(redrawn.cells[(0, 1)], Contact) and redrawn.cells[(0, 1)].negated
    assert ton_anchor in redrawn.cells  # drawn again where it was


def test_parallel_branches_become_an_o_and_draw_back_as_rows() -> None:
    program = _open("s7", "jumps")
    doc = program_to_ladder(program)
    net = doc.networks[1]  # "Buton" -> "Lamba"
    net.cells[(1, 0)] = Contact(texts=('"Start"',))
    net.links.add((0, 1))
    net.rows = 2
    rebuilt, found = ladder_to_program(doc)
    assert not found
    s7 = _model(rebuilt).entry.networks[1]
    assert [p.name for p in s7.parts].count("O") == 1
    again = program_to_ladder(rebuilt).networks[1]
    assert isinstance(again.cells[(1, 0)], Contact) and (0, 1) in again.links


def test_operands_are_read_as_tia_writes_them() -> None:
    assert operand_from_text('"DB".a.b').path == ("DB", "a", "b")
    assert operand_from_text("#Timer.Q").kind is OperandKind.LOCAL
    assert operand_from_text("%MW2").kind is OperandKind.ABSOLUTE
    assert operand_from_text("T#10s").kind is OperandKind.CONSTANT


def test_a_box_s7_has_not_is_a_diagnostic_at_its_cell() -> None:
    program = _open("s7", "timers")
    doc = program_to_ladder(program)
    doc.networks[1].cells[(0, 3)] = FunctionBox.new("ADDB", (2, 0, 0, 0))
    _rebuilt, found = ladder_to_program(doc)
    assert [d.code for d in found] == ["s7-grid-element"]
    assert found[0].args["network"] == 2 and found[0].args["column"] == 4
    assert (found[0].network, found[0].cell) == (1, (0, 3))  # outlined in the console


def test_networks_other_dialects_draw_are_unchanged() -> None:
    program = replace(_open("s7", "timers"), model=None)
    assert all(n.listing is not None or not _boxes(n) or not _boxes(n)[0].named
               for n in program_to_ladder(program).networks)


@pytest.mark.parametrize("name", NAMES)
def test_drawn_networks_copy_and_paste_with_their_pins_and_operands(name: str) -> None:
    for network in program_to_ladder(_open("s7", name)).networks:
        assert network_from_text(copy_text(network)) == network


def test_the_palette_places_what_the_drawing_draws() -> None:
    ton = palette.new_element("S7.TON")
    assert isinstance(ton, FunctionBox) and ton.origin == (("part", "TON"), ("time_type", "Time"))
    assert [(p.name, p.text) for p in ton.named] == [
        ("IN", ""), ("PT", "<???>"), ("Q", ""), ("ET", "...")]
    filled = palette.with_operands(ton, ['"T1"', "T#2s", ""])
    assert isinstance(filled, FunctionBox) and filled.instance == '"T1"'
    assert [p.text for p in filled.named] == ["", "T#2s", "", "..."]
    assert palette.operand_names(filled) == ["instance", "PT", "ET"]
    compare = palette.new_element("S7.EQ")
    assert isinstance(compare, Contact) and compare.mark == "==\nInt"
    coil = palette.new_element("S7.P_COIL")
    assert isinstance(coil, Coil) and coil.mark == "P" and len(coil.texts) == 2
    assert palette.new_element("S7.LABEL") is None


def test_fbd_networks_draw_as_the_lad_they_map_to_and_read_back_alike() -> None:
    from ladderworks.core.il.reading import parse_bytes
    from tests.core.dialects.s7.test_xml_fbd import _CMP, _OR_AND
    from tests.core.dialects.s7.xml_docs import document

    program = parse_bytes(document([_OR_AND, _CMP], language="FBD").encode()).program
    doc = program_to_ladder(program)
    first, second = doc.networks
    assert first.listing is None and second.listing is None
    assert first.links == {(0, 2)}  # the OR's two rows joined after the AND
    negated = first.cells[(0, 1)]
    assert isinstance(negated, Contact) and negated.negated and negated.texts == ("%I0.1",)
    compare = second.cells[(0, 1)]
    assert isinstance(compare, Contact) and compare.texts == ("%MW2", "10")
    for net in doc.networks:
        net.comments = [*net.comments, "changed"]
    rebuilt, found = ladder_to_program(doc)
    assert not found
    assert [n.instructions for n in rebuilt.networks] == \
        [n.instructions for n in program.networks]


def test_an_operand_typed_is_read_as_tia_writes_it() -> None:
    model = _model(_open("s7", "jumps"))
    shown, address = model.operand("Start")  # type: ignore[misc]
    assert shown == '"Start"' and address == model.resolve(operand_from_text('"Start"'))
    assert model.operand("#Sabit")[0] == "#Sabit"  # type: ignore[index]
    assert model.operand("%Q0.3")[0] == "%Q0.3"  # type: ignore[index]
    refused = model.operand("%MW2")  # a word on a contact: no bit
    assert not isinstance(refused, tuple) and refused.code == "s7-address"
