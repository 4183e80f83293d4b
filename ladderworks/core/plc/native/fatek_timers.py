"""Fatek FBs timers and counters as native code (core/plc/functions/fatek_timing.py): TMR
(its "ms", "at" and "wake" in the block's time values), CTR and UDCTR ("ck", "loaded" bits of
the block's flags), and RST (no state). The devices' places are known when the IR is made; the
memory is written in the order the Python code writes it (the present value, then the contact,
then FO), each read after the writes before it."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core.address import Address
from ladderworks.core.dialects.fatek.devices import (
    Device,
    bit_address,
    counter_is_32bit,
    counter_is_retentive,
    timer_base_ms,
    word_address,
    word_device_at,
)
from ladderworks.core.plc.functions import NEVER, REGISTRY, FunctionImpl, load_all
from ladderworks.core.plc.functions.fatek_timing import MAX16, places
from ladderworks.core.plc.native import layout
from ladderworks.core.plc.native.builtins import Emitter
from ladderworks.core.plc.native.fatek import _operand
from ladderworks.core.plc.native.fatek_contacts import StatefulEmitter
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.state_block import (
    AS_MS,
    AT,
    CHANGED,
    CK,
    ELAPSED,
    ELAPSED_SET,
    HAS_AT,
    HAS_CK,
    HAS_ELAPSED,
    HAS_LOADED,
    HAS_WAKE,
    LOADED,
    WAKE,
    Block,
    _fits,
    _load,
    _store,
)

_TOP32 = (1 << 31) - 1


def set_bit(f: FunctionText, at: Address, value: str) -> None:
    """`Memory.set_bit` of an i1."""
    assert at.bit is not None
    old = _load(f, at, 1)
    on = f.value(f"or i8 {old}, {1 << at.bit}")
    off = f.value(f"and i8 {old}, {0xFF ^ (1 << at.bit)}")
    _store(f, at, 1, f.value(f"select i1 {value}, i8 {on}, i8 {off}"))


def outputs(f: FunctionText, fo: object, value: str) -> None:
    """`write_outputs(memory, fo, value)`: FO0 = an i1, the other FO 0."""
    if isinstance(fo, Address):
        _store(f, fo, 1, f.value(f"zext i1 {value} to i8"))


def _fo_fits(fo: object) -> bool:
    return fo is None or (isinstance(fo, Address) and _fits(fo, 1))


def _time(f: FunctionText, word: int) -> str:
    return f.value(f"load i64, ptr {f.word_ptr(word)}, align 4")


def _wake(b: Block, wake: str) -> None:
    """`ctx.wake(state, wake)`: the block's wake, the scan's the earlier."""
    f = b.f
    b.store64(WAKE, wake)
    scan_wake = _time(f, layout.WAKE)
    earlier = f.value(f"icmp slt i64 {wake}, {scan_wake}")
    f.add(f"store i64 {f.value(f'select i1 {earlier}, i64 {wake}, i64 {scan_wake}')}, "
          f"ptr {f.word_ptr(layout.WAKE)}, align 4")


def _floor_divmod(f: FunctionText, value: str, base: int) -> tuple[str, str]:
    """Python's divmod by a positive constant (i64)."""
    quotient = f.value(f"sdiv i64 {value}, {base}")
    rest = f.value(f"srem i64 {value}, {base}")
    below = f.value(f"icmp slt i64 {rest}, 0")
    return (f.value(f"select i1 {below}, i64 {f.value(f'sub i64 {quotient}, 1')}, "
                    f"i64 {quotient}"),
            f.value(f"select i1 {below}, i64 {f.value(f'add i64 {rest}, {base}')}, i64 {rest}"))


def _signed(f: FunctionText, at: Address, width: int) -> str:
    return f.value(f"sext i{8 * width} {_load(f, at, width)} to i64")


def _store_value(f: FunctionText, at: Address, width: int, value: str) -> None:
    _store(f, at, width, f.value(f"trunc i64 {value} to i{8 * width}"))


def _tmr(b: Block, impl: FunctionImpl, params: Sequence[object],
         inputs: list[str]) -> str | None:
    """FBS.TMR: EN = 0 clears "ms", CV, Tn and FO0; else CV counts the base's ticks."""
    number, preset, fo = params
    if not isinstance(number, int) or not inputs or not _fo_fits(fo):
        return None
    base = timer_base_ms(number)
    _device, cv_at, width, contact = places("T", number)
    preset_of = _operand(preset, 2)
    if width != 2 or not _fits(cv_at, 2) or not _fits(contact, 1) or preset_of is None:
        return None
    f = b.f
    flags = b.flags()
    on, off, joined = f.label(), f.label(), f.label()
    f.add(f"br i1 {f.truth(inputs[0])}, label %{on}, label %{off}")
    f.start(off)  # ms = None; CV, the contact and FO 0
    b.set_flags(flags, f.value(f"and i32 {f.value(f'or i32 {flags}, {HAS_ELAPSED | AS_MS}')}, "
                               f"{~ELAPSED_SET}"))
    _store(f, cv_at, 2, "0")
    set_bit(f, contact, "false")
    outputs(f, fo, "false")
    off_end = f.block
    f.add(f"br label %{joined}")
    f.start(on)
    now = _time(f, layout.NOW)
    has_at = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {HAS_AT}')}, 0")
    same = f.value(f"icmp eq i64 {b.load64(AT)}, {now}")
    counting = f.value(f"xor i1 {f.value(f'and i1 {has_at}, {same}')}, true")
    b.store64(AT, now)
    ms_set = f.value(f"icmp eq i32 {f.value(f'and i32 {flags}, {HAS_ELAPSED | ELAPSED_SET}')}"
                     f", {HAS_ELAPSED | ELAPSED_SET}")
    step = f.value(f"select i1 {counting}, i64 {_time(f, layout.SCAN_MS)}, i64 0")
    ticks, rest = _floor_divmod(f, f.value(f"add i64 {b.load64(ELAPSED)}, {step}"), base)
    counted = f.value(f"add i64 {_signed(f, cv_at, 2)}, {ticks}")
    capped = f.value(f"select i1 {f.value(f'icmp slt i64 {counted}, {MAX16}')}, "
                     f"i64 {counted}, i64 {MAX16}")
    value = f.value(f"select i1 {ms_set}, i64 {capped}, i64 0")
    most = f.value(f"icmp sge i64 {value}, {MAX16}")
    fresh = f.value(f"xor i1 {ms_set}, true")
    rest = f.value(f"select i1 {f.value(f'or i1 {most}, {fresh}')}, i64 0, i64 {rest}")
    b.store64(ELAPSED, rest)
    later = f.value(f"sub i64 {f.value(f'add i64 {now}, {base}')}, {rest}")
    _wake(b, f.value(f"select i1 {most}, i64 {NEVER}, i64 {later}"))
    _store_value(f, cv_at, 2, value)
    up = f.value(f"icmp sge i64 {value}, {preset_of(f)}")
    set_bit(f, contact, up)
    outputs(f, fo, up)
    ran = HAS_AT | HAS_ELAPSED | ELAPSED_SET | AS_MS | HAS_WAKE | CHANGED
    b.set_flags(flags, f.value(f"or i32 {flags}, {ran}"))
    on_end = f.block
    f.add(f"br label %{joined}")
    f.start(joined)
    w1 = f.value(f"phi i1 [false, %{off_end}], [{up}, %{on_end}]")
    return f.value(f"zext i1 {w1} to i8")


# a counter's work once CLR is 0: (f, the value's address, its width, CK's rising edge) ->
# the i1 FO0 (the contact's value); the memory written as the Python code writes it
Count = Callable[[FunctionText, Address, int, str], str]


def _counted(b: Block, ck: str, clr: str, counter: int | None, cv_at: Address, width: int,
             fo: object, count: Count) -> str:
    """What the counters share (`_count_input`): a non-retentive counter's value 0 at the
    first run ("loaded"), CK's edge against "ck", CLR = 1 clearing the value, the contact and
    FO; else `count`. A register (`counter` None) has no "loaded" and no contact."""
    f = b.f
    flags = b.flags()
    new = flags
    if counter is not None:
        if not counter_is_retentive(counter):
            loaded = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {HAS_LOADED}')}, 0")
            start, after = f.label(), f.label()
            f.add(f"br i1 {loaded}, label %{after}, label %{start}")
            f.start(start)
            _store(f, cv_at, width, "0")
            f.add(f"br label %{after}")
            f.start(after)
        new = f.value(f"or i32 {new}, {HAS_LOADED | LOADED}")
    before = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {CK}')}, 0")
    is_ck = f.truth(ck)
    rising = f.value(f"and i1 {is_ck}, {f.value(f'xor i1 {before}, true')}")
    new = f.value(f"or i32 {f.value(f'and i32 {new}, {~CK}')}, {HAS_CK}")
    b.set_flags(flags, f.value(f"select i1 {is_ck}, i32 {f.value(f'or i32 {new}, {CK}')}, "
                               f"i32 {new}"))
    cleared, counting, joined = f.label(), f.label(), f.label()
    f.add(f"br i1 {f.truth(clr)}, label %{cleared}, label %{counting}")
    f.start(cleared)
    _store(f, cv_at, width, "0")
    if counter is not None:
        set_bit(f, bit_address(Device("C", counter)), "false")
    outputs(f, fo, "false")
    cleared_end = f.block
    f.add(f"br label %{joined}")
    f.start(counting)
    up = count(f, cv_at, width, rising)
    if counter is not None:
        set_bit(f, bit_address(Device("C", counter)), up)
    outputs(f, fo, up)
    counting_end = f.block
    f.add(f"br label %{joined}")
    f.start(joined)
    w1 = f.value(f"phi i1 [false, %{cleared_end}], [{up}, %{counting_end}]")
    return f.value(f"zext i1 {w1} to i8")


def _counter_places(number: int) -> tuple[Address, int] | None:
    _device, cv_at, width, contact = places("C", number)
    return (cv_at, width) if _fits(cv_at, width) and _fits(contact, 1) else None


def _ctr(b: Block, impl: FunctionImpl, params: Sequence[object],
         inputs: list[str]) -> str | None:
    """FBS.CTR: each CK 0 -> 1 adds 1 up to its top; FO0 and Cn while CV >= PV."""
    number, preset, fo = params
    if not isinstance(number, int) or len(inputs) != 2 or not _fo_fits(fo):
        return None
    found = _counter_places(number)
    if found is None:
        return None
    cv_at, width = found
    preset_of = _operand(preset, width)
    if preset_of is None:
        return None
    top = _TOP32 if counter_is_32bit(number) else MAX16

    def count(f: FunctionText, at: Address, size: int, rising: str) -> str:
        value = _signed(f, at, size)
        adds = f.value(f"and i1 {rising}, {f.value(f'icmp slt i64 {value}, {top}')}")
        value = f.value(f"add i64 {value}, {f.value(f'zext i1 {adds} to i64')}")
        _store_value(f, at, size, value)  # the same bytes when nothing was added
        return f.value(f"icmp sge i64 {value}, {preset_of(f)}")

    return _counted(b, inputs[0], inputs[1], number, cv_at, width, fo, count)


def _udctr(b: Block, impl: FunctionImpl, params: Sequence[object],
           inputs: list[str]) -> str | None:
    """FBS.UDCTR: CK 0 -> 1 adds 1 (U/D = 1) or -1, wrapping; FO0 while CV = PV."""
    cv_at, preset, fo = params
    if not isinstance(cv_at, Address) or len(inputs) != 3 or not _fo_fits(fo):
        return None
    device = word_device_at(cv_at)
    counter = device.number if device is not None and device.kind == "C" else None
    if counter is not None:
        found = _counter_places(counter)
        if found is None:
            return None
        cv_at, width = found
    elif not _fits(cv_at, 2):
        return None
    else:
        width = 2
    preset_of = _operand(preset, width)
    if preset_of is None:
        return None
    up_down = inputs[1]

    def count(f: FunctionText, at: Address, size: int, rising: str) -> str:
        step = f.value(f"select i1 {f.truth(up_down)}, i{8 * size} 1, i{8 * size} -1")
        raw = _load(f, at, size)
        moved = f.value(f"add i{8 * size} {raw}, {step}")
        _store(f, at, size, f.value(f"select i1 {rising}, i{8 * size} {moved}, "
                                    f"i{8 * size} {raw}"))
        value = _signed(f, at, size)
        return f.value(f"icmp eq i64 {value}, {preset_of(f)}")

    return _counted(b, inputs[0], inputs[2], counter, cv_at, width, fo, count)


def _rst(f: FunctionText, params: Sequence[object], inputs: list[str]) -> str | None:
    """FBS.RST: EN = 1 clears the timer's or counter's value and its contact; W1 = EN."""
    kind, number = params
    if not isinstance(kind, int) or not isinstance(number, int) or not inputs:
        return None
    device = Device("T" if kind == 0 else "C", number)
    cv_at, width = word_address(device)
    contact = bit_address(device)
    if not (_fits(cv_at, width) and _fits(contact, 1)):
        return None
    _, after = f.branch(inputs[0])
    _store(f, cv_at, width, "0")
    set_bit(f, contact, "false")
    f.join(after)
    return inputs[0]


def _rows() -> tuple[dict[FunctionImpl, Emitter], dict[FunctionImpl,
                                                       tuple[str, StatefulEmitter]]]:
    load_all()
    stateful: dict[FunctionImpl, tuple[str, StatefulEmitter]] = {}
    for name, emitter in (("FBS.TMR", _tmr), ("FBS.CTR", _ctr), ("FBS.UDCTR", _udctr)):
        if name in REGISTRY:
            stateful[REGISTRY[name]] = ("fatek timing", emitter)
    emitters: dict[FunctionImpl, Emitter] = \
        {REGISTRY["FBS.RST"]: _rst} if "FBS.RST" in REGISTRY else {}
    return emitters, stateful


EMITTERS, STATEFUL = _rows()
