"""`ADDR[:W]` targets (CLI --print/--set/--trace, the time chart) and errors as diagnostics."""

from __future__ import annotations

import ast
from pathlib import Path

import pytest

from ladderworks.core.address import AddressError, parse_address
from ladderworks.core.diagnostics import MESSAGES, Diagnostic
from ladderworks.core.ladder.edits import EditRefused
from ladderworks.core.symbols import Symbol, SymbolTable, Target, parse_target

CORE = Path(__file__).resolve().parents[2] / "ladderworks"


@pytest.mark.parametrize(("text", "address", "width"), [
    ("R1.4", "R1.4", 1),
    ("R100", "R100", 1),
    (" D10:2 ", "D10", 2),
    ("D20:4", "D20", 4),
    ("D20:1", "D20", 1),
])
def test_addresses_with_and_without_width(text: str, address: str, width: int) -> None:
    assert parse_target(text) == Target(text.strip(), parse_address(address), width)


@pytest.mark.parametrize(("text", "code"), [
    ("D10:3", "target-width"),
    ("D10:", "target-width"),
    ("R1.4:2", "bit-width"),
    ("Q7.1", "unknown-area"),
    ("ESKIP", "bad-address"),  # no symbols to look it up in
])
def test_errors_are_diagnostics_with_english_text(text: str, code: str) -> None:
    with pytest.raises(AddressError) as info:
        parse_target(text)
    assert info.value.diagnostic.code == code
    assert "{" not in str(info.value) and str(info.value) == info.value.diagnostic.message()


def test_symbols_are_looked_up_only_when_the_text_is_no_address() -> None:
    table = SymbolTable()
    table.add(parse_address("G8.4"), Symbol("*ESP"))
    table.add(parse_address("R200"), Symbol("R100"))  # the address spelling wins
    assert parse_target("*ESP", table.address_of) == Target("*ESP", parse_address("G8.4"))
    assert parse_target("R100:2", table.address_of).address == parse_address("R100")
    with pytest.raises(AddressError) as info:
        parse_target("*ESP:2", table.address_of)
    assert info.value.code == "bit-width"


def test_every_refusal_is_a_diagnostic() -> None:
    refused = EditRefused("edit-outside", (3, 4), row=3, col=4)
    assert refused.diagnostic == Diagnostic("edit-outside", {"row": 3, "col": 4}, cell=(3, 4))
    assert str(refused) == "cell (3, 4) is outside the grid"
    assert isinstance(AddressError("bit-range", text="X0.9"), ValueError)


def _raised_codes(path: Path) -> set[str]:
    """Codes passed literally to Diagnostic(...) or to a refusal (`AddressError("code", ...)`)."""
    makers = {"Diagnostic", "AddressError", "TableError", "EditRefused", "Refused", "Problem"}
    codes = set()
    for node in ast.walk(ast.parse(path.read_text("utf-8"))):
        if (isinstance(node, ast.Call) and isinstance(node.func, ast.Name)
                and node.func.id in makers and node.args
                and isinstance(node.args[0], ast.Constant) and isinstance(node.args[0].value, str)):
            codes.add(node.args[0].value)
    return codes


def test_every_code_raised_in_the_sources_has_a_message() -> None:
    raised = set().union(*(_raised_codes(path) for path in CORE.rglob("*.py")))
    assert len(raised) > 50
    assert sorted(raised - set(MESSAGES)) == []
