"""The values of the instruction table's fields that say what consumers do with a row: what
is done with a parameter's data, the T/C memory of a numbered timer or counter, arithmetic's
operation (`core/instructions.py` re-exports them)."""

from __future__ import annotations

from enum import StrEnum


class ParamAccess(StrEnum):
    """What an instruction does with the data at a parameter's address."""

    READ = "read"
    WRITE = "write"  # written: the checks refuse an input (X, F) here
    READ_WRITE = "read-write"  # read and written (a register it keeps, SFT's data): an output too
    EITHER = "either"  # read or written as the run decides (XMOV's RW, a CNC window): not refused


class Numbered(StrEnum):
    """The T/C memory a numbered timer or counter uses; its number is its first parameter."""

    NONE = ""
    TIMER = "timer"  # TMR: its preset in T (FANUC: and a precision); the timer table lists it
    FIXED_TIMER = "fixed-timer"  # TMRB: its preset a constant; the timer table lists it
    COUNTER = "counter"  # CTR: its preset and value in C; the counter table lists it
    FIXED_COUNTER = "fixed-counter"  # CTRB: its value in C, after the CTRs'


class Operation(StrEnum):
    """What an instruction computes: arithmetic with its two operands, a data move, a
    comparison or an edge (a dialect's contact), by which its implementation is chosen."""

    NONE = ""
    ADD = "add"
    SUBTRACT = "subtract"
    MULTIPLY = "multiply"
    DIVIDE = "divide"  # the binary form also leaves the remainder in R9002
    MOVE = "move"
    INCREMENT = "increment"
    DECREMENT = "decrement"
    COMPARE = "compare"  # three result bits: greater, equal, less
    ZONE_COMPARE = "zone-compare"  # three result bits: below, inside, above
    EQUAL = "="
    GREATER = ">"
    LESS = "<"
    NOT_EQUAL = "<>"
    LESS_EQUAL = "<="
    GREATER_EQUAL = ">="
    RISING = "rising"  # an edge contact: on in the scan its bit went on
    FALLING = "falling"  # ... went off
