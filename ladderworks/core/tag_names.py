"""A program's names in the utilities: a tag typed for a place, the name shown for an address.

A dialect with a typed symbol table (S7: `SymbolTable.types`) names its places by tag
(`"Start"`, `"Motor".Q`, `#Timer.Q`, `"IEC_Timer_0_DB".ET`) or by absolute address (`%I0.0`,
`%MW2`); the bit display, the time chart, the force list and the cross reference use
`TagNames` to read what is typed and to show an address by its name. Addresses with neither a
name nor a spelling in the dialect (the engine's internal relays of an S7 program, R8192 and
up) are `internal`: the utilities do not show them.
"""

from __future__ import annotations

import re
from dataclasses import dataclass
from functools import cached_property

from ladderworks.core import dialects
from ladderworks.core.address import Address, AddressError
from ladderworks.core.il.program import Program
from ladderworks.core.symbols import SymbolTable

_PIECE = re.compile(r'(?:"[^"]*"|[^\s,;"])+')  # a name may hold spaces inside its quotes
_WIDTH_NAMES = {1: "Byte", 2: "Word", 4: "DWord"}


@dataclass(frozen=True, slots=True)
class Named:
    """A place typed by name or address: where, how many bytes (1 for a bit), its type."""

    text: str  # as shown: the tag as TIA writes it (`"Start"`), or the address (`%MW2`)
    address: Address
    width: int = 1
    type_name: str = ""  # TIA's type (`Bool`, `Int`, `Time`, `Real`), "" when unknown


def split_names(text: str) -> list[str]:
    """The names typed in one line, separated by spaces, commas or semicolons outside quotes:
    `"Lamba 1" %Q0.1, "Motor".Q` is three."""
    return _PIECE.findall(text)


class TagNames:
    """The names of one program (its symbol table, in its dialect's spelling)."""

    def __init__(self, symbols: SymbolTable | None, dialect: str | None) -> None:
        self.symbols = symbols
        self.dialect = dialect
        self.typed = symbols is not None and bool(symbols.types)

    @classmethod
    def of(cls, program: Program | None) -> TagNames:
        """The names of `program` (none for None)."""
        if program is None:
            return cls(None, None)
        return cls(program.symbols, program.dialect)

    def resolve(self, text: str) -> Named:
        """A tag or an address as typed; AddressError (the dialect's) when it is neither."""
        typed = text.strip()
        try:
            address, width = dialects.parse_target(typed, self.dialect)
        except AddressError:
            found = self._named(typed)
            if found is None:
                raise
            return found
        type_name = "Bool" if address.bit is not None else _WIDTH_NAMES.get(width, "")
        return Named(typed, address, width, type_name)

    def _named(self, typed: str) -> Named | None:
        symbols = self.symbols
        if symbols is None:
            return None
        for form in self._forms(typed):
            address = symbols.by_symbol.get(form)
            kind = symbols.types.get(form)
            if address is not None and kind is not None:
                return Named(form, address, 1 if address.bit is not None else kind[1], kind[0])
        address = symbols.address_of(typed)  # any case, or a name without a type
        if address is None:
            return None
        kind = symbols.type_of(typed) or symbols.type_of(f'"{typed}"')
        shown = self.name_of(address) or typed
        if kind is None:
            return Named(shown, address)
        return Named(shown, address, 1 if address.bit is not None else kind[1], kind[0])

    def _forms(self, typed: str) -> list[str]:
        """The spellings a typed name may be stored under: as typed, quoted, any case."""
        forms = [typed]
        if not typed.startswith(('"', "#", "%")):
            head, dot, rest = typed.partition(".")
            forms.append(f'"{head}"{dot}{rest}')
            forms.append(f'"{typed}"')
            forms.append(f"#{typed}")  # a block's own member (a block tested alone)
        lowered = {form.lower() for form in forms}
        return forms + [name for name in self._keys if name.lower() in lowered]

    @cached_property
    def _keys(self) -> list[str]:
        return list(self.symbols.types) if self.symbols is not None else []

    @cached_property
    def _by_address(self) -> dict[Address, list[str]]:
        """The names of each named address, the one to show first: a tag's own name, then
        quoted (`"..."`) or local (`#...`) names, shortest first (not a whole DB's)."""
        found: dict[Address, list[str]] = {}
        symbols = self.symbols
        if symbols is None:
            return found
        for name, address in symbols.by_symbol.items():
            kind = symbols.types.get(name)
            if not name.startswith(('"', "#")) or (kind is not None and kind[0] == "Struct"):
                continue
            found.setdefault(address, []).append(name)
        for names in found.values():
            names.sort(key=len)
        for address, symbol in symbols.by_address.items():
            if symbol.symbol:  # a tag's own name first
                found[address] = [symbol.symbol, *(n for n in found.get(address, ())
                                                   if n != symbol.symbol)]
        return found

    def name_of(self, address: Address, width: int = 0) -> str:
        """The name shown for `address` (`"Start"`, `"Calisma_DB".Q`), "" when it has none;
        with a `width`, where several names share the address, the one that wide, else the
        smallest (a timer's `"T1".PT`, not its instance `"T1"`, for a MOVE's operand)."""
        if self.symbols is None:
            return ""
        if not self.typed:
            return self.symbols.symbol(address)
        names = self._by_address.get(address)
        if not names:
            return ""
        if width and address.bit is None and len(names) > 1:  # the value that wide, else
            sizes = {n: self.symbols.types[n][1] for n in names if n in self.symbols.types}
            exact = [n for n in names if sizes.get(n) == width]  # the most specific one
            return exact[0] if exact else min(names, key=lambda n: sizes.get(n, 1 << 30))
        return names[0]

    def spelled(self, address: Address, width: int = 1) -> str:
        """The address in the dialect's spelling (`%MW2` for 2 bytes at R2), "" if none."""
        found = dialects.get(self.dialect)
        if found is None:
            return str(address)
        if address.bit is None and width in (2, 4) and found.byteorder == "big":
            from ladderworks.core.dialects.s7.devices import format_absolute

            text = format_absolute(address, width) or ""
        else:
            text = found.devices.format(address) or ""
        try:  # a place the dialect cannot spell back (S7: a DB member laid out at D16)
            dialects.parse_target(text, self.dialect)
        except AddressError:
            return ""
        return text

    def width_of(self, address: Address, width: int = 1) -> int:
        """The bytes of the name at `address` (its type's), else `width`."""
        name = self.name_of(address)
        kind = self.symbols.type_of(name) if name and self.symbols is not None else None
        return kind[1] if kind is not None and address.bit is None else width

    def shown(self, address: Address, width: int = 1) -> str:
        """The name, else the dialect's spelling (`%I0.0`), else "" (an internal relay)."""
        return self.name_of(address) or self.spelled(address, width)

    def internal(self, address: Address) -> bool:
        """True for a place the program's user never named nor can spell (S7: R8192.x)."""
        return self.typed and not self.shown(address)


_LAST: list[TagNames] = []


def names_for(symbols: SymbolTable | None, dialect: str | None) -> TagNames:
    """TagNames of a symbol table, the last one kept (a dock asks for every bit it shows)."""
    if _LAST and _LAST[0].symbols is symbols and _LAST[0].dialect == dialect:
        return _LAST[0]
    _LAST[:] = [TagNames(symbols, dialect)]
    return _LAST[0]


def network_titles(program: Program) -> list[str]:
    """The title of the source network each of `program`'s networks comes from (an S7 network
    lowers to several: its first carries the title, `Network 3` when untitled)."""
    titles: list[str] = []
    current = ""
    for network in program.networks:
        if network.comments:
            current = network.comments[0]
        titles.append(current)
    return titles


def network_names(program: Program, word: str = "Network") -> list[str]:
    """The source network each of `program`'s networks lowers from, as TIA names it: `Network
    3: Title` (`Network 3` untitled; `word` in the caller's language), a called block's inlined
    networks under the calling network, "" before the first (the start values); the
    `network_titles` when the program keeps no source model."""
    from ladderworks.core.ladder.source_model import source_networks

    found = source_networks(program)
    if found is None:
        return network_titles(program)
    return [network_name(number, title, word) for number, title in found]


def network_name(number: int, title: str, word: str = "Network") -> str:
    """`Network 3: Title`, `Network 3` (no title, or the title is that), "" for number 0."""
    if not number:
        return ""
    plain = f"{word} {number}"
    return plain if not title or title == plain or title == f"Network {number}" \
        else f"{plain}: {title}"


def typed_text(raw: int, type_name: str, width: int) -> str | None:
    """A raw value of `width` bytes as its type shows it, as TIA's watch table does (a Time
    `T#5S`, a Real `21.5`, an Int signed); None for a type shown as a plain number (a Byte, a
    Word, a bit)."""
    from ladderworks.core.dialects.s7.values import time_text
    from ladderworks.core.plc import typed

    low = type_name.lower()
    bits = 8 * width
    signed = raw - (1 << bits) if raw >> (bits - 1) & 1 else raw
    if low == "time" and width == 4:
        return time_text(signed)
    if low == "real" and width == 4:
        return f"{typed.bits_real(raw):.7g}"  # as the watch table (values.show)
    if low in ("sint", "int", "dint"):
        return str(signed)
    return None


def typed_value(text: str, type_name: str, width: int) -> int | None:
    """A value typed for a place of `type_name` as the raw bits stored (`T#5s` 5000, a Real's
    `21.5` its IEEE bits); None when it is neither (a plain number is the caller's)."""
    from ladderworks.core.dialects.s7.layout import time_ms
    from ladderworks.core.plc import typed

    clean = text.strip()
    ms = time_ms(clean)
    if ms is not None:
        return ms & ((1 << 8 * width) - 1)
    if type_name.lower() == "real" and width == 4:
        try:
            return typed.real_bits(float(clean))
        except ValueError:
            return None
    return None


def meaning(raw: int, type_name: str, width: int) -> int | float:
    """What raw bits mean for comparing: a Real's number, a Time's or an Int's signed value."""
    from ladderworks.core.plc import typed

    low = type_name.lower()
    if low == "real" and width == 4:
        return typed.bits_real(raw)
    if low in ("time", "sint", "int", "dint") and raw >> (8 * width - 1) & 1:
        return raw - (1 << 8 * width)
    return raw
