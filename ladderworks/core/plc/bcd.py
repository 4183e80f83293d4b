"""BCD encoding and decoding in one place: invalid digits are reported, never raised."""

from __future__ import annotations


def bcd_to_int(raw: int, digits: int) -> int | None:
    """Decode `digits` BCD digits held in `raw`; None if a nibble is above 9."""
    value = 0
    scale = 1
    for _ in range(digits):
        nibble = raw & 0xF
        if nibble > 9:
            return None
        value += nibble * scale
        scale *= 10
        raw >>= 4
    return value


def int_to_bcd(value: int, digits: int) -> int | None:
    """Encode 0 <= value < 10**digits as BCD; None if it does not fit or is negative."""
    if value < 0 or value >= 10**digits:
        return None
    raw = 0
    shift = 0
    while value:
        raw |= (value % 10) << shift
        value //= 10
        shift += 4
    return raw


def bcd_limit(width: int) -> int:
    """The largest BCD value `width` bytes hold (99, 9999, 99999999)."""
    return 10 ** (2 * width) - 1
