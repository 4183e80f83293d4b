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
from ladderworks.core.instructions import InstructionSpec
from ladderworks.core.plc.families import FAMILIES, IMPLEMENTED
from ladderworks.core.plc.memory import Memory

RESULT_REGISTER = Address(Area.R, 9000)
REMAINDER_REGISTER = Address(Area.R, 9002)  # DIVB leaves its remainder here (R9002..)

# Bits of R9000 after binary arithmetic, COMPB and DCNVB.
FLAG_ZERO = 0x01  # R9000.0: the result is zero (COMPB: input = comparison)
FLAG_NEGATIVE = 0x02  # R9000.1: the result is negative (COMPB: input < comparison)
FLAG_OVERFLOW = 0x20  # R9000.5: overflow, or the operation could not be done
NEVER = 1 << 62  # a time no run reaches (FunctionContext.wake_ms when no timer runs)


@dataclass(slots=True)
class FunctionContext:
    """What a functional instruction sees of the PLC."""

    memory: Memory
    now_ms: int = 0  # virtual time at the start of this scan
    scan_ms: int = 0  # time since the previous scan
    extra: dict[str, Any] = field(default_factory=dict)  # engine-owned tables (timers, ...)
    dialect: str = "seed"  # the program's dialect: "seed" (LadderWorks) or "fanuc" (LADDER-III)
    # DIFU/DIFD edge memories, one per (instruction name, edge number), shared by call sites
    edges: dict[tuple[str, int], bool] = field(default_factory=dict)
    # the earliest time a timer said it may act differently (core/plc/skipping.py reads it)
    wake_ms: int = NEVER

    def wake(self, state: dict, at_ms: int = NEVER) -> None:
        """Say that from `at_ms` on this call site may write or answer otherwise than now
        (a running timer's next tick or its preset reached; NEVER: not while its time runs
        on): no scan from then is skipped. Kept in its state as "wake" too."""
        state["wake"] = at_ms
        if at_ms < self.wake_ms:
            self.wake_ms = at_ms

    def power_on(self) -> None:
        """Forget what instructions keep outside their call sites (cold start: edge memories)."""
        self.edges.clear()

    def set_result_register(self, value: int, width: int = 6) -> None:
        """Write R9000.. (the function result register), bypassing the program's write ban."""
        self.memory.write(RESULT_REGISTER, value, width)


FunctionImpl = Callable[[FunctionContext, dict, tuple[bool, ...], tuple], bool]

REGISTRY: dict[str, FunctionImpl] = {}


def function(name: str) -> Callable[[FunctionImpl], FunctionImpl]:
    """Decorator: register the implementation of functional instruction `name`, whose row's
    `family` names its module."""

    def register(impl: FunctionImpl) -> FunctionImpl:
        family = impl.__module__.rpartition(".")[2]
        if name not in FAMILIES.get(family, ()):
            raise LookupError(f"{impl.__module__} implements {name}: its row in "
                              f"ladderworks/core/instructions.py must say family={family!r}")
        REGISTRY[name] = impl
        return impl

    return register


def held_output(state: dict, rst: bool, act: bool) -> bool | None:
    """W1 of an error-output instruction when it does not run, or None when it runs.

    RST = 1 clears W1 (and takes priority: nothing else is done); ACT = 0 keeps the W1 of the
    last execution. The value is kept in `state["w1"]`.
    """
    if rst:
        state["w1"] = False
        return False
    if not act:
        return bool(state.get("w1", False))
    return None


def output(state: dict, w1: bool) -> bool:
    """Remember and return the W1 of this execution."""
    state["w1"] = w1
    return w1


def fits(memory: Memory, address: Address, width: int) -> bool:
    """True when `width` bytes from `address` lie inside its area (writes never grow one)."""
    return width > 0 and address.byte + width <= len(memory.areas[address.area])


def executed_once_this_scan(ctx: FunctionContext, state: dict) -> bool:
    """True the first time a call site runs in this scan (a scan is known by `ctx.now_ms`).

    Timers add `ctx.scan_ms` only then, so a timer that is not executed (skipped by JMP, in a
    subprogram not called) is frozen, and one called twice in a scan counts the scan once.
    """
    if state.get("at") == ctx.now_ms:
        return False
    state["at"] = ctx.now_ms
    return True


def load_all() -> dict[str, FunctionImpl]:
    """Import every family module of this package (each registers itself); the registry."""
    import importlib
    import pkgutil

    for info in sorted(pkgutil.iter_modules(__path__), key=lambda m: m.name):
        importlib.import_module(f"{__name__}.{info.name}")
    missing = IMPLEMENTED - REGISTRY.keys()
    if missing:
        raise LookupError(f"a family in the table, not implemented: {sorted(missing)}")
    return REGISTRY


def impl_for(spec: InstructionSpec) -> FunctionImpl:
    """The implementation the scan calls for `spec`: its registered one, or for a `SUB n` the
    table does not know (`spec.known` False) the CNC-side stub (W1 = ACT, nothing else).

    Raises KeyError for a known instruction without one (the structure ops: JMP, CALL, ...).
    """
    if not spec.known:
        from ladderworks.core.plc.functions.cnc import unknown_sub

        return unknown_sub
    if spec.name not in REGISTRY:
        load_all()
    return REGISTRY[spec.name]


def result_flags(value: int) -> int:
    """R9000 bits for a result that was stored: zero and negative."""
    return (FLAG_ZERO if value == 0 else 0) | (FLAG_NEGATIVE if value < 0 else 0)


def signed_range(width: int) -> tuple[int, int]:
    """The lowest and highest signed binary value of `width` bytes."""
    half = 1 << (8 * width - 1)
    return -half, half - 1
