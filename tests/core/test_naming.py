"""What an element shows: the program's symbol and comment first, the manual's as fallback."""

from __future__ import annotations

from ladderworks.core.address import parse_address
from ladderworks.core.naming import Names, address_names
from ladderworks.core.symbols import Symbol, SymbolTable

G84 = parse_address("G8.4")  # the manual: ESP, EMERGENCY STOP / ACİL DUR


def _table(symbol: str, *comments: str) -> SymbolTable:
    table = SymbolTable()
    table.add(G84, Symbol(symbol, comments))
    return table


def test_without_program_symbols_the_manual_names_the_signal() -> None:
    assert address_names(G84, None) == Names("*ESP", "EMERGENCY STOP")
    assert address_names(G84, None, turkish=True) == Names("*ESP", "ACİL DUR")


def test_the_programs_symbol_and_comment_come_first() -> None:
    table = _table("ACILSTOP", "ACİL STOP BUTONU", "KAPI AÇIK")
    assert address_names(G84, table) == Names("ACILSTOP", "ACİL STOP BUTONU / KAPI AÇIK")


def test_a_program_comment_without_a_symbol_is_not_hidden_behind_the_manual() -> None:
    assert address_names(G84, _table("", "KENDİ AÇIKLAMAM")) == Names("*ESP", "KENDİ AÇIKLAMAM")


def test_a_program_symbol_without_a_comment_keeps_the_manuals_description() -> None:
    assert address_names(G84, _table("ACILSTOP")) == Names("ACILSTOP", "EMERGENCY STOP")


def test_an_address_nobody_names_has_nothing() -> None:
    assert address_names(parse_address("R900.0"), None) == Names()
