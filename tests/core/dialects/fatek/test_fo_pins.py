"""A box's FO1, FO2 … outputs drawn as its own output pins, each with its coils, in one network
(as WinProladder draws them), coded back to the same instructions."""

from __future__ import annotations

import itertools

from ladderworks.core.compiler import compile
from ladderworks.core.dialects.fatek.printer import network_lines, spelling
from ladderworks.core.il.printer import encode_program
from ladderworks.core.il.program import Program
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.ladder.art import draw_network
from ladderworks.core.ladder.clipboard import copy_text, network_from_text
from ladderworks.core.ladder.convert import ladder_to_program, program_to_ladder
from ladderworks.core.ladder.decompose import network_to_instructions
from ladderworks.core.ladder.edits import delete_row, insert_row
from ladderworks.core.ladder.layout import layout_network
from ladderworks.core.ladder.model import WIRE, Coil, FunctionBox
from ladderworks.core.ladder.power import PowerFlow
from ladderworks.core.plc.engine import ScanEngine
from tests.core.dialects.fatek.test_programs import fatek, get, put

# DIALECTS.md 2.4 (001:1081-1095): FO0 Sa=Sb, FO1 Sa>Sb, FO2 Sa<Sb
CMP = ("ORG X0\nFUN 17 CMP\n Sa: R0\n Sb: R1\nFO 0\nOUT Y0\nFO 1\nOUT Y1\nFO 2\nOUT Y2\n"
       "OUT M5\n")
# HSPSO with its inputs EN, PAU, ABT and outputs ACT, ERR, DN (FO0-FO2) as the printout has it
HSPSO = ("ORG X0\nLD X1\nLD X2\nFUN 140 HSPSO\n  Ps: 0\n  SR: R1300\n  WR: R1500\n"
         "FO 0\nOUT M21\nFO 1\nOUT M23\nFO 2\nOUT M22\n")


def _round_trip(program: Program) -> Program:
    """The program as the grid codes it (every network printed from its drawing), read back."""
    lines: list[str] = []
    for index, network in enumerate(program.networks):
        instructions, diags = network_to_instructions(layout_network(network.instructions),
                                                      index, "fatek")
        assert instructions is not None, diags
        assert instructions == network.instructions
        network.instructions = instructions
        lines.extend(network_lines(network, index == 0))
    return fatek("\n".join(lines) + "\n")


def test_cmp_is_one_network_with_its_fo_pins_and_their_coils() -> None:
    program = fatek(CMP)
    assert len(program.networks) == 1
    net = layout_network(program.networks[0].instructions)
    assert net.listing is None
    box = net.cells[(0, 8)]
    assert isinstance(box, FunctionBox) and box.height == 3
    assert [(offset, str(contact.address)) for offset, contact in box.outputs] == \
        [(1, "R2700.1"), (2, "R2700.2")]
    coils = {cell: str(e.address) for cell, e in net.cells.items() if isinstance(e, Coil)}
    assert coils == {(0, 10): "Y0.0", (1, 10): "Y0.1", (2, 10): "Y0.2", (3, 10): "R0.5"}
    assert (2, 10) in net.cells and (3, 10) in net.cells and (2, 10) in net.links
    assert (1, 10) not in net.links and (0, 10) not in net.links  # each pin its own row
    art = "\n".join(draw_network(net, spell=spelling()))
    assert "FO1" in art and "FO2" in art and "FO25" not in art
    assert _round_trip(program).networks[0].instructions == program.networks[0].instructions


def test_cmp_of_the_seed_runs_equal_after_the_grid_sets_fo2_only() -> None:
    program = fatek(CMP)
    again = _round_trip(fatek(CMP))
    for source in (program, again):
        plc = ScanEngine(compile(source), period_ms=10)
        put(plc, "R0", 1)
        put(plc, "R1", 2)
        put(plc, "X0", 1)
        plc.scan()
        assert [get(plc, name) for name in ("Y0", "Y1", "Y2", "M5")] == [0, 0, 1, 1]


def test_hspso_is_one_network_with_inputs_and_act_err_dn_pins() -> None:
    program = fatek(HSPSO)
    assert len(program.networks) == 1
    net = layout_network(program.networks[0].instructions)
    box = net.cells[(0, 8)]
    assert isinstance(box, FunctionBox)
    assert box.pins == (0, 1, 2) and box.height == 3
    assert [offset for offset, _ in box.outputs] == [1, 2]
    for row, name in enumerate(("X0", "X1", "X2")):
        assert spelling().address(net.cells[(row, 0)].address) == name  # type: ignore[union-attr]
        assert all(net.cells[(row, c)] == WIRE for c in range(1, 8))
    assert [spelling().address(net.cells[(row, 10)].address)  # type: ignore[union-attr]
            for row in range(3)] == ["M21", "M23", "M22"]
    assert _round_trip(program).networks[0].instructions == program.networks[0].instructions
    text = "\n".join(network_lines(program.networks[0], True))
    assert "FO       1\nOUT      M23\nFO       2\nOUT      M22" in text


def test_unchanged_saves_byte_for_byte_and_an_edited_pin_coil_prints_in_fatek_form() -> None:
    data = ("; header\n" + CMP).encode()
    program = parse_bytes(data, "fatek").program
    kept: list = []
    doc = program_to_ladder(program, kept)
    saved, diags = ladder_to_program(doc, kept)
    assert not diags and encode_program(saved) == data
    net = doc.networks[0]
    net.cells[(1, 10)] = Coil(fatek("ORG X0\nOUT Y7\n").networks[0].instructions[1].operand)
    changed, diags = ladder_to_program(doc, kept)
    assert not diags
    text = encode_program(changed).decode()
    assert "FO       1\nOUT      Y7\nFO       2" in text
    again = fatek(text)
    assert again.networks[0].instructions == changed.networks[0].instructions


def test_the_box_and_its_pins_copy_paste_and_rows_move_them() -> None:
    net = layout_network(fatek(HSPSO).networks[0].instructions)
    pasted = network_from_text(copy_text(net))
    assert pasted is not None and pasted.cells == net.cells
    grown = net.copy()
    insert_row(grown, 1)
    box = grown.cells[(0, 8)]
    assert isinstance(box, FunctionBox) and [o for o, _ in box.outputs] == [2, 3]
    delete_row(grown, 1)
    assert grown.cells == net.cells and grown.links == net.links
    instructions, diags = network_to_instructions(grown, 0, "fatek")
    assert instructions == fatek(HSPSO).networks[0].instructions, diags
    delete_row(grown, 2)  # the ERR pin's row: the box goes with it
    assert not any(isinstance(e, FunctionBox) for e in grown.cells.values())


def test_a_pin_carries_its_bit_in_the_power_flow() -> None:
    net = layout_network(fatek(CMP).networks[0].instructions)
    for values in itertools.product((False, True), repeat=2):
        flow = PowerFlow(net, lambda a, v=values: a.bit in (1, 2) and a.byte == 2700
                         and v[a.bit - 1])
        assert [flow.node(row, 10) for row in (1, 2)] == list(values)


def test_a_pin_followed_by_a_contact_is_drawn_on_its_box() -> None:
    program = fatek("ORG X0\nFUN 17 CMP\n Sa: R0\n Sb: R1\nFO 1\nAND X3\nOUT Y1\n")
    assert len(program.networks) == 1  # was a rung of its own (`FO17` contact) before
    assert layout_network(program.networks[0].instructions).listing is None


def test_the_pins_feed_their_coils_no_break_is_marked() -> None:
    """A pin is a source of power for its coils, as W1 is: no open-circuit mark there."""
    from ladderworks.core.ladder.open_circuit import open_ends

    assert open_ends(layout_network(fatek(CMP).networks[0].instructions)) == []


# `FO n` followed by logic: the pin, then the contacts in series after it, then its coils
LOGIC = ("ORG X0\nFUN 17 CMP\n Sa: R0\n Sb: R1\nFO 0\nOUT Y0\nFO 1\nAND X3\nAND NOT X4\n"
         "OUT Y1\nFO 2\nOUT Y2\n")


def test_fo_followed_by_contacts_is_the_pin_then_the_contacts_in_one_network() -> None:
    program = fatek(LOGIC)
    assert len(program.networks) == 1
    net = layout_network(program.networks[0].instructions)
    assert net.listing is None
    box = next(e for e in net.cells.values() if isinstance(e, FunctionBox))
    box_cell = next(c for c, e in net.cells.items() if e is box)
    assert [offset for offset, _ in box.outputs] == [1, 2]
    row = box_cell[0] + 1
    after = [net.cells[(row, c)] for c in range(box_cell[1] + box.width, net.coil_column)]
    assert [str(e.address) for e in after if hasattr(e, "address")] == ["X0.3", "X0.4"]
    art = "\n".join(draw_network(net, spell=spelling()))
    assert "FO1" in art and "|/|" in art
    again = _round_trip(program)
    assert again.networks[0].instructions == program.networks[0].instructions
    assert encode_program(program) == LOGIC.encode()


def test_fo_with_logic_runs_as_before_on_every_input() -> None:
    """The network read and the one coded from its drawing run as CMP's FO give them."""
    program = fatek(LOGIC)
    redrawn = _round_trip(fatek(LOGIC))
    for values in itertools.product((0, 1), repeat=4):
        seen = []
        for source in (program, redrawn):
            plc = ScanEngine(compile(source), period_ms=10)
            for name, value in zip(("X0", "X3", "X4", "R0"), values, strict=True):
                put(plc, name, value)
            put(plc, "R1", 1)
            plc.scan()
            seen.append([get(plc, y) for y in ("Y0", "Y1", "Y2")])
        x0, x3, x4, r0 = values
        assert seen[0] == seen[1] == [x0 & (r0 == 1), x0 & (r0 > 1) & x3 & (1 - x4),
                                      x0 & (r0 < 1)]


def test_logic_or_ed_with_a_pin_stays_a_rung_of_its_own() -> None:
    program = fatek("ORG X0\nFUN 17 CMP\n Sa: R0\n Sb: R1\nFO 1\nOR X3\nOUT Y1\n")
    assert len(program.networks) == 2
    for network in program.networks:
        assert layout_network(network.instructions).listing is None


def test_pins_chosen_in_the_editor_are_coded_with_their_coils() -> None:
    """A box with only W1 gets FO2 and FO1 shown (each on a row of its own); the coils drawn
    on them code as `RD FO.n` and the coil; FO2 taken away again keeps FO1 on its row."""
    from ladderworks.core.ladder.edits import EditRefused
    from ladderworks.core.ladder.output_pins import set_output_pins, shown_pins

    program = fatek("ORG X0\nFUN 17 CMP\n Sa: R0\n Sb: R1\nFO 0\nOUT Y0\n")
    net = layout_network(program.networks[0].instructions)
    (row, col), box = next((c, e) for c, e in net.cells.items() if isinstance(e, FunctionBox))
    set_output_pins(net, row, col + 1, (2, 1, 9))  # any cell of the box; 9 is no FO bit
    box = net.cells[(row, col)]
    assert isinstance(box, FunctionBox) and shown_pins(box) == (1, 2) and box.height == 3
    coils = {1: "Y1", 2: "Y2"}
    for offset, _contact in box.outputs:
        for c in range(col + box.width, net.coil_column):
            net.cells[(row + offset, c)] = WIRE
        net.cells[(row + offset, net.coil_column)] = Coil(
            parse_bytes(f"ORG X0\nOUT {coils[offset]}\n".encode(), "fatek").program
            .networks[0].instructions[1].operand)
    code, problems = network_to_instructions(net, 0, "fatek")
    assert code is not None, problems
    assert [(ins.name, str(ins.operand)) for ins in code[-4:]] == [
        ("RD", "R2700.1"), ("WRT", "Y0.1"), ("RD", "R2700.2"), ("WRT", "Y0.2")]
    set_output_pins(net, row, col, (1,))
    box = net.cells[(row, col)]
    assert isinstance(box, FunctionBox) and [o for o, _ in box.outputs] == [1]
    try:
        set_output_pins(net, row, net.coil_column, (1,))
    except EditRefused as refused:
        assert refused.diagnostic.code == "edit-no-pins"
    else:
        raise AssertionError("a coil has no pins")


def test_every_mix_of_pins_and_their_contacts_codes_back_the_same() -> None:
    """FO1 / FO2 each with 0-2 contacts (NO or NC) before its coil: drawn, coded back equal."""
    shapes = itertools.product((0, 1, 2), (0, 1, 2), (False, True))
    for first, second, negated in shapes:
        contacts = ["AND NOT X4" if negated else "AND X4", "AND X5"]
        text = ("ORG X0\nFUN 17 CMP\n Sa: R0\n Sb: R1\nFO 0\nOUT Y0\nFO 1\n"
                + "".join(f"{c}\n" for c in contacts[:first]) + "OUT Y1\nFO 2\n"
                + "".join(f"{c}\n" for c in contacts[:second]) + "OUT Y2\nOUT Y3\n")
        program = fatek(text)
        assert len(program.networks) == 1, text
        assert _round_trip(program).networks[0].instructions == \
            program.networks[0].instructions, text
