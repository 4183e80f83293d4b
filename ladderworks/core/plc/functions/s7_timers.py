"""S7-1200 IEC timers TP, TON, TOF, TONR and the -(PT)- / -(RT)- coils, on IEC_TIMER instances.

The instance (16 bytes, S7-1200 system manual V4.2 p. 240) holds PT (+0, Time in ms), ET (+4),
IN (+8.0), Q (+8.1), running (+8.2) and the start time (+12, the virtual clock in ms, 32 bits).
ET and Q are computed from the start time **when the box runs**, so a box skipped by a jump
catches up at its next run (DIALECTS.md 3.5). The box's PT is taken when timing starts; a PT
change while timing has no effect, except for TONR, which takes PT at every run (system
manual 11/2011 p. 172). `-(PT)-` writes the instance's PT (effective at once); `-(RT)-` clears
ET and Q and restarts a running timer. docs/dialects.md, S7-1200 timers.
"""

from __future__ import annotations

from ladderworks.core.address import Address
from ladderworks.core.plc import typed
from ladderworks.core.plc.functions import NEVER, FunctionContext, function
from ladderworks.core.plc.memory import Memory

IN, Q, RU = 0, 1, 2
MASK32 = 0xFFFFFFFF


class Timer:
    """The places of one IEC_TIMER instance in memory (made once per call site)."""

    __slots__ = ("data", "et_at", "flags", "memory", "pt_at", "start_at")

    def __init__(self, memory: Memory, base: Address) -> None:
        self.memory = memory
        self.data = memory.areas[base.area]
        self.pt_at = Address(base.area, base.byte)
        self.et_at = Address(base.area, base.byte + 4)
        self.start_at = Address(base.area, base.byte + 12)
        self.flags = base.byte + 8

    @classmethod
    def unbound(cls, base: Address) -> Timer:
        """The Timer of the instance at `base` bound to no memory (`timer_of` binds one at its
        next run): the native scan's call-site states hold these."""
        timer = cls.__new__(cls)
        timer.memory = None  # type: ignore[assignment]
        timer.data = bytearray()
        timer.pt_at = Address(base.area, base.byte)
        timer.et_at = Address(base.area, base.byte + 4)
        timer.start_at = Address(base.area, base.byte + 12)
        timer.flags = base.byte + 8
        return timer

    def __eq__(self, other: object) -> bool:
        """Timers of the same instance are equal, whatever memory each is bound to."""
        return isinstance(other, Timer) and other.pt_at == self.pt_at

    __hash__ = None  # type: ignore[assignment]

    def __reduce__(self) -> tuple:
        """Pickled as None (a scan process's state): it is found again in the memory there."""
        return (type(None), ())

    def get(self, offset: int) -> int:
        """A 4-byte signed member (PT +0, ET +4)."""
        return self.memory.read(self.pt_at if offset == 0 else self.et_at, 4, signed=True)

    def put(self, offset: int, value: int) -> None:
        """Store a 4-byte member."""
        self.memory.write(self.pt_at if offset == 0 else self.et_at, value, 4)

    def flag(self, bit: int) -> bool:
        """IN, Q or running."""
        return bool(self.data[self.flags] >> bit & 1)

    def set_flag(self, bit: int, value: bool) -> None:
        """Set IN, Q or running."""
        if value:
            self.data[self.flags] |= 1 << bit
        else:
            self.data[self.flags] &= ~(1 << bit) & 0xFF

    def start(self, now_ms: int) -> None:
        """Remember the time timing starts."""
        self.memory.write(self.start_at, now_ms & MASK32, 4)

    def elapsed(self, now_ms: int) -> int:
        """Milliseconds since the start (the 32-bit clock's difference)."""
        return (now_ms - self.memory.read(self.start_at, 4)) & MASK32


def timer_of(ctx: FunctionContext, state: dict, instance: Address) -> Timer:
    """The call site's Timer (its places found at its first run)."""
    timer = state.get("timer")
    if timer is None or timer.memory is not ctx.memory \
            or timer.data is not ctx.memory.areas[instance.area]:  # areas moved (scan process)
        timer = state["timer"] = Timer(ctx.memory, instance)
    return timer


def _pt(ctx: FunctionContext, value: object) -> int:
    return max(0, int(typed.read(ctx.memory, value, typed.ValueType.TIME)))  # negative acts as 0


def _finish(ctx: FunctionContext, state: dict, timer: Timer, q: bool, et: int, et_out: object,
            running: bool) -> bool:
    timer.put(4, et)
    timer.set_flag(Q, q)
    timer.set_flag(RU, running)
    typed.write(ctx.memory, et_out, typed.ValueType.TIME, et)
    # while running, ET changes at every scan: no scan may be skipped until it stops
    ctx.wake(state, ctx.now_ms + 1 if running else NEVER)
    return q


@function("S7.TON")
def ton(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """On-delay: Q once IN has been 1 for PT; IN = 0 resets ET and Q (001:194-200)."""
    instance, pt_in, et_out = params
    timer = timer_of(ctx, state, instance)
    now, signal = ctx.now_ms, bool(inputs[0])
    was = timer.flag(IN)
    timer.set_flag(IN, signal)
    if not signal:
        return _finish(ctx, state, timer, False, 0, et_out, False)
    if not was:
        timer.start(now)
        timer.put(0, _pt(ctx, pt_in))
    pt = timer.get(0)
    et = min(timer.elapsed(now), pt)
    return _finish(ctx, state, timer, et >= pt, et, et_out, et < pt)


@function("S7.TOF")
def tof(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Off-delay: Q = 1 with IN; after IN drops Q stays for PT; IN back resets ET (001:306-312)."""
    instance, pt_in, et_out = params
    timer = timer_of(ctx, state, instance)
    now, signal = ctx.now_ms, bool(inputs[0])
    was = timer.flag(IN)
    timer.set_flag(IN, signal)
    if signal:
        return _finish(ctx, state, timer, True, 0, et_out, False)
    if was:
        timer.start(now)
        timer.put(0, _pt(ctx, pt_in))
    elif not timer.flag(RU) and not timer.flag(Q):
        return _finish(ctx, state, timer, False, timer.get(4), et_out, False)
    pt = timer.get(0)
    et = min(timer.elapsed(now), pt)
    return _finish(ctx, state, timer, et < pt, et, et_out, et < pt)


@function("S7.TP")
def tp(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Pulse: IN 0 → 1 starts Q for PT; IN meanwhile has no effect (no retrigger); after the
    pulse ET stays PT while IN is 1 and is 0 once IN is 0 (001:176-186)."""
    instance, pt_in, et_out = params
    timer = timer_of(ctx, state, instance)
    now, signal = ctx.now_ms, bool(inputs[0])
    was = timer.flag(IN)
    timer.set_flag(IN, signal)
    if timer.flag(RU):
        pt = timer.get(0)
        et = min(timer.elapsed(now), pt)
        if et < pt:
            return _finish(ctx, state, timer, True, et, et_out, True)
        return _finish(ctx, state, timer, False, et if signal else 0, et_out, False)
    if signal and not was:
        timer.start(now)
        pt = _pt(ctx, pt_in)
        timer.put(0, pt)
        return _finish(ctx, state, timer, pt > 0, 0, et_out, pt > 0)
    et = timer.get(4) if signal else 0
    return _finish(ctx, state, timer, False, et, et_out, False)


@function("S7.TONR")
def tonr(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Retentive on-delay: ET adds up while IN is 1, kept while IN is 0; Q once ET reaches PT;
    R resets ET and Q whatever IN is (001:328-336; system manual p. 172)."""
    instance, pt_in, et_out = params
    timer = timer_of(ctx, state, instance)
    now, signal, reset = ctx.now_ms, bool(inputs[0]), bool(inputs[1])
    was = timer.flag(IN)
    timer.set_flag(IN, signal)
    pt = _pt(ctx, pt_in)
    timer.put(0, pt)
    if reset:
        timer.start(now)
        return _finish(ctx, state, timer, False, 0, et_out, False)
    et = timer.get(4)
    if was:  # the time since its last run counts while IN was 1 (computed when it runs)
        et = min(et + timer.elapsed(now), pt)
    if signal:
        timer.start(now)
    return _finish(ctx, state, timer, et >= pt, et, et_out, signal and et < pt)


@function("S7.PT")
def load_time(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
              params: tuple) -> bool:
    """-(PT)-: with power, the instance's PT := the value (001:338-376)."""
    instance, pt_in = params
    if inputs[0]:
        timer_of(ctx, state, instance).put(0, _pt(ctx, pt_in))
    return bool(inputs[0])


@function("S7.RT")
def reset_timer(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...],
                params: tuple) -> bool:
    """-(RT)-: with power, ET := 0 and Q := 0; a running timer starts again from now."""
    (instance,) = params
    if inputs[0]:
        timer = timer_of(ctx, state, instance)
        timer.put(4, 0)
        timer.set_flag(Q, False)
        timer.start(ctx.now_ms)
    return bool(inputs[0])
