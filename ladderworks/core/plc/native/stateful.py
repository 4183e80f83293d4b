"""Functional instructions with a call-site state, as native code: TMR, TMRB, TMRBF and the
signed binary arithmetic (ADDB, SUBB, MULB, DIVB) here, CODB, XMOVB and the counters in
tables.py; each state in a block of state words (state_block.py), written back into its dict
when the dicts are read. `kind` says which ops these are, `emit` writes one.
"""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core.address import Address
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
    parity,
    signed_range,
    timers,
    transfer,
)
from ladderworks.core.plc.functions import (
    rotation as rotations,
)
from ladderworks.core.plc.functions import (
    shift as shifts,
)
from ladderworks.core.plc.native import (
    bcd,
    builtins,
    contacts,
    delta_blocks,
    delta_extra,
    delta_float,
    delta_libm,
    delta_logic,
    delta_pulses,
    delta_scale32,
    delta_timers,
    fatek,
    fatek_rows,
    layout,
    rotation,
    s7_bits,
    s7_convert,
    s7_real,
    s7_timers,
    s7_values,
    search,
    shift,
    words,
    words32,
)
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.state_block import (
    AT,
    CHANGED,
    ELAPSED,
    ELAPSED_SET,
    HAS_AT,
    HAS_ELAPSED,
    HAS_ON,
    HAS_WAKE,
    ON,
    WAKE,
    Block,
    _fits,
    _held,
    _load,
    _store,
)
from ladderworks.core.plc.native.tables import _codb, _counter, _dcnvb, _xmovb

_I32 = (-(1 << 31), (1 << 31) - 1)


def _binary_code() -> object:
    load_all()
    spec = next(s for s in FUNCTIONS if s.binary and s.operation is not Operation.NONE)
    return REGISTRY[spec.name].__code__


_ARITHMETIC = _binary_code()  # the code every signed binary arithmetic implementation shares


StatefulEmitter = Callable[[Block, FunctionImpl, Sequence[object], list[str]], str | None]
# rows of other modules, each with its state in a block: implementation -> (kind, emitter);
# a module adds its own dict with one `ROWS.update(module.STATEFUL)` line below
ROWS: dict[FunctionImpl, tuple[str, StatefulEmitter]] = {}
ROWS.update(fatek_rows.STATEFUL)
ROWS.update(s7_values.STATEFUL)
ROWS.update(s7_bits.STATEFUL)
ROWS.update(s7_convert.STATEFUL)
ROWS.update(s7_real.STATEFUL)  # after s7_values, s7_convert: their rows, floats added
ROWS.update(s7_timers.STATEFUL)
ROWS.update(search.STATEFUL)
ROWS.update(delta_timers.STATEFUL)
ROWS.update(delta_extra.STATEFUL)
ROWS.update(delta_pulses.STATEFUL)


def kind(spec: InstructionSpec, impl: FunctionImpl | None) -> str | None:
    """"tmr", "tmrb", "tmrbf", "codb", "xmovb" or "arithmetic" for an op done here natively,
    else None."""
    if impl in ROWS:
        assert impl is not None
        return ROWS[impl][0]
    if impl is timers.tmr:
        return "tmr"
    if impl is convert.codb:
        return "codb"
    if impl is convert.dcnvb:
        return "dcnvb"
    if impl in (counters.ctr, counters.ctrc, counters.ctrb):
        return "counter"
    if impl is transfer.xmovb:
        return "xmovb"
    if impl is timers.tmrb:
        return "tmrb"
    if impl is timers.tmrc:
        return "tmrc"
    if impl is timers.tmrbf:
        return "tmrbf"
    if bcd.is_bcd_arithmetic(spec, impl):
        return "bcd"
    if impl is shifts.sft:
        return "sft"
    if impl is rotations.rot:
        return "rot"
    if impl is rotations.rotb:
        return "rotb"
    if impl is parity.pari:
        return "pari"
    if impl is convert.cod:
        return "cod"
    if impl in words.PULSES:
        return "pulse"
    if impl in fatek.BOXES:
        return "fatek"
    if impl in contacts.EDGES:
        return "edge contact"
    if impl in contacts.PULSES:
        return "pls"
    if getattr(impl, "__code__", None) is _ARITHMETIC and spec.operation is not Operation.NONE:
        return "arithmetic"
    return None


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


def _tmrc(b: Block, params: Sequence[object], inputs: list[str], dialect: str) -> str | None:
    """TMRC: the preset (2 bytes, in units of its accuracy) read from memory, the elapsed
    units written to its 4-byte register; a wake at the next unit (timers.tmrc)."""
    accuracy, preset_at, register = params
    if not isinstance(accuracy, int) or not _fits(preset_at, 2) or not _fits(register, 4) \
            or dialect == "s7":  # the native loads are little-endian, as the PMC's memory
        return None
    assert isinstance(preset_at, Address) and isinstance(register, Address)
    units_ms = timers.FANUC_TMRC_UNIT_MS if dialect == "fanuc" else timers.TMRC_UNIT_MS
    unit = units_ms.get(accuracy, units_ms[0])
    f = b.f
    flags = b.flags()
    on, off, joined = f.label(), f.label(), f.label()
    f.add(f"br i1 {f.truth(inputs[-1])}, label %{on}, label %{off}")
    f.start(off)  # elapsed = None, the register 0
    b.set_flags(flags, f.value(f"and i32 {f.value(f'or i32 {flags}, {HAS_ELAPSED}')}, "
                               f"{~ELAPSED_SET}"))
    _store(f, register, 4, "0")
    off_end = f.block
    f.add(f"br label %{joined}")
    f.start(on)
    elapsed, new = _elapsed(b, flags)
    preset = f.value(f"zext i16 {_load(f, preset_at, 2)} to i64")
    counted = f.value(f"udiv i64 {elapsed}, {unit}")
    below = f.value(f"icmp slt i64 {counted}, {preset}")
    units = f.value(f"select i1 {below}, i64 {counted}, i64 {preset}")
    next_unit = f.value(f"sub i64 {f.value(f'add i64 {_time(f, layout.NOW)}, {unit}')}, "
                        f"{f.value(f'urem i64 {elapsed}, {unit}')}")
    wake = f.value(f"select i1 {below}, i64 {next_unit}, i64 {NEVER}")
    b.store64(WAKE, wake)
    scan_wake = _time(f, layout.WAKE)
    earlier = f.value(f"icmp slt i64 {wake}, {scan_wake}")
    f.add(f"store i64 {f.value(f'select i1 {earlier}, i64 {wake}, i64 {scan_wake}')}, "
          f"ptr {f.word_ptr(layout.WAKE)}, align 4")
    _store(f, register, 4, f.value(f"trunc i64 {units} to i32"))
    b.set_flags(flags, f.value(f"or i32 {f.value(f'or i32 {new}, {HAS_WAKE}')}, {CHANGED}"))
    done = f.value(f"xor i1 {below}, true")  # the preset reached
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


# the stateless rows of bcd.py and words.py join builtins' (they use its helpers)
builtins.EMITTERS.update(bcd.EMITTERS)
builtins.EMITTERS.update(words.EMITTERS)
builtins.EMITTERS.update(words32.EMITTERS)
builtins.EMITTERS.update(contacts.EMITTERS)
builtins.EMITTERS.update(fatek.EMITTERS)
builtins.EMITTERS.update(fatek_rows.EMITTERS)
builtins.EMITTERS.update(delta_timers.EMITTERS)
builtins.EMITTERS.update(delta_logic.EMITTERS)
builtins.EMITTERS.update(delta_blocks.EMITTERS)
builtins.EMITTERS.update(delta_float.EMITTERS)
builtins.EMITTERS.update(delta_extra.EMITTERS)
builtins.EMITTERS.update(delta_libm.EMITTERS)
builtins.EMITTERS.update(delta_scale32.EMITTERS)
words.PULSES.update(words32.PULSES)
words.PULSES.update(delta_logic.PULSES)
words.PULSES.update(delta_blocks.PULSES)
words.PULSES.update(delta_float.PULSES)
words.PULSES.update(delta_extra.PULSES)
words.PULSES.update(delta_libm.PULSES)
words.PULSES.update(delta_scale32.PULSES)
_OPS = {Operation.ADD: "add", Operation.SUBTRACT: "sub", Operation.MULTIPLY: "mul"}


def emit(f: FunctionText, spec: InstructionSpec, impl: FunctionImpl, params: Sequence[object],
         inputs: list[str], base: int, number: int, dirty_list: int, marks: int,
         dialect: str) -> str | None:
    """The op's native code with its state in block `number` (at word `base`); None: not
    native (nothing emitted)."""
    found = kind(spec, impl)
    block = Block(f, base, number, dirty_list, marks, dialect)
    try:
        if impl in ROWS:
            return ROWS[impl][1](block, impl, params, inputs)
        if found == "tmr":
            return _tmr(block, params, inputs, dialect)
        if found == "tmrb":
            return _tmrb(block, params, inputs)
        if found == "tmrc":
            return _tmrc(block, params, inputs, dialect)
        if found == "tmrbf":
            return _tmrbf(block, params, inputs)
        if found == "xmovb":
            return _xmovb(block, params, inputs)
        if found == "counter":
            return _counter(block, impl, params, inputs)
        if found == "dcnvb":
            return _dcnvb(block, params, inputs, dialect)
        if found == "codb":
            return _codb(block, params, inputs)
        if found == "pls":
            return contacts.pls_plf(block, impl, params, inputs)
        if found == "edge contact":
            return contacts.edge(block, impl, params, inputs)
        if found == "fatek":
            return fatek.emit(block, impl, params, inputs)
        if found == "pulse":
            return words.pulse(block, impl, params, inputs)
        if found == "pari":
            return shift.pari(block, params, inputs)
        if found == "cod":
            return bcd.cod(block, params, inputs)
        if found == "rot":
            return rotation.rot(block, params, inputs)
        if found == "rotb":
            return rotation.rotb(block, params, inputs)
        if found == "sft":
            return shift.sft(block, params, inputs)
        if found == "bcd":
            return bcd.arithmetic(block, spec.operation, params, inputs)
        if found == "arithmetic":
            return _arithmetic(spec.operation)(block, params, inputs)
    except (ValueError, TypeError):
        return None
    return None


# -- the dicts and the blocks ------------------------------------------------------------------

