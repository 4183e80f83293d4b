"""Fit width: the zoom that keeps the coil column and the right rail of the networks in view
(all but a few unusually wide ones), kept on resize; below a readable zoom it says so."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QEvent, QObject, QRectF, Signal
from PySide6.QtWidgets import QStyle

from ladderworks.core.ladder.model import LadderNetwork
from ladderworks.gui.editor.geometry import network_width, typical_width
from ladderworks.gui.editor.grid_view import ZOOM_MIN
from ladderworks.gui.editor.ladder_model import is_blank
from ladderworks.gui.editor.view import LadderEditor

translate = QCoreApplication.translate

SHARE_FITTED = 0.95  # of the networks fitted whole: one 1,816-px network does not shrink all
READABLE = 0.6  # below it addresses are hard to read: fit width still fits, and says so
SMALLEST = ZOOM_MIN  # fit width zooms no smaller (the zoom range's end): a narrower view scrolls
NARROWEST = 808.0  # the scene's least width: a small program is not blown up past it
MARGIN = 12.0  # the scene's margins left and right of a network


class FitWidth(QObject):
    """While on, the editor's zoom fits the typical network into the view's width (the widest
    of 95 % of them, at a readable zoom), again after each resize (window, docks) and each
    change of the drawing's width; `describe()` says what it fitted."""

    fitted_changed = Signal()  # fit() ran: `describe()` may say something else

    def __init__(self, editor: LadderEditor) -> None:
        super().__init__(editor)
        self._editor = editor
        self.enabled = False
        self.fitted = (0, 0)  # networks whole in the view's width after the last fit, of all
        editor.installEventFilter(self)
        editor.scene().sceneRectChanged.connect(self._scene_changed)

    def set_enabled(self, on: bool) -> None:
        """Turn fit width on (fitting now) or off (the zoom stays where it is)."""
        self.enabled = on
        if on:
            self.fit()

    def _room(self) -> int:
        """The view's width for the drawing (a vertical scroll bar's room kept, so showing or
        hiding it does not change the fit)."""
        editor = self._editor
        scroll = editor.style().pixelMetric(QStyle.PixelMetric.PM_ScrollBarExtent, None, editor)
        return max(editor.width() - 2 * editor.frameWidth() - scroll - 2, 1)

    def _drawn(self) -> list[LadderNetwork]:
        """The networks to fit: the blank one at the end to draw in is none of them."""
        networks = self._editor.networks
        return networks[:-1] if networks and is_blank(networks[-1]) else list(networks)

    def needed(self) -> float:
        """The zoom at which the typical network's width fills the view: the widest of 95 % of
        the networks (all of a small program)."""
        typical = typical_width(self._drawn(), SHARE_FITTED) + MARGIN
        return self._room() / max(typical, NARROWEST)

    def factor(self) -> float:
        """The zoom fit width sets: what the view needs, no smaller than SMALLEST."""
        return max(self.needed(), SMALLEST)

    def describe(self) -> str:
        """What fit width fitted, in the UI language ("" while it is off)."""
        if not self.enabled:
            return ""
        fitted, total = self.fitted
        zoom = round(100 * self._editor.zoom())
        if self.needed() < SMALLEST - 1e-3:
            return translate("FitWidth", "Fit width: the ladder is too narrow ({0} px) for its "
                             "networks even at {1} %: close or narrow a dock, or widen the "
                             "window").format(self._room(), zoom)
        if fitted >= total and self._editor.zoom() < READABLE - 1e-3:
            return translate("FitWidth", "Fit width: every network fits at {0} % (a dock "
                             "closed reads larger)").format(zoom)
        if fitted >= total:
            return translate("FitWidth", "Fit width: every network fits the window's width")
        return translate("FitWidth", "Fit width: {0} of {1} networks fit the window's width; "
                         "the {2} wider ones scroll sideways").format(
                             fitted, total, total - fitted)

    def fit(self) -> None:
        """Zoom to fit the width now, and count the networks it fitted."""
        factor = self.factor()
        if abs(factor - self._editor.zoom()) > 1e-3:
            self._editor.set_zoom(factor)
        room = self._room() / self._editor.zoom() + 0.5
        networks = self._drawn()
        fits = sum(1 for network in networks if network_width(network) + MARGIN <= room)
        self.fitted = (fits, len(networks))
        self.fitted_changed.emit()

    def _scene_changed(self, _rect: QRectF) -> None:
        if self.enabled:
            self.fit()

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """Fit again when the editor is resized."""
        if watched is self._editor and event.type() == QEvent.Type.Resize and self.enabled:
            self.fit()
        return False
