"""A program's symbol table (`%@2` sections): address <-> symbol and comments, P symbols."""

from __future__ import annotations

import re
from collections import deque
from collections.abc import Callable, Iterator, Sequence
from dataclasses import dataclass, field
from itertools import repeat

from ladderworks.core.address import Address, AddressError, parse_address, parse_address_cached

_PROGRAM_RE = re.compile(r"^[Pp]0*(\d{1,6})$")


@dataclass(frozen=True, slots=True)
class Symbol:
    """An address's symbol and its comments, as the program's `%@2` section gives them."""

    symbol: str
    comments: tuple[str, ...] = ()

    @property
    def comment(self) -> str:
        """The first comment, or ""."""
        return self.comments[0] if self.comments else ""


_SET_SYMBOL, _SET_COMMENTS = (vars(Symbol)[name].__set__ for name in ("symbol", "comments"))
_new = object.__new__


def new_symbol(symbol: str, comments: tuple[str, ...]) -> Symbol:
    """Symbol(symbol, comments) made faster (a `%@2` section has thousands): it sets the slots
    as the frozen dataclass's __init__ does, without its checks."""
    entry = _new(Symbol)
    _SET_SYMBOL(entry, symbol)
    _SET_COMMENTS(entry, comments)
    return entry


def new_symbols(symbols: Sequence[str]) -> list[Symbol]:
    """new_symbol(symbol, ()) of each symbol, the objects made and their slots set by C loops
    (map), not one Python call each."""
    entries = list(map(_new, repeat(Symbol, len(symbols))))
    deque(map(_SET_SYMBOL, entries, symbols), maxlen=0)
    deque(map(_SET_COMMENTS, entries, repeat(())), maxlen=0)
    return entries


@dataclass(slots=True)
class SymbolTable:
    """Symbols by address and addresses by symbol; subprogram symbols (`P38`) by number."""

    by_address: dict[Address, Symbol] = field(default_factory=dict)
    by_symbol: dict[str, Address] = field(default_factory=dict)
    programs: dict[int, Symbol] = field(default_factory=dict)
    program_by_symbol: dict[str, int] = field(default_factory=dict)
    # a typed dialect's names (S7): symbol -> (its type as the vendor writes it, its bytes);
    # a global DB's own name (`"DB_Modbus"`) is here with its whole size, not in by_symbol
    types: dict[str, tuple[str, int]] = field(default_factory=dict)

    def __len__(self) -> int:
        return len(self.by_address) + len(self.programs)

    def __iter__(self) -> Iterator[tuple[Address, Symbol]]:
        return iter(sorted(self.by_address.items()))

    def add(self, address: Address, symbol: Symbol) -> None:
        """Record one entry (a later entry for the same address replaces the earlier)."""
        self.by_address[address] = symbol
        if symbol.symbol:
            self.by_symbol.setdefault(symbol.symbol, address)

    def add_program(self, number: int, symbol: Symbol) -> None:
        """Record the symbol of subprogram `number`."""
        self.programs[number] = symbol
        if symbol.symbol:
            self.program_by_symbol.setdefault(symbol.symbol, number)

    def lookup(self, address: Address) -> Symbol | None:
        """The program's symbol of an address (a bit falls back to nothing, not its byte)."""
        return self.by_address.get(address)

    def symbol(self, address: Address) -> str:
        """The symbol text of an address, or ""."""
        found = self.by_address.get(address)
        return found.symbol if found is not None else ""

    def address_of(self, symbol: str) -> Address | None:
        """The address a symbol names (exact, then case-insensitive), or None."""
        found = self.by_symbol.get(symbol)
        if found is None:
            upper = symbol.upper()
            found = next((a for s, a in self.by_symbol.items() if s.upper() == upper), None)
        return found

    def type_of(self, symbol: str) -> tuple[str, int] | None:
        """(type name, bytes) of a typed name (exact, then case-insensitive), or None."""
        found = self.types.get(symbol)
        if found is None and self.types:
            upper = symbol.upper()
            found = next((t for s, t in self.types.items() if s.upper() == upper), None)
        return found

    def program_symbol(self, number: int) -> str:
        """The symbol of subprogram `P<number>`, or ""."""
        found = self.programs.get(number)
        return found.symbol if found is not None else ""

    def program_of(self, symbol: str) -> int | None:
        """The subprogram number a symbol names, or None."""
        return self.program_by_symbol.get(symbol)


def add_entry(table: SymbolTable, address_text: str, symbol: str,
              comments: tuple[str, ...]) -> bool:
    """Add `address_text` (an address or `Pn`) with its symbol; False if it is not one."""
    entry = Symbol(symbol, comments if all(comments) else tuple(c for c in comments if c))
    program = _PROGRAM_RE.match(address_text) if address_text[:1] in ("P", "p") else None
    if program:
        table.add_program(int(program.group(1)), entry)
        return True
    try:
        address = parse_address_cached(address_text, None, 1)
    except AddressError:
        return False
    table.add(address, entry)
    return True


def resolve(text: str, symbols: SymbolTable | None = None, *, width: int = 1) -> Address:
    """An address typed as itself (`X21.7`, `D10`) or as a program symbol (`ESKIP`).

    The address spelling wins; a text that is not a valid address is looked up in `symbols`.
    Raises the address's AddressError when neither fits."""
    try:
        return parse_address(text, width=width)
    except AddressError:
        found = symbols.address_of(text.strip()) if symbols is not None else None
        if found is None:
            raise
        return found


@dataclass(frozen=True, slots=True)
class Target:
    """An address with the width read or written there, as typed: `D10:2`, `ESKIP`, `*ESP:1`."""

    text: str
    address: Address
    width: int = 1


def parse_target(text: str,
                 address_of: Callable[[str], Address | None] | None = None) -> Target:
    """`ADDR[:W]`: an address or a symbol (looked up by `address_of`), width 1, 2 or 4 bytes
    (a dialect's program: `dialects.typed_target`).

    Raises AddressError: the address's own codes, `target-width` for another width after the
    colon, `bit-width` for a bit address with a width."""
    typed = text.strip()
    spelled, colon, width_text = typed.partition(":")
    width = 1
    if colon:
        if width_text.strip() not in ("1", "2", "4"):
            raise AddressError("target-width", text=typed)
        width = int(width_text)
    try:
        address = parse_address(spelled, width=width)
    except AddressError:
        name = spelled.strip()
        found = address_of(name) if address_of is not None and looks_like_symbol(name) else None
        if found is None:
            raise
        address = found
    if address.bit is not None and colon:
        raise AddressError("bit-width", text=typed)
    return Target(typed, address, width)


def describe(address: Address, symbols: SymbolTable | None = None) -> str:
    """The name to show for an address: the program's symbol, else the manual's signal name."""
    if symbols is not None:
        found = symbols.symbol(address)
        if found:
            return found
    from ladderworks.core.signals import signal_at

    signal = signal_at(address)
    return signal.name if signal is not None else ""


def looks_like_symbol(text: str) -> bool:
    """True for text that may be a symbol: no spaces, no `=`, `,` or `@`, not empty."""
    return bool(text) and not any(ch.isspace() or ch in "=,@" for ch in text)
