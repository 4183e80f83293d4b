"""A value lane of the time chart drawn as a logic analyser's bus: a band with each value in it."""

from __future__ import annotations

import pyqtgraph as pg
from PySide6.QtGui import QColor, QFontMetrics

from ladderworks.core.tag_names import typed_text

BAND_LOW = 0.1  # the band spans these fractions of a lane's 0..1 height
BAND_HIGH = 0.9
SLANT_PX = 3  # the band's crossing at a change, in pixels either side


def value_text(value: int, width: int) -> str:
    """A value as the lane writes it: decimal, and hex for a byte or more (`148 (94h)`)."""
    digits = 2 * width
    return f"{value} ({value & (1 << 8 * width) - 1:0{digits}X}h)"


class BusLane:
    """The band and value texts of one value lane, redrawn from the lane's steps."""

    def __init__(self, item: pg.PlotItem, colour: QColor, base: float, width: int,
                 type_name: str = "") -> None:
        self.item = item
        self.type_name = type_name  # an S7 tag's type: a Time as T#5s, a Real as 21.5
        self.colour = colour
        self.base = base
        self.width = width
        self.outline = pg.PlotDataItem(pen=pg.mkPen(colour, width=1.5), connect="pairs")
        item.addItem(self.outline)
        self.labels: list[pg.TextItem] = []
        self.values: list[int] = []
        self.spans: list[tuple[float, float]] = []  # each label's segment (ms)
        self._steps: tuple[list[float], list[int]] = ([], [])
        item.getViewBox().sigTransformChanged.connect(self._on_zoom)

    def remove(self) -> None:
        """Take the lane off the chart."""
        self.item.getViewBox().sigTransformChanged.disconnect(self._on_zoom)
        self.item.removeItem(self.outline)
        for label in self.labels:
            self.item.removeItem(label)
        self.labels = []

    def texts(self) -> list[tuple[float, str]]:
        """Each value written in the lane and shown at this zoom: (start time in ms, text)."""
        return [(span[0], label.toPlainText()) for span, label in zip(self.spans, self.labels,
                                                                       strict=True)
                if label.isVisible()]

    def set_steps(self, xs: list[float], values: list[int]) -> None:
        """Draw the lane: `values[i]` holds from `xs[i]` to `xs[i + 1]`."""
        if (xs, values) == self._steps:
            return
        self._steps = (list(xs), list(values))
        count = len(values)
        for label in self.labels[count:]:
            self.item.removeItem(label)
        del self.labels[count:]
        while len(self.labels) < count:
            label = pg.TextItem(color=self.colour, anchor=(0, 0.5))
            self.item.addItem(label, ignoreBounds=True)
            self.labels.append(label)
        self.spans = [(xs[i], xs[i + 1]) for i in range(count)]
        self.values = list(values)
        self._on_zoom()

    def _on_zoom(self, *_args: object) -> None:
        """Redraw the crossings at the new scale; write a value only where it fits."""
        view = self.item.getViewBox()
        per_pixel = view.viewPixelSize()[0] or 1.0
        slant = SLANT_PX * per_pixel
        low, high = self.base + BAND_LOW, self.base + BAND_HIGH
        middle = self.base + 0.5
        xs: list[float] = []
        ys: list[float] = []
        for start, end in self.spans:
            left, right = start + slant, max(end - slant, start + slant)
            xs += [left, right, left, right, start, left, start, left]
            ys += [high, high, low, low, middle, high, middle, low]
            xs += [right, end, right, end]
            ys += [high, middle, low, middle]
        self.outline.setData(xs, ys)
        if not self.labels:
            return
        metrics = QFontMetrics(self.labels[0].textItem.font())
        margin = 2 * self.labels[0].textItem.document().documentMargin()
        band = (BAND_HIGH - BAND_LOW) / (view.viewPixelSize()[1] or 1.0)
        tall_enough = band >= 0.8 * metrics.height()  # a crowded chart: the readout has them
        for (start, end), value, label in zip(self.spans, self.values, self.labels, strict=True):
            room = (end - start) / per_pixel - 2 * SLANT_PX - margin if tall_enough else 0
            typed = typed_text(value, self.type_name, self.width)
            full, short = (typed, typed) if typed else (value_text(value, self.width), str(value))
            text = full if metrics.horizontalAdvance(full) <= room else short
            label.setText(text)
            label.setVisible(metrics.horizontalAdvance(text) <= room)
            label.setPos(start + slant, middle)
