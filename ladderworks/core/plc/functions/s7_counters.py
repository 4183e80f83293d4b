"""S7-1200 IEC counters CTU, CTD, CTUD on IEC_COUNTER instances (S7-1200 system manual pp.
179-180; seed 001:696-811).

The instance (LadderWorks' layout, 12 bytes): CV (+0, 4 bytes, the counter's type), PV (+4),
the last CU (+8.0), CD (+8.1), R (+8.2), LD (+8.3), QU (+8.4), QD (+8.5). CU/CD count on
0 → 1; CV stops at its type's limit; CU and CD in one scan leave CV unchanged; R and LD act
on their 0 → 1 as the manual's timing diagrams show, and hold CV while 1. CTU: Q = CV ≥ PV;
CTD: Q = CV ≤ 0; CTUD: QU = CV ≥ PV, QD = CV ≤ 0. docs/dialects.md, S7-1200 counters.
"""

from __future__ import annotations

from ladderworks.core.address import Address
from ladderworks.core.plc import typed
from ladderworks.core.plc.functions import FunctionContext, function

CU, CD, R, LD, QU, QD = range(6)


def _at(base: Address, offset: int, bit: int | None = None) -> Address:
    return Address(base.area, base.byte + offset, bit)


def _places(state: dict, params: tuple) -> tuple:
    """The instance's places and the count type's limits, found once per call site."""
    places = state.get("places")
    if places is None:
        instance, vtype_number = params[0], params[1]
        vtype = typed.ValueType(vtype_number)
        places = state["places"] = (vtype, _at(instance, 0), _at(instance, 4),
                                    instance.byte + 8, typed.limits(vtype), typed.WIDTH[vtype])
    return places


def _count(ctx: FunctionContext, state: dict, params: tuple, up: bool, down: bool,
           reset: bool, load: bool) -> tuple[int, int]:
    """The counters' common step: the new CV (stored with PV in the instance and CV's pin)."""
    vtype, cv_at, pv_at, flags_at, (low, high), width = _places(state, params)
    pv_in, cv_out = params[2], params[3]
    memory = ctx.memory
    data = memory.areas[cv_at.area]
    flags = data[flags_at]
    rose_up = up and not flags & 1
    rose_down = down and not flags & 2
    data[flags_at] = (flags & 0xF0) | up | down << 1 | reset << 2 | load << 3
    pv = int(typed.read(memory, pv_in, vtype))
    memory.write(pv_at, pv, 4)
    cv = memory.read(cv_at, 4, signed=True)
    if reset:
        cv = 0
    elif load:
        cv = pv
    elif rose_up and not rose_down:
        cv = min(cv + 1, high)
    elif rose_down and not rose_up:
        cv = max(cv - 1, low)
    memory.write(cv_at, cv, 4)
    if isinstance(cv_out, Address):
        memory.write(cv_out, typed.wrap(cv, vtype), width)
    return cv, pv


@function("S7.CTU")
def ctu(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Up counter: CU 0 → 1 adds 1; R resets; Q = CV ≥ PV (001:713-737)."""
    cv, pv = _count(ctx, state, params, bool(inputs[0]), False, bool(inputs[1]), False)
    return cv >= pv


@function("S7.CTD")
def ctd(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Down counter: CD 0 → 1 subtracts 1; LD loads PV; Q = CV ≤ 0 (001:759-767)."""
    cv, _pv = _count(ctx, state, params, False, bool(inputs[0]), False, bool(inputs[1]))
    return cv <= 0


@function("S7.CTUD")
def ctud(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Up/down counter: QU = CV ≥ PV (the box's output), QD = CV ≤ 0 to its pin (001:787-805)."""
    up, down, reset, load = (bool(v) for v in inputs)
    cv, pv = _count(ctx, state, params, up, down, reset, load)
    qd_out = params[4]
    if isinstance(qd_out, Address) and qd_out.bit is not None:
        ctx.memory.set_bit(qd_out, cv <= 0)
    data = ctx.memory.areas[params[0].area]
    flags_at = params[0].byte + 8
    data[flags_at] = (data[flags_at] & 0xCF) | (cv >= pv) << QU | (cv <= 0) << QD
    return cv >= pv
