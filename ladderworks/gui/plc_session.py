"""PlcSession: the Qt side of the PLC — one ScanEngine, run, watched and forced from the GUI.

Public API (stable; docks of issues 7 and 8 build on it)::

    session = PlcSession(parent=None, realtime=True, period_ms=8, publish_ms=40)

    # program
    session.load(binary: bytes, program=None) -> list[Diagnostic]  # [] when loaded
    session.program -> Program | None                       # its source, when known
    session.load_program(program: Program) -> CompileResult  # compile + load
    session.binary -> BinaryProgram | None                  # ops with their source map
    session.engine -> ScanEngine | None
    # running
    session.start(); session.stop(); session.running -> bool
    session.step(ms) -> int; session.run_scans(n) -> int    # virtual clock, only while running
    session.publish()                                       # emit status + snapshot now
    session.status() -> PlcStatus; session.snapshot() -> PlcSnapshot
    session.monitor(on: bool)     # counted: power flow per op is recorded while > 0 users
    # machine side (X/F as a machine or CNC would, any other area too)
    session.set_bit(address, value); session.write(address, value, width=1)
    session.bit(address) -> int; session.read(address, width=1) -> int
    # forcing and disabling (applied by the engine at scan boundaries)
    session.force(address, value); session.release(address) -> bool
    session.disable(op) -> int; session.enable(op) -> int   # op: index | (network, instruction)
    session.release_all(); session.forces() -> list[ForceEntry]
    # tracing (samples taken inside the scan loop)
    session.start_trace(addresses, period_ms, widths=None); session.stop_trace()
    session.trace_samples() -> list[TraceSample]           # samples not taken yet
    # tables and alarms
    session.timer_preset(n) / set_timer_preset(n, ms)
    session.counter(n) -> (preset, value) / set_counter_preset(n, preset)
    session.alarm_table = AlarmTable(...); session.alarms() -> list[ActiveAlarm]
    session.reset_alarms()

Signals: `program_loaded(BinaryProgram)`, `running_changed(bool)`, `status_changed(PlcStatus)`,
`snapshot_ready(PlcSnapshot)`, `forces_changed(list[ForceEntry])`,
`alarms_changed(list[ActiveAlarm])`.

With `realtime=True` `start()` runs the core's RealTimeRunner (a thread scanning at the period
on the wall clock) and a QTimer publishes every `publish_ms`, reading a snapshot under the
engine's lock. With `realtime=False` nothing runs by itself: `step(ms)` / `run_scans(n)` scan
on the virtual clock and publish at once, so tests get the same signals without a thread.
The memory image belongs to the session: X/F inputs and K/D/T/C tables survive loading a new
program; a load clears Y, G, R and A (cold start). Forced bits stay forced across a load;
disabled elements are enabled (their op numbers belong to the old program). Releasing a
forced X/F bit gives it back the value the machine side last wrote with `set_bit`.
"""

from __future__ import annotations

import time
from collections.abc import Iterable
from contextlib import AbstractContextManager, nullcontext
from dataclasses import dataclass, field

from PySide6.QtCore import QObject, QTimer, Signal

from ladderworks.core.address import Address, Area
from ladderworks.core.alarms import ActiveAlarm, ActiveAlarms, AlarmTable
from ladderworks.core.compiler import CompileResult, compile_program
from ladderworks.core.compiler.binary import BinaryProgram
from ladderworks.core.diagnostics import Diagnostic, DiagnosticError
from ladderworks.core.il.program import Program
from ladderworks.core.plc.engine import DEFAULT_PERIOD_MS, ScanEngine
from ladderworks.core.plc.forcing import ForceEntry
from ladderworks.core.plc.functions.counters import (
    counter_preset_address,
    counter_value_address,
    write_counter_preset,
)
from ladderworks.core.plc.functions.timers import read_timer_preset, write_timer_preset
from ladderworks.core.plc.memory import Memory
from ladderworks.core.plc.runner import RealTimeRunner, ScanStats
from ladderworks.core.plc.trace import TraceSample, TraceSampler

PUBLISH_MS = 40  # 25 snapshots a second: smooth for eyes, cheap for the scan thread

OpRef = int | tuple[int, int]
# Areas the machine and the CNC write (the program only reads them): a released force gives
# the bit back its machine value.
MACHINE_AREAS = frozenset({Area.X, Area.F})


@dataclass(frozen=True, slots=True)
class PlcStatus:
    """What the PLC control screen shows: running or not, scans and their times (ms)."""

    loaded: bool = False
    running: bool = False
    scan_count: int = 0
    now_ms: int = 0
    period_ms: int = DEFAULT_PERIOD_MS
    min_ms: float = 0.0
    avg_ms: float = 0.0
    max_ms: float = 0.0
    overruns: int = 0


@dataclass(frozen=True, slots=True)
class PlcSnapshot:
    """A consistent copy of the PLC between two scans: every area and the power flow."""

    scan_count: int = 0
    now_ms: int = 0
    areas: dict[Area, bytes] = field(default_factory=dict)
    power_flow: bytes = b""  # ST0 after each op (all 0 unless monitored)
    monitored: bool = False
    disabled: frozenset[int] = frozenset()

    def bit(self, address: Address) -> int:
        """The bit at a bit address (0 or 1)."""
        assert address.bit is not None
        return self.areas[address.area][address.byte] >> address.bit & 1

    def read(self, address: Address, width: int = 1) -> int:
        """The `width`-byte little-endian value at a byte address."""
        data = self.areas[address.area]
        return int.from_bytes(data[address.byte:address.byte + width], "little")


class _ScanFigures:
    """Min/avg/max of scans run on the virtual clock (the runner keeps its own)."""

    def __init__(self) -> None:
        self.count = 0
        self.total = 0.0
        self.low = float("inf")
        self.high = 0.0

    def add(self, seconds: float) -> None:
        self.count += 1
        self.total += seconds
        self.low = min(self.low, seconds)
        self.high = max(self.high, seconds)


class PlcSession(QObject):
    """Owns the ScanEngine of the loaded program; runs it and tells the GUI what it does."""

    program_loaded = Signal(object)
    running_changed = Signal(object)  # a bool
    status_changed = Signal(object)
    snapshot_ready = Signal(object)
    forces_changed = Signal(list)
    alarms_changed = Signal(list)

    def __init__(self, parent: QObject | None = None, *, realtime: bool = True,
                 period_ms: int = DEFAULT_PERIOD_MS, publish_ms: int = PUBLISH_MS) -> None:
        super().__init__(parent)
        self.realtime = realtime
        self.period_ms = period_ms
        self.memory = Memory()
        self.engine: ScanEngine | None = None
        self.binary: BinaryProgram | None = None
        self.program: Program | None = None  # the source of the binary, when known
        self.alarm_table = AlarmTable()
        self._alarms = ActiveAlarms(self.alarm_table)
        self._alarm_view: list[ActiveAlarm] = []
        self._runner: RealTimeRunner | None = None
        self._running = False
        self._figures = _ScanFigures()
        self._stopped_stats: ScanStats | None = None
        self._monitors = 0
        self._held: dict[Address, bool] = {}  # forced X/F bits: the machine's own value
        self._trace: TraceSampler | None = None
        self._timer = QTimer(self)
        self._timer.setInterval(publish_ms)
        self._timer.timeout.connect(self.publish)

    # -- the program ---------------------------------------------------------------------

    def load(self, binary: bytes, program: Program | None = None) -> list[Diagnostic]:
        """Load a compiled binary (the PLC stops first); the diagnostics if it is refused.
        `program` is the source it was compiled from (views use its comments), if known."""
        try:
            engine = ScanEngine(binary, period_ms=self.period_ms, memory=self.memory)
        except DiagnosticError as error:
            return list(error.diagnostics)
        self.stop()
        old = self.engine
        self.engine = engine
        self.binary = engine.program
        self.program = program
        engine.cold_start()
        engine.monitored = self._monitors > 0
        if old is not None:
            if old.trace is not None:
                engine.trace = old.trace  # a running trace goes on with the new program
            for address, value in old.force_table.forced().items():
                engine.force(address, value)  # forced bits stay; disabled elements do not
        self._figures = _ScanFigures()
        self._stopped_stats = None
        self._alarms.clear()
        self.program_loaded.emit(engine.program)
        self.forces_changed.emit(engine.forces())
        self.publish()
        return []

    def load_program(self, program: Program) -> CompileResult:
        """Compile a program and load it when it compiles."""
        result = compile_program(program)
        if result.binary is not None:
            problems = self.load(result.binary, program)
            if problems:
                return CompileResult(None, result.diagnostics + problems)
        return result

    # -- running -------------------------------------------------------------------------

    @property
    def running(self) -> bool:
        """True while the PLC program is started."""
        return self._running

    def start(self) -> bool:
        """Start scanning; False when no program is loaded."""
        if self.engine is None:
            return False
        if self._running:
            return True
        self._running = True
        if self.realtime:
            self._runner = RealTimeRunner(self.engine)
            self._runner.start()
            self._timer.start()
        self.running_changed.emit(True)
        self.publish()
        return True

    def stop(self) -> None:
        """Stop scanning (outputs Y go to 0, the safe state)."""
        if not self._running:
            return
        self._timer.stop()
        if self._runner is None and self.engine is not None:
            self.engine.stop()
        if self._runner is not None:
            self._runner.stop()
            self._stopped_stats = self._runner.stats()
            self._runner = None
        self._running = False
        self.running_changed.emit(False)
        self.publish()

    def run_scans(self, count: int) -> int:
        """Run `count` scans on the virtual clock (only while started), then publish."""
        engine = self.engine
        if engine is None or not self._running or self._runner is not None:
            return 0
        for _ in range(count):
            began = time.perf_counter()
            engine.scan()
            self._figures.add(time.perf_counter() - began)
        self._update_alarms(engine)
        self.publish()
        return count

    def step(self, ms: int) -> int:
        """Advance the virtual clock by `ms` (one scan per period); returns the scans run."""
        engine = self.engine
        if engine is None or not self._running or self._runner is not None:
            return 0
        count = -(-ms // engine.period_ms)
        return self.run_scans(count)

    def status(self) -> PlcStatus:
        """The figures now."""
        engine = self.engine
        if engine is None:
            return PlcStatus(period_ms=self.period_ms)
        runner = self._runner
        if runner is not None:
            s = runner.stats()
            low, avg, high, overruns = s.min_ms, s.avg_ms, s.max_ms, s.overruns
        elif self._stopped_stats is not None:
            s = self._stopped_stats
            low, avg, high, overruns = s.min_ms, s.avg_ms, s.max_ms, s.overruns
        else:
            f = self._figures
            low = f.low * 1e3 if f.count else 0.0
            avg = f.total / f.count * 1e3 if f.count else 0.0
            high, overruns = f.high * 1e3, 0
        return PlcStatus(True, self._running, engine.scan_count, engine.now_ms,
                         engine.period_ms, low, avg, high, overruns)

    def snapshot(self) -> PlcSnapshot:
        """A copy of memory and power flow taken between two scans."""
        engine = self.engine
        if engine is None:
            return PlcSnapshot(areas=self.memory.snapshot())
        with engine.lock:
            return PlcSnapshot(engine.scan_count, engine.now_ms, self.memory.snapshot(),
                               bytes(engine.power_flow), engine.monitored,
                               engine.force_table.disabled)

    def publish(self) -> None:
        """Emit the status and a snapshot now (the timer calls this while running)."""
        snap = self.snapshot()
        if self._runner is not None and self.engine is not None:
            self._update_alarms(self.engine)
        self.status_changed.emit(self.status())
        self.snapshot_ready.emit(snap)

    def monitor(self, on: bool) -> None:
        """A view starts (True) or stops (False) needing the power flow of every op."""
        self._monitors = max(0, self._monitors + (1 if on else -1))
        if self.engine is not None:
            self.engine.monitored = self._monitors > 0

    # -- memory as the machine sees it -----------------------------------------------------

    def _lock(self) -> AbstractContextManager[object]:
        return self.engine.lock if self.engine is not None else nullcontext()

    def set_bit(self, address: Address, value: bool | int) -> None:
        """Set a bit (e.g. a switch input X2.1) between two scans; on a forced bit the force
        wins and the value is what the bit goes back to when the force is released."""
        with self._lock():
            if address in self._held:
                self._held[address] = bool(value)
            else:
                self.memory.set_bit(address, value)
        if not self._running:
            self.publish()

    def write(self, address: Address, value: int, width: int = 1) -> None:
        """Store a value of `width` bytes at a byte address between two scans."""
        with self._lock():
            self.memory.write(address, value, width)
        if not self._running:
            self.publish()

    def bit(self, address: Address) -> int:
        """The bit at a bit address now."""
        with self._lock():
            return self.memory.bit(address)

    def read(self, address: Address, width: int = 1) -> int:
        """The `width`-byte value at a byte address now."""
        with self._lock():
            return self.memory.read(address, width)

    # -- forcing and disabling -----------------------------------------------------------

    def _forces_changed(self) -> None:
        self.forces_changed.emit(self.forces())
        if not self._running:
            self.publish()

    def force(self, address: Address, value: bool | int) -> None:
        """Hold a bit at 0 or 1 before and after the logic of every scan."""
        if self.engine is None:
            return
        with self.engine.lock:
            if address.area in MACHINE_AREAS and address not in self._held:
                self._held[address] = bool(self.memory.bit(address))
            self.engine.force(address, value)
            self.engine.force_table.apply(self.memory)
        self._forces_changed()

    def release(self, address: Address) -> bool:
        """Stop forcing a bit."""
        done = False
        if self.engine is not None:
            with self.engine.lock:
                done = self.engine.release(address)
                if address in self._held:
                    self.memory.set_bit(address, self._held.pop(address))
        self._forces_changed()
        return done

    def disable(self, op: OpRef) -> int:
        """Make an element passive (PASİF) from the next scan; its op index."""
        assert self.engine is not None
        index = self.engine.disable(op)
        self._forces_changed()
        return index

    def enable(self, op: OpRef) -> int:
        """Make a passive element act again."""
        assert self.engine is not None
        index = self.engine.enable(op)
        self._forces_changed()
        return index

    def release_all(self) -> None:
        """Release every force and enable every element."""
        if self.engine is not None:
            with self.engine.lock:
                self.engine.release_all()
                for address, value in self._held.items():
                    self.memory.set_bit(address, value)
                self._held.clear()
        self._forces_changed()

    def forces(self) -> list[ForceEntry]:
        """Everything forced or disabled."""
        return self.engine.forces() if self.engine is not None else []

    # -- tracing -------------------------------------------------------------------------

    def start_trace(self, addresses: Iterable[Address], period_ms: int,
                    widths: list[int] | None = None) -> TraceSampler | None:
        """Sample addresses every `period_ms` inside the scan loop (ring buffer)."""
        if self.engine is None:
            return None
        self._trace = self.engine.start_trace(addresses, period_ms, widths=widths)
        return self._trace

    def stop_trace(self) -> None:
        """Stop sampling (samples not taken yet stay available until taken)."""
        if self.engine is not None:
            self.engine.stop_trace()

    def trace_samples(self) -> list[TraceSample]:
        """Samples not taken yet, oldest first."""
        return self._trace.take() if self._trace is not None else []

    # -- tables and alarms ---------------------------------------------------------------

    def timer_preset(self, number: int) -> int:
        """TMR `number`'s preset (ms) from the T table."""
        with self._lock():
            return read_timer_preset(self.memory, number)

    def set_timer_preset(self, number: int, ms: int) -> None:
        """Change TMR `number`'s preset (ms) in the T table."""
        with self._lock():
            write_timer_preset(self.memory, number, ms)
        if not self._running:
            self.publish()

    def counter(self, number: int) -> tuple[int, int]:
        """CTR `number`'s (preset, current value) from the C table."""
        with self._lock():
            return (self.memory.read(counter_preset_address(number), 2),
                    self.memory.read(counter_value_address(number), 2))

    def set_counter_preset(self, number: int, preset: int) -> None:
        """Change CTR `number`'s preset in the C table."""
        with self._lock():
            write_counter_preset(self.memory, number, preset)
        if not self._running:
            self.publish()

    def set_alarm_table(self, table: AlarmTable) -> None:
        """Use these alarm message texts (AlarmMsg.dat)."""
        self.alarm_table = table
        self._alarms.table = table

    def alarms(self) -> list[ActiveAlarm]:
        """The active alarm list, newest first."""
        return self._alarms.alarms

    def reset_alarms(self) -> None:
        """The reset key: alarms whose bit dropped leave the list."""
        self._alarms.reset()
        self._emit_alarms()

    def _update_alarms(self, engine: ScanEngine) -> None:
        """Feed the alarm list every A-area change the engine logged, at its scan's time."""
        changes = engine.take_alarm_changes()
        for now_ms, a_bytes in changes:
            self._alarms.update(a_bytes, now_ms)
        if changes:
            self._emit_alarms()

    def _emit_alarms(self) -> None:
        self._alarm_view = self._alarms.alarms
        self.alarms_changed.emit(list(self._alarm_view))

