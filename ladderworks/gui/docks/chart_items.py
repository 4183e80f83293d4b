"""The time chart's step traces and axes: pyqtgraph's, letting a due PLC scan run first.

A redraw of the chart paints every lane, fill and axis in one Qt paint event (15-25 ms for six
lanes); the real-time scan thread, due in the middle of it, waited for the interpreter until
the paint gave it up. Each of these items calls its `before_paint` (the chart's
`SnapshotGate.yield_to_scan`) first, so a due scan goes first and runs whole.
"""

from __future__ import annotations

from collections.abc import Callable
from typing import Any

import pyqtgraph as pg

from ladderworks.gui.locale_numbers import LocaleAxis


def _nothing() -> None:
    """No pause (an item drawn outside a chart that scans in real time)."""


class YieldingCurve(pg.PlotCurveItem):
    """A step trace (or its fill) that lets a due scan run before it paints."""

    def __init__(self, before_paint: Callable[[], None] = _nothing, **options: Any) -> None:
        step = options.pop("stepMode", None)  # set after: an empty trace is not a step trace
        super().__init__(**options)
        self.opts["stepMode"] = step
        self.before_paint = before_paint

    def paint(self, painter: Any, option: Any, widget: Any = None) -> None:
        """Paint, after a due scan."""
        self.before_paint()
        super().paint(painter, option, widget)


class YieldingAxis(pg.AxisItem):
    """The lane names' axis, letting a due scan run before it paints."""

    def __init__(self, orientation: str, before_paint: Callable[[], None] = _nothing) -> None:
        super().__init__(orientation)
        self.before_paint = before_paint

    def paint(self, painter: Any, option: Any, widget: Any = None) -> None:
        """Paint, after a due scan."""
        self.before_paint()
        super().paint(painter, option, widget)


class YieldingLocaleAxis(YieldingAxis, LocaleAxis):
    """The time axis (the UI language's decimal sign), letting a due scan run first; without
    its title its last tick carries the `unit` (`900 ms`)."""

    unit = ""  # said after the last tick's number ("" while the axis shows its title)

    def tickStrings(self, values: list[float], scale: float, spacing: float) -> list[str]:
        """The numbers, the last one followed by the unit when the title is not shown."""
        strings = super().tickStrings(values, scale, spacing)
        if self.unit and strings:
            strings[-1] = f"{strings[-1]} {self.unit}"
        return strings
