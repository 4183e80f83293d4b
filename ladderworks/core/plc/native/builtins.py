"""Functional instructions as native code (the others call back into their Python
implementation). Each one here does exactly what its implementation in core/plc/functions/
does, with the parameters known when the IR is made."""

from __future__ import annotations

from collections.abc import Sequence

from ladderworks.core.instructions import InstructionSpec
from ladderworks.core.plc.native.ir_text import FunctionText


def declarations() -> list[str]:
    """The IR declarations the native functions use."""
    return []


def edge_key(spec: InstructionSpec, params: Sequence[object]) -> tuple[str, int] | None:
    """The DIFU/DIFD edge memory an op uses natively (None: none)."""
    return None


def emit(f: FunctionText, spec: InstructionSpec, params: Sequence[object], inputs: list[str],
         edges: dict[tuple[str, int], int], edge_base: int) -> str | None:
    """Emit `spec`'s code into `f`; its W1 (an i32 0/1 value), or None when not native."""
    return None
