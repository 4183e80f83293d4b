"""WPLSoft's exported instruction lists (`000012,MPS`): recognised, read, drawn, run, and saved
in their own form (separator, line ends, step numbers)."""

from __future__ import annotations

from itertools import pairwise

import pytest

from ladderworks.core.compiler import compile, compile_program
from ladderworks.core.dialects.delta import csv_form
from ladderworks.core.dialects.delta.reader import read_instructions
from ladderworks.core.il import Network
from ladderworks.core.il.printer import encode_program
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.ladder.convert import program_to_ladder
from ladderworks.core.plc.engine import ScanEngine

from .conftest import EXAMPLES, delta, get, put

SPACES = "LD X0\nOR Y0\nANI X1\nOUT Y0\nLD Y0\nTMR T0 K50\nLD T0\nOUT Y1\nEND\n"
FORMS = {
    "comma, steps, LF": "000000,LD,X0\n000001,OR,Y0\n000002,ANI,X1\n000003,OUT,Y0\n"
                        "000004,LD,Y0\n000005,TMR,T0,K50\n000009,LD,T0\n000010,OUT,Y1\n"
                        "000011,END\n",
    "semicolon, trailing, CRLF": (EXAMPLES / "wplsoft_semicolon.csv").read_text("utf-8"),
    "tabs, steps": "000000\tLD\tX0\n000001\tOR\tY0\n000002\tANI\tX1\n000003\tOUT\tY0\n"
                   "000004\tLD\tY0\n000005\tTMR\tT0\tK50\n000009\tLD\tT0\n000010\tOUT\tY1\n"
                   "000011\tEND\n",
    "comma, no steps": "LD,X0\nOR,Y0\nANI,X1\nOUT,Y0\nLD,Y0\nTMR,T0,K50\nLD,T0\nOUT,Y1\nEND\n",
}


def _read(data: bytes):
    result = parse_bytes(data)
    assert result.program.dialect == "delta", "recognised from its content"
    assert result.ok, [d.located("t") for d in result.diagnostics]
    return result.program


@pytest.mark.parametrize("name", FORMS)
def test_each_form_reads_as_the_instruction_list_and_saves_byte_for_byte(name: str) -> None:
    data = FORMS[name].encode()
    program = _read(data)
    assert [n.instructions for n in program.networks] == \
        [n.instructions for n in delta(SPACES).networks]
    assert encode_program(program) == data


@pytest.mark.parametrize("name", FORMS)
@pytest.mark.parametrize("monitored", [False, True])
def test_each_form_runs_as_written(name: str, monitored: bool) -> None:
    plc = ScanEngine(compile(_read(FORMS[name].encode())), period_ms=10)
    plc.monitored = monitored
    put(plc, "X0", 1)
    plc.step(10)
    put(plc, "X0", 0)
    plc.step(10)
    assert get(plc, "Y0") == 1 and get(plc, "Y1") == 0  # sealed in, the timer running
    plc.step(5000)
    assert get(plc, "Y1") == 1
    put(plc, "X1", 1)
    plc.step(10)
    assert get(plc, "Y0") == 0


def test_a_changed_network_is_written_in_the_files_form_with_wplsofts_steps() -> None:
    data = (EXAMPLES / "wplsoft_semicolon.csv").read_bytes()
    program = _read(data)
    first = program.networks[0]
    more = delta("LD X0\nOR Y0\nANI X1\nANI X2\nOUT Y0\nEND\n").networks[0]
    program.networks[0] = Network(list(more.instructions), first.comments)
    text = encode_program(program).decode()
    assert text.splitlines(keepends=True)[:6] == [
        "000000;LD;X0;\r\n", "000001;OR;Y0;\r\n", "000002;ANI;X1;\r\n", "000003;ANI;X2;\r\n",
        "000004;OUT;Y0;\r\n", "000005;LD;Y0;\r\n"]
    assert text.endswith("000006;TMR;T0;K50;\r\n000010;LD;T0;\r\n000011;OUT;Y1;\r\n"
                         "000012;END;\r\n")


def test_a_deleted_network_moves_the_steps_after_it_back() -> None:
    program = _read((EXAMPLES / "wplsoft_semicolon.csv").read_bytes())
    del program.networks[1]  # LD Y0 / TMR T0 K50: 5 steps
    assert encode_program(program).decode().splitlines()[4:] == [
        "000004;LD;T0;", "000005;OUT;Y1;", "000006;END;"]


def test_the_outputs_example_is_drawn_as_ladder_and_runs() -> None:
    data = (EXAMPLES / "wplsoft_outputs.csv").read_bytes()
    result = parse_bytes(data)
    assert result.ok and result.program.dialect == "delta"
    assert [d.code for d in result.diagnostics] == []
    doc = program_to_ladder(result.program)
    assert all(net.listing is None for net in doc.networks)  # every network drawn as ladder
    assert encode_program(result.program) == data
    plc = ScanEngine(compile(result.program), period_ms=10)
    for x in ("X2", "X0", "X1", "X3", "X6"):
        put(plc, x, 1)
    plc.step(10)
    # MOV among the coils, in a branch after MPS; INV after X3 X4; PID (not simulated) passes on
    assert [get(plc, name) for name in ("Y1", "D0", "Y2", "Y3", "D1", "Y4", "Y5", "Y6")] == \
        [1, 5, 1, 1, 7, 0, 1, 1]


def test_wplsofts_step_sizes_match_its_export_of_a_real_program() -> None:
    """Each line's step is the one before plus that instruction's size (steps)."""
    from tests.real_programs import real_programs_dir

    path = real_programs_dir() / "delta" / "METALURGICA_c91257f_proejto_clp.csv"
    rows = [line.split(",") for line in path.read_text("ascii").splitlines()]
    wrong = [(a[1], int(b[0]) - int(a[0]), csv_form.steps(a[1], len(a) - 2))
             for a, b in pairwise(rows)
             if int(b[0]) - int(a[0]) != csv_form.steps(a[1], len(a) - 2)]
    assert wrong == []


def test_a_list_of_instructions_becomes_a_program() -> None:
    """The .dvp reader's entry: (step, mnemonic, operands) in, a Program out."""
    program, diagnostics = read_instructions(
        [(0, "LD", ("X0",)), (1, "MOV", ("K5", "D0")), (6, "DMUL", ("D0", "K2", "D2")),
         (19, "PID", ("D0", "K2", "D100", "D2")), (28, "OUT", ("Y0",)), (29, "END", ())])
    assert [d.code for d in diagnostics] == []
    assert program.dialect == "delta"
    assert [ins.spec.text_name for ins in program.networks[0].instructions][:3] == \
        ["RD", "MOV", "DMUL"]
    assert program.networks[0].instructions[2].spec.simulated is True
    assert program.networks[0].instructions[3].spec.simulated is False  # PID: shown only
    assert encode_program(program).decode().splitlines()[:2] == ["000000,LD,X0", "000001,MOV,K5,D0"]


@pytest.mark.parametrize("text", [
    "LD X0\nOUT Y0\n",  # instruction mode text: no separators
    "000000 LD X0\n",  # steps and spaces: instruction mode text too
])
def test_instruction_mode_text_is_not_an_export(text: str) -> None:
    assert csv_form.detect(text.splitlines()) is None


def test_text_after_the_operands_is_the_elements_comment() -> None:
    data = b"000000,LD,X0,Start button\r\n000001,OUT,Y0,Motor\r\n000002,END\r\n"
    program = _read(data)
    assert [ins.comment for ins in program.networks[0].instructions] == ["Start button", "Motor"]
    assert encode_program(program) == data


def test_quoted_fields_read_and_a_changed_network_is_quoted_too() -> None:
    data = b'"000000","LD","X0"\r\n"000001","OUT","Y0"\r\n"000002","END"\r\n'
    program = _read(data)
    assert encode_program(program) == data
    more = delta("LD X0\nANI X1\nOUT Y0\nEND\n").networks[0]
    program.networks[0] = Network(list(more.instructions))
    assert encode_program(program).decode().splitlines() == [
        '"000000","LD","X0"', '"000001","ANI","X1"', '"000002","OUT","Y0"', '"000003","END"']


def test_operands_the_simulator_has_no_device_for_keep_the_instruction_shown() -> None:
    """K4M0 (a bit group), D0E0 / E1 (index registers): kept, warned, passed by."""
    text = ("000000,LD,X0\n000001,MOV,K4M0,D0\n000006,OUT,Y0\n"
            "000007,LD,M0E0\n000008,OUT,Y1\n000009,END\n")
    program = _read(text.encode())
    names = [ins.spec.text_name for n in program.networks for ins in n.instructions]
    assert names == ["RD", "MOV", "WRT", "LD", "WRT", "END"]
    compiled = compile_program(program)
    assert compiled.binary is not None
    assert [(d.code, d.line) for d in compiled.diagnostics] == [("not-simulated", 2),
                                                                ("not-simulated", 4)]
    plc = ScanEngine(compiled.binary)
    put(plc, "X0", 1)
    plc.scan()
    assert (get(plc, "Y0"), get(plc, "Y1")) == (1, 0)  # MOV passes on, the LD never conducts
    assert encode_program(program) == text.encode()


def test_a_column_header_line_is_a_comment() -> None:
    data = b"Step,Instruction,Operand\n000000,LD,X0\n000001,OUT,Y0\n000002,END\n"
    program = _read(data)
    assert program.networks[0].comments == ["Step, Instruction, Operand"]
    assert [ins.spec.text_name for ins in program.networks[0].instructions] == ["RD", "WRT"]
    assert encode_program(program) == data
