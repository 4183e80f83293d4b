"""The relays a scan starts with that the engine sets: FANUC's system relay R9091 (its clocks
R9091.5 and .6), and a clock's bit set for a time (after skipped scans)."""

from __future__ import annotations

from collections.abc import Iterable, Mapping

from ladderworks.core.address import Address, Area

# System relay R9091: .0 always 0, .1 always 1, .5 a 200 ms clock, .6 a 1 s clock.
SYSTEM_RELAY = 9091
# R9091.5 and R9091.6: (bit, period, time on) in ms
SYSTEM_CLOCKS = ((Address(Area.R, SYSTEM_RELAY, 5), 200, 104),
                 (Address(Area.R, SYSTEM_RELAY, 6), 1000, 504))


def system_relays(areas: Mapping[Area, bytearray], now: int) -> None:
    """R9091 as a scan at `now` starts with it."""
    value = 0b10
    for bit, period, on in SYSTEM_CLOCKS:
        if now % period < on:
            value |= 1 << (bit.bit or 0)
    areas[Area.R][SYSTEM_RELAY] = value


def set_clocks(areas: Mapping[Area, bytearray], clocks: Iterable[tuple[Address, int, int]],
               now: int) -> None:
    """Each clock's bit (bit, period, time on) as a scan at `now` starts with it, and no other
    bit of its byte."""
    for bit, period, on in clocks:
        data, mask = areas[bit.area], 1 << (bit.bit or 0)
        data[bit.byte] = data[bit.byte] | mask if now % period < on \
            else data[bit.byte] & ~mask & 0xFF
