"""SET/RST coils and the FANUC PMC boxes: text → grid → text, and what the grid holds."""

from __future__ import annotations

import pytest

from ladderworks.core.address import parse_address
from ladderworks.core.il import parse, print_program
from ladderworks.core.il.program import Instruction
from ladderworks.core.instructions import PMC_ORDER, Write, lookup
from ladderworks.core.ladder.clipboard import copy_text, network_from_text
from ladderworks.core.ladder.convert import ladder_to_program, program_to_ladder
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.ladder.edits import add_parallel, invert
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.ladder.model import Coil, FunctionBox, LadderNetwork
from ladderworks.core.ladder.power import PowerFlow
from ladderworks.core.ladder.reading import read_rung
from tests.core.ladder.strategies import PMC_EXAMPLES


def _round_trip(text: str) -> tuple[str, LadderNetwork]:
    """The text read, drawn, coded from the drawing only, and printed; and the drawing."""
    program = parse(f"%@3\n{text}\n%\n").program
    doc = program_to_ladder(program)
    for network in doc.networks:
        assert network.listing is None, print_program(program)
        network.source = None
    back, diagnostics = ladder_to_program(doc)
    assert diagnostics == []
    return print_program(back), doc.networks[0]


def _body(text: str) -> str:
    return "%@3\n" + text + "\n%\n"


def test_set_and_reset_coils_round_trip_as_coils() -> None:
    text = "RD X0.0\nAND.NOT X0.1\nSET R1.0\nRST R1.1\nWRT.NOT Y0.2"
    printed, network = _round_trip(text)
    assert printed == _body(text)
    coils = [e for _, e in network.elements() if isinstance(e, Coil)]
    assert [(c.write, c.negated) for c in coils] == [
        (Write.SET, False), (Write.RESET, False), (Write.OUT, True)]


def test_set_and_reset_after_a_function_output_as_real_programs_write_them() -> None:
    text = "RD X0.0\nWINDW D7151\nSET R5311.4\nRST R5306.1\nWRT R1.0"
    printed, network = _round_trip(text)
    assert printed == _body(text)
    box = next(e for _, e in network.elements() if isinstance(e, FunctionBox))
    assert box.name == "WINDW" and box.has_output


def test_set_and_reset_in_an_output_chain() -> None:
    text = "RD X0.0\nSET R1.0\nAND X0.1\nRST R1.1"
    assert _round_trip(text)[0] == _body(text)


@pytest.mark.parametrize("name", PMC_ORDER)
def test_every_pmc_box_round_trips(name: str) -> None:
    spec = lookup(name)
    assert spec is not None
    inputs = [f"RD{'.STK' if i else ''} X0.{i}" for i in range(len(spec.inputs))]
    outputs = ["SET R9.0", "WRT R9.1"] if spec.w1 else []
    text = "\n".join([*inputs, PMC_EXAMPLES[name], *outputs])
    printed, network = _round_trip(text)
    assert printed == _body(text)
    anchor, box = next((a, e) for a, e in network.elements() if isinstance(e, FunctionBox))
    assert box.name == name and len(box.pins) == len(spec.inputs)
    if spec.inputs:
        assert anchor[1] + box.width == network.coil_column  # right-aligned
    else:
        assert anchor == (0, 0)  # on the left rail


@pytest.mark.parametrize("text", ["SPE", "END3", "CALLU 7", "SP 5", "LBL 3"])
def test_boxes_without_control_inputs_sit_on_the_rail(text: str) -> None:
    name, *params = text.split()
    rung = read_rung([Instruction(name, params=tuple(int(p) for p in params))])
    assert rung.box is not None and rung.inputs == [] and not rung.box.pins
    network = layout_network([Instruction(name, params=tuple(int(p) for p in params))])
    assert isinstance(network.cells[(0, 0)], FunctionBox) and network.listing is None


def test_a_box_without_control_inputs_takes_no_logic() -> None:
    network = layout_network(parse(_body("RD X0.0\nSPE")).program.instructions())
    assert network.listing is not None  # nothing can feed SPE: kept as text


def test_an_unknown_sub_is_a_box_with_act_and_its_raw_parameters() -> None:
    params = (parse_address("R1"), parse_address("R2"), 7)
    rung = read_rung([Instruction("RD", parse_address("X0.0")),
                      Instruction("SUB.219", params=params),
                      Instruction("WRT", parse_address("R3.0"))])
    box = rung.box
    assert box is not None and box.spec.sub == 219 and not box.spec.known
    assert box.inputs == ("ACT",) and box.has_output and len(box.spec.params) == 3
    assert FunctionBox.new("SUB.219", params).pins == (0,)


@pytest.mark.parametrize("name", ["CALL", "CALLU", "SP", "JMPB", "JMPC", "LBL"])
def test_program_and_label_parameters_round_trip(name: str) -> None:
    spec = lookup(name)
    assert spec is not None
    text = "\n".join([*(["RD X0.0"] if spec.inputs else []), PMC_EXAMPLES[name]])
    assert _round_trip(text)[0] == _body(text)


def test_not_tool_turns_set_into_reset_and_or_tool_adds_the_same_kind() -> None:
    network = layout_network(parse(_body("RD X0.0\nSET R1.0")).program.instructions())
    cell = (0, network.coil_column)
    invert(network, *cell)
    assert network.cells[cell] == Coil(parse_address("R1.0"), write=Write.RESET)
    add_parallel(network, *cell)
    added = network.cells[(1, network.coil_column)]
    assert isinstance(added, Coil) and added.write is Write.RESET and added.address is None


def test_grid_text_keeps_set_and_reset() -> None:
    network = layout_network(parse(_body("RD X0.0\nSET R1.0\nRST R1.1")).program.instructions())
    again = network_from_text(copy_text(network))
    assert again == network
    code, problems = network_to_instructions(again)
    assert problems == [] and [i.name for i in code or []] == ["RD", "SET", "RST"]


@pytest.mark.parametrize("closed", [False, True])
def test_set_and_reset_act_only_with_power(closed: bool) -> None:
    network = layout_network(parse(_body("RD X0.0\nSET R1.0\nRST R1.1\nWRT R1.2")
                                   ).program.instructions())
    flow = PowerFlow(network, lambda _: closed)
    expected = [("R1.0", True), ("R1.1", False)] if closed else []
    assert [(str(a), v) for a, v in flow.writes()] == [*expected, ("R1.2", closed)]
