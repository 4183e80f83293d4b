"""Parity check: PARI checks one byte for even or odd parity."""

from __future__ import annotations

from ladderworks.core.plc.functions import FunctionContext, function, held_output, output


@function("PARI")
def pari(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """W1 = 1 when the byte's count of 1-bits is odd (O.E = 0) or even (O.E = 1)."""
    odd_check, rst, act = inputs
    held = held_output(state, rst, act)
    if held is not None:
        return held
    (address,) = params
    ones_odd = bin(ctx.memory.read(address, 1)).count("1") % 2 == 1
    return output(state, ones_odd != bool(odd_check))
