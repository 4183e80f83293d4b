"""Delta DVP's PLSY and DPLSY as native code (core/plc/functions/delta_modules.py's
`_pulses`), the state in a block (state_block.py): "prev" (the input at the last run),
"ms" (at ELAPSED, a time value as a Fatek timer's "ms": the skipper moves it on), "at" (the
scan it last counted) and "wake". The pulses counted, ms x Hz // 1000, may pass 64 bits: it is
an i128 (q x Hz + r x Hz // 1000 of ms = 1000 q + r), compared and clamped as Python's
integers are, its low 32 bits stored; the next pulse's time, ceil((count + 1) x 1000 / Hz),
is ms + ceil((1000 - ms x Hz mod 1000) / Hz) when the count is that product's, else (a count
read from D1030/D1032, 32-bit) divided in 64 bits. An output other than Y0/Y1: the operation
error while the input is on, no state."""

from __future__ import annotations

from collections.abc import Sequence

from ladderworks.core.address import Address
from ladderworks.core.dialects.delta.rows_extra import ACTIONS
from ladderworks.core.plc.functions import NEVER, REGISTRY, FunctionImpl, load_all
from ladderworks.core.plc.functions.delta_modules import COUNTS
from ladderworks.core.plc.native import layout
from ladderworks.core.plc.native.builtins import _when
from ladderworks.core.plc.native.delta_logic import error, reader, writer
from ladderworks.core.plc.native.delta_timers import _REFUSED, StatefulEmitter
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.state_block import (
    AS_MS,
    AT,
    CHANGED,
    ELAPSED,
    ELAPSED_SET,
    HAS_AT,
    HAS_ELAPSED,
    HAS_PREV,
    HAS_WAKE,
    PREV,
    WAKE,
    Block,
)
from ladderworks.core.plc.native.words import _bit, _place


def _time(f: FunctionText, word: int) -> str:
    return f.value(f"load i64, ptr {f.word_ptr(word)}, align 4")


def _floor(f: FunctionText, value: str, by: int) -> tuple[str, str]:
    """Python's value // by and value % by (by > 0) of an i64."""
    q, r = f.value(f"sdiv i64 {value}, {by}"), f.value(f"srem i64 {value}, {by}")
    negative = f.value(f"icmp slt i64 {r}, 0")
    return (f.value(f"select i1 {negative}, i64 {f.value(f'sub i64 {q}, 1')}, i64 {q}"),
            f.value(f"select i1 {negative}, i64 {f.value(f'add i64 {r}, {by}')}, i64 {r}"))


def _ceiling(f: FunctionText, value: str, by: str) -> str:
    """-(-value // by) of i64s, by > 0."""
    q, r = f.value(f"sdiv i64 {value}, {by}"), f.value(f"srem i64 {value}, {by}")
    up = f.value(f"icmp sgt i64 {r}, 0")
    return f.value(f"add i64 {q}, {f.value(f'zext i1 {up} to i64')}")


def _pulses(wide: bool) -> StatefulEmitter:
    def emit(b: Block, impl: FunctionImpl, params: Sequence[object],
             inputs: list[str]) -> str | None:
        if len(params) != 3 or not inputs:
            return None
        frequency, total, output = params
        f = b.f
        place = COUNTS.get(output) if isinstance(output, Address) else None
        try:
            if place is None:
                _when(f, inputs[-1], lambda: error(f))
                return inputs[-1]
            assert isinstance(output, Address)
            count_at, done = place
            for bit in (output, done):
                _place(bit, 1)
            read_hz, read_limit = reader(frequency, wide), reader(total, wide)
            read_count, store = reader(count_at, True), writer(count_at, True)
        except _REFUSED:
            return None
        act = f.truth(inputs[-1])
        flags = b.flags()
        before = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {PREV}')}, 0")
        start = f.value(f"and i1 {act}, {f.value(f'xor i1 {before}, true')}")
        kept = f.value(f"or i32 {f.value(f'and i32 {flags}, {~PREV}')}, "
                       f"{HAS_PREV | HAS_ELAPSED | AS_MS | ELAPSED_SET | HAS_WAKE | CHANGED}")
        on, off, joined = f.label(), f.label(), f.label()
        f.add(f"br i1 {act}, label %{on}, label %{off}")
        f.start(off)  # the output off, ms 0, no wake
        _bit(f, output, "false")
        b.store64(ELAPSED, "0")
        b.store64(WAKE, str(NEVER))
        b.set_flags(flags, kept)
        f.add(f"br label %{joined}")
        f.start(on)
        now = _time(f, layout.NOW)
        has_at = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {HAS_AT}')}, 0")
        old_at = b.load64(AT)
        again = f.value(f"and i1 {has_at}, {f.value(f'icmp eq i64 {old_at}, {now}')}")
        has_ms = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {HAS_ELAPSED}')}, 0")
        old_ms = f.value(f"select i1 {has_ms}, i64 {b.load64(ELAPSED)}, i64 0")
        counted = f.value(f"add i64 {old_ms}, {_time(f, layout.SCAN_MS)}")
        ms = f.value(f"select i1 {start}, i64 0, i64 "
                     f"{f.value(f'select i1 {again}, i64 {old_ms}, i64 {counted}')}")
        b.store64(ELAPSED, ms)
        b.store64(AT, f.value(f"select i1 {again}, i64 {old_at}, i64 {now}"))
        moved = f.value(f"or i1 {start}, {f.value(f'xor i1 {again}, true')}")
        at_flag = f.value(f"select i1 {f.value(f'or i1 {moved}, {has_at}')}, i32 {HAS_AT}, "
                          f"i32 0")

        def begin() -> None:
            _bit(f, done, "false")
            store(f, "0")

        _when(f, f.value(f"zext i1 {start} to i8"), begin)
        hz, limit, count = read_hz(f), read_limit(f), read_count(f)
        positive = f.value(f"icmp sgt i64 {hz}, 0")
        open_ended = f.value(f"icmp sle i64 {limit}, 0")
        short = f.value(f"or i1 {open_ended}, {f.value(f'icmp slt i64 {count}, {limit}')}")
        cond = f.value(f"and i1 {positive}, {short}")
        q, r = _floor(f, ms, 1000)
        product = f.value(f"mul i128 {f.value(f'sext i64 {q} to i128')}, "
                          f"{f.value(f'sext i64 {hz} to i128')}")
        part = f.value(f"sdiv i64 {f.value(f'mul i64 {r}, {hz}')}, 1000")
        pulses = f.value(f"add i128 {product}, {f.value(f'sext i64 {part} to i128')}")
        wide_count = f.value(f"sext i64 {count} to i128")
        wide_limit = f.value(f"sext i64 {limit} to i128")
        from_pulses = f.value(f"icmp sge i128 {pulses}, {wide_count}")
        larger = f.value(f"select i1 {from_pulses}, i128 {pulses}, i128 {wide_count}")
        reached = f.value(f"and i1 {f.value(f'icmp sgt i64 {limit}, 0')}, "
                          f"{f.value(f'icmp sle i128 {wide_limit}, {larger}')}")
        clamped = f.value(f"select i1 {reached}, i128 {wide_limit}, i128 {larger}")
        _when(f, f.value(f"zext i1 {cond} to i8"),
              lambda: store(f, f.value(f"trunc i128 {clamped} to i64")))
        final = f.value(f"select i1 {cond}, i128 {clamped}, i128 {wide_count}")
        finished = f.value(f"and i1 {f.value(f'icmp sgt i64 {limit}, 0')}, "
                           f"{f.value(f'icmp sle i128 {wide_limit}, {final}')}")
        assert done.bit is not None
        was = f.truth(f.bit(done.area, done.byte, done.bit, False))
        _bit(f, done, f.value(f"or i1 {finished}, {was}"))
        pulsing = f.value(f"and i1 {positive}, {f.value(f'xor i1 {finished}, true')}")
        _bit(f, output, pulsing)
        safe_hz = f.value(f"select i1 {positive}, i64 {hz}, i64 1")
        hz_rest = f.value(f"srem i64 {safe_hz}, 1000")
        rest = f.value(f"srem i64 {f.value(f'mul i64 {r}, {hz_rest}')}, 1000")
        by_pulses = f.value(f"add i64 {ms}, "
                            f"{_ceiling(f, f.value(f'sub i64 1000, {rest}'), safe_hz)}")
        small = f.value(f"trunc i128 {final} to i64")
        next_count = f.value(f"mul i64 {f.value(f'add i64 {small}, 1')}, 1000")
        by_count = _ceiling(f, next_count, safe_hz)
        base = f.value(f"select i1 {from_pulses}, i64 {by_pulses}, i64 {by_count}")
        ahead = f.value(f"sub i64 {base}, {ms}")
        step = f.value(f"select i1 {f.value(f'icmp sgt i64 {ahead}, 1')}, i64 {ahead}, i64 1")
        wake = f.value(f"select i1 {pulsing}, i64 {f.value(f'add i64 {now}, {step}')}, "
                       f"i64 {NEVER}")
        b.store64(WAKE, wake)
        scan_wake = _time(f, layout.WAKE)
        earlier = f.value(f"icmp slt i64 {wake}, {scan_wake}")
        f.add(f"store i64 {f.value(f'select i1 {earlier}, i64 {wake}, i64 {scan_wake}')}, "
              f"ptr {f.word_ptr(layout.WAKE)}, align 4")
        b.set_flags(flags, f.value(f"or i32 {f.value(f'or i32 {kept}, {at_flag}')}, "
                                   f"{f.value(f'select i1 {act}, i32 {PREV}, i32 0')}"))
        f.add(f"br label %{joined}")
        f.start(joined)
        return inputs[-1]

    return emit


def _rows() -> dict[FunctionImpl, tuple[str, StatefulEmitter]]:
    load_all()
    found: dict[FunctionImpl, tuple[str, StatefulEmitter]] = {}
    for name, action in ACTIONS.items():
        impl = REGISTRY.get(name)
        if impl is not None and action.startswith("pulses"):
            found[impl] = ("dvp pulses", _pulses(action.endswith("32")))
    return found


STATEFUL = _rows()
