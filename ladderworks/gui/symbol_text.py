"""How the console names an address: the program's symbol first, else the manual's signal."""

from __future__ import annotations

from ladderworks.core.address import Address
from ladderworks.core.naming import address_names
from ladderworks.core.signals import signal_at
from ladderworks.core.symbols import SymbolTable, describe
from ladderworks.gui.translation import ui_is_turkish


def name_and_text(address: object, symbols: SymbolTable | None) -> tuple[str, str] | None:
    """(name, description): the program's symbol and comment, each falling back to the manual's
    signal name and its description in the UI language (`core.naming`); None for an address
    with neither."""
    if not isinstance(address, Address):
        return None
    names = address_names(address, symbols, turkish=ui_is_turkish())
    if not names.symbol and not names.comment:
        return None
    return names.symbol, names.comment


def labelled(address: Address, symbols: SymbolTable | None) -> str:
    """The address with its name: `X21.7 ESKIP` (just `X21.7` when it has none)."""
    name = describe(address, symbols)
    return f"{address} {name}" if name else str(address)


def tooltip(address: Address, symbols: SymbolTable | None) -> str:
    """Lines for a tooltip: `X21.7  ESKIP`, then the comment (or the signal's descriptions)."""
    lines = [str(address)]
    found = symbols.lookup(address) if symbols is not None else None
    if found is not None and found.symbol:
        lines[0] += f"  {found.symbol}"
        lines += [comment for comment in found.comments if comment]
        return "\n".join(lines)
    signal = signal_at(address)
    if signal is not None:
        lines[0] += f"  {signal.name}"
        lines += [text for text in (signal.turkish, signal.english, signal.notes) if text]
    return "\n".join(lines)
