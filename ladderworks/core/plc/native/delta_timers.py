"""Delta DVP's TMR, CNT and DCNT as native code (core/plc/functions/dvp_timers.py,
dvp_counters.py), each with its state in a block (state_block.py: TMR's "at", "wake", and in
the pad word's flags (MORE) "running" and "ms" (at ELAPSED); a counter's "prev"), and RST of
a T, C or D device (no state).
A high-speed counter (C235-C255: dvp_high_speed) keeps its inputs' last values ("x", "y").
A parameter the Python code would take otherwise (a timer or counter not of its letter, data
past its area) calls back."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core.address import Address
from ladderworks.core.dialects.delta import DEVICES, M1028, M1200, WIDE_COUNTERS, C, T, X
from ladderworks.core.dialects.delta.tables import timer_base_ms
from ladderworks.core.plc.functions import NEVER, FunctionImpl, dvp_counters, dvp_timers
from ladderworks.core.plc.functions.dvp_data import bit_after
from ladderworks.core.plc.functions.dvp_high_speed import ONE_INPUT, TABLE, UP_DOWN, HighSpeed
from ladderworks.core.plc.native import layout, words, words32
from ladderworks.core.plc.native.builtins import Emitter, _load, _store, _when
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.state_block import (
    AT,
    CHANGED,
    ELAPSED,
    ELAPSED_SET,
    HAS_AT,
    HAS_HX,
    HAS_HY,
    HAS_MS,
    HAS_PREV,
    HAS_RUNNING,
    HAS_WAKE,
    HX,
    HY,
    MORE,
    PREV,
    RUNNING,
    WAKE,
    Block,
)
from ladderworks.core.plc.native.words import _bit, _place, _Refused

StatefulEmitter = Callable[[Block, FunctionImpl, Sequence[object], list[str]], str | None]
_REFUSED = (_Refused, ValueError, TypeError, KeyError, AssertionError)


def _time(f: FunctionText, word: int) -> str:
    return f.value(f"load i64, ptr {f.word_ptr(word)}, align 4")


def _number(device: object, letter: object) -> int:
    """The number of timer / counter `device` (its value's address) of `letter` (T, C)."""
    if not isinstance(device, Address) or device.bit is not None:
        raise _Refused
    number = letter.word_number(device)  # type: ignore[attr-defined]
    if number is None:
        raise _Refused
    return int(number)


def _base(f: FunctionText, number: int) -> str:
    """`dvp_timers.base_ms`: M1028 read now where it matters."""
    slow, fast = timer_base_ms(number, False), timer_base_ms(number, True)
    if slow == fast:
        return str(slow)
    _place(M1028, 1)
    assert M1028.bit is not None
    on = f.truth(f.bit(M1028.area, M1028.byte, M1028.bit, False))
    return f.value(f"select i1 {on}, i64 {fast}, i64 {slow}")


def _tmr(b: Block, impl: FunctionImpl, params: Sequence[object],
         inputs: list[str]) -> str | None:
    """TMR Tn SV: off: value 0, contact off, not running, ms 0; on, once a scan: the scan's
    time (not in the scan it starts) in ticks of its base up to the set value."""
    timer, preset = params
    number = _number(timer, T)
    assert isinstance(timer, Address)
    place, contact = _place(timer, 2), T.bit_address(number)
    _place(contact, 1)
    target_of = words._source(preset)
    f = b.f
    flags = b.flags()
    more = b.more(flags)  # "running", "ms" (at ELAPSED, ELAPSED_SET: a time value)
    has_ms = f.value(f"icmp ne i32 {f.value(f'and i32 {more}, {HAS_MS}')}, 0")
    ms = f.value(f"select i1 {has_ms}, i64 {b.load64(ELAPSED)}, i64 0")
    on, off, run, count, stop, counted, joined = (f.label() for _ in range(7))
    f.add(f"br i1 {f.truth(inputs[-1])}, label %{on}, label %{off}")
    f.start(off)  # running False, ms 0
    _store(f, place, 2, "0")
    _bit(f, contact, "false")
    b.store64(ELAPSED, "0")
    stopped = f.value(f"and i32 {f.value(f'or i32 {more}, {HAS_RUNNING | HAS_MS}')}, "
                      f"{~RUNNING}")
    changed = b.set_more(more, stopped)
    moved = f.value(f"select i1 {f.value(f'icmp ne i64 {ms}, 0')}, i32 {CHANGED}, i32 0")
    b.set_flags(flags, f.value(f"or i32 {f.value(f'or i32 {flags}, {MORE | ELAPSED_SET}')}, "
                               f"{f.value(f'or i32 {changed}, {moved}')}"))
    f.add(f"br label %{joined}")
    f.start(on)  # executed_once_this_scan: "at" is not now
    now = _time(f, layout.NOW)
    has_at = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {HAS_AT}')}, 0")
    again = f.value(f"and i1 {has_at}, {f.value(f'icmp eq i64 {b.load64(AT)}, {now}')}")
    f.add(f"br i1 {again}, label %{joined}, label %{run}")
    f.start(run)
    b.store64(AT, now)
    running = f.value(f"icmp eq i32 {f.value(f'and i32 {more}, {HAS_RUNNING | RUNNING}')}, "
                      f"{HAS_RUNNING | RUNNING}")
    step = f.value(f"select i1 {running}, i64 {_time(f, layout.SCAN_MS)}, i64 0")
    elapsed = f.value(f"add i64 {ms}, {step}")
    target = target_of(f)
    current = f.value(f"sext i16 {_load(f, place, 2)} to i64")
    base = _base(f, number)
    f.add(f"br i1 {f.value(f'icmp slt i64 {current}, {target}')}, label %{count}, "
          f"label %{stop}")
    f.start(count)
    ticks = f.value(f"sdiv i64 {elapsed}, {base}")
    left = f.value(f"srem i64 {elapsed}, {base}")
    next_tick = f.value(f"sub i64 {f.value(f'add i64 {now}, {base}')}, {left}")
    grown = f.value(f"add i64 {current}, {ticks}")
    lower = f.value(f"select i1 {f.value(f'icmp slt i64 {grown}, {target}')}, i64 {grown}, "
                    f"i64 {target}")
    value = f.value(f"select i1 {f.value(f'icmp slt i64 {lower}, 32767')}, i64 {lower}, "
                    f"i64 32767")
    _store(f, place, 2, f.value(f"trunc i64 {value} to i16"))
    f.add(f"br label %{counted}")
    f.start(stop)  # at the set value: no time counts on
    f.add(f"br label %{counted}")
    f.start(counted)
    kept = f.value(f"phi i64 [{left}, %{count}], [0, %{stop}]")
    wake = f.value(f"phi i64 [{next_tick}, %{count}], [{NEVER}, %{stop}]")
    final = f.value(f"phi i64 [{value}, %{count}], [{current}, %{stop}]")
    b.store64(ELAPSED, kept)
    b.store64(WAKE, wake)
    scan_wake = _time(f, layout.WAKE)
    earlier = f.value(f"icmp slt i64 {wake}, {scan_wake}")
    f.add(f"store i64 {f.value(f'select i1 {earlier}, i64 {wake}, i64 {scan_wake}')}, "
          f"ptr {f.word_ptr(layout.WAKE)}, align 4")
    _bit(f, contact, f.value(f"icmp sge i64 {final}, {target}"))
    b.set_more(more, f.value(f"or i32 {more}, {HAS_RUNNING | RUNNING | HAS_MS}"))
    b.set_flags(flags, f.value(f"or i32 {flags}, "
                               f"{HAS_AT | HAS_WAKE | MORE | ELAPSED_SET | CHANGED}"))
    f.add(f"br label %{joined}")
    f.start(joined)
    return inputs[-1]


def _rising(b: Block, act: str) -> str:
    """`dvp_data.rising` (the input kept as "prev"): an i1."""
    f = b.f
    flags = b.flags()
    before = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {PREV}')}, 0")
    kept = f.value(f"or i32 {f.value(f'and i32 {flags}, {~PREV}')}, {HAS_PREV}")
    b.set_flags(flags, f.value(f"select i1 {act}, i32 {f.value(f'or i32 {kept}, {PREV}')}, "
                               f"i32 {kept}"))
    return f.value(f"and i1 {act}, {f.value(f'xor i1 {before}, true')}")


def _cnt(b: Block, impl: FunctionImpl, params: Sequence[object],
         inputs: list[str]) -> str | None:
    """CNT Cn SV: +1 at a rising input below the set value; the contact: value >= SV."""
    counter, preset = params
    number = _number(counter, C)
    assert isinstance(counter, Address)
    place, contact = _place(counter, 2), C.bit_address(number)
    _place(contact, 1)
    target_of = words._source(preset)
    f = b.f
    target = target_of(f)
    current = f.value(f"sext i16 {_load(f, place, 2)} to i64")
    up = f.value(f"and i1 {_rising(b, f.truth(inputs[-1]))}, "
                 f"{f.value(f'icmp slt i64 {current}, {target}')}")
    value = f.value(f"add i64 {current}, {f.value(f'zext i1 {up} to i64')}")
    _store(f, place, 2, f.value(f"trunc i64 {value} to i16"))
    _bit(f, contact, f.value(f"icmp sge i64 {value}, {target}"))
    return inputs[-1]


def _dcnt(b: Block, impl: FunctionImpl, params: Sequence[object],
          inputs: list[str]) -> str | None:
    """DCNT Cn SV: C200-C234 +1 or -1 (M1200+n-200) at a rising input; C235-C255 count their
    X inputs (`_high_speed`); 32-bit wrapping; the contact: value >= SV."""
    counter, preset = params
    number = _number(counter, C)
    if number < WIDE_COUNTERS:
        raise _Refused
    assert isinstance(counter, Address)
    place, contact = _place(counter, 4), C.bit_address(number)
    _place(contact, 1)
    flag = _place(bit_after(M1200, number - WIDE_COUNTERS), 1)
    target_of = words32._source(preset)
    f = b.f
    act = f.truth(inputs[-1])
    if number in TABLE:
        value = _high_speed(b, TABLE[number], flag, act, _load(f, place, 4))
    else:
        down = f.truth(f.bit(flag.area, flag.byte, flag.bit or 0, False))
        step = f.value(f"select i1 {_rising(b, act)}, "
                       f"i32 {f.value(f'select i1 {down}, i32 -1, i32 1')}, i32 0")
        value = f.value(f"add i32 {_load(f, place, 4)}, {step}")
    _store(f, place, 4, value)
    wide = f.value(f"sext i32 {value} to i64")
    _bit(f, contact, f.value(f"icmp sge i64 {wide}, {target_of(f)}"))
    return inputs[-1]


def _x(f: FunctionText, number: int | None) -> str:
    """An X input of a high-speed counter (none: off), an i1."""
    if number is None:
        return "false"
    place = _place(X.bit_address(number), 1)
    return f.truth(f.bit(place.area, place.byte, place.bit or 0, False))


def _high_speed(b: Block, counter: HighSpeed, flag: Address, act: str, current: str) -> str:
    """`dvp_high_speed.step`: the inputs' last values kept as "x" and "y"; the new value."""
    f = b.f
    first, second = _x(f, counter.first), _x(f, counter.second)
    flags = b.flags()
    more = b.more(flags)
    was_x = f.value(f"icmp ne i32 {f.value(f'and i32 {more}, {HX}')}, 0")
    was_y = f.value(f"icmp ne i32 {f.value(f'and i32 {more}, {HY}')}, 0")
    rise_first = f.value(f"and i1 {first}, {f.value(f'xor i1 {was_x}, true')}")
    rise_second = f.value(f"and i1 {second}, {f.value(f'xor i1 {was_y}, true')}")
    changed_second = f.value(f"xor i1 {second}, {was_y}")
    kept = f.value(f"or i32 {f.value(f'and i32 {more}, {~(HX | HY)}')}, {HAS_HX | HAS_HY}")
    with_x = f.value(f"or i32 {kept}, {f.value(f'select i1 {first}, i32 {HX}, i32 0')}")
    changed = b.set_more(more, f.value(f"or i32 {with_x}, "
                                       f"{f.value(f'select i1 {second}, i32 {HY}, i32 0')}"))
    b.set_flags(flags, f.value(f"or i32 {f.value(f'or i32 {flags}, {MORE}')}, {changed}"))
    reset = _x(f, counter.reset)
    counting = f.value(f"and i1 {f.value(f'xor i1 {reset}, true')}, {act}")
    if counter.start is not None:
        counting = f.value(f"and i1 {counting}, {_x(f, counter.start)}")
    if counter.kind == ONE_INPUT:
        down = f.truth(f.bit(flag.area, flag.byte, flag.bit or 0, False))
        delta = f.value(f"select i1 {rise_first}, "
                        f"i32 {f.value(f'select i1 {down}, i32 -1, i32 1')}, i32 0")
    elif counter.kind == UP_DOWN:
        delta = f.value(f"sub i32 {f.value(f'zext i1 {rise_first} to i32')}, "
                        f"{f.value(f'zext i1 {rise_second} to i32')}")
    else:  # A's edge with B steady: B off up, B on down
        steady = f.value(f"and i1 {rise_first}, {f.value(f'xor i1 {changed_second}, true')}")
        delta = f.value(f"select i1 {steady}, "
                        f"i32 {f.value(f'select i1 {second}, i32 -1, i32 1')}, i32 0")
    delta = f.value(f"select i1 {counting}, i32 {delta}, i32 0")
    if counter.kind != ONE_INPUT:  # the direction shown when it counted
        moved = f.value(f"icmp ne i32 {delta}, 0")
        old = f.truth(f.bit(flag.area, flag.byte, flag.bit or 0, False))
        _bit(f, flag, f.value(f"select i1 {moved}, i1 {f.value(f'icmp slt i32 {delta}, 0')}, "
                              f"i1 {old}"))
    counted = f.value(f"add i32 {current}, {delta}")
    return f.value(f"select i1 {reset}, i32 0, i32 {counted}")


def _guarded(emit: StatefulEmitter) -> StatefulEmitter:
    def run(b: Block, impl: FunctionImpl, params: Sequence[object],
            inputs: list[str]) -> str | None:
        if len(params) != 2 or not inputs:
            return None
        try:
            return emit(b, impl, params, inputs)
        except _REFUSED:
            return None

    return run


def _rst(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    """RST Tn / Cn / Dn while the input is on: the value 0 (its own width), a contact off."""
    if len(params) != 1 or not inputs:
        return None
    (device,) = params
    try:
        width = DEVICES.width_at(device)  # type: ignore[arg-type]
        place = _place(device, width)
        if width not in (1, 2, 4, 8):
            return None
        found = DEVICES.device_of(place)
        contact = found[0].bit_address(found[1]) \
            if found is not None and found[0].bits is not None else None
        if contact is not None:
            _place(contact, 1)
    except _REFUSED:
        return None

    def body() -> None:
        _store(f, place, width, "0")
        if contact is not None:
            _bit(f, contact, "false")

    _when(f, inputs[-1], body)
    return inputs[-1]


STATEFUL: dict[FunctionImpl, tuple[str, StatefulEmitter]] = {
    dvp_timers.tmr: ("dvp timer", _guarded(_tmr)),
    dvp_counters.cnt: ("dvp counter", _guarded(_cnt)),
    dvp_counters.dcnt: ("dvp counter", _guarded(_dcnt)),
}
EMITTERS: dict[FunctionImpl, Emitter] = {dvp_counters.rst: _rst}
