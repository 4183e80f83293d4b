"""S7-1200's IEC timers (TP, TON, TOF, TONR, -(PT)-, -(RT)-) and counters (CTU, CTD, CTUD)
as native code (core/plc/functions/s7_timers.py, s7_counters.py). Their state is their
instance in memory (big-endian: PT, ET, the IN/Q/running bits and the start time; CV, PV and
the inputs' bits), read and written in Python's order; the call site's dict holds what
Python's function keeps there: "timer" (the instance's Timer) and "wake" (the next scan while
a timer runs, else NEVER), or "places" (a counter's): the block's flags say they are there,
its INSTANCE word which instance (state_block.py)."""

from __future__ import annotations

from collections.abc import Sequence

from ladderworks.core.address import Address
from ladderworks.core.plc import typed
from ladderworks.core.plc.functions import NEVER, REGISTRY, FunctionImpl, load_all
from ladderworks.core.plc.functions.s7_counters import LD, QD, QU, R
from ladderworks.core.plc.functions.s7_timers import IN, RU, Q
from ladderworks.core.plc.native import layout
from ladderworks.core.plc.native.builtins import _fits, _when
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.s7_values import (
    VT,
    Emitter,
    big_endian,
    load,
    read_int,
    readable,
    set_bit,
    store,
    value_type,
    write_int,
)
from ladderworks.core.plc.native.state_block import (
    CHANGED,
    HAS_PLACES,
    HAS_TIMER,
    HAS_WAKE,
    INSTANCE,
    WAKE,
    Block,
    instance_word,
)

TIMER_BYTES, COUNTER_BYTES = 16, 12


class _Timer:
    """The IR of one IEC_TIMER instance (`s7_timers.Timer`)."""

    def __init__(self, b: Block, base: Address) -> None:
        self.b, self.f, self.base = b, b.f, Address(base.area, base.byte)

    def at(self, offset: int, bit: int | None = None) -> Address:
        return Address(self.base.area, self.base.byte + offset, bit)

    def get(self, offset: int) -> str:
        """PT (+0) or ET (+4): 4 bytes signed, as i64."""
        return self.f.value(f"sext i32 {load(self.f, self.at(offset), 4)} to i64")

    def put(self, offset: int, value: str) -> None:
        store(self.f, self.at(offset), 4, self.f.value(f"trunc i64 {value} to i32"))

    def flag(self, number: int) -> str:
        """IN, Q or running (i1)."""
        return self.f.truth(self.f.bit(self.base.area, self.base.byte + 8, number, False))

    def set_flag(self, number: int, value: str) -> None:
        set_bit(self.f, self.at(8, number), value)

    def now(self) -> str:
        return self.f.value(f"load i64, ptr {self.f.word_ptr(layout.NOW)}, align 4")

    def start(self) -> None:
        """The start := now (its low 32 bits)."""
        store(self.f, self.at(12), 4, self.f.value(f"trunc i64 {self.now()} to i32"))

    def elapsed(self) -> str:
        """(now - start) mod 2**32 (i64)."""
        f = self.f
        start = f.value(f"zext i32 {load(f, self.at(12), 4)} to i64")
        return f.value(f"and i64 {f.value(f'sub i64 {self.now()}, {start}')}, 4294967295")

    def restart(self, when: str, pt_operand: object) -> None:
        """When the i1 `when`: the start := now, PT := the PT operand (read after the start)."""

        def body() -> None:
            self.start()
            self.put(0, self.pt_of(pt_operand))

        _when(self.f, self.f.value(f"zext i1 {when} to i8"), body)

    def pt_of(self, operand: object) -> str:
        """`s7_timers._pt`: the Time operand, negative as 0."""
        value = read_int(self.f, operand, VT.TIME)
        return self.f.value(f"select i1 {self.f.value(f'icmp slt i64 {value}, 0')}, i64 0, "
                            f"i64 {value}")

    def capped(self) -> tuple[str, str]:
        """(PT, min(elapsed, PT)) as the instance holds them now."""
        pt = self.get(0)
        elapsed = self.elapsed()
        less = self.f.value(f"icmp slt i64 {elapsed}, {pt}")
        return pt, self.f.value(f"select i1 {less}, i64 {elapsed}, i64 {pt}")

    def bound(self) -> None:
        """The dict's "timer" is there (`timer_of`), its instance in the INSTANCE word."""
        b = self.b
        b.f.store_word(b.base + INSTANCE, str(instance_word(self.base)))
        flags = b.flags()
        b.set_flags(flags, b.f.value(f"or i32 {flags}, {HAS_TIMER}"))

    def finish(self, q: str, et: str, et_out: object, running: str) -> str:
        """`s7_timers._finish`: ET, Q and running into the instance, ET to its pin, the wake."""
        f, b = self.f, self.b
        self.put(4, et)
        self.set_flag(Q, q)
        self.set_flag(RU, running)
        write_int(f, et_out, VT.TIME, et)
        wake = f.value(f"select i1 {running}, i64 {f.value(f'add i64 {self.now()}, 1')}, "
                       f"i64 {NEVER}")
        old = b.load64(WAKE)
        b.store64(WAKE, wake)
        scan_wake = f.value(f"load i64, ptr {f.word_ptr(layout.WAKE)}, align 4")
        earlier = f.value(f"icmp slt i64 {wake}, {scan_wake}")
        f.add(f"store i64 {f.value(f'select i1 {earlier}, i64 {wake}, i64 {scan_wake}')}, "
              f"ptr {f.word_ptr(layout.WAKE)}, align 4")
        b.f.store_word(b.base + INSTANCE, str(instance_word(self.base)))
        flags = b.flags()
        new = f.value(f"or i32 {flags}, {HAS_TIMER | HAS_WAKE}")
        moved = f.value(f"icmp ne i64 {old}, {wake}")
        b.set_flags(flags, f.value(f"select i1 {moved}, i32 "
                                   f"{f.value(f'or i32 {new}, {CHANGED}')}, i32 {new}"))
        return f.value(f"zext i1 {q} to i8")


def _timer_params(b: Block, params: Sequence[object], count: int) -> bool:
    """An instance inside memory, PT (and ET's pin) as Python reads and writes them."""
    if len(params) != count or not big_endian(b):
        return False
    instance = params[0]
    if not isinstance(instance, Address) or not _fits(Address(instance.area, instance.byte),
                                                      TIMER_BYTES):
        return False
    if count > 1 and not readable(params[1], VT.TIME):
        return False
    et_out = params[2] if count > 2 else None
    return not isinstance(et_out, Address) or readable(et_out, VT.TIME)


def _select(f: FunctionText, test: str, first: str, second: str, kind: str = "i64") -> str:
    return f.value(f"select i1 {test}, {kind} {first}, {kind} {second}")


def _entered(b: Block, params: Sequence[object], inputs: list[str]
             ) -> tuple[_Timer, str, str] | None:
    """A TON/TOF/TP/TONR's timer and its IN now and at its last run (now kept for the next);
    None when its parameters are not native."""
    if not _timer_params(b, params, 3):
        return None
    assert isinstance(params[0], Address)
    t = _Timer(b, params[0])
    signal = b.f.truth(inputs[0])
    was = t.flag(IN)
    t.set_flag(IN, signal)
    return t, signal, was


def _ton(b: Block, impl: FunctionImpl, params: Sequence[object],
         inputs: list[str]) -> str | None:
    entered = _entered(b, params, inputs)
    if entered is None:
        return None
    t, signal, was = entered
    f = b.f
    starts = f.value(f"and i1 {signal}, {f.value(f'xor i1 {was}, true')}")
    t.restart(starts, params[1])
    pt, et = t.capped()
    q = f.value(f"and i1 {signal}, {f.value(f'icmp sge i64 {et}, {pt}')}")
    running = f.value(f"and i1 {signal}, {f.value(f'icmp slt i64 {et}, {pt}')}")
    return t.finish(q, _select(f, signal, et, "0"), params[2], running)


def _tof(b: Block, impl: FunctionImpl, params: Sequence[object],
         inputs: list[str]) -> str | None:
    entered = _entered(b, params, inputs)
    if entered is None:
        return None
    t, signal, was = entered
    f = b.f
    off = f.value(f"xor i1 {signal}, true")
    falls = f.value(f"and i1 {off}, {was}")
    t.restart(falls, params[1])
    idle = f.value(f"or i1 {t.flag(RU)}, {t.flag(Q)}")
    before_off = f.value(f"and i1 {off}, {f.value(f'xor i1 {was}, true')}")
    resting = f.value(f"and i1 {before_off}, {f.value(f'xor i1 {idle}, true')}")  # ET kept
    kept = t.get(4)
    pt, et = t.capped()
    timing = f.value(f"icmp slt i64 {et}, {pt}")
    counting = f.value(f"and i1 {off}, {f.value(f'xor i1 {resting}, true')}")
    q = f.value(f"or i1 {signal}, {f.value(f'and i1 {counting}, {timing}')}")
    running = f.value(f"and i1 {counting}, {timing}")
    et_value = _select(f, signal, "0", _select(f, resting, kept, et))
    return t.finish(q, et_value, params[2], running)


def _tp(b: Block, impl: FunctionImpl, params: Sequence[object],
        inputs: list[str]) -> str | None:
    entered = _entered(b, params, inputs)
    if entered is None:
        return None
    t, signal, was = entered
    f = b.f
    pulsing = t.flag(RU)
    rises = f.value(f"and i1 {signal}, {f.value(f'xor i1 {was}, true')}")
    starts = f.value(f"and i1 {f.value(f'xor i1 {pulsing}, true')}, {rises}")
    t.restart(starts, params[1])
    timed = f.value(f"or i1 {pulsing}, {starts}")
    kept = t.get(4)
    pt, et = t.capped()
    on = f.value(f"and i1 {timed}, {f.value(f'icmp slt i64 {et}, {pt}')}")
    shown = _select(f, signal, _select(f, timed, et, kept), "0")
    return t.finish(on, _select(f, on, et, shown), params[2], on)


def _tonr(b: Block, impl: FunctionImpl, params: Sequence[object],
          inputs: list[str]) -> str | None:
    entered = _entered(b, params, inputs) if len(inputs) == 2 else None
    if entered is None:
        return None
    t, signal, was = entered
    f = b.f
    reset = f.truth(inputs[1])
    pt = t.pt_of(params[1])
    t.put(0, pt)
    kept = t.get(4)
    grown = f.value(f"add i64 {kept}, {t.elapsed()}")
    capped = _select(f, f.value(f"icmp slt i64 {grown}, {pt}"), grown, pt)
    et = _select(f, was, capped, kept)
    _when(f, f.value(f"zext i1 {f.value(f'or i1 {reset}, {signal}')} to i8"), t.start)
    runs = f.value(f"xor i1 {reset}, true")
    q = f.value(f"and i1 {runs}, {f.value(f'icmp sge i64 {et}, {pt}')}")
    running = f.value(f"and i1 {f.value(f'and i1 {runs}, {signal}')}, "
                      f"{f.value(f'icmp slt i64 {et}, {pt}')}")
    return t.finish(q, _select(f, reset, "0", et), params[2], running)


def _load_time(b: Block, impl: FunctionImpl, params: Sequence[object],
               inputs: list[str]) -> str | None:
    """-(PT)-: with power, PT := the value."""
    if not _timer_params(b, params, 2):
        return None
    assert isinstance(params[0], Address)
    t = _Timer(b, params[0])

    def body() -> None:
        t.bound()
        t.put(0, t.pt_of(params[1]))

    _when(b.f, inputs[0], body)
    return inputs[0]


def _reset_timer(b: Block, impl: FunctionImpl, params: Sequence[object],
                 inputs: list[str]) -> str | None:
    """-(RT)-: with power, ET := 0, Q := 0, the start := now."""
    if not _timer_params(b, params, 1):
        return None
    assert isinstance(params[0], Address)
    t = _Timer(b, params[0])

    def body() -> None:
        t.bound()
        t.put(4, "0")
        t.set_flag(Q, "false")
        t.start()

    _when(b.f, inputs[0], body)
    return inputs[0]


def _counter(up: bool, down: bool) -> Emitter:
    """CTU (up), CTD (down), CTUD (both): `s7_counters._count` and each one's outputs."""

    def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
             inputs: list[str]) -> str | None:
        both = up and down
        if len(params) != (5 if both else 4) or len(inputs) != (4 if both else 2) or \
                not big_endian(b):
            return None
        instance, vtype = params[0], value_type(params[1], floats=False)
        if vtype is None or not isinstance(instance, Address) or \
                not _fits(instance, COUNTER_BYTES) or not readable(params[2], vtype):
            return None
        cv_out = params[3]
        width = typed.WIDTH[vtype]
        if isinstance(cv_out, Address) and not _fits(cv_out, width):
            return None
        qd_out = params[4] if both else None
        if isinstance(qd_out, Address) and qd_out.bit is not None and not _fits(qd_out, 1):
            return None
        f = b.f
        places = Address(instance.area, instance.byte)
        cv_at, pv_at = places, Address(places.area, places.byte + 4)
        flags_at = Address(places.area, places.byte + 8)
        values = dict(zip(("up", "down", "reset", "load") if both else
                          (("up", "reset") if up else ("down", "load")), inputs, strict=True))
        cu, cd, rs, ld = (values.get(k, "0") for k in ("up", "down", "reset", "load"))
        old = load(f, flags_at, 1)
        rose_up = f.value(f"and i8 {cu}, {f.value(f'xor i8 {old}, 1')}")
        rose_up = f.value(f"and i8 {rose_up}, 1")
        shifted = f.value(f"lshr i8 {old}, 1")
        rose_down = f.value(f"and i8 {cd}, {f.value(f'xor i8 {shifted}, 1')}")
        rose_down = f.value(f"and i8 {rose_down}, 1")
        stored = f.value(f"and i8 {old}, -16")
        for value, shift in ((cu, 0), (cd, 1), (rs, R), (ld, LD)):
            stored = f.value(f"or i8 {stored}, {f.value(f'shl i8 {value}, {shift}')}")
        store(f, flags_at, 1, stored)
        pv = read_int(f, params[2], vtype)
        store(f, pv_at, 4, f.value(f"trunc i64 {pv} to i32"))
        cv = f.value(f"sext i32 {load(f, cv_at, 4)} to i64")
        low, high = typed.limits(vtype)
        plus = f.value(f"add i64 {cv}, 1")
        minus = f.value(f"sub i64 {cv}, 1")
        upped = _select(f, f.value(f"icmp slt i64 {plus}, {high}"), plus, str(high))
        downed = _select(f, f.value(f"icmp sgt i64 {minus}, {low}"), minus, str(low))
        only_up = f.truth(f.value(f"and i8 {rose_up}, {f.value(f'xor i8 {rose_down}, 1')}"))
        only_down = f.truth(f.value(f"and i8 {rose_down}, {f.value(f'xor i8 {rose_up}, 1')}"))
        cv = _select(f, only_down, downed, cv)
        cv = _select(f, only_up, upped, cv)
        cv = _select(f, f.truth(ld), pv, cv)
        cv = _select(f, f.truth(rs), "0", cv)
        store(f, cv_at, 4, f.value(f"trunc i64 {cv} to i32"))
        if isinstance(cv_out, Address):  # Memory.write at its byte, even of a bit address
            store(f, Address(cv_out.area, cv_out.byte), width,
                  f.value(f"trunc i64 {cv} to i{8 * width}"))
        at_top = f.value(f"icmp sge i64 {cv}, {pv}")
        at_zero = f.value(f"icmp sle i64 {cv}, 0")
        if both:
            if isinstance(qd_out, Address) and qd_out.bit is not None:
                set_bit(f, qd_out, at_zero)
            now = f.value(f"and i8 {load(f, flags_at, 1)}, {0xCF - 256}")
            now = f.value(f"or i8 {now}, {f.value(f'shl i8 {_i8(f, at_top)}, {QU}')}")
            now = f.value(f"or i8 {now}, {f.value(f'shl i8 {_i8(f, at_zero)}, {QD}')}")
            store(f, flags_at, 1, now)
        f.store_word(b.base + INSTANCE, str(instance_word(places, int(vtype))))
        flags = b.flags()
        b.set_flags(flags, f.value(f"or i32 {flags}, {HAS_PLACES}"))
        return _i8(f, at_zero if down and not up else at_top)

    return emit


def _i8(f: FunctionText, value: str) -> str:
    return f.value(f"zext i1 {value} to i8")


load_all()
STATEFUL: dict[FunctionImpl, tuple[str, Emitter]] = {
    REGISTRY["S7.TON"]: ("s7 timer", _ton),
    REGISTRY["S7.TOF"]: ("s7 timer", _tof),
    REGISTRY["S7.TP"]: ("s7 timer", _tp),
    REGISTRY["S7.TONR"]: ("s7 timer", _tonr),
    REGISTRY["S7.PT"]: ("s7 timer", _load_time),
    REGISTRY["S7.RT"]: ("s7 timer", _reset_timer),
    REGISTRY["S7.CTU"]: ("s7 counter", _counter(True, False)),
    REGISTRY["S7.CTD"]: ("s7 counter", _counter(False, True)),
    REGISTRY["S7.CTUD"]: ("s7 counter", _counter(True, True)),
}
"""S7's timers and counters: implementation -> (kind, emitter)."""
