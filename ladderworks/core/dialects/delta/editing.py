"""The lines of Delta text the function dialog reads to check typed operands of a row."""

from __future__ import annotations

from ladderworks.core.dialects.delta.printer import mnemonic_of
from ladderworks.core.dialects.delta.rows_extra import (
    LOOP_BACK_ROW,
    LOOP_ROW,
    LOOP_TEST_ROW,
    PULSED,
    STEP_MOVE_ROWS,
    STEP_NEXT_ROW,
    STEP_ROW,
)
from ladderworks.core.instructions import BY_NAME, Flow, InstructionSpec, Kind

# The step ladder's rows the reader makes of STL and of a step's SET/OUT Sm: placed from the
# palette they would not read back as themselves (a STL is read with its LD Sn).
NOT_PLACED = frozenset((STEP_ROW.name, STEP_NEXT_ROW.name, *STEP_MOVE_ROWS.values(),
                        LOOP_ROW.name, LOOP_TEST_ROW.name, LOOP_BACK_ROW.name, *PULSED))


def _main_end() -> str:
    """The mnemonic of the row that ends the main program (FEND), from the table's `flow`."""
    for spec in list(BY_NAME.values()):
        if spec.dialect == "delta" and spec.flow is Flow.MAIN_END:
            return mnemonic_of(spec)
    raise LookupError("no main-end row")


def probe_lines(spec: InstructionSpec, texts: list[str]) -> list[str]:
    """`spec`'s line with the typed operands: after `LD X0` when it has inputs, alone when not
    (a pointer is its operand alone, `P1`; a subroutine's pointer after FEND)."""
    operands = [text.strip() for text in texts if text.strip()]
    if spec.name in NOT_PLACED:  # read only as part of a step ladder: not placed alone
        return [spec.name]
    if spec.flow in (Flow.LABEL, Flow.SUBPROGRAM):
        line = " ".join(operands) or mnemonic_of(spec)
        return [_main_end(), line] if spec.flow is Flow.SUBPROGRAM else [line]
    line = " ".join([mnemonic_of(spec), *operands])
    if spec.inputs and spec.kind is not Kind.END:
        return ["LD X0", line]
    return [line]
