"""PlcRun: the session policy of one simulated PLC, shared by the CLI, scenarios and the GUI.

The policy, in one place:

- The memory image belongs to the run, not to a program: X/F (machine inputs) and the K/D/T/C
  tables survive loading a new program; a load is a cold start (Y, G, R, A and every
  timer/counter/edge state cleared), then the PMC parameters are written over the tables.
- Forced bits stay forced across a load; disabled elements are enabled again (their op
  numbers belong to the old program); a running trace goes on with the new program.
- A forced X/F bit is *held*: the machine side's writes are kept aside and the bit gets its
  machine value back when the force is released.
- Scan figures: the real-time runner's own, or min/avg/max of scans run on the virtual clock.

`PlcRun` has no Qt: the GUI's `PlcSession` only adds a publish timer and signals.
"""

from __future__ import annotations

import time
from collections.abc import Callable, Iterable
from contextlib import AbstractContextManager, nullcontext

from ladderworks.core.address import Address, Area
from ladderworks.core.alarms import ActiveAlarm, ActiveAlarms, AlarmTable
from ladderworks.core.compiler import CompileResult, compile_program
from ladderworks.core.compiler.binary import BinaryProgram
from ladderworks.core.compiler.skipped import SkippedInstruction, skipped, skipped_ops
from ladderworks.core.diagnostics import Diagnostic, DiagnosticError
from ladderworks.core.dialects.fatek.ascii_format import AsciiFormat
from ladderworks.core.dialects.fatek.terminal import AsciiTerminal
from ladderworks.core.il.program import Program
from ladderworks.core.plc.engine import DEFAULT_PERIOD_MS, ScanEngine, load_binary
from ladderworks.core.plc.forcing import ForceEntry
from ladderworks.core.plc.functions.counters import (
    counter_preset_address,
    counter_value_address,
)
from ladderworks.core.plc.functions.fatek_io import ASCII_FILES, ASCII_TERMINAL
from ladderworks.core.plc.memory import Memory
from ladderworks.core.plc.parameters import PARAMETER_AREAS, PmcParameters
from ladderworks.core.plc.plc_status import PlcSnapshot, PlcStatus, ScanFigures
from ladderworks.core.plc.process_runner import ProcessRunner, ProcessSlot, ScanProcessError
from ladderworks.core.plc.runner import RealTimeRunner, ScanStats
from ladderworks.core.plc.scan_state import ScanLock
from ladderworks.core.plc.timer_table import TimerLayout, dialect_of, timer_layout
from ladderworks.core.plc.trace import TraceSample, TraceSampler

__all__ = ["MACHINE_AREAS", "OpRef", "PlcRun", "PlcSnapshot", "PlcStatus", "compile_and_load"]

OpRef = int | tuple[int, int]
# Areas the machine and the CNC write (the program only reads them): a released force gives
# the bit back its machine value.
MACHINE_AREAS = frozenset({Area.X, Area.F})


def compile_and_load(program: Program,
                     load: Callable[[bytes, Program], list[Diagnostic]]) -> CompileResult:
    """Compile `program` and, when it compiles, `load` it; load problems refuse the result."""
    result = compile_program(program)
    if result.binary is not None:
        problems = load(result.binary, program)
        if problems:
            return CompileResult(None, result.diagnostics + problems)
    return result


class PlcRun:
    """One PLC: the loaded program's engine, its memory, forces, trace, alarms and parameters."""

    def __init__(self, *, realtime: bool = False, period_ms: int = DEFAULT_PERIOD_MS,
                 divisions: int = 1, every_scan: bool = False,
                 scan_process: bool = False, backend: str = "python") -> None:
        self.realtime = realtime  # start() runs a wall-clock thread; else the virtual clock
        # real-time scans run in a process of their own (core/plc/scan_process.py), unless
        # time travel keeps the history; else on a thread of this process
        self.scan_process = scan_process
        self.process_error = ""  # why the last start scans here after all ("" when it did not)
        self._slot = ProcessSlot()
        self._handover = False  # the thread scans until the scan process has built the program
        self._data: bytes | None = None  # the loaded binary as given (the process builds it)
        self._lock = ScanLock()  # every engine's lock: a scan process's lock joins it
        self.every_scan = every_scan  # `advance` skips no scan (ScanEngine.every_scan)
        # the scan's code, "python" or "native" (llvmlite; docs/engine.md): each engine loaded
        # asks for it, and says in `backend_reason` why the Python scan runs if it does
        self.backend = backend
        self.period_ms = period_ms
        self.divisions = divisions  # level 2 and 3 run every `divisions` scans (docs/engine.md)
        self.memory = Memory()
        self.engine: ScanEngine | None = None
        self.binary: BinaryProgram | None = None
        self.program: Program | None = None  # the source of the binary, when known
        self.skipped: list[SkippedInstruction] = []  # the loaded program's, not simulated
        self.parameters = PmcParameters()
        self.alarm_table = AlarmTable()
        self.ascii_terminal = AsciiTerminal()  # what a Fatek FUN 94 ASCWR sends to Port 1
        # a Fatek program's ASCII files by S (core/dialects/fatek/ascii_files.py)
        self.ascii_files: dict[Address, AsciiFormat | None] = {}
        self.trace: TraceSampler | None = None
        self._alarms = ActiveAlarms(self.alarm_table)
        self._runner: RealTimeRunner | ProcessRunner | None = None
        self._running = False
        self._figures = ScanFigures()
        self._stopped_stats: ScanStats | None = None
        self._monitors = 0
        self._held: dict[Address, bool] = {}  # forced X/F bits: the machine's own value
        # told of every input change from outside: (kind, address, value, width), kind being
        # "set", "write", "force" or "release" (the scenario recorder listens here)
        self.input_listeners: list[Callable[[str, Address, int, int], None]] = []

    # -- the program ---------------------------------------------------------------------

    def use_ascii_files(self, files: dict[Address, AsciiFormat | None]) -> None:
        """The ASCII files FUN 94 sends (a Fatek program's, read beside it); kept across loads."""
        self.ascii_files.clear()
        self.ascii_files.update(files)
        self._slot.send_files(files)

    def load(self, binary: bytes | BinaryProgram,
             program: Program | None = None) -> list[Diagnostic]:
        """Load a binary (stops first): cold start, then the parameters; [] when loaded."""
        try:
            decoded = binary if isinstance(binary, BinaryProgram) else load_binary(binary)
        except DiagnosticError as error:
            return list(error.diagnostics)  # refused: the PLC runs on
        # stopped first: a scan process holds memory's areas until it stops, and the new
        # engine's code binds them
        self.stop()
        # monitored from the start when a view monitors: one variant generated, not two
        engine = ScanEngine(decoded, period_ms=self.period_ms, memory=self.memory,
                            divisions=self.divisions, monitored=self._monitors > 0,
                            backend=self.backend)
        old = self.engine
        self.engine = engine
        engine.lock = self._lock
        engine.on_setup = self._setup_changed
        self._data = binary if isinstance(binary, bytes) else None
        self.binary = engine.program
        self.program = program
        # the instructions the scan passes by (not simulated): the IDE marks them, the PLC
        # control screen and the CLI list them
        self.skipped = skipped(program) if program is not None else skipped_ops(engine.program)
        engine.extra[ASCII_TERMINAL] = self.ascii_terminal  # a Fatek program's FUN 94 output
        engine.extra[ASCII_FILES] = self.ascii_files
        engine.cold_start()
        engine.every_scan = self.every_scan
        self.parameters.apply(self.memory)
        engine.monitored = self._monitors > 0
        if old is not None:
            if old.trace is not None:
                engine.trace = old.trace  # a running trace goes on with the new program
            for address, value in old.force_table.forced().items():
                engine.force(address, value)  # forced bits stay; disabled elements do not
        self._figures = ScanFigures()
        self._stopped_stats = None
        self._alarms.clear()
        self._slot.build(engine, self._data, self.ascii_files)  # while the user looks
        return []

    def load_program(self, program: Program) -> CompileResult:
        """Compile a program and load it when it compiles."""
        return compile_and_load(program, self.load)

    @property
    def dialect(self) -> str:
        """The loaded program's dialect ("seed" before a load)."""
        return dialect_of(self.program if self.program is not None else self.binary)

    @property
    def program_dialect(self) -> str:
        """The loaded program's own dialect, as Program.dialect says it ("delta" for a Delta
        program; `dialect` is its timer-table layout): how its addresses are spelled."""
        name = getattr(self.program if self.program is not None else self.binary, "dialect",
                       "seed")
        return name if isinstance(name, str) else "seed"

    # -- running -------------------------------------------------------------------------

    @property
    def running(self) -> bool:
        """True while the PLC program is started."""
        return self._running

    @property
    def threaded(self) -> bool:
        """True while the real-time runner's thread scans."""
        return self._runner is not None

    def due_in(self) -> float | None:
        """Seconds until the real-time thread's next scan (None when no thread scans)."""
        return None if self._runner is None else self._runner.due_in()

    def start(self) -> bool:
        """Start scanning (a thread when real-time); False when no program is loaded."""
        if self.engine is None:
            return False
        if not self._running:
            self._running = True
            if self.realtime:  # on a thread until the scan process has built the program
                runner = self._process_runner(wait=False)
                self._handover = runner is None and self._process_wanted()
                self._runner = runner or RealTimeRunner(self.engine)
                self._runner.start()
        return True

    def _process_wanted(self) -> bool:
        """True when the scans belong in the scan process (and nothing went wrong there)."""
        engine = self.engine
        return (self.scan_process and self.realtime and engine is not None
                and engine.history is None and not self.process_error)

    def _hand_over(self) -> None:
        """The scan process has built the program: the scans move there from the thread,
        between two scans (the state goes with them, as at STOP and START)."""
        if not self._handover or not isinstance(self._runner, RealTimeRunner):
            return
        runner = self._process_runner(wait=False) if self._process_wanted() else None
        if runner is None:
            self._handover = self._process_wanted()  # still building; else stays here
            return
        self._handover = False
        self._runner.stop(safe=False)
        self._runner = runner
        runner.start()

    def prepare(self) -> None:
        """Start the scan process and build the loaded program there, in the background (a
        real program takes seconds; the scans run on a thread of this process meanwhile)."""
        self._process_runner(wait=False)

    def _process_runner(self, wait: bool = True) -> ProcessRunner | None:
        """A runner in the scan process (started and built when needed); None to scan here."""
        engine = self.engine
        self.process_error = ""
        if engine is None or not self._process_wanted():
            return None
        try:
            return self._slot.runner(self, engine, self._data, self.ascii_files, self._lock,
                                     wait)
        except (OSError, ScanProcessError) as error:
            self.process_error = str(error)
            return None

    def _setup_changed(self) -> None:
        """Forces, disabled elements, monitoring, trace or history changed on the engine."""
        runner, engine = self._runner, self.engine
        if not isinstance(runner, ProcessRunner) or engine is None:
            return
        if engine.history is None:
            runner.send_setup()
            return
        runner.stop(safe=False)  # time travel records every scan: they run here from now
        self._runner = RealTimeRunner(engine)
        self._runner.start()

    def close(self) -> None:
        """End the scan process (the IDE closes): the PLC stops first."""
        self.stop()
        self._slot.close()

    def stop(self) -> bool:
        """Stop scanning (outputs Y go to 0, the safe state); False if it was not running."""
        self._handover = False
        if not self._running:
            return False
        if self._runner is None and self.engine is not None:
            self.engine.stop()
        if self._runner is not None:
            self._runner.stop()
            self._stopped_stats = self._runner.stats()
            if isinstance(self._runner, ProcessRunner) and self._runner.error:
                self.process_error = self._runner.error
            self._runner = None
        self._running = False
        return True

    def run_scans(self, count: int) -> int:
        """Run `count` scans on the virtual clock (only while started and not threaded)."""
        engine = self.engine
        if engine is None or not self._running or self._runner is not None:
            return 0
        for _ in range(count):
            began = time.perf_counter()
            engine.scan()
            self._figures.add(time.perf_counter() - began)
        return count

    def step(self, ms: int) -> int:
        """Advance the virtual clock by `ms` (one scan per period); returns the scans run."""
        engine = self.engine
        if engine is None or not self._running or self._runner is not None:
            return 0
        return self.advance(engine.now_ms + ms)

    def advance(self, limit_ms: int, until: Callable[[], bool] | None = None) -> int:
        """The scans due before `limit_ms` on the virtual clock, stopping after one at which
        `until()` holds (ScanEngine.advance: a repeating state's scans skipped unless
        `every_scan`); the scans done, 0 when not started or real-time."""
        engine = self.engine
        if engine is None or not self._running or self._runner is not None:
            return 0
        began, skipped = time.perf_counter(), engine.skipped
        count = engine.advance(limit_ms, until)
        ran = count - (engine.skipped - skipped)
        if ran:
            self._figures.add((time.perf_counter() - began) / ran)
        return count

    def status(self) -> PlcStatus:
        """The figures now."""
        engine = self.engine
        if engine is None:
            return PlcStatus(period_ms=self.period_ms)
        self._hand_over()
        if isinstance(self._runner, ProcessRunner) and self._runner.lost:
            self.stop()  # the safe state; the PLC control shows why (process_error)
        if isinstance(self._runner, ProcessRunner):
            with self._lock.local:
                self._runner.sync()
        stats = self._runner.stats() if self._runner is not None else self._stopped_stats
        if stats is not None:
            low, avg, high, overruns = stats.min_ms, stats.avg_ms, stats.max_ms, stats.overruns
        else:
            f = self._figures
            low = f.low * 1e3 if f.count else 0.0
            avg = f.total / f.count * 1e3 if f.count else 0.0
            high, overruns = f.high * 1e3, 0
        scanner = ("process" if isinstance(self._runner, ProcessRunner) else
                   "thread" if self._runner is not None else "")
        return PlcStatus(True, self._running, engine.scan_count, engine.now_ms,
                         engine.period_ms, low, avg, high, overruns, scanner,
                         self.process_error, engine.backend_used,
                         engine.backend_reason or "")

    def snapshot(self) -> PlcSnapshot:
        """A copy of memory and power flow taken between two scans."""
        engine = self.engine
        if engine is None:
            return PlcSnapshot(areas=self.memory.snapshot(), byteorder=self.memory.byteorder)
        self._hand_over()
        if isinstance(self._runner, ProcessRunner):
            return self._runner.snapshot()
        with engine.lock:
            return PlcSnapshot(engine.scan_count, engine.now_ms, self.memory.snapshot(),
                               bytes(engine.power_flow), engine.monitored,
                               engine.force_table.disabled, self.memory.byteorder)

    def monitor(self, on: bool) -> None:
        """A view starts (True) or stops (False) needing the power flow of every op."""
        self._monitors = max(0, self._monitors + (1 if on else -1))
        if self.engine is not None:
            self.engine.monitored = self._monitors > 0

    # -- memory as the machine sees it -----------------------------------------------------

    def _told(self, kind: str, address: Address, value: int, width: int = 1) -> None:
        for listener in self.input_listeners:
            listener(kind, address, value, width)

    def lock(self) -> AbstractContextManager[object]:
        """The engine's lock (nothing to lock before a load)."""
        return self._lock if self.engine is not None else nullcontext()

    def set_bit(self, address: Address, value: bool | int) -> None:
        """Set a bit between two scans; on a held (forced X/F) bit, what it goes back to."""
        with self.lock():
            if address in self._held:
                self._held[address] = bool(value)
            else:
                self.memory.set_bit(address, value)
            self._told("set", address, int(bool(value)))

    def write(self, address: Address, value: int, width: int = 1) -> None:
        """Store a value of `width` bytes at a byte address between two scans."""
        with self.lock():
            self.memory.write(address, value, width)
            self._told("write", address, value, width)

    def bit(self, address: Address) -> int:
        """The bit at a bit address now."""
        with self.lock():
            return self.memory.bit(address)

    def read(self, address: Address, width: int = 1) -> int:
        """The `width`-byte value at a byte address now."""
        with self.lock():
            return self.memory.read(address, width)

    # -- forcing and disabling -----------------------------------------------------------

    def force(self, address: Address, value: bool | int) -> bool:
        """Hold a bit at 0 or 1 before and after the logic of every scan; False unloaded."""
        if self.engine is None:
            return False
        with self.engine.lock:
            if address.area in MACHINE_AREAS and address not in self._held:
                self._held[address] = bool(self.memory.bit(address))
            self.engine.force(address, value)
            self.engine.force_table.apply(self.memory)
            self._told("force", address, int(bool(value)))
        return True

    def release(self, address: Address) -> bool:
        """Stop forcing a bit (a held X/F bit gets its machine value back)."""
        if self.engine is None:
            return False
        with self.engine.lock:
            done = self.engine.release(address)
            if address in self._held:
                self.memory.set_bit(address, self._held.pop(address))
            if done:
                self._told("release", address, 0)
        return done

    def disable(self, op: OpRef) -> int:
        """Make an element passive (PASİF) from the next scan; its op index."""
        assert self.engine is not None
        return self.engine.disable(op)

    def enable(self, op: OpRef) -> int:
        """Make a passive element act again."""
        assert self.engine is not None
        return self.engine.enable(op)

    def release_all(self) -> None:
        """Release every force and enable every element."""
        if self.engine is None:
            return
        with self.engine.lock:
            forced = list(self.engine.force_table.forced())
            self.engine.release_all()
            for address in forced:
                self._told("release", address, 0)
            for address, value in self._held.items():
                self.memory.set_bit(address, value)
            self._held.clear()

    def forces(self) -> list[ForceEntry]:
        """Everything forced or disabled."""
        return self.engine.forces() if self.engine is not None else []

    # -- tracing -------------------------------------------------------------------------

    def start_trace(self, addresses: Iterable[Address], period_ms: int,
                    widths: list[int] | None = None) -> TraceSampler | None:
        """Sample addresses every `period_ms` inside the scan loop (ring buffer)."""
        if self.engine is None:
            return None
        self.trace = self.engine.start_trace(addresses, period_ms, widths=widths)
        return self.trace

    def stop_trace(self) -> None:
        """Stop sampling (samples not taken yet stay available until taken)."""
        if self.engine is not None:
            self.engine.stop_trace()

    def trace_samples(self) -> list[TraceSample]:
        """Samples not taken yet, oldest first."""
        return self.trace.take() if self.trace is not None else []

    # -- PMC parameters: the T, C, K and D tables ----------------------------------------

    @property
    def timers(self) -> TimerLayout:
        """Where the loaded program's TMR presets live (by its dialect)."""
        return timer_layout(self.dialect)

    def set_parameter(self, address: Address, value: int, width: int = 1) -> None:
        """Set a PMC parameter: in memory now and in `parameters` (saved with the program)."""
        with self.lock():
            self.memory.write(address, value, width)
            self.parameters.set(address, value, width)

    def set_parameters(self, parameters: PmcParameters) -> None:
        """Use these parameters (a program opened): T, C, K, D = defaults + these values."""
        with self.lock():
            self.parameters = parameters.copy()
            self.memory.clear(*PARAMETER_AREAS)
            self.parameters.apply(self.memory)

    def timer_preset(self, number: int) -> int:
        """TMR `number`'s preset (ms in seed programs, ticks in FANUC ones)."""
        return self.read(self.timers.preset_address(number), self.timers.width)

    def set_timer_preset(self, number: int, value: int) -> None:
        """Change TMR `number`'s preset (a PMC parameter)."""
        self.set_parameter(self.timers.preset_address(number), value, self.timers.width)

    def counter(self, number: int) -> tuple[int, int]:
        """CTR `number`'s (preset, current value) from the C table."""
        return (self.read(counter_preset_address(number), 2),
                self.read(counter_value_address(number), 2))

    def set_counter_preset(self, number: int, preset: int) -> None:
        """Change CTR `number`'s preset (a PMC parameter)."""
        self.set_parameter(counter_preset_address(number), preset, 2)

    def set_counter_value(self, number: int, value: int) -> None:
        """Change CTR `number`'s current value (a PMC parameter)."""
        self.set_parameter(counter_value_address(number), value, 2)

    # -- alarms --------------------------------------------------------------------------

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

    def update_alarms(self) -> bool:
        """Feed the alarm list every A-area change the engine logged; True if any."""
        if self.engine is None:
            return False
        changes = self.engine.take_alarm_changes()
        for now_ms, a_bytes in changes:
            self._alarms.update(a_bytes, now_ms)
        return bool(changes)
