"""The cross reference: readers and writers of each address, with network, label and unit."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.cli import main
from ladderworks.core.address import parse_address
from ladderworks.core.il import parse, parse_bytes
from ladderworks.core.ladder.convert import program_to_ladder
from ladderworks.core.xref import Access, CrossReference, Use, UseKind
from tests.real_programs import real_bytes, real_programs_dir

EXAMPLES = Path(__file__).resolve().parents[2] / "resources" / "examples"

# A LADDER-III style program: labels, level 1, level 2, a subprogram P1 called from level 2.
FANUC_TEXT = """%@3
N00001:
RD         X0.1
AND.NOT    R10.2
WRT        Y0.0
N00002:
RD         X0.2
SET        R10.2
N00003:
RD         X0.3
RST        R10.2
N00004:
SUB 1
N00005:
RD         R10.2
SUB 44
R20
D100
N00006:
RD         R10.2
SUB 3
5
WRT        R11.0
N00007:
SUB 66
P1
N00008:
SUB 2
N00009:
SUB 71
P1
N00010:
RD.NOT     D101.3
WRT.NOT    R30.0
N00011:
SUB 72
N00012:
SUB 64
%
"""


def _xref(text: str) -> CrossReference:
    result = parse(text)
    assert result.ok, result.diagnostics
    return CrossReference.from_program(result.program)


def _summary(uses: list[Use]) -> list[tuple[str, int, str, str, UseKind, Access, str, str]]:
    return [(str(u.address), u.network + 1, u.label, u.unit, u.kind, u.access, u.instruction,
             u.parameter) for u in uses]


def test_a_bit_lists_every_reader_and_writer_with_its_network_label_and_unit() -> None:
    xref = _xref(FANUC_TEXT)
    assert _summary(xref.uses_of(parse_address("R10.2"))) == [
        ("R10.2", 1, "N00001", "L1", UseKind.CONTACT_NOT, Access.READ, "AND.NOT", ""),
        ("R10.2", 2, "N00002", "L1", UseKind.SET, Access.WRITE, "SET", ""),
        ("R10.2", 3, "N00003", "L1", UseKind.RESET, Access.WRITE, "RST", ""),
        ("R10.2", 5, "N00005", "L2", UseKind.CONTACT, Access.READ, "RD", ""),
        ("R10.2", 6, "N00006", "L2", UseKind.CONTACT, Access.READ, "RD", ""),
    ]
    assert _summary(xref.uses_of(parse_address("R30.0"))) == [
        ("R30.0", 10, "N00010", "P1", UseKind.COIL_NOT, Access.WRITE, "WRT.NOT", "")]
    assert _summary(xref.uses_of(parse_address("Y0.0"))) == [
        ("Y0.0", 1, "N00001", "L1", UseKind.COIL, Access.WRITE, "WRT", "")]


def test_a_word_parameter_is_a_use_of_each_of_its_bytes_and_their_bits() -> None:
    xref = _xref(FANUC_TEXT)
    movw_in = ("R20", 5, "N00005", "L2", UseKind.PARAMETER, Access.READ, "MOVW", "input")
    movw_out = ("D100", 5, "N00005", "L2", UseKind.PARAMETER, Access.WRITE, "MOVW", "output")
    assert _summary(xref.uses_of(parse_address("R20"))) == [movw_in]
    assert _summary(xref.uses_of(parse_address("R21.6"))) == [movw_in]
    assert _summary(xref.uses_of(parse_address("D101"))) == [movw_out, (
        "D101.3", 10, "N00010", "P1", UseKind.CONTACT_NOT, Access.READ, "RD.NOT", "")]
    assert _summary(xref.uses_of(parse_address("D101.3")))[0] == movw_out
    assert xref.uses_of(parse_address("D102")) == []
    assert xref.uses_of(parse_address("D101.2")) == [xref.uses_of(parse_address("D101"))[0]]


def test_timer_and_counter_numbers_use_their_t_and_c_bytes() -> None:
    fanuc = _xref(FANUC_TEXT)  # TMR 5 of a LADDER-III program: T8 (2 bytes) and T9008
    assert [(str(u.address), u.width, u.kind, u.parameter) for u in fanuc.uses
            if u.instruction == "TMR"] == [("T8", 2, UseKind.NUMBER, "preset"),
                                           ("T9008", 2, UseKind.NUMBER, "precision")]
    assert fanuc.uses_of(parse_address("T9.0"))[0].instruction == "TMR"
    seed = _xref((EXAMPLES / "timer_relay.LAD").read_text("utf-8"))  # TMR 1: T0..T3, in ms
    (timer,) = seed.uses_of(parse_address("T3"))
    assert (timer.instruction, timer.width, timer.access) == ("TMR", 4, Access.READ)
    counter = _xref("%@3\nRD X0.0\nRD.STK X0.1\nRD.STK X0.2\nRD.STK X0.3\nCTR 3\nWRT R1.0\n%\n")
    assert [(str(u.address), u.width, u.access, u.parameter) for u in counter.uses
            if u.kind is UseKind.NUMBER] == [("C8", 2, Access.READ, "preset"),
                                             ("C10", 2, Access.READ_WRITE, "value")]


def test_addresses_are_listed_in_area_order_x_y_f_g_r_a_d_t() -> None:
    xref = _xref(FANUC_TEXT)
    assert [str(a) for a in xref.addresses()] == [
        "X0.1", "X0.2", "X0.3", "Y0.0", "R10.2", "R11.0", "R20", "R30.0", "D100", "D101.3",
        "T8", "T9008"]
    assert [str(u.address) for u in xref.sorted_uses()][:5] == [
        "X0.1", "X0.2", "X0.3", "Y0.0", "R10.2"]


def test_the_seed_examples_functions_read_inputs_and_write_outputs() -> None:
    text = (EXAMPLES / "all_functions.LAD").read_text("utf-8")
    program = parse(text).program
    xref = CrossReference.from_program(program)
    for use in xref.uses:
        if use.kind is UseKind.PARAMETER and use.parameter in ("output", "result"):
            assert use.access is Access.WRITE, use
        elif use.kind is UseKind.PARAMETER and use.parameter in ("input", "a", "b", "code"):
            assert use.access is Access.READ, use
    assert {u.instruction for u in xref.uses if u.kind is UseKind.PARAMETER} >= {
        "DECB", "MOVE", "COMPB", "ADDB"}


def test_x22_eskip_and_esp_and_the_grid_gives_the_same_uses_with_cells() -> None:
    program = parse_bytes(real_bytes("FANUC_STUDER_X22_P036")).program
    xref = CrossReference.from_program(program)
    eskip = program.symbols.address_of("ESKIP")
    assert str(eskip) == "X21.7"
    readers = xref.uses_of(eskip)
    assert readers and all(u.access is Access.READ for u in readers)
    writers = [u for u in xref.uses_of(parse_address("G8.4")) if u.access is Access.WRITE]
    assert writers and writers[0].kind is UseKind.COIL and writers[0].label.startswith("N")
    assert {u.unit for u in xref.uses} >= {"L1", "L2"}
    assert any(u.unit.startswith("P") for u in xref.uses)
    document = program_to_ladder(program)
    grid = CrossReference.from_ladder(document.networks, program.dialect)

    def key(u: Use) -> tuple[object, ...]:  # the grid knows a contact, not RD from AND
        contact = u.kind in (UseKind.CONTACT, UseKind.CONTACT_NOT)
        return (str(u.address), u.network, u.label, u.unit, u.kind, u.access,
                "" if contact else u.instruction, u.parameter)

    assert sorted(map(key, grid.uses)) == sorted(map(key, xref.uses))
    for use in grid.uses_of(parse_address("G8.4")):
        assert use.cell is not None
        found = document.networks[use.network].element_at(*use.cell)
        assert found is not None and getattr(found[1], "address", None) == use.address


def test_every_real_program_and_fragment_indexes_every_address_operand() -> None:
    folder = real_programs_dir()
    for path in sorted(folder.glob("FANUC_*.txt")):
        data = real_bytes(path.stem)
        program = parse_bytes(data).program
        xref = CrossReference.from_program(program)
        operands = sum(1 for ins in program.instructions() if ins.operand is not None)
        bit_uses = sum(1 for u in xref.uses if u.kind not in (UseKind.PARAMETER,
                                                              UseKind.NUMBER))
        assert bit_uses == operands, path.name


def _run(capsys: pytest.CaptureFixture[str], *argv: str) -> tuple[int, str, str]:
    code = main(list(argv))
    out = capsys.readouterr()
    return code, out.out, out.err


def test_cli_xref_of_a_symbol_prints_the_table(capsys: pytest.CaptureFixture[str]) -> None:
    path = real_programs_dir() / "FANUC_STUDER_X22_P036.txt"
    code, out, err = _run(capsys, "xref", str(path), "ESKIP", "G8.4")
    assert code == 0 and err == ""
    lines = out.splitlines()
    assert lines[0].split() == ["ADDRESS", "SYMBOL", "NETWORK", "LABEL", "UNIT", "LINE",
                                "INSTRUCTION", "ELEMENT", "ACCESS"]
    eskip = [line.split() for line in lines[1:] if line.startswith("X21.7")]
    assert eskip and all(row[1] == "ESKIP" and row[-1] == "read" for row in eskip)
    esp = [line.split() for line in lines[1:] if line.startswith("G8.4")]
    assert any(row[1] == "*ESP" and row[-2:] == ["coil", "write"] for row in esp)


def test_cli_xref_without_addresses_lists_all_sorted(tmp_path: Path,
                                                     capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "fanuc.LAD"
    path.write_text(FANUC_TEXT, "utf-8")
    code, out, _ = _run(capsys, "xref", str(path))
    assert code == 0
    rows = [line.split() for line in out.splitlines()[1:]]
    assert [row[0] for row in rows][:4] == ["X0.1", "X0.2", "X0.3", "Y0.0"]
    assert ["D100:2", "-", "5", "N00005", "L2", "16", "MOVW", "parameter", "output",
            "write"] in rows
    assert len(rows) == len(CrossReference.from_program(parse(FANUC_TEXT).program))


def test_cli_xref_errors_and_exit_codes(tmp_path: Path,
                                        capsys: pytest.CaptureFixture[str]) -> None:
    path = tmp_path / "fanuc.LAD"
    path.write_text(FANUC_TEXT, "utf-8")
    code, out, err = _run(capsys, "xref", str(path), "R500.1")
    assert (code, out) == (1, "") and "R500.1 is not used in" in err
    code, _, err = _run(capsys, "xref", str(path), "NOSUCH")
    assert code == 2 and "'NOSUCH' is neither an address nor a symbol of" in err
    code, _, err = _run(capsys, "xref", str(path), "R99999")
    assert code == 2 and "byte number out of range" in err
    broken = tmp_path / "broken.LAD"
    broken.write_text("%@3\nRD X0.1\nFOO R1\nWRT Y0.0\n%\n", "utf-8")
    code, _, err = _run(capsys, "xref", str(broken))
    assert code == 1 and f"{broken}:3:" in err
    code, _, err = _run(capsys, "xref", str(tmp_path / "missing.LAD"))
    assert code == 2 and "missing.LAD" in err
