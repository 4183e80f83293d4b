"""Which PLC snapshots a dock's update takes: none while it is hidden, and no more than keep
its share of the GUI thread small, so the real-time scan thread gets the interpreter's lock
(the GIL) when its period comes (issue 30: a hidden tables dock refreshing 1,500 D rows 25
times a second left S41_F036's scans waiting for it)."""

from __future__ import annotations

import time
from collections.abc import Callable

from PySide6.QtCore import QObject, Qt, QTimer
from PySide6.QtWidgets import QWidget

from ladderworks.core.plc.session import PlcSnapshot
from ladderworks.gui.plc_session import PlcSession

# True: the behaviour before the gate (every snapshot updates the dock, shown or not);
# benchmarks/realtime_docks.py sets it to measure before and after in one run
UPDATE_ALWAYS = False
# of the GUI thread's time that may be spent while the PLC scans in real time: the rest
# leaves the interpreter to the scan thread
SHARE = 0.25
# True: a long update waits for the gap after a scan, and a dock may ask for a least time
# between its updates (the time chart's redraws); benchmarks/realtime_docks.py flips it
PACED = True
# True: the time chart follows the record by setting its span at each redraw, without the
# view's auto-range (which goes over every curve's data in each paint); benchmarks flip it
SPAN_SET = True
# True: the time chart's and the diagnostic's items let a due scan run before each paints
# (yield_to_scan): a chart paint of six lanes takes 15-25 ms, a diagnostic network ~3 ms, and
# a scan due meanwhile waited up to 5 ms for the interpreter; benchmarks flip it
YIELD = True
# an update starts only when the real-time thread's next scan is at least this far (seconds)
QUIET = 0.003
# how often a gate looks again for the gap after a scan before it updates anyway
TRIES = 12


class UpdateBudget:
    """Lets an update run when the GUI thread's CPU time since the last one (the update, the
    repaints it caused, every other dock's work) is at most `share` of the time gone by."""

    def __init__(self, share: float | None = None,
                 clock: Callable[[], float] = time.perf_counter,
                 cpu: Callable[[], float] = time.thread_time,
                 interval: float = 0.0) -> None:
        self.share = share if share is not None else SHARE
        self.interval = interval  # least seconds between two updates (when PACED)
        self.clock = clock
        self.cpu = cpu  # this thread's CPU time: the GUI thread's, as updates run there
        self.marks: tuple[float, float] | None = None  # (clock, cpu) when the last one began

    def wait(self) -> float:
        """Seconds until an update may run (0: now)."""
        if self.marks is None:
            return 0.0
        began, busy = self.marks
        gone = self.clock() - began
        least = self.interval if PACED else 0.0
        return max(0.0, (self.cpu() - busy) / self.share - gone, least - gone)

    def run(self, update: Callable[[], None]) -> None:
        """Run `update` and start counting from it."""
        self.marks = (self.clock(), self.cpu())
        update()


class SnapshotGate(QObject):
    """Hands the session's snapshots to `update` when `widget` is shown and, while the
    real-time thread scans, the budget allows; one held back is made up for (with a new
    snapshot, never an older one over a newer state) when the budget allows or the widget is
    shown again. On the virtual clock (tests, stepping) every snapshot is shown at once."""

    def __init__(self, widget: QWidget, update: Callable[[PlcSnapshot], None],
                 session: PlcSession, budget: UpdateBudget | None = None) -> None:
        super().__init__(widget)
        self.widget = widget
        self.update = update
        self.session = session
        self.budget = budget if budget is not None else UpdateBudget()
        self.pending = False  # a snapshot was held back
        self.updates = 0  # how many ran (tests, benchmarks)
        self.deferred = 0  # how often an update waited for the gap after a scan (tests)
        self.yields = 0  # how often a paint let a due scan go first (tests, benchmarks)
        self._tries = 0
        self._timer = QTimer(self)
        self._timer.setTimerType(Qt.TimerType.PreciseTimer)
        self._timer.setSingleShot(True)
        self._timer.timeout.connect(self.flush)

    def offer(self, snapshot: PlcSnapshot) -> None:
        """A new snapshot: shown now, later, or when the widget is shown."""
        if UPDATE_ALWAYS:
            self._run(snapshot)
            return
        self.pending = True
        if not self.widget.isVisible():
            return
        wait = self.wait()
        if wait <= 0:
            self._run(snapshot)
        elif not self._timer.isActive():
            self._timer.start(max(1, round(wait * 1000)))

    def wait(self) -> float:
        """Seconds before the next update may run: the budget's wait and, when PACED, until
        the gap after the real-time thread's next scan if that scan is due within QUIET."""
        if not self.session.run.threaded:
            return 0.0
        wait = self.budget.wait()
        if wait > 0 or not PACED or self._tries >= TRIES:
            return wait
        due = self.session.run.due_in()
        if due is None or due >= QUIET:
            return 0.0
        self._tries += 1
        self.deferred += 1
        return due + 0.0005  # just after the scan has begun: it is found running, or done

    def flush(self) -> None:
        """Make up for a snapshot held back, with the latest (when the widget is shown),
        when the budget and the scan's gap allow."""
        if not (self.pending and self.widget.isVisible()):
            return
        wait = self.wait()
        if wait > 0:
            self._timer.start(max(1, round(wait * 1000)))
            return
        self._run(self.session.run.snapshot())

    def let_scan(self) -> None:
        """Between two pieces of a long update: while the real-time thread scans, give it the
        interpreter if its period has come (a sleep of 0 releases the GIL), so it does not wait
        for the rest of the update (a switch comes only every 5 ms otherwise)."""
        if self.session.run.threaded and not UPDATE_ALWAYS:
            time.sleep(0.0002)

    def yield_to_scan(self) -> None:
        """Within a long paint: if the real-time thread's scan is due within a millisecond
        (or running, or waiting for the interpreter), sleep till it has begun, so that it runs
        at its time and whole (the GUI thread waits a switch interval, 5 ms, before it asks
        for the interpreter back)."""
        if not (YIELD and self.session.run.threaded) or UPDATE_ALWAYS:
            return
        due = self.session.run.due_in()
        if due is not None and due < 0.001:
            self.yields += 1
            time.sleep(due + 0.0002)

    def _run(self, snapshot: PlcSnapshot) -> None:
        self.pending = False
        self._tries = 0
        self._timer.stop()
        self.updates += 1
        self.budget.run(lambda: self.update(snapshot))
