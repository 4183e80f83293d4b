"""What the part lowerings in other modules (calls.py, boxes.py) see of the block lowering:
a Protocol that `lowering.BlockLowering` meets (no import of it: no cycle)."""

from __future__ import annotations

from typing import Protocol

from ladderworks.core.address import Address
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.s7.graph import Block, Operand, Part
from ladderworks.core.dialects.s7.layout import Layout, Place
from ladderworks.core.dialects.s7.stack import Expr, PinGraph
from ladderworks.core.il.program import Instruction, Network, ParamValue
from ladderworks.core.plc import typed


class BlockLowering(Protocol):
    """What a call or a box needs of the lowering of its block (lowering.BlockLowering)."""

    block: Block
    layout: Layout
    scope: tuple[str, ...]
    depth: int
    eno: Address | None
    networks: list[Network]
    diagnostics: list[Diagnostic]

    def fail(self, index: int, where: Part | None, code: str, **args: object) -> Exception: ...
    def new_relay(self, index: int, part: Part) -> Address: ...
    def new_label(self) -> int: ...
    def emit(self, instructions: list[Instruction]) -> None: ...
    def statement(self, part: Part, inputs: list[Expr], tail: list[Instruction],
                  keep: Address | None) -> Expr | None: ...
    def bit_expr(self, operand: Operand, negated: bool, index: int, part: Part) -> Expr: ...
    def value(self, index: int, part: Part, operand: Operand | None,
              vtype: typed.ValueType, pin: str) -> ParamValue: ...
    def place(self, index: int, part: Part, operand: Operand, instance: str = "",
              guess: str = "") -> Place: ...
    def shown_only(self, index: int, where: Part, power: Expr, code: str,
                   **args: object) -> Expr: ...
    def power(self, graph: PinGraph, part: Part, pin: str,
              outputs: dict[str, Expr | None]) -> Expr | None: ...
    labels: dict[str, int]

    def keep(self, graph: PinGraph, part: Part) -> Address | None: ...
    def vtype(self, index: int, graph: PinGraph, part: Part, pins: tuple[str, ...]
              ) -> typed.ValueType: ...
    def lower_callee(self, callee: Block, scope: tuple[str, ...], eno: Address | None = None
                     ) -> tuple[list[Network], list[Diagnostic]]: ...
