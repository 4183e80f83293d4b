"""PlcSession: the Qt adapter of the core's `PlcRun` — one PLC run from the GUI, with signals.

What the run holds is read from the run itself: `session.run` is the `PlcRun` (its `engine`,
`binary`, `program`, `memory`, `running`, `status()`, `snapshot()`, `bit()`, `read()`,
`forces()`, `parameters`, `timers`, `timer_preset()`, `counter()`, `alarms()`, the trace, the
monitoring count; the policy — cold start, machine inputs, held bits, forces and trace over a
reload, PMC parameters, scan figures — is all there). This adapter keeps only what a dock must
hear about: each operation here changes the run and emits the signal that says so —
`program_loaded(BinaryProgram)`, `running_changed(bool)`, `status_changed(PlcStatus)`,
`snapshot_ready(PlcSnapshot)`, `forces_changed(list[ForceEntry])`,
`alarms_changed(list[ActiveAlarm])`, `parameters_changed(PmcParameters)`,
`symbols_changed(SymbolTable | None)` — and the publish timer.

With `realtime=True` `start()` runs the core's RealTimeRunner (a thread scanning at the period
on the wall clock) and a QTimer publishes every `publish_ms`, reading a snapshot under the
engine's lock. With `realtime=False` nothing runs by itself: `step(ms)` / `run_scans(n)` scan
on the virtual clock and publish at once, so tests get the same signals without a thread.
"""

from __future__ import annotations

from PySide6.QtCore import QObject, Qt, QTimer, Signal
from PySide6.QtGui import QGuiApplication

from ladderworks.core.address import Address
from ladderworks.core.compiler import CompileResult
from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.il.program import Program
from ladderworks.core.plc.engine import DEFAULT_PERIOD_MS
from ladderworks.core.plc.functions.counters import counter_preset_address
from ladderworks.core.plc.parameters import PmcParameters
from ladderworks.core.plc.session import (
    MACHINE_AREAS,
    OpRef,
    PlcRun,
    PlcSnapshot,
    PlcStatus,
    compile_and_load,
)
from ladderworks.core.symbols import SymbolTable

__all__ = ["MACHINE_AREAS", "PUBLISH_MS", "PlcSession", "PlcSnapshot", "PlcStatus"]

PUBLISH_MS = 40  # 25 snapshots a second: smooth for eyes, cheap for the scan thread


class PlcSession(QObject):
    """The Qt face of a `PlcRun`: a publish timer while the thread scans, and signals."""

    program_loaded = Signal(object)
    running_changed = Signal(object)  # a bool
    status_changed = Signal(object)
    snapshot_ready = Signal(object)
    forces_changed = Signal(list)
    alarms_changed = Signal(list)
    parameters_changed = Signal(object)  # the PmcParameters now
    symbols_changed = Signal(object)  # the open program's SymbolTable, or None
    family_changed = Signal(str)  # the dialect whose words the docks show (`family`)

    def __init__(self, parent: QObject | None = None, *, realtime: bool = True,
                 period_ms: int = DEFAULT_PERIOD_MS, publish_ms: int = PUBLISH_MS,
                 scan_process: bool = True) -> None:
        super().__init__(parent)
        # real time: the scans run in a process of their own (core/plc/scan_process.py)
        self.run = PlcRun(realtime=realtime, period_ms=period_ms, scan_process=scan_process)
        self._timer = QTimer(self)
        self._timer.setInterval(publish_ms)
        self._timer.timeout.connect(self.publish)
        self.symbols: SymbolTable | None = None
        # (dialect, file) of the program loaded: a load from elsewhere asks about the forces
        self.loaded_origin: tuple[str, str] | None = None
        self.console_dialect = "seed"  # the dialect of the program the console shows

    # -- the program ---------------------------------------------------------------------

    def load(self, binary: bytes, program: Program | None = None, *,
             origin: tuple[str, str] | None = None, keep_forces: bool = True
             ) -> list[Diagnostic]:
        """Load a compiled binary (the PLC stops first); the diagnostics if it is refused.
        `program` is the source it was compiled from (views use its comments), if known;
        `origin` its (dialect, file); `keep_forces` False releases the old program's forces."""
        was_running = self.run.running
        # a native scan's first compile of a large program takes seconds (docs/engine.md)
        busy = self.run.backend == "native" and QGuiApplication.instance() is not None
        if busy:
            QGuiApplication.setOverrideCursor(Qt.CursorShape.WaitCursor)
        try:
            problems = self.run.load(binary, program)
        finally:
            if busy:
                QGuiApplication.restoreOverrideCursor()
        if problems:
            return problems
        self.loaded_origin = origin
        if not keep_forces:
            self.run.release_all()
        if was_running:
            self._stopped()
        assert self.run.binary is not None
        self.run.prepare()  # the scan process builds it while the user looks (START waits less)
        self.program_loaded.emit(self.run.binary)
        self.family_changed.emit(self.family)
        self.forces_changed.emit(self.run.forces())
        self.publish()
        return []

    @property
    def family(self) -> str:
        """The dialect whose devices the docks' examples and texts name: the PLC's program's
        once one is loaded, else the one the console shows."""
        return self.run.program_dialect if self.run.binary is not None else self.console_dialect

    def set_console_dialect(self, dialect: str) -> None:
        """The console shows a program of `dialect` (File › Open, New)."""
        self.console_dialect = dialect
        self.family_changed.emit(self.family)

    def load_program(self, program: Program) -> CompileResult:
        """Compile a program and load it when it compiles (with this adapter's signals)."""
        return compile_and_load(program, self.load)

    # -- running -------------------------------------------------------------------------

    def start(self) -> bool:
        """Start scanning; False when no program is loaded."""
        was_running = self.run.running
        if not self.run.start():
            return False
        if not was_running:
            if self.run.threaded:
                self._timer.start()
            self.running_changed.emit(True)
            self.publish()
        return True

    def stop(self) -> None:
        """Stop scanning (outputs Y go to 0, the safe state)."""
        if self.run.stop():
            self._stopped()

    def close(self) -> None:
        """Stop, and end the scan process (the window closes or the program quits)."""
        self.stop()
        self.run.close()

    def _stopped(self) -> None:
        self._timer.stop()
        self.running_changed.emit(False)
        self.publish()

    def run_scans(self, count: int) -> int:
        """Run `count` scans on the virtual clock (only while started), then publish."""
        done = self.run.run_scans(count)
        if done:
            self._update_alarms()
            self.publish()
        return done

    def step(self, ms: int) -> int:
        """Advance the virtual clock by `ms` (one scan per period); returns the scans run."""
        engine = self.run.engine
        if engine is None:
            return 0
        return self.run_scans(-(-ms // engine.period_ms)) if ms > 0 else 0

    def publish(self) -> None:
        """Emit the status and a snapshot now (the timer calls this while running)."""
        snap = self.run.snapshot()
        if self.run.threaded:
            self._update_alarms()
        status = self.run.status()  # a scan process gone stops the PLC (PlcRun.status)
        self.status_changed.emit(status)
        self.snapshot_ready.emit(snap)
        if self._timer.isActive() and not status.running:
            self._timer.stop()
            self.running_changed.emit(False)

    def _publish_if_stopped(self) -> None:
        if not self.run.running:
            self.publish()

    # -- memory as the machine sees it -----------------------------------------------------

    def set_bit(self, address: Address, value: bool | int) -> None:
        """Set a bit (e.g. a switch input X2.1) between two scans; on a forced bit the force
        wins and the value is what the bit goes back to when the force is released."""
        self.run.set_bit(address, value)
        self._publish_if_stopped()

    def write(self, address: Address, value: int, width: int = 1) -> None:
        """Store a value of `width` bytes at a byte address between two scans."""
        self.run.write(address, value, width)
        self._publish_if_stopped()

    # -- forcing and disabling -----------------------------------------------------------

    def _forces_changed(self) -> None:
        self.forces_changed.emit(self.run.forces())
        self._publish_if_stopped()

    def force(self, address: Address, value: bool | int) -> None:
        """Hold a bit at 0 or 1 before and after the logic of every scan."""
        if self.run.force(address, value):
            self._forces_changed()

    def release(self, address: Address) -> bool:
        """Stop forcing a bit."""
        done = self.run.release(address)
        self._forces_changed()
        return done

    def disable(self, op: OpRef) -> int:
        """Make an element passive (PASİF) from the next scan; its op index."""
        index = self.run.disable(op)
        self._forces_changed()
        return index

    def enable(self, op: OpRef) -> int:
        """Make a passive element act again."""
        index = self.run.enable(op)
        self._forces_changed()
        return index

    def release_all(self) -> None:
        """Release every force and enable every element."""
        self.run.release_all()
        self._forces_changed()

    # -- tracing -------------------------------------------------------------------------

    # -- PMC parameters (tables) ---------------------------------------------------------

    def set_parameter(self, address: Address, value: int, width: int = 1) -> None:
        """Set a T/C/K/D value as a PMC parameter (saved with the program)."""
        self.run.set_parameter(address, value, width)
        self.parameters_changed.emit(self.run.parameters)
        self._publish_if_stopped()

    def set_parameters(self, parameters: PmcParameters) -> None:
        """Use these parameters (a program opened): T, C, K, D = defaults + these values."""
        self.run.set_parameters(parameters)
        self.parameters_changed.emit(self.run.parameters)
        self.publish()

    def set_timer_preset(self, number: int, value: int) -> None:
        """Change TMR `number`'s preset in the T table (a PMC parameter)."""
        layout = self.run.timers
        self.set_parameter(layout.preset_address(number), value, layout.width)

    def set_counter_preset(self, number: int, preset: int) -> None:
        """Change CTR `number`'s preset in the C table (a PMC parameter)."""
        self.set_parameter(counter_preset_address(number), preset, 2)

    # -- symbols -------------------------------------------------------------------------

    def set_symbols(self, symbols: SymbolTable | None) -> None:
        """The open program's symbols: the docks name addresses with them from now on."""
        self.symbols = symbols
        self.symbols_changed.emit(symbols)

    # -- alarms --------------------------------------------------------------------------

    def reset_alarms(self) -> None:
        """The reset key: alarms whose bit dropped leave the list."""
        self.run.reset_alarms()
        self._emit_alarms()

    def _update_alarms(self) -> None:
        if self.run.update_alarms():
            self._emit_alarms()

    def _emit_alarms(self) -> None:
        self.alarms_changed.emit(list(self.run.alarms()))
