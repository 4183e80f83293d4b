"""How an element is named on the ladder: the user's own words first, the manual's as fallback."""

from __future__ import annotations

from dataclasses import dataclass

from ladderworks.core.address import Address
from ladderworks.core.signals import signal_at
from ladderworks.core.symbols import SymbolTable


@dataclass(frozen=True, slots=True)
class Names:
    """What is shown with an element's address: a symbol and a comment (either may be "")."""

    symbol: str = ""
    comment: str = ""


def address_names(address: Address, symbols: SymbolTable | None, *,
                  turkish: bool = False) -> Names:
    """The program's symbol and comment of an address, each falling back to the manual.

    Symbol: the program's symbol, else the manual's signal name. Comment: the program's
    comment lines (joined with " / "), else the manual's description in the UI language
    (English when the manual has no Turkish). A comment in the program's symbol table is never
    replaced by the manual's, even when the program gives it no symbol."""
    entry = symbols.lookup(address) if symbols is not None else None
    signal = signal_at(address)
    symbol = entry.symbol if entry is not None and entry.symbol else ""
    comment = " / ".join(c for c in entry.comments if c) if entry is not None else ""
    if signal is not None:
        symbol = symbol or signal.name
        own = signal.turkish if turkish else signal.english
        comment = comment or own or signal.english
    return Names(symbol, comment)

