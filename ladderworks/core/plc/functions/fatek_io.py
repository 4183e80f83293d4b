"""Fatek FBs FUN 94 ASCWR (seed 004) and the functions drawn but not simulated (motion and
high-speed ones: FUN 140 HSPSO, FUN 141 MPARA …) (docs/dialects.md, Fatek).

ASCWR: EN (top), PAU, ABT; on EN 0 -> 1 with PAU = ABT = 0 the ASCII file stored for its S
register is rendered, each variable read then (004:240-242), and written at once to the
terminal in `ctx.extra["ascii_terminal"]` (no baud rate: the transmission takes no scan time).
FO0 ACT (sending) is therefore 0; FO1 ERR: no ASCII file for S, or one with errors; FO2 DN:
the file was sent, kept until EN goes back to 0.
"""

from __future__ import annotations

from collections.abc import Callable

from ladderworks.core.address import Address
from ladderworks.core.dialects.fatek.ascii_format import AsciiFormat, Variable, render
from ladderworks.core.dialects.fatek.devices import Device, word_address
from ladderworks.core.plc.functions import FunctionContext, function
from ladderworks.core.plc.functions.fatek_timing import write_outputs
from ladderworks.core.plc.memory import Memory

ASCII_FILES = "ascii_files"  # ctx.extra: {S register address: AsciiFormat or None (errors)}
ASCII_TERMINAL = "ascii_terminal"  # ctx.extra: the AsciiTerminal ASCWR writes to


def variable_reader(memory: Memory) -> Callable[[Variable], int]:
    """The value of a variable's register (`R0`, `DR10`) in `memory`."""

    def read(variable: Variable) -> int:
        """The signed value of the variable's register (0 outside memory)."""
        address, width = word_address(Device(variable.register, variable.number))
        if not 0 <= address.byte <= len(memory.areas[address.area]) - width:
            return 0
        return memory.read(address, width, signed=True)

    return read


@function("FBS.ASCWR")
def fatek_ascii_write(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                      params: tuple) -> bool:
    """FUN 94 ASCWR: the ASCII file at S to the simulated terminal."""
    _md, source, _pointer, fo = params
    enable, pause, abort = inputs
    rising = enable and not state.get("en", False)
    state["en"] = bool(enable)
    if abort or not enable:
        state["done"] = state["error"] = False
    elif rising and not pause:
        files: dict[Address, AsciiFormat | None] = ctx.extra.get(ASCII_FILES, {})
        fmt = files.get(source) if isinstance(source, Address) else None
        terminal = ctx.extra.get(ASCII_TERMINAL)
        if fmt is None:
            state["error"], state["done"] = True, False
        else:
            if terminal is not None:
                terminal.write(render(fmt, variable_reader(ctx.memory)))
            state["error"], state["done"] = False, True
    write_outputs(ctx.memory, fo, False, state.get("error", False), state.get("done", False))
    return False


def fatek_not_simulated(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                        params: tuple) -> bool:
    """A function kept and drawn but not simulated: nothing happens, its FO stay 0."""
    write_outputs(ctx.memory, params[1])
    return False


for _name in ("FBS.HSPSO", "FBS.MPARA", "FBS.PSOFF", "FBS.PSCNV", "FBS.176", "FBS.FUN"):
    function(_name)(fatek_not_simulated)
