"""Compile checks on the walk's and the parameter checks' own paths: exact codes, arguments,
positions and order (programs built in code have line 0: their order is the walk's)."""

from __future__ import annotations

import gc

from ladderworks.core.address import Address, Area, format_address
from ladderworks.core.compiler import check
from ladderworks.core.il import Instruction, Network, Program, parse
from ladderworks.core.il.program import FANUC, LabelRef, ProgramRef


def found(program: Program) -> list[tuple[str, dict[str, object], int, str, int | None]]:
    """(code, args, line, severity, network) of every diagnostic of `program`, in order."""
    return [(d.code, d.args, d.line, d.severity.value, d.network) for d in check(program)]


def lines(text: str) -> list[tuple[str, dict[str, object], int]]:
    """(code, args, line) of every diagnostic of the ladder-section lines `text`."""
    result = parse("%@3\n" + text.strip() + "\n%\n")
    return [(d.code, d.args, d.line) for d in check(result.program)]


def one(*instructions: Instruction) -> Program:
    """A program of one network built in code (every line 0)."""
    return Program([Network(list(instructions))])


R0_0 = Address(Area.R, 0, 0)


def fanuc(program: Program) -> Program:
    """`program` as a FANUC 30i program (its address map)."""
    program.dialect = FANUC
    return program


def function(name: str, *params: object) -> Program:
    """RD R0.0 and the functional instruction `name` with `params`, built in code."""
    return one(Instruction("RD", R0_0), Instruction(name, params=params))  # type: ignore[arg-type]


def test_a_byte_address_parameter_needs_room_for_its_width() -> None:
    assert found(function("MOVW", Address(Area.D, 9999), Address(Area.D, 0))) == [
        ("byte-range", {"text": "D9999", "area": "D", "last": 9998, "ranges": "0-9999"},
         0, "error", 0)]
    assert found(function("MOVW", Address(Area.D, 9998), Address(Area.D, 0))) == []
    # X and Y have several ranges (a FANUC 30i program): the bytes must lie in one of them
    assert found(fanuc(function("MOVW", Address(Area.X, 127), Address(Area.R, 0)))) == [
        ("byte-range", {"text": "X127", "area": "X", "last": 1126,
                        "ranges": "0-127, 200-327, 400-527, 600-727, 1000-1127"},
         0, "error", 0)]
    assert found(fanuc(function("MOVW", Address(Area.X, 200), Address(Area.R, 0)))) == []
    # a seed program has the seed's map: X0-X127 only
    assert found(function("MOVW", Address(Area.X, 200), Address(Area.R, 0))) == [
        ("byte-range", {"text": "X200", "area": "X", "last": 127, "ranges": "0-127"},
         0, "error", None)]


def test_a_width_given_by_the_format_parameter() -> None:
    assert found(function("NUMEB", 4, 0, Address(Area.D, 9997))) == [
        ("byte-range", {"text": "D9997", "area": "D", "last": 9996, "ranges": "0-9999"},
         0, "error", 0)]
    assert found(function("NUMEB", 2, 0, Address(Area.D, 9998))) == []


def test_a_bit_or_an_impossible_byte_where_a_byte_address_belongs() -> None:
    assert found(function("MOVB", Address(Area.R, 0, 1), Address(Area.R, 1))) == [
        ("byte-expected", {"text": "R0.1"}, 0, "error", 0)]
    assert found(function("MOVB", Address(Area.R, -1), Address(Area.R, 1))) == [
        ("bad-address", {"text": "R-1"}, 0, "error", 0)]
    assert found(function("MOVB", Address(Area.R, 10**7), Address(Area.R, 1))) == [
        ("byte-range", {"text": "R10000000", "area": "R", "last": 9499, "ranges": "0-9499"},
         0, "error", 0)]


def test_function_outputs_into_inputs_and_the_result_register() -> None:
    assert found(function("MOVB", Address(Area.R, 0), Address(Area.X, 3))) == [
        ("write-input", {"name": "MOVB", "address": "X3"}, 0, "error", 0)]
    assert found(function("MOVB", Address(Area.R, 0), Address(Area.F, 3))) == [
        ("write-input", {"name": "MOVB", "address": "F3"}, 0, "error", 0)]
    assert found(function("MOVB", Address(Area.R, 0), Address(Area.R, 9005))) == [
        ("write-result-register", {"name": "MOVB", "address": "R9005"}, 0, "error", 0)]
    assert found(function("MOVB", Address(Area.R, 0), Address(Area.R, 9006))) == []
    assert found(function("MOVB", Address(Area.X, 3), Address(Area.R, 0))) == []  # read


def test_numbers_and_addresses_in_the_wrong_place() -> None:
    assert found(function("MOVB", 5, Address(Area.R, 0))) == [
        ("param-kind-address", {"name": "MOVB", "index": 1, "param": "input", "text": "5"},
         0, "error", 0)]
    assert found(function("TMRB", Address(Area.R, 0), 100)) == [
        ("param-kind-number", {"name": "TMRB", "index": 1, "param": "timer", "text": "R0"},
         0, "error", 0)]
    assert found(function("TMRB", LabelRef(3), 100)) == [
        ("param-kind-number", {"name": "TMRB", "index": 1, "param": "timer", "text": "L3"},
         0, "error", 0)]
    assert found(function("MOVB", Address(Area.R, 0))) == [
        ("param-count", {"name": "MOVB", "expected": 2, "found": 1}, 0, "error", 0)]


def test_numbers_out_of_range_and_choices() -> None:
    assert found(function("NUMEB", 3, 0, Address(Area.R, 0))) == [
        ("param-choice", {"name": "NUMEB", "index": 1, "param": "format", "value": 3,
                          "choices": "1, 2, 4"}, 0, "error", 0)]
    program = one(Instruction("RD", R0_0), Instruction("TMRB", params=(0, 100)))
    assert [(code, args["lo"], args["value"]) for code, args, *_ in found(program)] == [
        ("param-range", 1, 0)]


def test_a_call_of_a_missing_subprogram_and_a_program_number_out_of_range() -> None:
    program = Program([
        Network([Instruction("CALLU", params=(ProgramRef(5),))]),
        Network([Instruction("END1")]),
    ])
    assert [code for code, *_ in found(program)] == ["call-missing"]


def test_equal_coil_addresses_are_one_coil_whatever_the_objects() -> None:
    program = Program([
        Network([Instruction("RD", R0_0), Instruction("WRT", Address(Area.Y, 0, 0))]),
        Network([Instruction("RD", R0_0), Instruction("WRT", Address(Area.Y, 0, 0))]),
        Network([Instruction("RD", R0_0), Instruction("SET", Address(Area.Y, 0, 0))]),
        Network([Instruction("RD", R0_0), Instruction("WRT", Address(Area.Y, 0, 1))]),
        Network([Instruction("RD", R0_0), Instruction("WRT", Address(Area.G, 0, 0))]),
        Network([Instruction("RD", R0_0), Instruction("RST", Address(Area.R, 0, 1))]),
        Network([Instruction("RD", R0_0), Instruction("SET", Address(Area.R, 0, 1))]),
    ])
    assert found(program) == [
        ("coil-twice", {"address": "Y0.0"}, 0, "warning", 1),
        ("coil-mixed-network", {"address": "Y0.0", "other": 2}, 0, "warning", 2),
    ]


def test_contacts_need_logic_before_them_and_an_address() -> None:
    assert lines("AND R0.0\nOR.NOT R0.1\nWRT R1.0") == [
        ("no-logic", {"name": "AND"}, 2)]
    assert found(one(Instruction("RD"), Instruction("AND", R0_0),
                     Instruction("WRT", Address(Area.R, 1, 0)))) == [
        ("missing-operand", {"name": "RD"}, 0, "error", 0),
        ("no-logic", {"name": "AND"}, 0, "error", 0)]
    assert found(one(Instruction("RD", R0_0), Instruction("AND", "R0.x"),  # type: ignore[arg-type]
                     Instruction("WRT"))) == [
        ("bad-address", {"text": "R0.x"}, 0, "error", 0),
        ("missing-operand", {"name": "WRT"}, 0, "error", 0)]  # a coil: nothing dangles


def test_a_network_ending_in_a_contact_or_a_stack_operation_dangles() -> None:
    program = Program([
        Network([Instruction("RD", R0_0), Instruction("AND", R0_0)]),
        Network([Instruction("RD", R0_0), Instruction("RD.STK", R0_0)]),
        Network([Instruction("RD", R0_0), Instruction("RD.STK", R0_0), Instruction("AND.STK"),
                 Instruction("WRT", Address(Area.R, 1, 0))]),
        Network([Instruction("RD", R0_0)]),
    ])
    assert found(program) == [
        ("dangling-logic", {}, 0, "warning", 0), ("dangling-logic", {}, 0, "warning", 1),
        ("dangling-logic", {}, 0, "warning", 3)]


def test_a_write_with_no_logic_before_it() -> None:
    assert lines("WRT R1.0\nRD R0.0\nWRT R1.1") == [("no-logic", {"name": "WRT"}, 2)]


def test_after_an_unknown_instruction_the_network_is_not_checked() -> None:
    program = Program([
        Network([Instruction("RD", R0_0), Instruction("JMP", params=(0,)),
                 Instruction("NOPE"), Instruction("AND"), Instruction("WRT", R0_0),
                 Instruction("END1"), Instruction("ZAP")]),
        Network([Instruction("AND", R0_0), Instruction("WRT", Address(Area.R, 1, 0))]),
        Network([Instruction("END2")]),
    ])
    assert found(program) == [
        ("unknown-instruction", {"name": "NOPE"}, 0, "error", 0),
        ("unknown-instruction", {"name": "ZAP"}, 0, "error", 0),
        # level 1 ends at END1 (unchecked as it is): its JMP 0 range is closed when the next
        # known instruction is reached
        ("jmp-without-jmpe", {}, 0, "error", 0),
        ("no-logic", {"name": "AND"}, 0, "error", 1)]


def test_units_close_their_jump_ranges_where_they_end() -> None:
    assert lines("RD R0.0\nJMP 0\nRD R0.1\nWRT R0.2\nEND1\nRD R0.3\nCOM 0\nRD R0.4\n"
                 "WRT R0.5\nEND2\nRD R0.6\nWRT R0.7\nJMPE") == [
        ("jmp-without-jmpe", {}, 3), ("com-without-come", {}, 8),
        ("jmpe-without-jmp", {}, 14)]


def test_the_canonical_spelling_of_every_area() -> None:
    assert [format_address(Address(area, 12)) for area in Area] == [
        f"{area.value}12" for area in Area]
    assert [str(Address(area, 1000, 7)) for area in Area] == [
        f"{area.value}1000.7" for area in Area]


def test_unknown_instructions_do_not_shift_the_structure_problems() -> None:
    program = Program([
        Network([Instruction("FOO")]),
        Network([Instruction("RD", R0_0), Instruction("WRT", Address(Area.R, 1, 0))]),
        Network([Instruction("END1")]),
        Network([Instruction("BAR")]),
        Network([Instruction("END2")]),
        Network([Instruction("SP", params=(ProgramRef(1),))]),
        Network([Instruction("RD", R0_0), Instruction("JMPB", params=(LabelRef(4),))]),
        Network([Instruction("END")]),
    ])
    assert found(program) == [
        ("unknown-instruction", {"name": "FOO"}, 0, "error", 0),
        ("unknown-instruction", {"name": "BAR"}, 0, "error", 3),
        ("sp-without-spe", {}, 0, "error", 5),
        ("label-missing", {"label": 4}, 0, "error", 6)]


def test_an_unknown_sub_has_a_row_for_its_parameter_count() -> None:
    program = Program([
        Network([Instruction("RD", R0_0), Instruction("SUB.219", params=(1, 2))]),
        Network([Instruction("RD", R0_0),
                 Instruction("SUB.219", params=(Address(Area.R, 0, 3),))]),
        Network([Instruction("RD", R0_0), Instruction("SUB.219", params=(2**33,))]),
    ])
    assert found(program) == [
        ("unknown-sub", {"number": 219}, 0, "warning", 0),
        ("unknown-sub", {"number": 219}, 0, "warning", 1),
        ("byte-expected", {"text": "R0.3"}, 0, "error", 1),
        ("unknown-sub", {"number": 219}, 0, "warning", 2),
        ("param-range", {"name": "SUB.219", "index": 1, "param": "p1", "lo": -2**31,
                         "hi": 2**32 - 1, "value": 2**33}, 0, "error", 2)]


def test_check_leaves_the_cycle_collector_as_it_found_it() -> None:
    program = function("MOVB", Address(Area.R, 0), Address(Area.X, 3))
    was = gc.isenabled()
    try:
        gc.enable()
        assert [code for code, *_ in found(program)] == ["write-input"]
        assert gc.isenabled()
        gc.disable()
        assert [code for code, *_ in found(program)] == ["write-input"]
        assert not gc.isenabled()
    finally:
        if was:
            gc.enable()
