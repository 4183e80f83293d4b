"""Read views of the sections other than the ladder: `%@0`, `%@1`, `%@2…`, `%@4`, `%@5`."""

from __future__ import annotations

import re
from collections import deque
from itertools import compress, count, repeat
from operator import is_
from typing import cast

from ladderworks.core.address import (
    PLAIN_SPELLING,
    Address,
    AddressError,
    Area,
    parse_address,
    parse_address_cached,
    parse_address_once,
    plain_addresses,
)
from ladderworks.core.diagnostics import Diagnostic, Severity
from ladderworks.core.il.program import IoModule, Message, Program, Section
from ladderworks.core.symbols import SymbolTable, add_entry, new_symbol, new_symbols

_COLUMNS_RE = re.compile(r"(SYM|ADR|CM1|CM2)\s*=\s*(\d{1,2})", re.IGNORECASE)
_MESSAGE_RE = re.compile(r"^\s*(\S+)\s+(\d{1,6})(?:[ \t](.*))?$")
_ITEM_RE = re.compile(r"^\s*(\d{1,6})(?:[ \t](.*))?$")
_IO_RE = re.compile(r"^\s*([XYxy]\d{1,6})\s+(\d{1,4})\s+(\d{1,4})\s+(\d{1,4})\s*(.*)$")

# one line a line of a `%@2` section's joined lines: a plain address at the line's start and
# one symbol word (`D37.4   C62179`), or any other line (empty groups)
_PLAIN_SYMBOL_RE = re.compile(rf"({PLAIN_SPELLING})[ \t]+(\S+)[ \t]*\n|[^\n]*\n")

# the `%@2` variants read as `ADDRESS symbol [comment ...]`; `%@2-E(...)` is CSV
_SYMBOL_KINDS = ("", "-C", "-C2")


def _warn(out: list[Diagnostic], section: Section, line: int, text: str) -> None:
    out.append(Diagnostic("section-line", {"section": section.title, "text": text[:40]},
                          line, 1, Severity.WARNING))


def _is_comment(line: str) -> bool:
    stripped = line.strip()
    return not stripped or stripped.startswith((";", "//"))


def read_symbols(section: Section, first: int, table: SymbolTable,
                 out: list[Diagnostic], *, build: bool = True) -> None:
    """Add a `%@2`, `%@2-C`, `%@2-C2` or `%@2-E(...)` section's entries to `table` (with
    `build` False, only its common lines' diagnostics are wanted: they are checked, not
    added)."""
    kind = section.title[3:]
    if kind.upper().startswith("-E"):
        _read_csv_symbols(section, first, table, out)
        return
    by_address, by_symbol = table.by_address, table.by_symbol
    read = parse_address_cached if build else parse_address_once  # once: no cache to fill
    lines = section.lines
    # the common lines (`D37.4   C62179`) found in one findall, their addresses made at once;
    # a line whose address is None here is read alone below
    found = _PLAIN_SYMBOL_RE.findall("\n".join(lines) + "\n")
    if len(found) != len(lines):  # a line with a line break (never read from a file)
        found = [("", "", "", "", "")] * len(lines)
    texts, _, _, _, symbols = zip(*found, strict=True) if found else ((), (), (), (), ())
    addresses = list(map(plain_addresses(found).get, texts))
    start = 0  # the common lines from here to the next other line are added at once
    for offset in compress(count(), map(is_, addresses, repeat(None))):
        if build:
            _add_plain(table, addresses[start:offset], symbols[start:offset])
        start = offset + 1
        line = lines[offset]
        words = line.split(None, 2)
        if not words or words[0].startswith((";", "//")):  # blank or a comment line
            continue
        comment = words[2].strip() if len(words) > 2 else ""
        if len(words) == 2 and words[0][0] not in "Pp":  # `D37.4   C62179`: table.add inline
            try:
                address = read(words[0], None, 1)
            except AddressError:
                _warn(out, section, first + offset, line.strip())
                continue
            if not build:
                continue
            by_address[address] = new_symbol(words[1], ())
            by_symbol.setdefault(words[1], address)
        elif len(words) < 2 or not add_entry(table, words[0], words[1], (comment,)):
            _warn(out, section, first + offset, line.strip())
    if build:
        _add_plain(table, addresses[start:], symbols[start:])


def _add_plain(table: SymbolTable, addresses: list[Address | None],
               symbols: tuple[str, ...]) -> None:
    """Add two-word lines' entries, as the line-by-line branch of read_symbols adds them."""
    known = cast("list[Address]", addresses)  # the common lines' addresses: never None
    table.by_address.update(zip(known, new_symbols(symbols), strict=True))
    deque(map(table.by_symbol.setdefault, symbols, known), maxlen=0)  # the first one stays


def _read_csv_symbols(section: Section, first: int, table: SymbolTable,
                      out: list[Diagnostic]) -> None:
    import csv  # only for a `%@2-E` section: most programs have none

    columns = {name.upper(): int(number) - 1 for name, number in
               _COLUMNS_RE.findall(section.title)}
    sym, adr = columns.get("SYM", 0), columns.get("ADR", 1)
    comments = [columns[c] for c in ("CM1", "CM2") if c in columns]
    for offset, row in enumerate(csv.reader(section.lines)):
        line = section.lines[offset] if offset < len(section.lines) else ""
        if _is_comment(line):
            continue
        cells = [cell.strip() for cell in row]
        if max(sym, adr) >= len(cells) or not add_entry(
                table, cells[adr], cells[sym],
                tuple(cells[c] for c in comments if c < len(cells))):
            _warn(out, section, first + offset, line.strip())


def read_messages(section: Section, first: int, program: Program,
                  out: list[Diagnostic]) -> None:
    """`%@4`: `A0.1<TAB>1000 TEXT` lines, an A bit's message number and text."""
    for offset, line in enumerate(section.lines):
        if _is_comment(line):
            continue
        match = _MESSAGE_RE.match(line)
        address = None
        if match:
            try:
                address = parse_address(match.group(1), want_bit=True)
            except AddressError:
                address = None
        if match is None or address is None or address.area is not Area.A:
            _warn(out, section, first + offset, line.strip())
            continue
        program.messages[address] = Message(address, int(match.group(2)),
                                            (match.group(3) or "").rstrip())


def read_items(section: Section, first: int, out: list[Diagnostic]) -> dict[int, str]:
    """`%@0` / `%@1`: `n text` lines by item number (text as written, trailing spaces kept)."""
    items: dict[int, str] = {}
    for offset, line in enumerate(section.lines):
        if _is_comment(line):
            continue
        match = _ITEM_RE.match(line)
        if match is None:
            _warn(out, section, first + offset, line.strip())
            continue
        items[int(match.group(1))] = match.group(2) or ""
    return items


def read_io_modules(section: Section, first: int, out: list[Diagnostic]) -> list[IoModule]:
    """`%@5`: `X03 1 0 1 /6` lines (first byte, group, base, slot, module name)."""
    modules: list[IoModule] = []
    for offset, line in enumerate(section.lines):
        if _is_comment(line):
            continue
        match = _IO_RE.match(line)
        if match is None:
            _warn(out, section, first + offset, line.strip())
            continue
        address, group, base, slot, name = match.groups()
        modules.append(IoModule(address.upper(), int(group), int(base), int(slot),
                                name.strip()))
    return modules


def read_views(program: Program, firsts: dict[int, int], out: list[Diagnostic], *,
               build: bool = True) -> None:
    """Fill the program's views from its sections; `firsts[id(section)]` is its first line
    (with `build` False only the diagnostics are wanted: the symbol table may be partial)."""
    table = SymbolTable()
    for section in program.sections():
        first = firsts.get(id(section), 1)
        title = section.title.upper()
        if section.number == 0:
            program.system_params.update(
                {str(k): v.strip() for k, v in read_items(section, first, out).items()})
        elif section.number == 1:
            program.title.update(read_items(section, first, out))
        elif section.number == 2 and (title[3:] in _SYMBOL_KINDS or title.startswith("%@2-E")):
            read_symbols(section, first, table, out, build=build)
        elif section.number == 4:
            read_messages(section, first, program, out)
        elif section.number == 5:
            program.io_modules.extend(read_io_modules(section, first, out))
    program.symbols = table
