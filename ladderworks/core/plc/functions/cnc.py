"""Instructions that talk to the CNC, simulated with no CNC attached (docs/instructions.md):
AXCTL, WINDR, WINDW, EXIN, DISPB, and any `SUB n` the instruction table does not know.

Each completes in the scan that asks: W1 = ACT (AXCTL: ACT and not RST); no CNC data changes.
WINDR/WINDW write completion code 0 ("done") at control block + 2; the data is left alone.
"""

from __future__ import annotations

from ladderworks.core.plc.functions import FunctionContext, fits, function

COMPLETION_OFFSET = 2  # WINDR/WINDW control block: +0 function, +2 completion code (2 bytes)


@function("AXCTL")
def axctl(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """PMC axis control without a CNC: W1 = ACT and not RST, the data block is not read."""
    rst, act = inputs
    return bool(act) and not rst


def _window(ctx: FunctionContext, inputs: tuple[bool, ...], params: tuple) -> bool:
    """WINDR/WINDW: ACT = 1 writes completion code 0 and gives W1 = 1."""
    if not inputs[-1]:
        return False
    completion = params[0].offset(COMPLETION_OFFSET)
    if fits(ctx.memory, completion, 2):
        ctx.memory.write(completion, 0, 2)
    return True


@function("WINDR")
def windr(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Read CNC window data without a CNC: completion code 0, data unchanged, W1 = ACT."""
    return _window(ctx, inputs, params)


@function("WINDW")
def windw(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Write CNC window data without a CNC: completion code 0, W1 = ACT."""
    return _window(ctx, inputs, params)


@function("EXIN")
def exin(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """External data input without a CNC: W1 = ACT, the control data is not touched."""
    return bool(inputs[-1])


@function("DISPB")
def dispb(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Message display: no W1; the A bits that are 1 are shown by the simulator's alarm panel."""
    return False


def unknown_sub(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                params: tuple) -> bool:
    """A `SUB n` the table does not know: W1 = ACT, nothing else (its parameters are unused)."""
    return bool(inputs[-1]) if inputs else False
