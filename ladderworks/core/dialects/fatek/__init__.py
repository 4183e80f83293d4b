"""The Fatek FBs dialect: WinProladder mnemonic listings, Fatek's devices and instructions,
FUN 94's ASCII output. docs/dialects.md says what it covers and where each choice comes from.
"""

from __future__ import annotations

from ladderworks.core.address import Address, Area
from ladderworks.core.dialects.base import Dialect
from ladderworks.core.dialects.fatek.devices import CLOCKS, DEVICES, FIRST_SCAN, Device, bit_address
from ladderworks.core.dialects.fatek.rows import FAMILIES, ROWS
from ladderworks.core.dialects.fatek.sniff import score

NAME = "fatek"
M1924 = bit_address(Device("M", FIRST_SCAN))  # on for the first scan after RUN
_CLOCKS = tuple((bit_address(Device("M", number)), period) for number, period in CLOCKS.items())


def _set(areas: dict[Area, bytearray], address: Address, on: bool) -> None:
    data = areas[address.area]
    mask = 1 << (address.bit or 0)
    data[address.byte] = data[address.byte] | mask if on else data[address.byte] & ~mask & 0xFF


def relays(areas: dict[Area, bytearray], now_ms: int, first: bool) -> None:
    """Fatek's special relays, set before each scan: M1924 and the clocks M1920-M1923 (on for
    the first half of each period)."""
    _set(areas, M1924, first)
    for address, period in _CLOCKS:
        _set(areas, address, now_ms % period < period // 2)


DIALECT = Dialect(
    name=NAME, title="Fatek FBs", title_tr="Fatek FBs", code=3, devices=DEVICES, rows=ROWS,
    sniff=score, reader="ladderworks.core.dialects.fatek.reader:read",
    printer="ladderworks.core.dialects.fatek.printer:network_lines", relays=relays,
    clocks=tuple((address, period, period // 2) for address, period in _CLOCKS),
    period_ms=10, extensions=(".lst", ".fbs"),
    namer="ladderworks.core.dialects.fatek.printer:mnemonic_of",
    spelling="ladderworks.core.dialects.fatek.printer:spelling",
    tables="ladderworks.core.dialects.fatek.tables:TABLES", families=FAMILIES,
    probe="ladderworks.core.dialects.fatek.editing:probe_lines",
    operand_texts="ladderworks.core.dialects.fatek.editing:operand_texts",
    placed="ladderworks.core.dialects.fatek.editing:placed_params",
    local_bits=((Area.R, 440, 444),),  # TR0-TR39 (devices.py)
    style="ladderworks.core.dialects.fatek.printed:style_of",
    companions="ladderworks.core.dialects.fatek.comments:attach_companions",
    closing=("END",))
