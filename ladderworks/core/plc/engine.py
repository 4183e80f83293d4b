"""The scan engine: memory image, virtual clock, generated scan code, forces, power flow, trace."""

from __future__ import annotations

import threading
from collections import deque
from collections.abc import Callable, Iterable
from contextlib import AbstractContextManager
from dataclasses import fields
from typing import Any

from ladderworks.core import dialects
from ladderworks.core.address import Address, Area
from ladderworks.core.compiler import check, disassemble
from ladderworks.core.compiler.binary import BinaryProgram, SourcePosition, decode
from ladderworks.core.diagnostics import DiagnosticError
from ladderworks.core.plc.codegen import GeneratedScan, generate
from ladderworks.core.plc.forcing import ForceEntry, ForceTable
from ladderworks.core.plc.functions import FunctionContext, load_all
from ladderworks.core.plc.history import ScanHistory
from ladderworks.core.plc.memory import Memory
from ladderworks.core.plc.native import unavailable as native_unavailable
from ladderworks.core.plc.native.scan import NativeScan, native_variant
from ladderworks.core.plc.relays import SYSTEM_CLOCKS, set_clocks, system_relays
from ladderworks.core.plc.scan_state import ScanSetup, ScanState
from ladderworks.core.plc.skipping import ClockRelay, CycleSkipper, clocks_read
from ladderworks.core.plc.trace import DEFAULT_CAPACITY, TraceSampler

DEFAULT_PERIOD_MS = 8  # FANUC level-1 period
BACKENDS = ("python", "native")  # the scan's code: generated Python, or native (llvmlite)
ALARM_LOG_CAPACITY = 4096  # A-area changes kept until a view takes them

# Kept on a cold start (and across stop): keep relays, data table, timer and counter tables.
RETAINED_AREAS: frozenset[Area] = frozenset({Area.K, Area.D, Area.T, Area.C})
# Cleared on a cold start; X and F are the machine's and CNC's, never touched by the engine.
CLEARED_AREAS: tuple[Area, ...] = tuple(
    area for area in Area if area not in RETAINED_AREAS and area not in (Area.X, Area.F))


def load_binary(data: bytes) -> BinaryProgram:
    """Decode a binary and re-run the compile checks on it (a hand-made or damaged file
    cannot reach the scan); raises DiagnosticError (BinaryFormatError for a bad file)."""
    binary = decode(data)
    program = disassemble(binary)  # the decoded binary: decoding twice took ~0.5 s
    errors = [d for d in check(program, binary.dialect) if d.is_error]
    if errors:
        raise DiagnosticError(errors)
    return binary


def _context(memory: Memory, period_ms: int, dialect: str) -> FunctionContext:
    """The functions' context; `dialect` is set when FunctionContext has the field."""
    names = {f.name for f in fields(FunctionContext)}
    extra: dict[str, Any] = {"dialect": dialect} if "dialect" in names else {}
    return FunctionContext(memory, 0, period_ms, **extra)


class ScanEngine:
    """Runs a compiled binary: one `scan()` is the program once, top to bottom.

    Time is virtual: each scan happens at `now_ms`, then the clock moves on by `period_ms`.
    Forces are written into memory before and after the logic; disabled ops, the monitored
    mode and the trace take effect at the next scan boundary. Every public method takes
    `lock`, so a runner thread and a GUI thread may share an engine.
    """

    def __init__(self, binary: bytes | BinaryProgram, *, period_ms: int = DEFAULT_PERIOD_MS,
                 memory: Memory | None = None, divisions: int = 1,
                 monitored: bool = False, backend: str = "python") -> None:
        if period_ms <= 0:
            raise ValueError("the scan period must be at least 1 ms")
        if divisions < 1:
            raise ValueError("level 2 needs at least 1 division")
        self.divisions = divisions  # scans (level-1 runs) per pass of levels 2 and 3
        self.program = binary if isinstance(binary, BinaryProgram) else load_binary(binary)
        self.memory = memory if memory is not None else Memory()
        self.period_ms = period_ms
        self.now_ms = 0
        self.scan_count = 0
        # the lock every public method takes (PlcRun puts its ScanLock here, for a scan process)
        self.lock: AbstractContextManager[object] = threading.RLock()
        self.force_table = ForceTable()
        self.trace: TraceSampler | None = None
        self._history: ScanHistory | None = None
        # told after a change of the setup (forces, disabled ops, monitoring, trace, history):
        # a scan process is sent the new setup (PlcRun)
        self.on_setup: Callable[[], None] | None = None
        self._power_flow = bytearray(len(self.program.ops))
        self._flow_stale: GeneratedScan | NativeScan | None = None  # the variant whose power
        # flow is not in the bytes yet
        # every change of the A area, with the time of the scan that made it (newest last)
        self.alarm_log: deque[tuple[int, bytes]] = deque(maxlen=ALARM_LOG_CAPACITY)
        self._alarm_bits = bytes(self.memory.areas[Area.A])
        self._monitored = monitored  # the first variant made is the one to run
        self._registry = load_all()
        self._states: list[dict[str, Any]] = [{} for _ in self.program.ops]
        self._variants: dict[tuple[bool, frozenset[int]], GeneratedScan | NativeScan] = {}
        if backend not in BACKENDS:
            raise ValueError(f"unknown scan backend {backend!r}")
        self.backend = backend  # the one asked for: "python" or "native"
        # why the Python scan runs although the native one was asked for (None: it runs)
        self.backend_reason: str | None = None
        self._ctx = _context(self.memory, period_ms, self.program.dialect)
        found = dialects.get(self.program.dialect)
        self.memory.byteorder = "big" if found is not None and found.byteorder == "big" \
            else "little"
        self._dialect_relays = found.relays if found is not None else None
        self._first_scan = True  # the first scan since the engine was made or cold-started
        self._clocks = SYSTEM_CLOCKS + (found.clocks if found is not None else ())
        # the clocks an op reads and the others: found at the first run that may skip scans
        # (about 0.2 s for X22; a load for the real-time PLC never needs them)
        self._clocks_split: tuple[tuple[ClockRelay, ...], tuple[ClockRelay, ...]] | None = None
        # True: `advance` runs every scan; False: it skips the scans of a state that repeats
        # (core/plc/skipping.py), with the same result after every scan it runs
        self.every_scan = False
        self.skipped = 0  # scans skipped since the engine was made
        self.alarm_changes = 0  # changes of the A area logged since the engine was made
        # True while a scan process scans the program (core/plc/process_runner.py): memory's
        # areas are then shared, and a variant made now would keep them; it is made at the
        # next scan here instead
        self.parked = False
        self._pending = False
        self._current = self._variant()

    @property
    def extra(self) -> dict[str, Any]:
        """The tables the functional instructions share with their owner (a Fatek program's
        ASCII files and terminal: `plc/functions/fatek_io.py`)."""
        return self._ctx.extra

    # -- the scan ------------------------------------------------------------------------

    def _variant(self) -> GeneratedScan | NativeScan:
        key = (self._monitored, self.force_table.disabled)
        variant = self._variants.get(key)
        if variant is None:
            if len(self._variants) > 16:
                self._variants.clear()
            variant = self._native(key) if self.backend_used == "native" else None
            if variant is not None:  # the variants of one program layout share state words
                variant.share_words(list(self._variants.values()))
            if variant is None:
                variant = generate(self.program.ops, self.memory.areas, self._registry,
                                   self._states, disabled=key[1], monitored=key[0])
            self._variants[key] = variant
        return variant

    @property
    def backend_used(self) -> str:
        """The backend that scans: "native" when asked for and it could be built."""
        return "native" if self.backend == "native" and self.backend_reason is None \
            else "python"

    def _native(self, key: tuple[bool, frozenset[int]]) -> NativeScan | None:
        """The native variant of `key`, or None (the reason in `backend_reason`: the Python
        scan runs from then on)."""
        reason = native_unavailable()
        if reason is None:
            try:
                return native_variant(self.program.ops, self.program.dialect,
                                      self.memory.areas, self._registry, self._states,
                                      disabled=key[1], monitored=key[0])
            except Exception as error:  # an IR or LLVM failure: the Python scan runs
                reason = f"the native compile failed: {error}"
        self.backend_reason = reason
        self._variants.clear()  # every variant of one engine comes from one backend
        return None

    def _choose(self) -> None:
        """Use the variant of the monitoring and disabled ops now (parked: at the next scan)."""
        self._pending = True
        if not self.parked:
            self._settle()

    def _settle(self) -> None:
        """Make the variant a change asked for while parked, if any."""
        if self._pending:
            self._pending = False
            self._switch()

    def _switch(self) -> None:
        """Run the variant of the setup now, going on from the states the last one left."""
        variant = self._variant()
        variant.adopt(self._current)
        self._current = variant

    @property
    def source(self) -> str:
        """The Python source of the scan now in use (for the curious and for tests)."""
        if not self.parked:
            self._settle()
        return self._current.source

    def scan(self) -> None:
        """One scan at `now_ms`, then advance the clock by one period."""
        with self.lock:
            if self._pending:
                self._settle()
            now = self.now_ms
            ctx = self._ctx
            ctx.now_ms = now
            ctx.scan_ms = self.period_ms
            self._relays(now)
            self._first_scan = False
            self.force_table.apply(self.memory)
            try:
                self._current.scan(ctx, None, self.scan_count % self.divisions == 0)
                if self._monitored:
                    self._flow_stale = self._current  # made into bytes when read (power_flow)
            finally:
                self.force_table.apply(self.memory)
            alarms = self.memory.areas[Area.A]
            if alarms != self._alarm_bits:  # ~100 ns: the alarm panel misses no pulse
                self._alarm_bits = bytes(alarms)
                self.alarm_log.append((now, self._alarm_bits))
                self.alarm_changes += 1
            if self.trace is not None:
                self.trace.sample(self.memory, now)
            if self._history is not None:  # time travel (core/plc/history.py), off by default
                self._history.record(self)
            self.scan_count += 1
            self.now_ms = now + self.period_ms

    def call_states(self) -> list[dict[str, Any]]:
        """Every op's call-site state (timers, counters: a dict per op, empty for the others)
        as the last scan left it; with the DIFU/DIFD memories in `ctx.edges`."""
        with self.lock:
            self._current.sync()
            return self._states

    def run_scans(self, count: int) -> None:
        """Run `count` scans."""
        for _ in range(count):
            self.scan()

    def step(self, ms: int) -> int:
        """Advance the virtual clock by `ms`, scanning once per period; the scans run."""
        with self.lock:
            return self.advance(self.now_ms + ms)

    def advance(self, limit_ms: int, until: Callable[[], bool] | None = None) -> int:
        """Run the scans due before `limit_ms` (stopping after one at which `until()` holds);
        the scans done, skipped ones included.

        Unless `every_scan` is set, a trace is sampling or history kept, the scans of a state
        that repeats are skipped (core/plc/skipping.py): memory and every state are then what
        running them would have left, after every scan that runs and at the end. `until` must
        read memory only.
        """
        with self.lock:
            skipper = None
            self._current.sync()
            if not self.every_scan and self.trace is None and self.history is None:
                if self._clocks_split is None:
                    read = clocks_read(self.program.ops, self._clocks, self.program.dialect)
                    self._clocks_split = read, tuple(c for c in self._clocks if c not in read)
                native = self._current if hasattr(self._current, "skip_state") else None
                skipper = CycleSkipper(self.memory.areas, self._current.states, self._ctx,
                                       self._clocks_split[0], self.period_ms, self.divisions,
                                       self._clocks_split[1], native, self._monitored)
            count = 0
            while self.now_ms < limit_ms:
                self.scan()
                count += 1
                if until is not None and until():
                    break
                if skipper is not None:
                    if skipper.native is None:
                        self._current.sync()  # the skipper reads the call sites' states
                    skipped = skipper.after_scan(self.now_ms, limit_ms, self.alarm_changes)
                    if skipped:
                        self.now_ms += skipped * self.period_ms
                        self.scan_count += skipped
                        self.skipped += skipped
                        count += skipped
                        if skipper.native is None:
                            # it moved these timers on (nothing else changed since sync)
                            self._current.states_changed(skipper.moved)
                        self._unread_clocks(self.now_ms - self.period_ms)
                        self.force_table.apply(self.memory)  # forces win, as after a scan
            self._current.sync()
            return count

    def _relays(self, now: int) -> None:
        """The relays a scan at `now` starts with: R9091 and the dialect's (Delta M1000..)."""
        system_relays(self.memory.areas, now)
        if self._dialect_relays is not None:
            self._dialect_relays(self.memory.areas, now, self._first_scan)

    def _unread_clocks(self, now: int) -> None:
        """After a skip: the bits of the clocks no op reads or writes (left out of the
        skipper's state) as the last skipped scan (at `now`) began with them. Every other
        relay bit is what the scans left, which they repeat (a clock an op uses does not
        change within a skip; a program that writes over a relay, as S7's MOVE into %MD0
        over the clock memory byte, leaves its own value)."""
        assert self._clocks_split is not None
        set_clocks(self.memory.areas, self._clocks_split[1], now)

    # -- start and stop ------------------------------------------------------------------

    def stop(self) -> None:
        """The safe state: every output Y is 0. Everything else is kept as it is."""
        with self.lock:
            self.memory.clear(Area.Y)

    def cold_start(self) -> None:
        """Clear Y, G, R and A and every timer/counter/edge state; K, D, T, C are kept."""
        with self.lock:
            self.memory.clear(*CLEARED_AREAS)
            for state in self._states:
                state.clear()
            self._ctx.power_on()  # DIFU/DIFD edge memories are shared by number, not per call
            self._first_scan = True
            self._power_flow[:] = bytes(len(self._power_flow))
            for variant in self._variants.values():
                variant.clear_flow()
                variant.states_changed()
            self._flow_stale = None

    # -- moving to and from a scan process (core/plc/scan_process.py) ----------------------

    def export_state(self) -> ScanState:
        """What the next scan depends on besides memory and the setup (a copy)."""
        with self.lock:
            self._current.sync()
            return ScanState(self.now_ms, self.scan_count, self._first_scan,
                             [dict(state) for state in self._states], dict(self._ctx.edges),
                             self._alarm_bits)

    def import_state(self, state: ScanState) -> None:
        """Go on from `state` (another engine of the same program left it)."""
        with self.lock:
            self.now_ms, self.scan_count = state.now_ms, state.scan_count
            self._first_scan = state.first_scan
            for mine, theirs in zip(self._states, state.states, strict=True):
                mine.clear()  # in place: the scan's code holds these dicts
                mine.update(theirs)
            self._ctx.edges.clear()
            self._ctx.edges.update(state.edges)
            self._alarm_bits = state.alarm_bits
            for variant in self._variants.values():
                variant.states_changed()

    def setup(self) -> ScanSetup:
        """The forces, disabled elements and trace now (a scan process monitors the scans a
        view asks for: core/plc/scan_process.py)."""
        with self.lock:
            trace = self.trace.spec() if self.trace is not None else None
            return ScanSetup(self.force_table.forced(), self.force_table.disabled_lines(),
                             trace)

    def use_setup(self, setup: ScanSetup) -> None:
        """Take another engine's setup; a trace of another ident starts sampling afresh."""
        with self.lock:
            self.force_table = setup.force_table()
            self._switch()
            spec = setup.trace
            if spec is None:
                self.trace = None
            elif self.trace is None or self.trace.ident != spec.ident:
                self.trace = TraceSampler.from_spec(spec)

    def adopt_clock(self, scan_count: int, now_ms: int, flow: bytes | memoryview) -> None:
        """The scan count, clock and power flow another engine's last scan left."""
        with self.lock:
            self.scan_count, self.now_ms = scan_count, now_ms
            self._power_flow[:] = flow
            self._flow_stale = None

    # -- monitoring ----------------------------------------------------------------------

    @property
    def power_flow(self) -> bytearray:
        """The last monitored scan's result of every op, one byte per op (made from the
        scan's lists when first read after the scan: a view reading it 10 times a second
        does not pay for a copy in every scan)."""
        with self.lock:
            if self._flow_stale is not None:
                self._flow_stale.flow_into(self._power_flow)
                self._flow_stale = None
            return self._power_flow

    @property
    def monitored(self) -> bool:
        """True when each scan records the power flow of every op in `power_flow`."""
        return self._monitored

    @monitored.setter
    def monitored(self, on: bool) -> None:
        with self.lock:
            self._monitored = bool(on)
            self._choose()
        self._setup_changed()

    @property
    def history(self) -> ScanHistory | None:
        """The scan history kept for time travel (core/plc/history.py): None, off, by default;
        set to keep every scan (it needs the monitored scan)."""
        return self._history

    @history.setter
    def history(self, history: ScanHistory | None) -> None:
        self._history = history
        self._setup_changed()

    def _setup_changed(self) -> None:
        if self.on_setup is not None:
            self.on_setup()

    def power_flow_map(self) -> list[tuple[SourcePosition, bool]]:
        """The last monitored scan's result of every op, with the op's source position."""
        with self.lock:
            return [(op.source, bool(flow))
                    for op, flow in zip(self.program.ops, self.power_flow, strict=True)]

    # -- forcing and disabling -----------------------------------------------------------

    def force(self, address: Address, value: bool | int) -> None:
        """Hold a bit at 0 or 1 (written before and after the logic of every scan)."""
        with self.lock:
            self.force_table.force(address, bool(value))
        self._setup_changed()

    def release(self, address: Address) -> bool:
        """Stop forcing a bit."""
        with self.lock:
            done = self.force_table.release(address)
        self._setup_changed()
        return done

    def op_index(self, op: int | SourcePosition | tuple[int, int]) -> int:
        """An op index from an index, a SourcePosition or a (network, instruction) pair."""
        if isinstance(op, int):
            if not 0 <= op < len(self.program.ops):
                raise IndexError(f"no op {op}")
            return op
        network, instruction = ((op.network, op.instruction)
                                if isinstance(op, SourcePosition) else op)
        for index, item in enumerate(self.program.ops):
            if (item.source.network, item.source.instruction) == (network, instruction):
                return index
        raise IndexError(f"no op at network {network}, instruction {instruction}")

    def disable(self, op: int | SourcePosition | tuple[int, int]) -> int:
        """Disable an element (from the next scan); returns its op index."""
        with self.lock:
            index = self.op_index(op)
            self.force_table.disable(index, self.program.ops[index].source.line)
            self._choose()
        self._setup_changed()
        return index

    def enable(self, op: int | SourcePosition | tuple[int, int]) -> int:
        """Enable a disabled element again; returns its op index."""
        with self.lock:
            index = self.op_index(op)
            self.force_table.enable(index)
            self._choose()
        self._setup_changed()
        return index

    def forces(self) -> list[ForceEntry]:
        """Everything forced or disabled, in one list."""
        with self.lock:
            return self.force_table.entries()

    def release_all(self) -> None:
        """Release every force and enable every element."""
        with self.lock:
            self.force_table.clear()
            self._choose()
        self._setup_changed()

    # -- tracing and alarms --------------------------------------------------------------

    def start_trace(self, addresses: Iterable[Address], period_ms: int,
                    capacity: int = DEFAULT_CAPACITY,
                    widths: list[int] | None = None) -> TraceSampler:
        """Sample `addresses` (bytes: `widths` bytes each) every `period_ms` from the next scan."""
        with self.lock:
            trace = self.trace = TraceSampler(list(addresses), period_ms, capacity, widths)
        self._setup_changed()
        return trace

    def stop_trace(self) -> TraceSampler | None:
        """Stop sampling; returns the sampler (its samples can still be taken)."""
        with self.lock:
            trace, self.trace = self.trace, None
        self._setup_changed()
        return trace

    def take_alarm_changes(self) -> list[tuple[int, bytes]]:
        """The A-area changes since the last call, oldest first: (scan time ms, 100 bytes)."""
        with self.lock:
            changes = list(self.alarm_log)
            self.alarm_log.clear()
            return changes

    def active_alarms(self) -> list[int]:
        """Numbers of the alarm bits that are on (A0.0 = 0, A0.1 = 1, ... A99.7 = 799)."""
        with self.lock:
            data = self.memory.areas[Area.A]
            return [byte * 8 + bit for byte, value in enumerate(data) if value
                    for bit in range(8) if value >> bit & 1]
