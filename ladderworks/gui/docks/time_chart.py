"""The PLC time chart (PLC ZAMAN KARTI): bit and value history from the engine, drawn as steps.

The samples are taken inside the scan loop by the engine's trace sampler at the chosen period;
this dock only takes them from the PLC session when it publishes, keeps them in a TraceRecord
and draws each lane as a sample-and-hold step trace.
"""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pyqtgraph as pg
from PySide6.QtCore import QCoreApplication, Qt
from PySide6.QtGui import QAction, QColor, QFontMetrics, QResizeEvent
from PySide6.QtWidgets import (
    QDockWidget,
    QHBoxLayout,
    QLabel,
    QLineEdit,
    QSpinBox,
    QVBoxLayout,
    QWidget,
)

from ladderworks.core.address import AddressError
from ladderworks.core.tag_names import split_names, typed_text
from ladderworks.gui import file_dialogs
from ladderworks.gui.button_flow import ButtonFlow
from ladderworks.gui.diagnostic_texts import diagnostic_text
from ladderworks.gui.docks import snapshot_gate, trace_files
from ladderworks.gui.docks.bus_lane import BusLane
from ladderworks.gui.docks.chart_items import YieldingAxis, YieldingCurve, YieldingLocaleAxis
from ladderworks.gui.docks.snapshot_gate import SnapshotGate, UpdateBudget
from ladderworks.gui.docks.trace_record import TracedSignal, TraceRecord, parse_traced
from ladderworks.gui.family_words import chart_example, chart_hint
from ladderworks.gui.files import atomic_write
from ladderworks.gui.live_text import set_live_text
from ladderworks.gui.os_errors import os_error_text
from ladderworks.gui.plc_session import PlcSession, PlcSnapshot
from ladderworks.gui.retranslate import Retranslating
from ladderworks.gui.symbol_text import program_name

translate = QCoreApplication.translate

LANE_HEIGHT = 1.6  # a lane's trace spans 0..1 of it; the rest separates it from the next
DEFAULT_PERIOD_MS = 8
MAX_PERIOD_MS = 60_000
# least seconds between two redraws while the PLC scans in real time (snapshot_gate.PACED):
# four a second follow a running machine; each one takes the interpreter from the scan thread
REDRAW_INTERVAL = 0.25
SHORT_PLOT = 140  # px: a plot this high or higher shows the time axis's title
_COLOURS = ("#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2")


def shown(value: int, signal: TracedSignal) -> str:
    """A lane's value as its type writes it (an S7 Time `T#5s`, a Real), else the number."""
    return typed_text(value, signal.type_name, signal.width) or str(value)


class TimeChartDock(Retranslating, QDockWidget):
    """Type the bits (or `ADDR:width` values) to watch, choose the sampling time, START."""

    def __init__(self, session: PlcSession, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.setObjectName("timeChartDock")
        self.session = session
        self.record = TraceRecord()
        self.sampling = False
        self.follows = 0  # how often a redraw set the span it follows (tests)
        self.following = True  # the span follows the record (until the user zooms or pans)
        self._curves: list[pg.GraphicsObject] = []  # one step trace per lane
        self._fills: list[YieldingCurve] = []  # the shading under each bit lane
        self._buses: dict[int, BusLane] = {}  # the value lanes, by lane
        body = QWidget(self)
        layout = QVBoxLayout(body)
        layout.setContentsMargins(4, 4, 4, 4)
        entry = QHBoxLayout()
        self.signals_label = QLabel(body)
        self.signals_edit = QLineEdit(body)
        self.signals_edit.setObjectName("timeChartSignals")
        self.signals_edit.returnPressed.connect(self.start)
        self.period_label = QLabel(body)
        self.period_spin = QSpinBox(body)
        self.period_spin.setObjectName("timeChartPeriod")
        self.period_spin.setRange(1, MAX_PERIOD_MS)
        self.period_spin.setValue(DEFAULT_PERIOD_MS)
        self.period_spin.setSuffix(" ms")
        # the signals take the whole row (a list of addresses wants the width; the Turkish
        # "ÖRNEKLEME ZAMANI:" beside it left a 1024-px screen a few characters of it); the
        # sampling time goes before START, in the row of buttons that wraps
        self.signals_edit.setMinimumWidth(self.signals_edit.fontMetrics().horizontalAdvance("M")
                                          * 10)
        entry.addWidget(self.signals_label)
        entry.addWidget(self.signals_edit, 1)
        layout.addLayout(entry)
        # buttons that wrap onto a second line in a narrow dock: none hides behind an overflow
        self.toolbar = ButtonFlow(body)
        self.toolbar.setObjectName("timeChartToolbar")
        period = QWidget(self.toolbar)
        period.setObjectName("timeChartPeriodField")
        period_row = QHBoxLayout(period)
        period_row.setContentsMargins(0, 0, 0, 0)
        period_row.addWidget(self.period_label)
        period_row.addWidget(self.period_spin)
        self.toolbar.add_widget(period)
        self.toolbar.add_separator()
        self.chart_actions: dict[str, QAction] = {}
        for name, slot in (
            ("action_time_chart_start", self.start),
            ("action_time_chart_stop", self.stop),
            ("action_time_chart_clear", self.clear),
            (None, None),
            ("action_time_chart_fit", self.fit),
            ("action_time_chart_zoom_in", lambda: self.zoom(0.5)),
            ("action_time_chart_zoom_out", lambda: self.zoom(2.0)),
            (None, None),
            ("action_time_chart_csv", self.export_csv_dialog),
            ("action_time_chart_png", self.export_png_dialog),
        ):
            if name is None:
                self.toolbar.add_separator()
                continue
            action = QAction(self)
            action.setObjectName(name)
            action.triggered.connect(lambda _c=False, s=slot: s())
            self.toolbar.add_action(action)
            self.chart_actions[name] = action
        layout.addWidget(self.toolbar)
        self.message = QLabel(body)
        self.message.setObjectName("timeChartMessage")
        self.message.setWordWrap(True)
        layout.addWidget(self.message)
        # samples are taken at every snapshot; the lanes are drawn when shown, in budget
        self.gate = SnapshotGate(self, lambda _snapshot: self._redraw(), session,
                                 UpdateBudget(interval=REDRAW_INTERVAL))
        before = self.gate.yield_to_scan  # each item of the chart lets a due scan go first
        self.plot = pg.PlotWidget(body, background="w", axisItems={
            "bottom": YieldingLocaleAxis("bottom", before), "left": YieldingAxis("left", before)})
        self.plot.setObjectName("timeChartPlot")
        # a 1024×600 screen: the chart fits in a third of the height, the ladder keeps the rest
        self.plot.setMinimumHeight(70)
        self.plot.scene().contextMenu = []  # pyqtgraph's own English "Export..."; ours are above
        self.plot.setMinimumWidth(380)  # room for the lane names and a readable time axis
        item = self.plot.getPlotItem()
        item.showGrid(x=True, y=False, alpha=0.25)
        item.hideButtons()
        item.setMenuEnabled(False)
        view = item.getViewBox()
        view.setMouseEnabled(x=True, y=False)
        view.enableAutoRange(x=True, y=False)
        view.sigRangeChangedManually.connect(self._stop_following)
        for side in ("left", "bottom"):
            item.getAxis(side).setTextPen("k")
            item.getAxis(side).setPen("k")
        item.getAxis("left").setTicks([[], []])  # it names the lanes: none yet, no 0 … 1.0
        self.time_cursor = pg.InfiniteLine(angle=90, movable=True,
                                           pen=pg.mkPen("#e07000", width=1.5))
        self.time_cursor.setZValue(10)
        self.time_cursor.sigPositionChanged.connect(self._show_cursor)
        item.addItem(self.time_cursor, ignoreBounds=True)
        self.plot.scene().sigMouseClicked.connect(self._clicked)  # a click puts the cursor
        # what the readout adds about the cursor's time (time travel: before its history)
        self.cursor_note: Callable[[float], str] | None = None
        layout.addWidget(self.plot, 1)
        self.cursor_label = QLabel(body)
        self.cursor_label.setObjectName("timeChartCursor")
        self.cursor_label.setWordWrap(True)
        self.cursor_label.setTextInteractionFlags(Qt.TextInteractionFlag.TextSelectableByMouse)
        layout.addWidget(self.cursor_label)
        self.setWidget(body)
        session.snapshot_ready.connect(self._take_samples)
        self.visibilityChanged.connect(lambda _shown: self.gate.flush())
        session.program_loaded.connect(self._on_program_loaded)
        session.family_changed.connect(lambda _family: self.signals_edit.setPlaceholderText(
            chart_example(self.session.family)))
        trace_files.add_actions(self)  # LADDER-III export and trace import
        self.retranslate()
        self._update_actions()

    # -- START / STOP / CLEAR ----------------------------------------------------------------

    def parse_signals(self) -> list[TracedSignal] | None:
        """The lanes typed in the box (None and a message when one is wrong or none is given)."""
        texts = split_names(self.signals_edit.text())  # `"Lamba 1"` is one name
        if not texts:
            self.say(lambda: chart_hint(self.session.family), error=True)
            return None
        signals: list[TracedSignal] = []
        for text in texts:
            try:
                signals.append(parse_traced(text, self.session.symbols,
                                            self.session.run.program_dialect))
            except AddressError as error:
                self.say(diagnostic_text(error.diagnostic), error=True)
                return None
        return signals

    def start(self) -> bool:
        """Start sampling the typed signals at the chosen period (inside the scan loop) on a
        fresh chart."""
        signals = self.parse_signals()
        if signals is None:
            return False
        if self.session.run.engine is None:
            self.say(lambda: translate("TimeChart", "Load (compile) a PLC program first"),
                      error=True)
            return False
        period = self.period_spin.value()
        self.record = TraceRecord(signals)
        self.record.period_ms = max(period, self.session.run.engine.period_ms)
        self._make_lanes()
        self.session.run.start_trace(
            [s.address for s in signals], period, widths=[s.width for s in signals]
        )
        self.sampling = True
        self.fit()
        self.say(lambda: translate("TimeChart", "Sampling every {0} ms").format(period))
        self._update_actions()
        return True

    def stop(self) -> None:
        """Stop sampling; what was sampled stays on the chart."""
        if not self.sampling:
            return
        self.session.run.stop_trace()
        self._take_samples()
        self.sampling = False
        count = len(self.record)
        self.say(lambda: translate("TimeChart", "Stopped: {0} samples").format(count))
        self._update_actions()

    def clear(self) -> None:
        """Wipe the chart (sampling goes on if started)."""
        if self.sampling:
            self.session.run.trace_samples()  # samples taken before CLEAR are not shown
        self.record.clear()
        self._redraw()
        self._show_cursor()

    def _on_program_loaded(self, _program: object) -> None:
        if self.sampling:  # the session keeps the sampler across a reload
            self.say(lambda: translate("TimeChart", "New program loaded; sampling goes on"))

    def _take_samples(self, snapshot: object = None) -> None:
        if not self.sampling:
            return
        samples = self.session.run.trace_samples()
        if samples and len(samples[0].values) == len(self.record.signals):
            self.record.extend(samples)
            if isinstance(snapshot, PlcSnapshot):
                self.gate.offer(snapshot)
            else:  # STOP: the whole record at once
                self._redraw()

    # -- drawing -----------------------------------------------------------------------------

    def program_dialect(self) -> str | None:
        """The loaded program's dialect (its devices name the lanes)."""
        return self.session.run.program_dialect

    def lane_name(self, signal: TracedSignal) -> str:
        """The lane's label: the address and, for a named signal, its short name."""
        name = program_name(signal.address, self.session.symbols,
                            self.session.run.program_dialect)
        return f"{signal.label} {name}" if name and name != signal.label else signal.label

    def lane_base(self, lane: int) -> float:
        """The y of a lane's 0 level (the first lane on top)."""
        return (len(self.record.signals) - 1 - lane) * LANE_HEIGHT

    def _make_lanes(self) -> None:
        item = self.plot.getPlotItem()
        for curve in self._curves + self._fills:
            item.removeItem(curve)
        for bus in self._buses.values():
            bus.remove()
        self._curves = []
        self._fills = []
        self._buses = {}
        ticks = []
        for lane, signal in enumerate(self.record.signals):
            colour = QColor(_COLOURS[lane % len(_COLOURS)])
            base = self.lane_base(lane)
            if signal.is_bit:  # a shaded 1-level; its own item, so no edge is drawn at the ends
                fill = QColor(colour)
                fill.setAlpha(50)
                shade = YieldingCurve(self.gate.yield_to_scan, stepMode="center", pen=None,
                                      fillLevel=base, brush=fill)
                item.addItem(shade)
                self._fills.append(shade)
                curve = YieldingCurve(self.gate.yield_to_scan, stepMode="center",
                                      pen=pg.mkPen(colour, width=2))
                item.addItem(curve)
            else:  # a value: a bus lane with each value written in it
                bus = BusLane(item, colour, base, signal.width, signal.type_name)
                self._buses[lane] = bus
                curve = bus.outline
            self._curves.append(curve)
            ticks.append((base + 0.5, self.lane_name(signal)))
        axis = item.getAxis("left")
        axis.setTicks([ticks, []])
        metrics = QFontMetrics(axis.font() if hasattr(axis, "font") else self.font())
        widest = max((metrics.horizontalAdvance(label) for _y, label in ticks), default=20)
        axis.setWidth(widest + 16)
        count = max(len(self.record.signals), 1)
        item.getViewBox().setYRange(-0.3, (count - 1) * LANE_HEIGHT + 1.3, padding=0)
        self._redraw()

    def lane_texts(self, lane: int) -> list[tuple[float, str]]:
        """The values written in a value lane at this zoom: (start time in ms, text)."""
        bus = self._buses.get(lane)
        return [] if bus is None else bus.texts()

    def lane_points(self, lane: int) -> tuple[list[float], list[float]]:
        """A lane's step points: x (one more than y) and y offset into its lane (a value
        scaled to the lane's height)."""
        xs, values = self.record.steps(lane)
        base = self.lane_base(lane)
        signal = self.record.signals[lane]
        scale = 1 if signal.is_bit else max(max(values, default=0), 1)
        return [float(x) for x in xs], [base + value / scale for value in values]

    def _redraw(self) -> None:
        fills = iter(self._fills)
        for lane, curve in enumerate(self._curves):
            if lane in self._buses:
                steps, values = self.record.steps(lane)
                self._buses[lane].set_steps([float(x) for x in steps], values)
                continue
            xs, ys = self.lane_points(lane)
            fill = next(fills)
            if not ys:  # no sample yet (a step trace needs one x more than its values)
                curve.clear()
                fill.clear()
                continue
            # the points are numbers: pyqtgraph's check for NaN and infinity is not needed
            light = snapshot_gate.PACED
            curve.setData(xs, ys, skipFiniteCheck=light)
            fill.setData(xs, ys, skipFiniteCheck=light)
            self.gate.let_scan()  # ~1 ms a lane: a scan that is due goes first
        self._follow()
        if self.record.times and self.time_cursor.value() < self.record.times[0]:
            self.time_cursor.setValue(self.record.times[0])
        self._show_cursor()

    def _follow(self) -> None:
        """While the chart follows the record, set its new time span now: left to the view's
        auto-range, the span changes when the chart paints, and it paints twice; and the
        auto-range goes over every curve's data in each paint (~12 ms of a 25 ms paint of six
        lanes, the interpreter held from the scan thread: `snapshot_gate.SPAN_SET`)."""
        view = self.plot.getPlotItem().getViewBox()
        following = self.following if snapshot_gate.SPAN_SET else view.autoRangeEnabled()[0]
        if not (snapshot_gate.PACED and following and self.record.times):
            return
        end = self.record.end_ms or self.record.times[-1]
        view.setXRange(self.record.times[0], end, padding=0.02)
        if not snapshot_gate.SPAN_SET:
            view.enableAutoRange(x=True, y=False)  # still following: finds the span just set
        self.follows += 1

    def _stop_following(self, _axes: object = None) -> None:
        """The user zoomed or panned the chart with the mouse: it stops following."""
        self.following = False

    # -- zoom, pan, cursor -----------------------------------------------------------------

    def time_range(self) -> tuple[float, float]:
        """The time span shown (ms)."""
        low, high = self.plot.getPlotItem().getViewBox().viewRange()[0]
        return low, high

    def set_time_range(self, low: float, high: float) -> None:
        """Show the span `low`..`high` ms (zoom and pan; the chart stops following)."""
        self.following = False
        self.plot.getPlotItem().getViewBox().setXRange(low, high, padding=0)

    def zoom(self, factor: float) -> None:
        """Zoom in time about the middle (factor < 1 zooms in)."""
        low, high = self.time_range()
        middle, half = (low + high) / 2, (high - low) / 2 * factor
        self.set_time_range(middle - half, middle + half)

    def fit(self) -> None:
        """Show the whole record and follow it while sampling."""
        self.following = True
        view = self.plot.getPlotItem().getViewBox()
        if not self.record.times:
            view.enableAutoRange(x=True, y=False)
            return
        end = self.record.end_ms or self.record.times[-1]
        view.setXRange(self.record.times[0], end, padding=0.02)
        if not snapshot_gate.SPAN_SET:
            view.enableAutoRange(x=True, y=False)

    def set_cursor(self, time_ms: float) -> None:
        """Put the cursor at `time_ms`."""
        self.time_cursor.setValue(time_ms)

    def _clicked(self, event: object) -> None:
        """A left click in the chart moves the cursor to the time clicked."""
        button = getattr(event, "button", None)
        position = getattr(event, "scenePos", None)
        if button is None or position is None or button() != Qt.MouseButton.LeftButton:
            return
        view = self.plot.getPlotItem().getViewBox()
        where = position()
        if view.sceneBoundingRect().contains(where):
            self.set_cursor(view.mapSceneToView(where).x())

    def cursor_values(self) -> dict[str, int | None]:
        """Each lane's value at the cursor, by lane label (None outside the record)."""
        at = self.time_cursor.value()
        return {
            signal.label: self.record.value_at(lane, at)
            for lane, signal in enumerate(self.record.signals)
        }

    def _show_cursor(self, *_args: object) -> None:
        if not self.record.signals:
            self.cursor_label.setText("")
            self._fit_labels()
            return
        values = "   ".join(
            f"{signal.label} = {'–' if value is None else shown(value, signal)}"
            for signal, value in zip(self.record.signals, self.cursor_values().values(),
                                     strict=False)
        )
        note = self.cursor_note(self.time_cursor.value()) if self.cursor_note else ""
        self.cursor_label.setText(
            translate("TimeChart", "Cursor {0} ms:").format(round(self.time_cursor.value()))
            + "   "
            + values
            + (f"   ({note})" if note else "")
        )
        self._fit_labels()

    # -- export ------------------------------------------------------------------------------

    def export_csv(self, path: str | Path) -> bool:
        """Write the record as CSV (`time_ms,ADDR,...`, as `ladderworks-cli run --trace`)."""
        try:
            atomic_write(path, self.record.csv_text())
        except OSError as error:
            self.say(
                translate("TimeChart", "Cannot write {0}: {1}").format(path, os_error_text(error)),
                error=True,
            )
            return False
        self.say(lambda: translate("TimeChart", "Saved {0}").format(path))
        return True

    def export_png(self, path: str | Path) -> bool:
        """Save the chart as a PNG picture."""
        if not self.plot.grab().save(str(path), "PNG"):
            self.say(translate("TimeChart", "Cannot write {0}").format(path), error=True)
            return False
        self.say(lambda: translate("TimeChart", "Saved {0}").format(path))
        return True

    def export_csv_dialog(self) -> None:
        """Ask for a file and export the CSV."""
        path = file_dialogs.save_file_name(
            self,
            translate("TimeChart", "Export time chart as CSV"),
            "trace.csv",
            translate("TimeChart", "CSV files (*.csv)"),
        )
        if path:
            self.export_csv(path)

    def export_png_dialog(self) -> None:
        """Ask for a file and export the PNG."""
        path = file_dialogs.save_file_name(
            self,
            translate("TimeChart", "Export time chart as PNG"),
            "trace.png",
            translate("TimeChart", "PNG pictures (*.png)"),
        )
        if path:
            self.export_png(path)

    def show_record(self, record: TraceRecord) -> None:
        """Show a finished record (an imported file, a scenario's run) instead of live samples."""
        if self.sampling:
            self.stop()
        self.record = record
        self.signals_edit.setText(" ".join(s.label for s in record.signals))
        self._make_lanes()
        self.fit()

    # -- texts -------------------------------------------------------------------------------

    def say(self, text: str | Callable[[], str], *, error: bool = False) -> None:
        """A message above the chart; one given as a function follows a language switch."""
        self.message.setStyleSheet("color:#c00000;" if error else "")
        if callable(text):
            set_live_text(self.message, text)
        else:
            self.message.setText(text)
        self._fit_labels()

    def _fit_labels(self) -> None:
        """Reserve the height the wrapped message and cursor readout need at this width: a
        dock does not ask its labels, and a squeezed layout would draw the readout over the
        time axis."""
        for label in (self.message, self.cursor_label):
            width = label.width() or self.widget().width()
            label.setMinimumHeight(label.heightForWidth(width) if label.text() else 0)

    def resizeEvent(self, event: QResizeEvent) -> None:
        """Wrapped lines change with the width; a short chart drops its axis title."""
        super().resizeEvent(event)
        self._fit_labels()
        self._fit_axis_title()

    def _fit_axis_title(self) -> None:
        """A chart under SHORT_PLOT px (a 1024×600 screen's third) gives the lanes the
        axis title's line: its last tick says the unit instead (`900 ms`)."""
        axis = self.plot.getPlotItem().getAxis("bottom")
        titled = self.plot.height() >= SHORT_PLOT
        axis.showLabel(titled)
        if isinstance(axis, YieldingLocaleAxis):
            unit = "" if titled else translate("TimeChart", "ms")
            if unit != axis.unit:
                axis.unit = unit
                axis.picture = None  # the tick texts again
                axis.update()

    def _update_actions(self) -> None:
        self.chart_actions["action_time_chart_start"].setEnabled(not self.sampling)
        self.chart_actions["action_time_chart_stop"].setEnabled(self.sampling)
        self.signals_edit.setReadOnly(self.sampling)
        self.period_spin.setEnabled(not self.sampling)

    def retranslate(self) -> None:
        """Set the texts in the current UI language."""
        self.setWindowTitle(translate("TimeChart", "PLC time chart"))
        self.signals_label.setText(translate("TimeChart", "Signals:"))
        self.signals_edit.setPlaceholderText(chart_example(self.session.family))
        self.period_label.setText(translate("TimeChart", "Sampling time:"))
        for name, text in (
            ("action_time_chart_start", translate("TimeChart", "START")),
            ("action_time_chart_stop", translate("TimeChart", "STOP")),
            ("action_time_chart_clear", translate("TimeChart", "CLEAR")),
            ("action_time_chart_fit", translate("TimeChart", "Fit")),
            ("action_time_chart_zoom_in", translate("TimeChart", "Zoom in")),
            ("action_time_chart_zoom_out", translate("TimeChart", "Zoom out")),
            ("action_time_chart_csv", translate("TimeChart", "CSV...")),
            ("action_time_chart_png", translate("TimeChart", "PNG...")),
        ):
            self.chart_actions[name].setText(text)
        actions = self.chart_actions
        actions["action_time_chart_csv"].setToolTip(
            translate("TimeChart", "Export the samples as CSV")
        )
        actions["action_time_chart_png"].setToolTip(
            translate("TimeChart", "Save the chart as a PNG picture")
        )
        self.plot.getPlotItem().setLabel("bottom", translate("TimeChart", "time (ms)"))
        self._fit_axis_title()
        self.plot.getPlotItem().getAxis("bottom").picture = None  # ticks in the new decimal sign
        self.plot.getPlotItem().getAxis("bottom").update()
        trace_files.retranslate(self)
        self._show_cursor()
