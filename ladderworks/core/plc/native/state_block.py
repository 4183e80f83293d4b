"""A call site's state in a block of state words while the native scan runs (stateful.py):
the block's layout, its IR (`Block`), an error output held as `held_output` holds it, and the
dicts written from the words (`pull`) and the words from the dicts (`push`).

The flags word says which keys the dict has and holds the booleans and a "changed" bit; three
64-bit values follow (`elapsed`, `at`, `wake`; CTRB's `value`, Delta TMR's `ms` and NEXT's
`left` at `elapsed`). A block that
changed in a scan puts its number in the changed list once (layout.DIRTY).
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

from ladderworks.core.address import Address
from ladderworks.core.plc.functions import s7_counters, s7_timers
from ladderworks.core.plc.native import layout
from ladderworks.core.plc.native.builtins import _fits as _fits
from ladderworks.core.plc.native.builtins import _load as _load
from ladderworks.core.plc.native.builtins import _store as _store
from ladderworks.core.plc.native.ir_text import AREA_ORDER, FunctionText

BLOCK = 8  # words per site: flags, pad, elapsed (i64), at (i64), wake (i64)
ELAPSED, AT, WAKE = 2, 4, 6
# flags: key present (and not None / its value)
HAS_ELAPSED, ELAPSED_SET, HAS_AT, HAS_WAKE, HAS_ON, ON, HAS_W1, W1 = (
    1, 2, 4, 8, 16, 32, 256, 512)
HAS_ACT, ACT, HAS_VALUE = 1024, 2048, 4096  # counters: the last ACT; CTRB's value (at ELAPSED)
HAS_PREV, PREV = 1 << 13, 1 << 14  # Delta's pulse forms: the input at the last execution
HAS_EN, EN, HAS_FO0, FO0 = 1 << 16, 1 << 17, 1 << 18, 1 << 19  # Fatek boxes: "en", "fo0"
# Fatek timers, counters, TU/TD: the elapsed value named "ms" (AS_MS: a time value as
# "elapsed" is), "ck" (the last CK), "loaded", "before" (the edge contact's last device bit)
AS_MS, HAS_CK, CK, HAS_LOADED, LOADED, HAS_BEFORE, BEFORE = (1 << k for k in range(20, 27))
CHANGED = 1 << 15
# S7: the call site's "timer" (s7_timers.Timer) / "places" (s7_counters) is in the dict; the
# pad word (INSTANCE) says its instance: area index << 24 | count type << 16 | byte
HAS_TIMER, HAS_PLACES, INSTANCE = 1 << 29, 1 << 30, 1  # high bits: far from the others
# Delta: MORE says the pad word (as INSTANCE: never both) holds more keys' flags: TMR's
# "running" and "ms" (at ELAPSED with ELAPSED_SET: a time value the skipper moves on), the
# high-speed counters' "x" and "y" (their inputs at the last execution), NEXT's "left" (at
# ELAPSED, not a time value)
MORE = 64
HAS_RUNNING, RUNNING, HAS_MS, HAS_HX, HX, HAS_HY, HY, HAS_LEFT = (1 << k for k in range(8))
_MORE_BOOLS = (("running", HAS_RUNNING, RUNNING), ("x", HAS_HX, HX), ("y", HAS_HY, HY))
_I32 = (-(1 << 31), (1 << 31) - 1)

class Block:
    """The IR of one site's state block (`base`: its first word)."""

    def __init__(self, f: FunctionText, base: int, number: int, dirty_list: int,
                 marks: int, dialect: str = "seed") -> None:
        self.f, self.base, self.number, self.dirty_list = f, base, number, dirty_list
        self.mark = marks + number
        self.dialect = dialect  # the program's: its byte order (dialects.get(...).byteorder)

    def ptr(self, offset: int) -> str:
        return self.f.word_ptr(self.base + offset)

    def flags(self) -> str:
        return self.f.value(f"load i32, ptr {self.ptr(0)}")

    def load64(self, offset: int) -> str:
        return self.f.value(f"load i64, ptr {self.ptr(offset)}, align 4")

    def store64(self, offset: int, value: str) -> None:
        self.f.add(f"store i64 {value}, ptr {self.ptr(offset)}, align 4")

    def more(self, flags: str) -> str:
        """The pad word's flags (`MORE`), 0 when the flags say it holds none."""
        f = self.f
        raw = f.value(f"load i32, ptr {self.ptr(INSTANCE)}")
        has = f.value(f"icmp ne i32 {f.value(f'and i32 {flags}, {MORE}')}, 0")
        return f.value(f"select i1 {has}, i32 {raw}, i32 0")

    def set_more(self, old: str, new: str) -> str:
        """Store the pad word's flags; CHANGED (for `set_flags`) when they differ, else 0."""
        f = self.f
        f.add(f"store i32 {new}, ptr {self.ptr(INSTANCE)}")
        differs = f.value(f"icmp ne i32 {old}, {new}")
        return f.value(f"select i1 {differs}, i32 {CHANGED}, i32 0")

    def set_flags(self, old: str, new: str) -> None:
        """Store the flags; a block whose flags or values changed (`new` has CHANGED set by
        the caller when values changed; the stored flags never have it) joins the changed
        list once (its mark word says it is in it)."""
        f = self.f
        differs = f.value(f"icmp ne i32 {old}, {new}")
        mark_ptr = f.word_ptr(self.mark)
        marked = f.value(f"load i32, ptr {mark_ptr}")
        first = f.value(f"and i1 {differs}, {f.value(f'icmp eq i32 {marked}, 0')}")
        stored = f.value(f"and i32 {new}, {~CHANGED}")
        f.add(f"store i32 {f.value(f'select i1 {differs}, i32 {stored}, i32 {old}')}, "
              f"ptr {self.ptr(0)}")
        step = f.value(f"zext i1 {first} to i32")
        f.add(f"store i32 {f.value(f'or i32 {marked}, {step}')}, ptr {mark_ptr}")
        count_ptr = f.word_ptr(layout.DIRTY)
        count = f.value(f"load i32, ptr {count_ptr}")
        slot = f.value(f"getelementptr i32, ptr %st, i64 {self.dirty_list}")
        entry = f.value(f"getelementptr i32, ptr {slot}, i32 {count}")
        f.add(f"store i32 {self.number}, ptr {entry}")
        f.add(f"store i32 {f.value(f'add i32 {count}, {step}')}, ptr {count_ptr}")


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


_FATEK_BOOLS = (("ck", HAS_CK, CK), ("loaded", HAS_LOADED, LOADED),
                ("before", HAS_BEFORE, BEFORE))
_VALUES = (("elapsed", HAS_ELAPSED, ELAPSED), ("at", HAS_AT, AT), ("wake", HAS_WAKE, WAKE))


def pull(words: Any, base: int, state: dict[str, Any]) -> None:
    """Write a site's dict from its block."""
    flags = words[base]
    if flags & HAS_ELAPSED:
        state["ms" if flags & AS_MS else "elapsed"] = \
            _get64(words, base + ELAPSED) if flags & ELAPSED_SET else None
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
    if flags & HAS_PREV:
        state["prev"] = bool(flags & PREV)
    if flags & HAS_EN:
        state["en"] = bool(flags & EN)
    if flags & HAS_FO0:
        state["fo0"] = bool(flags & FO0)
    if flags & HAS_VALUE:
        state["value"] = _get64(words, base + ELAPSED)
    for key, has, value_bit in _FATEK_BOOLS:
        if flags & has:
            state[key] = bool(flags & value_bit)
    if flags & (HAS_TIMER | HAS_PLACES):
        _pull_instance(words[base + INSTANCE], flags, state)
    if flags & MORE:
        more = words[base + INSTANCE]
        for key, has, value_bit in _MORE_BOOLS:
            if more & has:
                state[key] = bool(more & value_bit)
        for key, has in (("ms", HAS_MS), ("left", HAS_LEFT)):
            if more & has:
                state[key] = _get64(words, base + ELAPSED)


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
    for key, has, value_bit in (("on", HAS_ON, ON), ("w1", HAS_W1, W1), ("act", HAS_ACT, ACT),
                                ("prev", HAS_PREV, PREV), ("en", HAS_EN, EN),
                                ("fo0", HAS_FO0, FO0)):
        if key in state:
            flags |= has | (value_bit if state[key] else 0)
    if "value" in state:
        flags |= HAS_VALUE
        _set64(words, base + ELAPSED, int(state["value"]))
    if "ms" in state:
        flags |= HAS_ELAPSED | AS_MS
        if state["ms"] is not None:
            flags |= ELAPSED_SET
            _set64(words, base + ELAPSED, int(state["ms"]))
    for key, has, value_bit in _FATEK_BOOLS:
        if key in state:
            flags |= has | (value_bit if state[key] else 0)
    if state.get("timer") is not None:
        flags |= HAS_TIMER
        words[base + INSTANCE] = instance_word(state["timer"].pt_at)
    if state.get("places") is not None:
        flags |= HAS_PLACES
        places = state["places"]
        words[base + INSTANCE] = instance_word(places[1], int(places[0]))
    more = 0
    for key, has, value_bit in _MORE_BOOLS:
        if key in state:
            more |= has | (value_bit if state[key] else 0)
    # Delta TMR's "ms" (always with "running": the "ms" of other dialects' timers is theirs)
    for key, has in (("ms", HAS_MS), ("left", HAS_LEFT)):
        if key in state and (key != "ms" or "running" in state):
            more |= has
            flags |= ELAPSED_SET if key == "ms" else 0
            _set64(words, base + ELAPSED, int(state[key]))
    if more:
        flags |= MORE
        words[base + INSTANCE] = more
    words[base] = flags


def instance_word(instance: Address, vtype: int = 0) -> int:
    """The INSTANCE word of an S7 timer's or counter's instance (and count type)."""
    return AREA_ORDER.index(instance.area) << 24 | vtype << 16 | instance.byte


def _pull_instance(word: int, flags: int, state: dict[str, Any]) -> None:
    """An S7 site's "timer" or "places" as its Python function makes them at its first run
    (kept when the dict has one: they never change)."""
    instance = Address(AREA_ORDER[word >> 24], word & 0xFFFF)
    if flags & HAS_TIMER and state.get("timer") is None:
        state["timer"] = s7_timers.Timer.unbound(instance)
    if flags & HAS_PLACES and state.get("places") is None:
        s7_counters._places(state, (instance, word >> 16 & 0xFF))


def _get64(words: Any, word: int) -> int:
    return (words[word] & 0xFFFFFFFF) | (words[word + 1] << 32)


def _set64(words: Any, word: int, value: int) -> None:
    words[word] = ((value & 0xFFFFFFFF) ^ 0x80000000) - 0x80000000
    words[word + 1] = value >> 32

