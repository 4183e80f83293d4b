"""The real LADDER-III exports: read without errors, saved back byte for byte, edits stay local."""

from __future__ import annotations

import difflib

import pytest

from ladderworks.core.address import parse_address
from ladderworks.core.il import parse_bytes
from ladderworks.core.il.printer import encode_program, print_faithful
from ladderworks.core.il.program import FANUC, Instruction
from tests.real_programs import WHOLE, fragment_names, real_bytes


def _utf16(data: bytes) -> bytes:
    return b"\xff\xfe" + data.decode("ascii").encode("utf-16-le")


def _crlf(data: bytes) -> bytes:
    return data.replace(b"\n", b"\r\n")


@pytest.mark.parametrize("form", ["published", "utf-16le-bom", "crlf"])
@pytest.mark.parametrize("name", WHOLE)
def test_save_of_an_unmodified_real_program_writes_identical_bytes(name: str, form: str) -> None:
    data = real_bytes(name)
    data = {"published": data, "utf-16le-bom": _utf16(data), "crlf": _crlf(data)}[form]
    result = parse_bytes(data)
    assert result.ok, result.diagnostics[:5]
    assert result.program.dialect == FANUC and result.program.framed
    assert encode_program(result.program) == data


@pytest.mark.parametrize("name", fragment_names())
def test_fragments_read_cleanly_and_save_back(name: str) -> None:
    data = real_bytes(name)
    result = parse_bytes(data)
    assert result.ok, result.diagnostics[:5]
    assert encode_program(result.program) == data


def test_editing_one_network_of_x22_changes_only_its_lines() -> None:
    data = real_bytes("FANUC_STUDER_X22_P036")
    program = parse_bytes(data).program
    index, network = next((k, n) for k, n in enumerate(program.networks)
                          if n.instructions[0].operand == parse_address("X21.7"))
    first = network.instructions[0]
    network.instructions[0] = Instruction(first.name, parse_address("X21.6"))
    before = data.decode("ascii").split("\n")
    after = print_faithful(program).split("\n")
    start, stop = program.source.spans[index]
    changed = [(tag, i1, i2) for tag, i1, i2, _j1, _j2 in
               difflib.SequenceMatcher(None, before, after, autojunk=False).get_opcodes()
               if tag != "equal"]
    assert changed, "the edit is not in the saved text"
    assert all(start <= i1 and i2 <= stop for _tag, i1, i2 in changed), changed
    diff = list(difflib.unified_diff(before, after, lineterm="", n=0))[2:]
    assert [d for d in diff if not d.startswith("@@")] == ["-RD         X21.7",
                                                           "+RD         X21.6"]


def test_x22_sections_are_read_into_views() -> None:
    program = parse_bytes(real_bytes("FANUC_STUDER_X22_P036")).program
    symbols = program.symbols
    assert symbols is not None and len(symbols) > 12000
    assert symbols.symbol(parse_address("X21.7")) == "ESKIP"
    assert symbols.symbol(parse_address("G8.4")) == "*ESP"
    assert symbols.address_of("ESKIP") == parse_address("X21.7")
    assert symbols.program_symbol(38) == "C62297"
    assert program.title[4] == "P036" and program.title[5] == "01"
    assert program.system_params == {"2": "BINARY"}
    message = program.messages[parse_address("A0.1")]
    assert (message.number, message.text) == (1000, "STUDER ERRORMESSAGE")
    assert [m.address for m in program.io_modules][:2] == ["X03", "X09"]
    assert [s.title for s in program.sections()] == ["%@0", "%@1", "%@2-C", "%@4", "%@5"]
    labels = [n.label for n in program.networks[:3]]
    assert labels == ["N00000", "N00001", "N00002"]


def test_ladder_command_shows_program_symbols(capsys: pytest.CaptureFixture[str],
                                              tmp_path: object) -> None:
    from pathlib import Path

    from ladderworks.cli import main

    path = Path(str(tmp_path)) / "x22.mnc"
    path.write_bytes(real_bytes("FANUC_STUDER_X22_P036"))
    assert main(["ladder", str(path)]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert "   X21.7 ESKIP" in lines
    assert "   G8.4 *ESP" in lines
