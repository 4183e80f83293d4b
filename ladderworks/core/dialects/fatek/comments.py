"""WinProladder's element comments (device -> text) as a Fatek program's symbol table: the
comment is the name shown beside the address, as WinProladder prints it under the element."""

from __future__ import annotations

from collections.abc import Mapping

from ladderworks.core.dialects.fatek.devices import (
    BIT_RANGES,
    DeviceError,
    bit_address,
    parse_device,
    word_address,
)
from ladderworks.core.symbols import Symbol, SymbolTable


def comment_symbols(comments: Mapping[str, str]) -> SymbolTable:
    """The symbol table of `comments` (`M300` -> `START`): a bit device's comment on its bit,
    a register's on its word, a timer's or counter's on both; blank texts and spellings that
    are not Fatek devices are left out."""
    table = SymbolTable()
    for device_text, text in comments.items():
        name = text.strip()
        if not name:
            continue
        symbol = Symbol(name)
        for bit in (True, False):
            try:
                device = parse_device(device_text, bit=bit)
            except DeviceError:
                continue
            if bit and device.kind in BIT_RANGES:
                table.add(bit_address(device), symbol)
            elif not bit:
                table.add(word_address(device)[0], symbol)
    return table
