"""Functional instructions with a call-site state, as native code: TMR, TMRB, TMRBF, the
signed binary arithmetic (ADDB, SUBB, MULB, DIVB), CODB and XMOVB.

A site's state dict lives in a block of state words while the native code runs: a flags word
(which keys the dict has, the booleans' values, and a "changed" bit) and three 64-bit values
(`elapsed`, `at`, `wake`). A site whose state changed in a scan puts its number in the changed
list once; after the scan those dicts are written from the words (`pull`), and before a scan
after anything else changed the dicts (a cold start, a skip, another variant's scans) all the
blocks are written from them (`push`). So the dicts are the Python scan's after every scan.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence
from typing import Any

from ladderworks.core.address import AREA_SIZES, Address
from ladderworks.core.instructions import FUNCTIONS, InstructionSpec, Operation
from ladderworks.core.plc.functions import (
    FLAG_NEGATIVE,
    FLAG_OVERFLOW,
    FLAG_ZERO,
    NEVER,
    REGISTRY,
    REMAINDER_REGISTER,
    RESULT_REGISTER,
    FunctionImpl,
    convert,
    counters,
    load_all,
    signed_range,
    timers,
    transfer,
)
from ladderworks.core.plc.native import layout
from ladderworks.core.plc.native.ir_text import FunctionText

BLOCK = 8  # words per site: flags, pad, elapsed (i64), at (i64), wake (i64)
ELAPSED, AT, WAKE = 2, 4, 6
# flags: key present (and not None / its value)
HAS_ELAPSED, ELAPSED_SET, HAS_AT, HAS_WAKE, HAS_ON, ON, HAS_W1, W1 = (
    1, 2, 4, 8, 16, 32, 256, 512)
HAS_ACT, ACT, HAS_VALUE = 1024, 2048, 4096  # counters: the last ACT; CTRB's value (at ELAPSED)
CHANGED = 1 << 15
_I32 = (-(1 << 31), (1 << 31) - 1)


def _binary_code() -> object:
    load_all()
    spec = next(s for s in FUNCTIONS if s.binary and s.operation is not Operation.NONE)
    return REGISTRY[spec.name].__code__


_ARITHMETIC = _binary_code()  # the code every signed binary arithmetic implementation shares


def kind(spec: InstructionSpec, impl: FunctionImpl | None) -> str | None:
    """"tmr", "tmrb", "tmrbf", "codb", "xmovb" or "arithmetic" for an op done here natively,
    else None."""
    if impl is timers.tmr:
        return "tmr"
    if impl is convert.codb:
        return "codb"
    if impl in (counters.ctr, counters.ctrc, counters.ctrb):
        return "counter"
    if impl is transfer.xmovb:
        return "xmovb"
    if impl is timers.tmrb:
        return "tmrb"
    if impl is timers.tmrbf:
        return "tmrbf"
    if getattr(impl, "__code__", None) is _ARITHMETIC and spec.operation is not Operation.NONE:
        return "arithmetic"
    return None


class Block:
    """The IR of one site's state block (`base`: its first word)."""

    def __init__(self, f: FunctionText, base: int, number: int, dirty_list: int) -> None:
        self.f, self.base, self.number, self.dirty_list = f, base, number, dirty_list

    def ptr(self, offset: int) -> str:
        return self.f.word_ptr(self.base + offset)

    def flags(self) -> str:
        return self.f.value(f"load i32, ptr {self.ptr(0)}")

    def load64(self, offset: int) -> str:
        return self.f.value(f"load i64, ptr {self.ptr(offset)}, align 4")

    def store64(self, offset: int, value: str) -> None:
        self.f.add(f"store i64 {value}, ptr {self.ptr(offset)}, align 4")

    def set_flags(self, old: str, new: str) -> None:
        """Store the flags; a block whose flags or values changed (`new` has CHANGED set by
        the caller when values changed) joins the changed list once."""
        f = self.f
        differs = f.value(f"icmp ne i32 {old}, {new}")
        marked = f.value(f"and i32 {old}, {CHANGED}")
        first = f.value(f"and i1 {differs}, {f.value(f'icmp eq i32 {marked}, 0')}")
        marked_new = f.value(f"or i32 {new}, {CHANGED}")
        f.add(f"store i32 {f.value(f'select i1 {differs}, i32 {marked_new}, i32 {old}')}, "
              f"ptr {self.ptr(0)}")
        count_ptr = f.word_ptr(layout.DIRTY)
        count = f.value(f"load i32, ptr {count_ptr}")
        slot = f.value(f"getelementptr i32, ptr %st, i64 {self.dirty_list}")
        entry = f.value(f"getelementptr i32, ptr {slot}, i32 {count}")
        f.add(f"store i32 {self.number}, ptr {entry}")
        step = f.value(f"zext i1 {first} to i32")
        f.add(f"store i32 {f.value(f'add i32 {count}, {step}')}, ptr {count_ptr}")


def _time(f: FunctionText, word: int) -> str:
    return f.value(f"load i64, ptr {f.word_ptr(word)}, align 4")


def _elapsed(b: Block, flags: str) -> tuple[str, str]:
    """The running timer's elapsed ms (elapsed_ms with running = 1): (value, new flags)."""
    f = b.f
    now = _time(f, layout.NOW)
    has_at = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {HAS_AT}')}, 0")
    same = f.value(f"icmp eq i64 {b.load64(AT)}, {now}")
    counting = f.value(f"xor i1 {f.value(f'and i1 {has_at}, {same}')}, true")
    b.store64(AT, now)  # the same value when not counting
    was_set = f.value(f"icmp eq i32 {f.value(f'and i32 {flags}, {HAS_ELAPSED | ELAPSED_SET}')},"
                      f" {HAS_ELAPSED | ELAPSED_SET}")
    old = b.load64(ELAPSED)
    step = f.value(f"select i1 {counting}, i64 {_time(f, layout.SCAN_MS)}, i64 0")
    grown = f.value(f"add i64 {old}, {step}")
    elapsed = f.value(f"select i1 {was_set}, i64 {grown}, i64 0")
    b.store64(ELAPSED, elapsed)
    new = f.value(f"or i32 {flags}, {HAS_AT | HAS_ELAPSED | ELAPSED_SET}")
    return elapsed, new


def _reached(b: Block, elapsed: str, preset: int | str, flags: str) -> tuple[str, str]:
    """`timers.reached`: (i1 reached, new flags); the wake in the block and the scan's."""
    f = b.f
    done = f.value(f"icmp sge i64 {elapsed}, {preset}")
    later = f.value(f"sub i64 {f.value(f'add i64 {_time(f, layout.NOW)}, {preset}')}, {elapsed}")
    wake = f.value(f"select i1 {done}, i64 {NEVER}, i64 {later}")
    b.store64(WAKE, wake)
    scan_wake = _time(f, layout.WAKE)
    earlier = f.value(f"icmp slt i64 {wake}, {scan_wake}")
    f.add(f"store i64 {f.value(f'select i1 {earlier}, i64 {wake}, i64 {scan_wake}')}, "
          f"ptr {f.word_ptr(layout.WAKE)}, align 4")
    return done, f.value(f"or i32 {flags}, {HAS_WAKE}")


def _tmr(b: Block, params: Sequence[object], inputs: list[str], dialect: str) -> str | None:
    """TMR n: the preset read from the T area in each scan that runs the timer."""
    (number,) = params
    if not isinstance(number, int) or number < 1:
        return None
    return _timer(b, inputs, lambda: _tmr_preset(b.f, number, dialect))


def _read(f: FunctionText, address: Address, width: int) -> str:
    """`timers._read` as an i64: unsigned data, 0 past the end of the area."""
    if not _fits(address, width):
        return "0"
    return f.value(f"zext i{8 * width} {_load(f, address, width)} to i64")


def _tmr_preset(f: FunctionText, number: int, dialect: str) -> str:
    """The preset in ms of TMR `number` (timers.tmr's, by dialect)."""
    default_tick = timers.timer_tick(number)
    if dialect != "fanuc":
        raw = _read(f, timers.timer_preset_address(number), timers.TIMER_BYTES)
        ticks = f.value(f"udiv i64 {raw}, {default_tick}")
        return f.value(f"mul i64 {ticks}, {default_tick}")
    raw = _read(f, timers.timer_preset_address(number, "fanuc"), timers.FANUC_TIMER_BYTES)
    over = f.value(f"icmp ugt i64 {raw}, {timers.FANUC_MAX_TICKS}")
    ticks = f.value(f"select i1 {over}, i64 {timers.FANUC_MAX_TICKS}, i64 {raw}")
    code = _read(f, timers.timer_precision_address(number), 1)
    tick = str(default_tick)
    for value, ms in sorted(timers.TMR_PRECISION_MS.items()):
        tick = f.value(f"select i1 {f.value(f'icmp eq i64 {code}, {value}')}, i64 {ms}, "
                       f"i64 {tick}")
    return f.value(f"mul i64 {ticks}, {tick}")


def _tmrb(b: Block, params: Sequence[object], inputs: list[str]) -> str | None:
    _number, preset = params
    if not isinstance(preset, int):
        return None
    ms = str(timers.effective_preset(preset, timers.FAST_TICK_MS))
    return _timer(b, inputs, lambda: ms)


def _timer(b: Block, inputs: list[str], preset_of: Callable[[], str]) -> str:
    """An on-delay timer (TMR, TMRB): `preset_of()` gives the preset (read when it runs)."""
    f = b.f
    flags = b.flags()
    on, off = f.label(), f.label()
    joined = f.label()
    f.add(f"br i1 {f.truth(inputs[-1])}, label %{on}, label %{off}")
    f.start(off)
    stopped = f.value(f"and i32 {f.value(f'or i32 {flags}, {HAS_ELAPSED}')}, {~ELAPSED_SET}")
    b.set_flags(flags, stopped)
    off_end = f.block
    f.add(f"br label %{joined}")
    f.start(on)
    elapsed, new = _elapsed(b, flags)
    done, new = _reached(b, elapsed, preset_of(), new)
    b.set_flags(flags, f.value(f"or i32 {new}, {CHANGED}"))
    on_end = f.block
    f.add(f"br label %{joined}")
    f.start(joined)
    w1 = f.value(f"phi i1 [false, %{off_end}], [{done}, %{on_end}]")
    return f.value(f"zext i1 {w1} to i8")


def _tmrbf(b: Block, params: Sequence[object], inputs: list[str]) -> str | None:
    _number, preset = params
    if not isinstance(preset, int):
        return None
    preset = timers.effective_preset(preset, timers.FAST_TICK_MS)
    f = b.f
    flags = b.flags()
    act, idle, run, joined = f.label(), f.label(), f.label(), f.label()
    f.add(f"br i1 {f.truth(inputs[-1])}, label %{act}, label %{idle}")
    f.start(act)  # on = True, elapsed = None; W1 = 1
    held = f.value(f"and i32 {f.value(f'or i32 {flags}, {HAS_ON | ON | HAS_ELAPSED}')}, "
                   f"{~ELAPSED_SET}")
    b.set_flags(flags, held)
    act_end = f.block
    f.add(f"br label %{joined}")
    f.start(idle)  # not on: W1 = 0, nothing written
    is_on = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {ON}')}, 0")
    f.add(f"br i1 {is_on}, label %{run}, label %{joined}")
    f.start(run)
    elapsed, new = _elapsed(b, flags)
    done, new = _reached(b, elapsed, preset, new)
    ended = f.value(f"and i32 {new}, {~(ON | ELAPSED_SET)}")  # on = False, elapsed = None
    b.set_flags(flags, f.value(f"or i32 {f.value(f'select i1 {done}, i32 {ended}, i32 {new}')}"
                               f", {CHANGED}"))
    still_on = f.value(f"xor i1 {done}, true")  # W1 = state["on"] after the run
    run_end = f.block
    f.add(f"br label %{joined}")
    f.start(joined)
    w1 = f.value(f"phi i1 [true, %{act_end}], [false, %{idle}], [{still_on}, %{run_end}]")
    return f.value(f"zext i1 {w1} to i8")


def _arithmetic(operation: Operation) -> Callable[[Block, Sequence[object], list[str]],
                                                  str | None]:
    """ADDB/SUBB/MULB/DIVB: RST clears W1, ACT = 0 keeps it, else compute with R9000 flags."""

    def emit(b: Block, params: Sequence[object], inputs: list[str]) -> str | None:
        fmt, first_at, second, result_at = params
        if not isinstance(fmt, int) or len(inputs) != 2:
            return None
        width = fmt % 10
        if width not in (1, 2, 4) or not all(_fits(a, width) for a in (first_at, result_at)):
            return None
        if isinstance(second, Address):
            if not _fits(second, width):
                return None
        elif not (isinstance(second, int) and _I32[0] <= second <= _I32[1]):
            return None
        if operation is Operation.DIVIDE and not _fits(REMAINDER_REGISTER, width):
            return None
        assert isinstance(first_at, Address) and isinstance(result_at, Address)
        f = b.f
        bits = 8 * width
        lo, hi = signed_range(width)

        def compute() -> str:
            a = f.value(f"sext i{bits} {_load(f, first_at, width)} to i64")
            c = (f.value(f"sext i{bits} {_load(f, second, width)} to i64")
                 if isinstance(second, Address) else str(second))
            error = "false"
            remainder = ""
            if operation is Operation.DIVIDE:
                zero = f.value(f"icmp eq i64 {c}, 0")
                safe = f.value(f"select i1 {zero}, i64 1, i64 {c}")
                result = f.value(f"sdiv i64 {a}, {safe}")
                remainder = f.value(f"srem i64 {a}, {safe}")
                error = zero
            else:
                result = f.value(f"{_OPS[operation]} i64 {a}, {c}")
            outside = f.value(f"or i1 {f.value(f'icmp slt i64 {result}, {lo}')}, "
                              f"{f.value(f'icmp sgt i64 {result}, {hi}')}")
            failed = f.value(f"or i1 {error}, {outside}")
            bad, good, done = f.label(), f.label(), f.label()
            f.add(f"br i1 {failed}, label %{bad}, label %{good}")
            f.start(bad)
            _store(f, RESULT_REGISTER, 1, str(FLAG_OVERFLOW))
            f.add(f"br label %{done}")
            f.start(good)
            _store(f, result_at, width, f.value(f"trunc i64 {result} to i{bits}"))
            is_zero = f.value(f"zext i1 {f.value(f'icmp eq i64 {result}, 0')} to i8")
            negative = f.value(f"zext i1 {f.value(f'icmp slt i64 {result}, 0')} to i8")
            _store(f, RESULT_REGISTER, 1, f.value(
                f"or i8 {f.value(f'mul i8 {is_zero}, {FLAG_ZERO}')}, "
                f"{f.value(f'mul i8 {negative}, {FLAG_NEGATIVE}')}"))
            if remainder:
                _store(f, REMAINDER_REGISTER, width,
                       f.value(f"trunc i64 {remainder} to i{bits}"))
            f.add(f"br label %{done}")
            f.start(done)
            return failed

        return _held(b, inputs[0], inputs[1], compute)

    return emit


def _held(b: Block, rst: str, act: str, compute: Callable[[], str]) -> str:
    """An instruction with an error output (`held_output`): RST = 1 clears W1, ACT = 0 keeps
    the last one, else `compute()` (emitting in its own blocks) gives the i1 error, W1."""
    f = b.f
    flags = b.flags()
    reset, running, computing, joined = f.label(), f.label(), f.label(), f.label()
    f.add(f"br i1 {f.truth(rst)}, label %{reset}, label %{running}")
    f.start(reset)
    b.set_flags(flags, f.value(f"and i32 {f.value(f'or i32 {flags}, {HAS_W1}')}, {~W1}"))
    reset_end = f.block
    f.add(f"br label %{joined}")
    f.start(running)
    kept = f.value(f"icmp eq i32 {f.value(f'and i32 {flags}, {HAS_W1 | W1}')}, "
                   f"{HAS_W1 | W1}")
    f.add(f"br i1 {f.truth(act)}, label %{computing}, label %{joined}")
    f.start(computing)
    failed = compute()
    now = f.value(f"or i32 {f.value(f'and i32 {flags}, {~W1}')}, {HAS_W1}")
    with_error = f.value(f"or i32 {now}, {W1}")
    b.set_flags(flags, f.value(f"select i1 {failed}, i32 {with_error}, i32 {now}"))
    computed = f.block
    f.add(f"br label %{joined}")
    f.start(joined)
    w1 = f.value(f"phi i1 [false, %{reset_end}], [{kept}, %{running}], "
                 f"[{failed}, %{computed}]")
    return f.value(f"zext i1 {w1} to i8")


def _codb(b: Block, params: Sequence[object], inputs: list[str]) -> str | None:
    """CODB: output = table[index] (binary, 1/2/4 bytes); W1 = 1 past the table."""
    width, size, index, out = params[:4]
    table = params[4:]
    if len(inputs) != 2 or not (isinstance(width, int) and isinstance(size, int)):
        return None
    if width not in (1, 2, 4) or not (_fits(index, 1) and _fits(out, width)):
        return None
    if not all(isinstance(entry, int) for entry in table):
        return None
    assert isinstance(index, Address) and isinstance(out, Address)
    f = b.f
    rows = [(row, entry) for row, entry in enumerate(table[:max(0, min(size, len(table), 256))])
            if isinstance(entry, int) and -(1 << (8 * width - 1)) <= entry < 1 << (8 * width)]

    def compute() -> str:
        row = _load(f, index, 1)
        cases = [(number, entry, f.label()) for number, entry in rows]
        bad, done = f.label(), f.label()
        f.add(f"switch i8 {row}, label %{bad} [" +
              " ".join(f"i8 {_signed8(number)}, label %{label}" for number, _, label in cases)
              + "]")
        for _, entry, label in cases:
            f.start(label)
            raw = entry & ((1 << (8 * width)) - 1)
            _store(f, out, width, str(raw - (1 << (8 * width)) if raw >> (8 * width - 1)
                                      else raw))
            f.add(f"br label %{done}")
        f.start(bad)
        f.add(f"br label %{done}")
        f.start(done)
        return f.value("phi i1 " + ", ".join(
            [f"[false, %{label}]" for _, _, label in cases] + [f"[true, %{bad}]"]))

    return _held(b, inputs[0], inputs[1], compute)


def _xmovb(b: Block, params: Sequence[object], inputs: list[str]) -> str | None:
    """XMOVB: RW = 0 data = table[index], RW = 1 table[index] = data (1/2/4-byte entries,
    the index 4 bytes signed, the size a constant or 2 bytes signed at an address)."""
    width, size, table, data, index = params
    if len(inputs) != 3 or not (isinstance(width, int) and width in (1, 2, 4)):
        return None
    if not (isinstance(table, Address) and _fits(data, width) and _fits(index, 4)):
        return None
    if (isinstance(size, Address) and not _fits(size, 2)) or \
            not isinstance(size, Address | int) or isinstance(size, bool):
        return None
    if isinstance(size, int) and not _I32[0] <= size <= _I32[1]:
        return None
    assert isinstance(data, Address) and isinstance(index, Address)
    f = b.f
    bits = 8 * width
    limit = AREA_SIZES[table.area]

    def compute() -> str:
        count = (f.value(f"sext i16 {_load(f, size, 2)} to i64")
                 if isinstance(size, Address) else str(size))
        row = f.value(f"sext i32 {_load(f, index, 4)} to i64")
        inside = f.value(f"and i1 {f.value(f'icmp sge i64 {row}, 0')}, "
                         f"{f.value(f'icmp slt i64 {row}, {count}')}")
        byte = f.value(f"add i64 {f.value(f'mul i64 {row}, {width}')}, {table.byte}")
        fits = f.value(f"icmp sle i64 {f.value(f'add i64 {byte}, {width}')}, {limit}")
        good = f.value(f"and i1 {inside}, {fits}")
        move, done = f.label(), f.label()
        start = f.block
        f.add(f"br i1 {good}, label %{move}, label %{done}")
        f.start(move)
        entry = f.value(f"getelementptr i8, ptr {f.byte_ptr(table.area, 0)}, i64 {byte}")
        there = f.byte_ptr(data.area, data.byte)
        writes = f.truth(inputs[0])
        source = f.value(f"select i1 {writes}, ptr {there}, ptr {entry}")
        target = f.value(f"select i1 {writes}, ptr {entry}, ptr {there}")
        value = f.value(f"load i{bits}, ptr {source}, align 1")
        f.add(f"store i{bits} {value}, ptr {target}, align 1")
        f.add(f"br label %{done}")
        f.start(done)
        return f.value(f"phi i1 [true, %{start}], [false, %{move}]")

    return _held(b, inputs[1], inputs[2], compute)


def _counter(b: Block, impl: FunctionImpl, params: Sequence[object],
             inputs: list[str]) -> str | None:
    """CTR, CTRC, CTRB: `counters.ring_count` on the value where each keeps it."""
    if len(inputs) != 4:
        return None
    f = b.f
    stored_at: Address | None
    if impl is counters.ctr:
        (number,) = params
        if not isinstance(number, int):
            return None
        preset_at, stored_at = (counters.counter_preset_address(number),
                                counters.counter_value_address(number))
        if not (_fits(preset_at, 2) and _fits(stored_at, 2)):
            return None
        preset = f.value(f"zext i16 {_load(f, preset_at, 2)} to i64")
    elif impl is counters.ctrc:
        preset_param, register = params
        if not (_fits(preset_param, 2) and _fits(register, 2)):
            return None
        assert isinstance(preset_param, Address) and isinstance(register, Address)
        stored_at = register
        raw = f.value(f"zext i16 {_load(f, preset_param, 2)} to i64")
        over = f.value(f"icmp sgt i64 {raw}, {counters.MAX_PRESET}")
        preset = f.value(f"select i1 {over}, i64 {counters.MAX_PRESET}, i64 {raw}")
    else:
        number, fixed = params
        if not (isinstance(number, int) and isinstance(fixed, int)
                and _I32[0] <= fixed <= _I32[1]):
            return None
        where = counters.ctrb_value_address(number)
        stored_at = where if _fits(where, 2) else None
        preset = str(min(fixed, counters.MAX_PRESET))
    flags = b.flags()
    cn0, down, rst, act = (f.truth(value) for value in inputs)
    if stored_at is not None:
        current = f.value(f"zext i16 {_load(f, stored_at, 2)} to i64")
    else:  # CTRB past the C area: the value kept in the call site ("value", else 0)
        has = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {HAS_VALUE}')}, 0")
        current = f.value(f"select i1 {has}, i64 {b.load64(ELAPSED)}, i64 0")
    low = f.value(f"zext i1 {cn0} to i64")
    top = f.value(f"select i1 {f.value(f'icmp slt i64 {preset}, {low}')}, i64 {low}, "
                  f"i64 {preset}")
    before = f.value(f"icmp eq i32 {f.value(f'and i32 {flags}, {HAS_ACT | ACT}')}, "
                     f"{HAS_ACT | ACT}")
    rising = f.value(f"and i1 {act}, {f.value(f'xor i1 {before}, true')}")
    down_value = f.value(f"select i1 {f.value(f'icmp sle i64 {current}, {low}')}, i64 {top}, "
                         f"i64 {f.value(f'sub i64 {current}, 1')}")
    up_value = f.value(f"select i1 {f.value(f'icmp sge i64 {current}, {top}')}, i64 {low}, "
                       f"i64 {f.value(f'add i64 {current}, 1')}")
    counted = f.value(f"select i1 {down}, i64 {down_value}, i64 {up_value}")
    counted = f.value(f"select i1 {rising}, i64 {counted}, i64 {current}")
    start = f.value(f"select i1 {down}, i64 {top}, i64 {low}")
    value = f.value(f"select i1 {rst}, i64 {start}, i64 {counted}")
    at_end = f.value(f"select i1 {down}, i1 {f.value(f'icmp sle i64 {value}, {low}')}, "
                     f"i1 {f.value(f'icmp sge i64 {value}, {top}')}")
    w1 = f.value(f"and i1 {f.value(f'xor i1 {rst}, true')}, {at_end}")
    if stored_at is not None:
        _store(f, stored_at, 2, f.value(f"trunc i64 {value} to i16"))
    new = f.value(f"or i32 {f.value(f'and i32 {flags}, {~ACT}')}, {HAS_ACT}")
    new = f.value(f"select i1 {act}, i32 {f.value(f'or i32 {new}, {ACT}')}, i32 {new}")
    if impl is counters.ctrb:  # state["value"] = value
        old = b.load64(ELAPSED)
        b.store64(ELAPSED, value)
        kept = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {HAS_VALUE}')}, 0")
        same = f.value(f"and i1 {kept}, {f.value(f'icmp eq i64 {old}, {value}')}")
        new = f.value(f"or i32 {new}, {HAS_VALUE}")
        new = f.value(f"select i1 {same}, i32 {new}, i32 {f.value(f'or i32 {new}, {CHANGED}')}")
    b.set_flags(flags, new)
    return f.value(f"zext i1 {w1} to i8")


def _signed8(value: int) -> int:
    return value - 256 if value >= 128 else value


_OPS = {Operation.ADD: "add", Operation.SUBTRACT: "sub", Operation.MULTIPLY: "mul"}


def _fits(address: object, width: int) -> bool:
    from ladderworks.core.plc.native.builtins import _fits as fits

    return fits(address, width)


def _load(f: FunctionText, address: Address, width: int) -> str:
    from ladderworks.core.plc.native.builtins import _load as load

    return load(f, address, width)


def _store(f: FunctionText, address: Address, width: int, value: str) -> None:
    from ladderworks.core.plc.native.builtins import _store as store

    store(f, address, width, value)


def emit(f: FunctionText, spec: InstructionSpec, impl: FunctionImpl, params: Sequence[object],
         inputs: list[str], base: int, number: int, dirty_list: int,
         dialect: str) -> str | None:
    """The op's native code with its state in block `number` (at word `base`); None: not
    native (nothing emitted)."""
    found = kind(spec, impl)
    block = Block(f, base, number, dirty_list)
    try:
        if found == "tmr":
            return _tmr(block, params, inputs, dialect)
        if found == "tmrb":
            return _tmrb(block, params, inputs)
        if found == "tmrbf":
            return _tmrbf(block, params, inputs)
        if found == "xmovb":
            return _xmovb(block, params, inputs)
        if found == "counter":
            return _counter(block, impl, params, inputs)
        if found == "codb":
            return _codb(block, params, inputs)
        if found == "arithmetic":
            return _arithmetic(spec.operation)(block, params, inputs)
    except (ValueError, TypeError):
        return None
    return None


# -- the dicts and the blocks ------------------------------------------------------------------

_VALUES = (("elapsed", HAS_ELAPSED, ELAPSED), ("at", HAS_AT, AT), ("wake", HAS_WAKE, WAKE))


def pull(words: Any, base: int, state: dict[str, Any]) -> None:
    """Write a site's dict from its block (and clear its changed bit)."""
    flags = words[base]
    words[base] = flags & ~CHANGED
    if flags & HAS_ELAPSED:
        state["elapsed"] = _get64(words, base + ELAPSED) if flags & ELAPSED_SET else None
    if flags & HAS_AT:
        state["at"] = _get64(words, base + AT)
    if flags & HAS_WAKE:
        state["wake"] = _get64(words, base + WAKE)
    if flags & HAS_ON:
        state["on"] = bool(flags & ON)
    if flags & HAS_W1:
        state["w1"] = bool(flags & W1)
    if flags & HAS_ACT:
        state["act"] = bool(flags & ACT)
    if flags & HAS_VALUE:
        state["value"] = _get64(words, base + ELAPSED)


def push(words: Any, base: int, state: dict[str, Any]) -> None:
    """Write a site's block from its dict."""
    flags = 0
    for key, bit, offset in _VALUES:
        if key in state:
            flags |= bit
            value = state[key]
            if value is not None:
                _set64(words, base + offset, int(value))
                if key == "elapsed":
                    flags |= ELAPSED_SET
    for key, has, value_bit in (("on", HAS_ON, ON), ("w1", HAS_W1, W1), ("act", HAS_ACT, ACT)):
        if key in state:
            flags |= has | (value_bit if state[key] else 0)
    if "value" in state:
        flags |= HAS_VALUE
        _set64(words, base + ELAPSED, int(state["value"]))
    words[base] = flags


def _get64(words: Any, word: int) -> int:
    return (words[word] & 0xFFFFFFFF) | (words[word + 1] << 32)


def _set64(words: Any, word: int, value: int) -> None:
    words[word] = ((value & 0xFFFFFFFF) ^ 0x80000000) - 0x80000000
    words[word + 1] = value >> 32
