"""Fit width: the zoom that keeps the coil column and the right rail of the networks in view
(all but a few unusually wide ones, never below a readable zoom), kept on resize."""

from __future__ import annotations

from PySide6.QtCore import QCoreApplication, QEvent, QObject, QRectF, Signal
from PySide6.QtWidgets import QStyle

from ladderworks.gui.editor.geometry import network_width, typical_width
from ladderworks.gui.editor.view import LadderEditor

translate = QCoreApplication.translate

SHARE_FITTED = 0.95  # of the networks fitted whole: one 1,816-px network does not shrink all
READABLE = 0.6  # fit width zooms no smaller: addresses stay readable, wider networks scroll
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

    def factor(self) -> float:
        """The zoom at which the typical network's width fills the view: the widest of 95 % of
        the networks (all of a small program), no smaller than READABLE."""
        typical = typical_width(self._editor.networks, SHARE_FITTED) + MARGIN
        return max(self._room() / max(typical, NARROWEST), READABLE)

    def describe(self) -> str:
        """What fit width fitted, in the UI language ("" while it is off)."""
        if not self.enabled:
            return ""
        fitted, total = self.fitted
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
        networks = self._editor.networks
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
