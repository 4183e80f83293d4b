"""Time travel: the engine keeps every scan; the time chart's cursor shows one in the
diagnostic view (marked as the past), "why" jumps to the scan where a bit changed."""

from __future__ import annotations

import pyqtgraph as pg
from PySide6.QtCore import QCoreApplication, QObject, Qt
from PySide6.QtGui import QAction
from PySide6.QtWidgets import QSlider

from ladderworks.core.address import Address
from ladderworks.core.compiler.binary import BinaryProgram
from ladderworks.core.plc.history import ScanHistory, Why
from ladderworks.core.plc.session import PlcSnapshot
from ladderworks.gui.docks.diagnostic import DiagnosticDock
from ladderworks.gui.docks.online import OnlineMode
from ladderworks.gui.docks.time_chart import TimeChartDock
from ladderworks.gui.live_text import set_live_text
from ladderworks.gui.plc_session import PlcSession

translate = QCoreApplication.translate
ACTION = "action_plc_time_travel"


class TimeTravel(QObject):
    """PLC › Keep scan history: a ScanHistory on the engine, shown through the diagnostic."""

    def __init__(self, session: PlcSession, diagnostic: DiagnosticDock,
                 chart: TimeChartDock | None, online: OnlineMode | None = None,
                 parent: QObject | None = None) -> None:
        super().__init__(parent)
        self.session = session
        self.diagnostic = diagnostic
        self.chart = chart
        self.history: ScanHistory | None = None
        self._said_before = False  # the diagnostic says the cursor is before the history
        self.online = online  # the console's on-line drawing, if any
        self.action = QAction(self)
        self.action.setObjectName(ACTION)
        self.action.setCheckable(True)
        self.action.toggled.connect(self.enable)
        session.program_loaded.connect(self._on_program)
        diagnostic.why_requested.connect(self.why)
        diagnostic.live_requested.connect(self._live)
        # a slider over the scans kept, under the diagnostic's search bar
        self.slider = QSlider(Qt.Orientation.Horizontal, diagnostic)
        self.slider.setObjectName("diagnosticHistorySlider")
        self.slider.hide()
        self.slider.valueChanged.connect(self.show_scan)  # set by code with signals blocked
        body_layout = diagnostic.widget().layout()
        if body_layout is not None:
            body_layout.insertWidget(1, self.slider)  # type: ignore[attr-defined]
        session.snapshot_ready.connect(self._update_slider)
        if chart is not None:  # the chart's `time_cursor` is its pg.InfiniteLine
            line: pg.InfiniteLine = chart.time_cursor
            line.sigPositionChanged.connect(lambda _line: self.show_time(line.value()))
            chart.cursor_note = self.before_history
        self.retranslate()

    def retranslate(self) -> None:
        """Texts in the UI language."""
        self.action.setText(translate("TimeTravel", "Keep scan history (time travel)"))
        self.action.setToolTip(translate(
            "TimeTravel", "Keep every scan's power flow and values: the time chart's cursor "
            "shows an earlier scan in the PLC diagnostic"))

    def enable(self, on: bool) -> None:
        """Start (True) or stop keeping the history; it needs the power flow (monitored)."""
        if on == (self.history is not None):
            return
        if on:
            self.history = ScanHistory()
            self._attach()
            self.session.run.monitor(True)
        else:
            engine = self.session.run.engine
            if engine is not None:
                with self.session.run.lock():
                    engine.history = None
            self.history = None
            self.session.run.monitor(False)
            self.diagnostic.back_to_live()
        self.diagnostic.why_button.setVisible(on)
        self.slider.setVisible(on)
        if self.action.isChecked() != on:
            self.action.setChecked(on)

    def _live(self) -> None:
        if self.online is not None:
            self.online.back_to_live()

    def _attach(self) -> None:
        engine = self.session.run.engine
        if engine is not None and self.history is not None:
            with self.session.run.lock():
                engine.history = self.history

    def _on_program(self, _binary: BinaryProgram) -> None:
        if self.history is not None:  # the scans of another program mean nothing now
            self.history = ScanHistory()
            self._attach()
            self.diagnostic.back_to_live()

    def _update_slider(self, _snapshot: object = None) -> None:
        """The slider spans the scans kept (its handle stays put while in the past)."""
        history = self.history
        if history is None or history.first_scan is None or history.last_scan is None:
            return
        self.slider.blockSignals(True)
        self.slider.setRange(history.first_scan, history.last_scan)
        if self.diagnostic.past is None:
            self.slider.setValue(history.last_scan)
        self.slider.blockSignals(False)

    def history_start(self) -> float | None:
        """The PLC time (ms) of the first scan kept, None while none is."""
        if self.history is None:
            return None
        with self.session.run.lock():
            segments = self.history.segments
            return segments[0].time_ms if segments else None

    def before_history(self, time_ms: float) -> str:
        """What the chart's readout says of a cursor before the first scan kept ("" if not)."""
        start = self.history_start()
        if start is None or time_ms >= start:
            return ""
        return translate("TimeTravel", "before the scan history, which begins at {0} ms").format(
            round(start))

    def show_time(self, time_ms: float) -> bool:
        """Show the scan run at `time_ms` (or the last one before it) as the past; a time
        before the history shows no scan (the diagnostic says so, and stays as it was)."""
        if self.history is None:
            return False
        start = self.history_start()
        if start is not None and time_ms < start:
            set_live_text(self.diagnostic.message, lambda: translate(
                "TimeTravel", "The cursor is before the scan history, which begins at {0} ms: "
                "no scan to show").format(round(start)))
            self._said_before = True
            return False
        if self._said_before:  # the cursor is back in the history: the note goes
            self._said_before = False
            self.diagnostic.message.clear()
        with self.session.run.lock():
            scan = self.history.scan_at(time_ms)
        return scan is not None and self.show_scan(scan)

    def show_scan(self, scan: int) -> bool:
        """Show a kept scan as the past (False when it is not kept)."""
        if self.history is None:
            return False
        with self.session.run.lock():
            frame = self.history.frame(scan)
        if frame is None:
            return False
        self.slider.blockSignals(True)
        self.slider.setValue(frame.scan)
        self.slider.blockSignals(False)
        snapshot = PlcSnapshot(frame.scan, frame.time_ms, frame.areas, frame.power_flow, True,
                               frozenset())
        self.diagnostic.show_past(snapshot)
        if self.online is not None:
            self.online.show_past(snapshot)
        return True

    def why(self, address: Address) -> Why | None:
        """Go to the scan where a bit last changed (up to the scan shown) and mark the
        contacts that changed it."""
        history, engine = self.history, self.session.run.engine
        if history is None or engine is None or address.bit is None:
            set_live_text(self.diagnostic.message, lambda: translate(
                "TimeTravel", "Turn on PLC › Keep scan history and give a bit address"))
            return None
        past = self.diagnostic.past
        with self.session.run.lock():
            upto = past.scan_count if past is not None else history.last_scan
            found = history.why(engine, address, upto) if upto is not None else None
        if found is None:
            set_live_text(self.diagnostic.message, lambda: translate(
                "TimeTravel", "{0} did not change in the scans kept").format(address))
            return None
        if self.chart is not None and self.chart.record.times:
            self.chart.set_cursor(found.time_ms)
        self.show_time(found.time_ms)
        self.diagnostic.mark_ops(found.contacts or found.writers)
        set_live_text(self.diagnostic.message, lambda: translate(
            "TimeTravel", "{0} went to {1} in scan {2} at {3} ms").format(
                address, found.value, found.scan, found.time_ms))
        return found
