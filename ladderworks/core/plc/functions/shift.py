"""Shift register: SFT shifts 16 bits one place in every scan that runs it with ACT = 1."""

from __future__ import annotations

from ladderworks.core.plc.functions import FunctionContext, function

_TOP_BIT = 15
_MASK16 = 0xFFFF


def shift_word(data: int, right: bool, keep: bool) -> tuple[int, bool]:
    """Shift 16 bits one place; `keep` (CONT) leaves every 1 in place too. (new data, bit out)."""
    if right:
        out = bool(data & 1)
        shifted = data >> 1
    else:
        out = bool((data >> _TOP_BIT) & 1)
        shifted = (data << 1) & _MASK16
    if keep:
        shifted |= data
    return shifted, out


@function("SFT")
def sft(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """One shift per execution with ACT = 1 (the seed: to shift once, set ACT = 1 and at once
    back to 0); W1 = the bit shifted out, held; RST = 1: W1 = 0 and no shift."""
    direction, cont, rst, act = inputs
    if rst:
        state["w1"] = False
        return False
    if act:
        (address,) = params
        data, out = shift_word(ctx.memory.read(address, 2), direction, cont)
        ctx.memory.write(address, data, 2)
        state["w1"] = out
    return bool(state.get("w1", False))
