"""S7-1200 edge contacts and coils (P, N with their memory bit), P_TRIG / N_TRIG, SR / RS.

P contact: IN AND the operand rose since its memory bit was last written (the memory bit
then takes the operand); P coil: the operand is 1 for the run in which IN rose (the memory bit
keeps IN) and the coil passes IN on. SR: reset dominant; RS: set dominant."""

from __future__ import annotations

from ladderworks.core.plc.functions import FunctionContext, function


def _edge(ctx: FunctionContext, signal: bool, memory_bit: object, rising: bool) -> bool:
    memory = ctx.memory
    before = bool(memory.bit(memory_bit))  # type: ignore[arg-type]
    memory.set_bit(memory_bit, signal)  # type: ignore[arg-type]
    return (signal and not before) if rising else (before and not signal)


@function("S7.P")
def p_contact(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """-|P|-: IN AND the operand's rising edge."""
    operand, memory_bit = params
    return _edge(ctx, bool(ctx.memory.bit(operand)), memory_bit, True) and bool(inputs[0])


@function("S7.N")
def n_contact(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """-|N|-: IN AND the operand's falling edge."""
    operand, memory_bit = params
    return _edge(ctx, bool(ctx.memory.bit(operand)), memory_bit, False) and bool(inputs[0])


@function("S7.P_COIL")
def p_coil(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """-(P)-: the operand is 1 when IN rose."""
    operand, memory_bit = params
    ctx.memory.set_bit(operand, _edge(ctx, bool(inputs[0]), memory_bit, True))
    return bool(inputs[0])


@function("S7.N_COIL")
def n_coil(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """-(N)-: the operand is 1 when IN fell."""
    operand, memory_bit = params
    ctx.memory.set_bit(operand, _edge(ctx, bool(inputs[0]), memory_bit, False))
    return bool(inputs[0])


@function("S7.P_TRIG")
def p_trig(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """P_TRIG: 1 for the run in which IN rose."""
    return _edge(ctx, bool(inputs[0]), params[0], True)


@function("S7.N_TRIG")
def n_trig(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """N_TRIG: 1 for the run in which IN fell."""
    return _edge(ctx, bool(inputs[0]), params[0], False)


@function("S7.SR")
def sr(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """SR: S sets, R1 resets (reset dominant); Q = the operand."""
    (operand,) = params
    if inputs[1]:
        ctx.memory.set_bit(operand, False)
    elif inputs[0]:
        ctx.memory.set_bit(operand, True)
    return bool(ctx.memory.bit(operand))


@function("S7.RS")
def rs(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """RS: R resets, S1 sets (set dominant); Q = the operand."""
    (operand,) = params
    if inputs[1]:
        ctx.memory.set_bit(operand, True)
    elif inputs[0]:
        ctx.memory.set_bit(operand, False)
    return bool(ctx.memory.bit(operand))
