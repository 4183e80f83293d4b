"""A watch row's name or address as a place in the PLC's memory, with its data type.

A name is what the program's symbol table knows (an S7 tag `"Start"`, a member `#Timer.ET`,
`"DB_Celda".Contador.Total`, an instance's `"T1".Q`; a PMC symbol), an address is spelled as
the program's family spells it (`%MW2`, `%I0.0`; `X0.1`, `D100`; Delta `D0`, `M1`) with an
optional `:W` width (1, 2 or 4 bytes). docs/plc-utilities.md, "Watch table".
"""

from __future__ import annotations

import re
from dataclasses import dataclass

from ladderworks.core import dialects
from ladderworks.core.address import Address, AddressError
from ladderworks.core.diagnostics import Refused
from ladderworks.core.symbols import SymbolTable

# the bytes a value of an elementary type takes (the S7 layout's; Bool: a bit)
TYPE_WIDTHS = {"bool": 0, "byte": 1, "sint": 1, "usint": 1, "char": 1, "int": 2, "uint": 2,
               "word": 2, "dint": 4, "udint": 4, "dword": 4, "real": 4, "time": 4,
               "date": 2, "tod": 4, "time_of_day": 4, "lreal": 8, "lint": 8, "ulint": 8,
               "lword": 8, "ltime": 8}
# elementary types of 64 bits the table does not show (an LTOD, an LDT: no format of theirs)
WIDE_TYPES = frozenset({"ltod", "ldt", "date_and_ltime"})
_STRING_RE = re.compile(r"^string(?:\s*\[\s*(\d+)\s*\])?$", re.I)


class WatchError(Refused):
    """A name, an address or a value the watch table refuses; its diagnostic says why."""


@dataclass(frozen=True, slots=True)
class WatchPlace:
    """Where a row's value lives: its address (a bit for a Bool), its width in bytes (0 for
    a bit), its type name as the program writes it ("" when the program gives none) and its
    address as the family spells it."""

    address: Address
    width: int
    type_name: str
    spelled: str

    @property
    def is_bit(self) -> bool:
        """True for a bit (a Bool)."""
        return self.address.bit is not None

    @property
    def string_length(self) -> int | None:
        """The most characters of an S7 String (its layout: max, length, characters)."""
        match = _STRING_RE.match(self.type_name.strip())
        if match is None:
            return None
        return int(match.group(1) or 254)


def type_width(type_name: str) -> int | None:
    """The bytes of an elementary type (Bool 0, Int 2 …; String[n] n + 2), None otherwise."""
    low = type_name.strip().lower()
    if low in TYPE_WIDTHS:
        return TYPE_WIDTHS[low]
    match = _STRING_RE.match(low)
    if match is not None:
        return int(match.group(1) or 254) + 2
    return None


def _spell(address: Address, width: int, dialect: str | None) -> str:
    found = dialects.get(dialect)
    if found is None:
        return str(address)
    if found.devices.laid_out(address):  # an optimized S7 DB's member: no absolute address,
        return ""  # as TIA's watch table leaves it blank
    return found.devices.format_sized(address, max(width, 1)) or found.format_address(address)


def _symbol(text: str, symbols: SymbolTable) -> tuple[str, Address] | None:
    """The symbol `text` names and its address: as typed, or with its first component quoted
    (`DB_Celda.Contador.Total` for `"DB_Celda".Contador.Total`)."""
    tries = [text]
    if text and text[0] not in '"#%':
        head, dot, rest = text.partition(".")
        tries.append(f'"{head}"{dot}{rest}')
    for name in tries:
        address = symbols.address_of(name)
        if address is not None:
            return name, address
    return None


def resolve(text: str, symbols: SymbolTable | None, dialect: str | None) -> WatchPlace:
    """The place a typed name or address names in a program of `dialect`. WatchError."""
    typed = text.strip()
    if not typed:
        raise WatchError("watch-unknown", text=text)
    if symbols is not None:
        found = _symbol(typed, symbols)
        if found is not None:
            name, address = found
            typed_as = next((found for found in (symbols.type_of(form) for form in (
                name, f'"{name}"', f"#{name}")) if found is not None), None)
            type_name = typed_as[0] if typed_as is not None else ""
            width = type_width(type_name) if type_name else None
            if type_name.strip().lower() in WIDE_TYPES:
                raise WatchError("watch-wide", text=typed, type=type_name)
            if type_name and width is None:  # a struct, an instance: its members are watched
                raise WatchError("watch-struct", text=typed, type=type_name)
            if width is None:
                width = 0 if address.bit is not None else 1
            if address.bit is not None:
                width = 0
            return WatchPlace(address, width, type_name, _spell(address, width, dialect))
    try:
        target = dialects.typed_target(typed, None, dialect)
    except AddressError as error:
        raise WatchError("watch-unknown", text=typed) from error
    address = target.address
    width = 0 if address.bit is not None else target.width
    return WatchPlace(address, width, "Bool" if width == 0 else "",
                      _spell(address, width, dialect))
