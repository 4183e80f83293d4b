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
from ladderworks.core.plc.memory import Memory

CU, CD, R, LD, QU, QD = range(6)


def _at(base: Address, offset: int, bit: int | None = None) -> Address:
    return Address(base.area, base.byte + offset, bit)


def _edge(memory: Memory, base: Address, bit: int, value: bool) -> bool:
    place = _at(base, 8, bit)
    rising = value and not memory.bit(place)
    memory.set_bit(place, value)
    return rising


def _count(ctx: FunctionContext, params: tuple, up: bool, down: bool, reset: bool,
           load: bool) -> tuple[int, int, typed.ValueType]:
    """The counters' common step: the new CV (stored with PV in the instance and CV's pin)."""
    instance, vtype_number, pv_in, cv_out = params[:4]
    vtype = typed.ValueType(vtype_number)
    memory = ctx.memory
    width = typed.WIDTH[vtype]
    cv_at, pv_at = _at(instance, 0), _at(instance, 4)
    rose_up = _edge(memory, instance, CU, up)
    rose_down = _edge(memory, instance, CD, down)
    _edge(memory, instance, R, reset)
    _edge(memory, instance, LD, load)
    pv = int(typed.read(memory, pv_in, vtype))
    memory.write(pv_at, pv, 4)
    cv = memory.read(cv_at, 4, signed=True)
    low, high = typed.limits(vtype)
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
    return cv, pv, vtype


@function("S7.CTU")
def ctu(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Up counter: CU 0 → 1 adds 1; R resets; Q = CV ≥ PV (001:713-737)."""
    cv, pv, _ = _count(ctx, params, bool(inputs[0]), False, bool(inputs[1]), False)
    return cv >= pv


@function("S7.CTD")
def ctd(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Down counter: CD 0 → 1 subtracts 1; LD loads PV; Q = CV ≤ 0 (001:759-767)."""
    cv, _pv, _ = _count(ctx, params, False, bool(inputs[0]), False, bool(inputs[1]))
    return cv <= 0


@function("S7.CTUD")
def ctud(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Up/down counter: QU = CV ≥ PV (the box's output), QD = CV ≤ 0 to its pin (001:787-805)."""
    up, down, reset, load = (bool(v) for v in inputs)
    cv, pv, _ = _count(ctx, params, up, down, reset, load)
    qd_out = params[4]
    if isinstance(qd_out, Address) and qd_out.bit is not None:
        ctx.memory.set_bit(qd_out, cv <= 0)
    instance = params[0]
    ctx.memory.set_bit(_at(instance, 8, QU), cv >= pv)
    ctx.memory.set_bit(_at(instance, 8, QD), cv <= 0)
    return cv >= pv
