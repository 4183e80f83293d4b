"""Edge detection: DIFU (rising) and DIFD (falling), one edge memory per (kind, number).

The memory holds ACT as the instruction last saw it. It is 0 at power-on (so ACT = 1 in the
first scan gives a DIFU pulse) and changes only when the instruction executes: skipped by a
jump or in a subprogram that is not called, it is frozen. Two call sites with the same kind
and number share one memory (as on a FANUC PMC, where the result is then not guaranteed).
"""

from __future__ import annotations

from ladderworks.core.plc.functions import FunctionContext, function


def _previous(ctx: FunctionContext, kind: str, number: int, act: bool) -> bool:
    """The edge memory's value before this execution; stores ACT in it."""
    key = (kind, number)
    before = ctx.edges.get(key, False)
    ctx.edges[key] = bool(act)
    return before


@function("DIFU")
def difu(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """W1 = 1 for one execution when ACT has gone 0 -> 1 since the last one."""
    (act,) = inputs
    (number,) = params
    before = _previous(ctx, "DIFU", number, act)
    return bool(act) and not before


@function("DIFD")
def difd(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """W1 = 1 for one execution when ACT has gone 1 -> 0 since the last one."""
    (act,) = inputs
    (number,) = params
    before = _previous(ctx, "DIFD", number, act)
    return before and not act
