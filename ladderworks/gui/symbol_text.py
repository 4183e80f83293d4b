"""How the console names an address (the program's symbol first, else the manual's signal)."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication

from ladderworks.core import dialects
from ladderworks.core.address import Address
from ladderworks.core.dialects.spelling import spelling
from ladderworks.core.il import Instruction
from ladderworks.core.ladder import Coil, Contact, FunctionBox, LadderNetwork, open_cells
from ladderworks.core.naming import address_names
from ladderworks.core.signals import signal_at
from ladderworks.core.symbols import SymbolTable, describe
from ladderworks.core.tag_names import names_for
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


def program_name(address: Address, symbols: SymbolTable | None, dialect: str | None) -> str:
    """The name of `address` in a program of `dialect`: a dialect's has no FANUC signal names."""
    if dialects.get(dialect) is None:
        return describe(address, symbols)
    return (symbols.symbol(address) or "") if symbols is not None else ""


def tooltip(address: Address, symbols: SymbolTable | None, dialect: str | None = None) -> str:
    """Lines for a tooltip: `X21.7  ESKIP`, then the comment (or the signal's descriptions); in
    a program of a dialect its device (`X17`) and no FANUC signal."""
    names = names_for(symbols, dialect)
    if names.typed:  # S7: `%I0.0  "Start"`, a DB member by its name alone
        lines = [f"{names.spelled(address)}  {names.name_of(address)}".strip()]
        found = symbols.lookup(address) if symbols is not None else None
        lines += [comment for comment in (found.comments if found is not None else ()) if comment]
        return "\n".join(lines)
    lines = [dialects.format_address(address, dialect)]
    found = symbols.lookup(address) if symbols is not None else None
    if found is not None and found.symbol:
        lines[0] += f"  {found.symbol}"
        lines += [comment for comment in found.comments if comment]
        return "\n".join(lines)
    signal = signal_at(address) if dialects.get(dialect) is None else None
    if signal is not None:
        lines[0] += f"  {signal.name}"
        lines += [text for text in (signal.turkish, signal.english, signal.notes) if text]
    return "\n".join(lines)


def element_tooltip(network: LadderNetwork, row: int, col: int,
                    symbols: SymbolTable | None) -> str:
    """Tooltip of a cell's contact or coil: address, symbol, its comments; else ""."""
    found = network.element_at(row, col)
    if found is None or not isinstance(found[1], Contact | Coil) or found[1].address is None:
        return ""
    element = found[1]
    address = element.address
    if address is None:
        return ""
    text = tooltip(address, symbols)
    return text + (f"\n// {element.comment}" if element.comment else "")


def cell_status(network: LadderNetwork, index: int, row: int, col: int,
                symbols: SymbolTable | None, dialect: str | None = None) -> str:
    """Status-bar text of network `index`'s cell: the cell, and the address with its signal
    name and comment (or the function with its parameters); in a program of `dialect` in its
    spelling (`X0`, `TMR T0 K10`) and without FANUC signal names."""
    shown = spelling(dialect)
    parts = [QCoreApplication.translate("LadderEditor", "N{0} row {1} col {2}").format(
        index + 1, row + 1, col + 1)]
    if network.label:
        parts.append(network.label)
    found = network.element_at(row, col)
    if found is not None:
        element = found[1]
        if isinstance(element, Contact | Coil) and element.address is not None:
            parts.append(shown.address(element.address))
            described = (name_and_text(element.address, symbols) if not shown.dialect else
                         None)
            if described is not None:
                parts.append(" — ".join(text for text in described if text))
            if element.comment:
                parts.append(element.comment)
        elif isinstance(element, FunctionBox):
            parts.append(shown.instruction(Instruction(element.name, params=element.params)))
    if (row, col) in open_cells(network):  # the red mark, in words (keyboard users)
        parts.append(QCoreApplication.translate(
            "LadderEditor", "open circuit here: draw a wire or an element"))
    return "  |  ".join(parts)
