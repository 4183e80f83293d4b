"""Which reader reads a file, and a Delta file saved back byte for byte."""

from __future__ import annotations

import pytest

from ladderworks.core import dialects
from ladderworks.core.compiler import compile, disassemble
from ladderworks.core.compiler.binary import decode
from ladderworks.core.il import Instruction, parse_file
from ladderworks.core.il.printer import encode_program, print_program
from ladderworks.core.il.reading import UnknownDialect, choose, parse_bytes
from tests.core.dialects.conftest import EXAMPLES, bit_of, delta

PMC_TEXT = b"%@3\nRD X0.0\nWRT Y0.0\n%\n"
DELTA_TEXT = "; comment\nLD X0\nOR Y0\nANI X1\nOUT Y0\nEND\n"


def test_a_delta_list_is_recognised_from_its_content() -> None:
    assert choose(DELTA_TEXT.encode()) is dialects.get("delta")
    assert parse_bytes(DELTA_TEXT.encode()).program.dialect == "delta"


def test_a_pmc_program_is_not_taken_for_delta() -> None:
    assert choose(PMC_TEXT) is None
    assert parse_bytes(PMC_TEXT).program.dialect == "seed"
    for path in EXAMPLES.parent.glob("*.LAD"):
        assert choose(path.read_bytes()) is None, path.name


def test_a_dialect_can_be_forced_or_refused() -> None:
    forced = parse_bytes(b"LD X0\nOUT Y0\n", "delta")
    assert forced.ok and forced.program.dialect == "delta"
    assert parse_bytes(DELTA_TEXT.encode(), "pmc").program.dialect == "seed"
    with pytest.raises(UnknownDialect):
        parse_bytes(DELTA_TEXT.encode(), "siemens")


@pytest.mark.parametrize("path", sorted(EXAMPLES.glob("*.txt")), ids=lambda p: p.name)
def test_every_example_is_read_as_delta_and_saved_as_it_was(path) -> None:
    result = parse_file(path)
    assert result.ok, [d.located(path.name) for d in result.diagnostics]
    assert result.program.dialect == "delta"
    assert encode_program(result.program) == path.read_bytes()


@pytest.mark.parametrize(("encoding", "bom", "newline"), [
    ("utf-8", b"", "\n"), ("utf-8", b"\xef\xbb\xbf", "\r\n"), ("cp1254", b"", "\r\n"),
    ("utf-16-le", b"\xff\xfe", "\r\n"), ("utf-16-be", b"\xfe\xff", "\n"),
])
def test_text_forms_are_kept(encoding: str, bom: bytes, newline: str) -> None:
    text = ("; Motor çalıştırma — şalter\n000000  LD\tX0   // başlat\n1  ANI X1\n"
            "2  OUT Y0\n\n   P1\nLD X2 ; yorum\nOUT Y1\nEND").replace("\n", newline)
    data = bom + text.encode(encoding)
    result = parse_bytes(data)
    assert result.ok, result.diagnostics
    assert result.program.dialect == "delta"
    assert encode_program(result.program) == data
    first = result.program.networks[0].instructions
    assert [ins.name for ins in first] == ["RD", "AND.NOT", "WRT"]
    assert first[0].comment == "başlat"
    assert first[0].line == 2 and first[0].column == 9


def test_a_changed_network_is_written_in_delta_and_the_rest_kept() -> None:
    text = "; start\nLD X0\nOUT Y0\n; second\nLD X1\nOUT Y1\nEND\n"
    program = delta(text)
    network = program.networks[1]
    network.instructions[0] = Instruction("RD.NOT", bit_of("X7"))
    saved = encode_program(program).decode()
    assert saved == "; start\nLD X0\nOUT Y0\n; second\nLDI\tX7\nOUT\tY1\nEND\n"
    again = delta(saved)
    assert again.networks[1].instructions[0].operand == bit_of("X7")


def test_format_prints_every_network_in_delta() -> None:
    program = delta("LD X0\nMPS\nAND X1\nOUT Y0\nMPP\nTMR T1 K50\nLD= T1 K5\nOUT M10\n"
                    "LD X2\nCJ P3\nP3\nEND\n")
    text = print_program(program)
    assert text == ("LD\tX0\nMPS\nAND\tX1\nOUT\tY0\nMPP\nTMR\tT1\tK50\nLD=\tT1\tK5\n"
                    "OUT\tM10\nLD\tX2\nCJ\tP3\nP3\nEND\n")
    assert delta(text) == program


def test_the_binary_remembers_the_dialect() -> None:
    binary = compile(delta(DELTA_TEXT))
    assert decode(binary).dialect == "delta"
    assert disassemble(binary).dialect == "delta"


def test_no_real_fanuc_program_or_fragment_is_taken_for_delta() -> None:
    from tests.real_programs import real_programs_dir

    for path in sorted(real_programs_dir().glob("FANUC_*.txt")):
        data = path.read_bytes()
        assert choose(data) is None, path.name  # fragments too, without their %@3 framing


def test_the_seed_listings_are_recognised_as_written() -> None:
    # seed 003:999-1027 as DIALECTS.md prints it (no END), and seed 001:1000-1012
    seed_cj = ("LD  X0\nCJ  P1\nLDI X1\nLD  X3\nOR  Y0\nANB\nOUT  Y0\nP001\nLDI  X1\n"
               "ANI  X2\nLD  X3\nOR  X4\nOR Y0\nANB\nOUT Y0\n")
    seed_compare = "LD= T0  K5\nOUT  Y0\nLD X1\nLD< C1 C2\nOR> C2 K10\nANB\nOUT Y1\n"
    for text in (seed_cj, seed_compare):
        result = parse_bytes(text.encode())
        assert result.ok and result.program.dialect == "delta"
