"""PLC dialects beside the PMC's: the registry, content sniffing, and spelling by dialect.

A dialect (`base.Dialect`) is data: rows of the instruction table, an address map
(`devices.DeviceMap`) and a reader per file form. Its programs are ordinary `Program`s with
`Program.dialect` set to its name, so one engine runs them all. docs/dialects.md.
"""

from __future__ import annotations

import importlib
from collections.abc import Callable

from ladderworks.core import models
from ladderworks.core.address import AREA_SIZES, Address, AddressError, Area, parse_address
from ladderworks.core.dialects.base import Dialect
from ladderworks.core.instructions import add_rows
from ladderworks.core.symbols import Target
from ladderworks.core.symbols import parse_target as parse_pmc_target

__all__ = ["Dialect", "by_code", "every", "format_address", "get", "memory_sizes", "names",
           "parse_bit", "parse_target", "parse_word", "register", "sniff"]

# The modules of the built-in dialects, each with a `DIALECT`; a new dialect adds its line.
BUILTIN: tuple[str, ...] = (
    "ladderworks.core.dialects.delta",
    "ladderworks.core.dialects.fatek",
    "ladderworks.core.dialects.s7",
)

SNIFF_THRESHOLD = 50  # a text scoring this much for a dialect is read as that dialect

_REGISTRY: dict[str, Dialect] = {}


def register(dialect: Dialect) -> Dialect:
    """Add a dialect: its rows join the instruction table."""
    known = _REGISTRY.get(dialect.name)
    if known is not None and known is not dialect:
        raise ValueError(f"dialect {dialect.name} registered twice")
    if any(d.code == dialect.code and d is not dialect for d in _REGISTRY.values()):
        raise ValueError(f"dialect code {dialect.code} used twice")
    add_rows(dialect.rows)
    if known is None:  # a model of its own family in the one list of models (core/models.py)
        models.register(models.PmcModel(dialect.name, dialect.title, dialect.name))
    _REGISTRY[dialect.name] = dialect
    return dialect


def _load_builtin() -> None:
    for module in BUILTIN:
        register(importlib.import_module(module).DIALECT)


def names() -> list[str]:
    """The registered dialects' names."""
    return list(_REGISTRY)


def every() -> list[Dialect]:
    """The registered dialects."""
    return list(_REGISTRY.values())


def get(name: str | None) -> Dialect | None:
    """The dialect called `name`, None for the PMC's own ("seed", "fanuc") or an unknown one."""
    return _REGISTRY.get(name) if name else None


def of(program: object) -> Dialect | None:
    """The dialect of a Program (or anything with a `dialect` name), None for a PMC one."""
    name = getattr(program, "dialect", None)
    return get(name) if isinstance(name, str) else None


def by_code(code: int) -> Dialect | None:
    """The dialect with binary header code `code`."""
    return next((d for d in _REGISTRY.values() if d.code == code), None)


def sniff(text: str) -> Dialect | None:
    """The dialect a text is written in, recognised from its content; None: a PMC program."""
    best: tuple[int, Dialect | None] = (SNIFF_THRESHOLD - 1, None)
    for dialect in _REGISTRY.values():
        score = dialect.sniff(text)
        if score > best[0]:
            best = (score, dialect)
    return best[1]


def format_address(address: Address, dialect: str | None) -> str:
    """`address` as the program's dialect spells it (`X17` for Delta's X1.7)."""
    found = get(dialect)
    return found.format_address(address) if found is not None else str(address)


def parse_bit(text: str, dialect: str | None) -> Address:
    """A bit typed in the program's dialect (`X10`, `M5`); AddressError if it is none."""
    found = get(dialect)
    if found is None:
        return parse_address(text, want_bit=True)
    return found.devices.bit(text)


def parse_word(text: str, dialect: str | None) -> tuple[Address, int]:
    """A word typed in the program's dialect (`D10`) with its width in bytes; AddressError."""
    found = get(dialect)
    if found is None:
        return parse_address(text, want_bit=False), 1
    return found.devices.word(text)


def parse_target(text: str, dialect: str | None, want: str | None = None,
                 width: int = 1) -> tuple[Address, int]:
    """A value's place typed in the program's dialect, with its byte width: `X10`, `D0`, `T0`
    (its value; `want` "bit": its contact). `ADDR:W` gives the width (1, 2 or 4 bytes) of a
    word. A PMC program's address: core/address's spelling, `width` bytes. AddressError."""
    found = get(dialect)
    if found is None:
        return parse_address(text, width=width), width
    spelled, colon, width_text = text.strip().partition(":")
    address, size = found.devices.target(spelled, want)
    if colon:
        if width_text.strip() not in ("1", "2", "4") or address.bit is not None:
            raise AddressError("target-width", text=text)
        size = int(width_text)
    return address, size


def memory_sizes() -> dict[Area, int]:
    """The bytes to allocate per area: the PMC's map, grown where a dialect needs more."""
    sizes = dict(AREA_SIZES)
    for dialect in _REGISTRY.values():
        for area, size in dialect.memory_sizes().items():
            sizes[area] = max(sizes[area], size)
    return sizes


_load_builtin()


def typed_target(text: str, address_of: Callable[[str], Address | None] | None = None,
                 dialect: str | None = None) -> Target:
    """`ADDR[:W]` as a user types it for a program of `dialect`: its devices' spelling (`X10`,
    `D0`), else the PMC's address or symbol (`symbols.parse_target`). AddressError."""
    if get(dialect) is None:
        return parse_pmc_target(text, address_of)
    typed = text.strip()
    try:
        address, size = parse_target(typed, dialect)
    except AddressError:  # a symbol of the program (an S7 tag): `NAME[:W]`
        spelled, width_text = typed, ""
        if typed[-2:] in (":1", ":2", ":4"):
            spelled, width_text = typed[:-2], typed[-1]
        found = address_of(spelled.strip()) if address_of is not None else None
        if found is None:
            raise
        address, size = found, int(width_text or 1)
    return Target(typed, address, size)
