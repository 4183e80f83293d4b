"""Fit width: the zoom that keeps the coil column and the right rail in view, kept on resize."""

from __future__ import annotations

from PySide6.QtCore import QEvent, QObject, QRectF
from PySide6.QtWidgets import QStyle

from ladderworks.gui.editor.view import LadderEditor


class FitWidth(QObject):
    """While on, the editor's zoom fits the widest network into the view's width, again after
    each resize (window, docks) and each change of the drawing's width."""

    def __init__(self, editor: LadderEditor) -> None:
        super().__init__(editor)
        self._editor = editor
        self.enabled = False
        editor.installEventFilter(self)
        editor.scene().sceneRectChanged.connect(self._scene_changed)

    def set_enabled(self, on: bool) -> None:
        """Turn fit width on (fitting now) or off (the zoom stays where it is)."""
        self.enabled = on
        if on:
            self.fit()

    def factor(self) -> float:
        """The zoom at which the drawing's width fills the view (a vertical scroll bar's room
        kept, so showing or hiding it does not change the fit)."""
        editor = self._editor
        scroll = editor.style().pixelMetric(QStyle.PixelMetric.PM_ScrollBarExtent, None, editor)
        room = editor.width() - 2 * editor.frameWidth() - scroll - 2
        return max(room, 1) / max(editor.sceneRect().width(), 1.0)

    def fit(self) -> None:
        """Zoom to fit the width now."""
        factor = self.factor()
        if abs(factor - self._editor.zoom()) > 1e-3:
            self._editor.set_zoom(factor)

    def _scene_changed(self, _rect: QRectF) -> None:
        if self.enabled:
            self.fit()

    def eventFilter(self, watched: QObject, event: QEvent) -> bool:
        """Fit again when the editor is resized."""
        if watched is self._editor and event.type() == QEvent.Type.Resize and self.enabled:
            self.fit()
        return False
