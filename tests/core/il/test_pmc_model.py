"""The PMC model is the program's (issue 30, items 8 and 9): a seed program has the seed's
address map and ranges, a FANUC 30i program the 30i's, whatever the file's framing; the
model kept in the file as a comment line the seed's tools skip."""

from __future__ import annotations

import pytest

from ladderworks.core.address import parse_address
from ladderworks.core.compiler import check
from ladderworks.core.il import Instruction, Network, Program, parse
from ladderworks.core.il.parser import parse_bytes
from ladderworks.core.il.printer import encode_program, print_faithful, print_program
from ladderworks.core.il.program import FANUC, SEED
from ladderworks.core.models import MODELS, model_of, same_family

MARK = "// LADDERWORKS PMC MODEL: fanuc\n"


def _errors(text: str) -> list[tuple[str, int]]:
    result = parse(text)
    found = result.diagnostics + (check(result.program) if result.ok else [])
    return [(d.code, d.line) for d in found if d.is_error]


def _ladder(body: str) -> str:
    return "%@3\nRD X0.0\n" + body + "\n%\n"


@pytest.mark.parametrize("body", ["WRT A100.0", "WRT A249.7", "RD E5.0\nWRT Y0.0",
                                  "WRT G1008.4", "RD X200.0\nWRT Y0.0", "RD K900.1\nWRT Y0.0"])
def test_a_seed_program_has_the_seeds_map(body: str) -> None:
    assert _errors(_ladder(body)), "refused in a seed program"
    assert _errors(MARK + _ladder(body)) == [], "accepted in a FANUC 30i program"


def test_a100_is_the_seeds_byte_range_at_its_line() -> None:
    [diagnostic] = parse(_ladder("WRT A100.0")).diagnostics
    assert (diagnostic.code, diagnostic.line) == ("byte-range", 3)
    assert diagnostic.message() == "'A100.0': byte number out of range for area A (0-99)"
    assert _errors(_ladder("WRT A99.7")) == []


def test_framing_is_only_the_default() -> None:
    framed = "%@A\n%@3\nRD X0.0\nTMRB 245 1000\nWRT A100.0\n%\n%@E\n"
    assert parse(framed).program.dialect == FANUC and _errors(framed) == []
    seed = "; LADDERWORKS PMC MODEL: seed\n" + framed
    assert parse(seed).program.dialect == SEED
    assert {code for code, _line in _errors(seed)} == {"param-range", "byte-range"}


def test_a_seed_program_marked_fanuc_has_the_30i_ranges() -> None:
    text = MARK + _ladder("TMRB 245 1000\nWRT Y0.0")
    assert parse(text).program.dialect == FANUC
    assert _errors(text) == []
    assert [code for code, _ in _errors(_ladder("TMRB 245 1000\nWRT Y0.0"))] == ["param-range"]


def test_an_unknown_model_is_a_plain_comment() -> None:
    text = "// LADDERWORKS PMC MODEL: nosuch\n" + _ladder("WRT Y0.0")
    assert parse(text).program.dialect == SEED


def test_the_checks_judge_a_program_built_in_code_by_its_model() -> None:
    program = Program([Network([Instruction("RD", parse_address("X0.0")),
                                Instruction("WRT", parse_address("A100.0"))])])
    found = [(d.code, d.network) for d in check(program, by_network=True)]
    assert found == [("byte-range", 0)]
    program.dialect = FANUC
    assert check(program) == []


@pytest.mark.parametrize("text", [_ladder("WRT Y0.0"), MARK + _ladder("WRT A100.0"),
                                  "// LADDERWORKS PMC MODEL: seed\n" + _ladder("WRT Y0.0"),
                                  "%@A\n%@3\nRD X0.0\nWRT Y0.0\n%\n%@E\n"])
@pytest.mark.parametrize("newline", ["\n", "\r\n"])
def test_an_unmodified_file_saves_byte_for_byte(text: str, newline: str) -> None:
    data = text.replace("\n", newline).encode("utf-8")
    assert encode_program(parse_bytes(data).program) == data


def test_the_model_round_trips_through_the_file() -> None:
    program = parse(_ladder("WRT Y0.0")).program
    program.dialect = FANUC
    text = print_faithful(program)
    assert text == MARK + _ladder("WRT Y0.0")
    assert parse(text).program.dialect == FANUC
    again = parse(text).program
    again.dialect = SEED  # back to the framing's default: the marker goes
    assert print_faithful(again) == _ladder("WRT Y0.0")
    new = Program()
    new.dialect = FANUC  # a new program, printed canonically, keeps it too
    assert parse(print_program(new)).program.dialect == FANUC


def test_one_list_of_models() -> None:
    assert [key for key in MODELS][:2] == [SEED, FANUC]
    assert [m.key for m in same_family(SEED)][:2] == [SEED, FANUC]
    other = model_of("delta-dvp-test")
    assert other.family == "delta-dvp-test" and [m.key for m in same_family(other.key)] == []
