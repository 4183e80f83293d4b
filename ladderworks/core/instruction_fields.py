"""The values of the instruction table's fields (`core/instructions.py` re-exports them): a
row's kind, how a contact combines, what a coil writes, its part in the structure, a
parameter's kind and what is done with its data, a dialect's stack operation, the T/C memory
of a numbered timer or counter, and the operation by which an implementation is chosen."""

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


class Kind(StrEnum):
    """What sort of instruction a row is."""

    BASIC = "basic"  # bit logic on the result stack
    FUNCTION = "function"  # a functional instruction (box in the ladder)
    END = "end"  # END1 / END2 / END3 / END


class Combine(StrEnum):
    """How a basic instruction combines its bit with the result stack."""

    NONE = ""  # not a contact (coils, functions)
    READ = "read"  # RD, RD.NOT, RD.STK, RD.NOT.STK: starts a new value
    AND = "and"  # AND, AND.NOT, AND.STK
    OR = "or"  # OR, OR.NOT, OR.STK


class Write(StrEnum):
    """What a coil does with ST0."""

    NONE = ""  # not a coil
    OUT = "out"  # WRT / WRT.NOT: bit := ST0 (inverted for WRT.NOT)
    SET = "set"  # SET: ST0 = 1 -> bit := 1
    RESET = "reset"  # RST: ST0 = 1 -> bit := 0


class Flow(StrEnum):
    """The part a functional instruction plays in the program's structure."""

    NONE = ""  # an ordinary box: runs in place
    JUMP = "jump"  # JMP: skip to its JMPE (or n coils)
    JUMP_END = "jump-end"  # JMPE
    COMMON = "common"  # COM: gate coils (or n coils) to its COME
    COMMON_END = "common-end"  # COME
    LEVEL_END = "level-end"  # END1, END2, END3: end of a program level
    PROGRAM_END = "program-end"  # END: end of the subprogram area
    CALL = "call"  # CALL: run subprogram Pn when ACT = 1
    CALL_ALWAYS = "call-always"  # CALLU: run subprogram Pn
    SUBPROGRAM = "subprogram"  # SP: start of subprogram Pn
    SUBPROGRAM_END = "subprogram-end"  # SPE
    LABEL = "label"  # LBL Ln: jump target
    LABEL_JUMP = "label-jump"  # JMPB: jump to LBL Ln of the same unit when ACT = 1
    LABEL_JUMP_MAIN = "label-jump-main"  # JMPC: from a subprogram to LBL Ln of its level
    MAIN_END = "main-end"  # Delta FEND: end of the main program, subroutines follow


class ParamKind(StrEnum):
    """What a parameter holds."""

    NUMBER = "number"  # an integer constant with a range
    ADDRESS = "address"  # a byte address whose data has `width` bytes
    VALUE = "value"  # a constant or an address, chosen by a format parameter
    MASK = "mask"  # up to 4 binary digits (MOVE masks), printed as 4 digits
    TABLE = "table"  # a list of constants, its length given by another parameter
    PROGRAM = "program"  # a subprogram number, written `P5`
    LABEL = "label"  # a jump label number, written `L12`
    RAW = "raw"  # a constant or an address, kept as written (a `SUB n` we do not know)
    BIT = "bit"  # a bit address (a dialect's bit device: Delta CMP's first result bit)


class StackOp(StrEnum):
    """What a basic instruction without an operand does to the result stack (a dialect's)."""

    NONE = ""  # AND.STK / OR.STK combine and pop (by `combine`), or no stack effect
    DUP = "dup"  # Delta MPS: push a copy of ST0
    OVER = "over"  # Delta MRD: ST0 := the value below it
    DROP = "drop"  # Delta MPP: pop ST0 (the value below it is the result again)
    INVERT = "invert"  # Delta INV: ST0 := NOT ST0
