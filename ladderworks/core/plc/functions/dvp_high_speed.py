"""Delta DVP high-speed counters C235-C255 (DCNT): the X inputs each counts, as the scan sees them.

The table (docs/dialects.md, "high-speed counters"): C235-C245 one phase, one input (U/D), the
direction by M1235-M1245 (on: down); C246-C250 one phase, two inputs (U counts up, D down);
C251-C255 two phases (A/B: A's off->on counts up while B is off, down while B is on); some with
a reset input R (on: value 0) and a start input S (counting only while it is on). M1246-M1255
show the direction of the two-input ones (on: the last count was down). The simulation has no
inputs faster than the scan: an edge is an off->on change between two executions of the DCNT.
"""

from __future__ import annotations

from dataclasses import dataclass

from ladderworks.core.dialects.delta import M1200, WIDE_COUNTERS, X
from ladderworks.core.plc.functions.dvp_data import bit_after, wrap
from ladderworks.core.plc.memory import Memory

ONE_INPUT, UP_DOWN, PHASES = "U/D", "U,D", "A,B"


@dataclass(frozen=True, slots=True)
class HighSpeed:
    """A high-speed counter's kind and its X inputs (octal numbers as written: X6 is 6)."""

    kind: str
    first: int  # U/D, U or A
    second: int | None = None  # D or B
    reset: int | None = None  # R
    start: int | None = None  # S


def _one(first: int, reset: int | None = None, start: int | None = None) -> HighSpeed:
    return HighSpeed(ONE_INPUT, first, None, reset, start)


# [chosen] the DVP table's layout (docs/dialects.md: its source and what is chosen)
TABLE: dict[int, HighSpeed] = {
    **{235 + k: _one(k) for k in range(6)},
    241: _one(0, 1), 242: _one(2, 3), 243: _one(3, 4), 244: _one(0, 1, 6), 245: _one(2, 3, 7),
    246: HighSpeed(UP_DOWN, 0, 1), 247: HighSpeed(UP_DOWN, 0, 1, 2),
    248: HighSpeed(UP_DOWN, 3, 4, 5), 249: HighSpeed(UP_DOWN, 0, 1, 2, 6),
    250: HighSpeed(UP_DOWN, 3, 4, 5, 7),
    251: HighSpeed(PHASES, 0, 1), 252: HighSpeed(PHASES, 0, 1, 2),
    253: HighSpeed(PHASES, 3, 4, 5), 254: HighSpeed(PHASES, 0, 1, 2, 6),
    255: HighSpeed(PHASES, 3, 4, 5, 7),
}


def _x(memory: Memory, number: int | None) -> bool:
    return number is not None and bool(memory.bit(X.bit_address(number)))


def _edge(state: dict, key: str, now: bool) -> bool:
    """True when `now` went on since the last execution (the edge memory is off at power-on)."""
    was = state.get(key, False)
    state[key] = now
    return now and not was


def step(memory: Memory, state: dict, number: int, act: bool, current: int) -> int:
    """High-speed counter C`number`'s value after this execution of its DCNT (input `act`)."""
    counter = TABLE[number]
    flag = bit_after(M1200, number - WIDE_COUNTERS)  # M1235 ... M1255
    first, second = _x(memory, counter.first), _x(memory, counter.second)
    rise_first = _edge(state, "x", first)
    changed_second = second != state.get("y", False)
    rise_second = _edge(state, "y", second)
    if counter.reset is not None and _x(memory, counter.reset):
        return 0
    if not act or (counter.start is not None and not _x(memory, counter.start)):
        return current
    if counter.kind == ONE_INPUT:
        delta = (-1 if memory.bit(flag) else 1) if rise_first else 0
    elif counter.kind == UP_DOWN:
        delta = int(rise_first) - int(rise_second)
    else:  # A's edge with B steady: B off, A leads (up); B on, B leads (down)
        delta = (-1 if second else 1) if rise_first and not changed_second else 0
    if delta and counter.kind != ONE_INPUT:
        memory.set_bit(flag, delta < 0)
    return wrap(current + delta, 4)
