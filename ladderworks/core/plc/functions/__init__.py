"""Functional instructions: one module per family, each registering its implementations here.

Contract (read by the engine's generated code):
    impl(ctx, state, inputs, params) -> bool
- ctx: FunctionContext - memory, the virtual clock, the result register helper.
- state: a dict private to this call site (one per instruction in the program), for edges,
  accumulated time, etc. It starts empty and lives as long as the loaded program.
- inputs: the control inputs in the instruction table's order (first -> last, ACT last).
- params: the instruction's parameters as parsed (ints and Addresses; tables as trailing ints).
- returns W1 (False for instructions without W1); the engine leaves it in ST0.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

from ladderworks.core.address import Address, Area
from ladderworks.core.plc.memory import Memory

RESULT_REGISTER = Address(Area.R, 9000)


@dataclass(slots=True)
class FunctionContext:
    """What a functional instruction sees of the PLC."""

    memory: Memory
    now_ms: int = 0  # virtual time at the start of this scan
    scan_ms: int = 0  # time since the previous scan
    extra: dict[str, Any] = field(default_factory=dict)  # engine-owned tables (timers, ...)

    def set_result_register(self, value: int, width: int = 6) -> None:
        """Write R9000.. (the function result register), bypassing the program's write ban."""
        self.memory.write(RESULT_REGISTER, value, width)


FunctionImpl = Callable[[FunctionContext, dict, tuple[bool, ...], tuple], bool]

REGISTRY: dict[str, FunctionImpl] = {}


def function(name: str) -> Callable[[FunctionImpl], FunctionImpl]:
    """Decorator: register the implementation of functional instruction `name`."""

    def register(impl: FunctionImpl) -> FunctionImpl:
        REGISTRY[name] = impl
        return impl

    return register
