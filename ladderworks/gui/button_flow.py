"""A row of tool buttons that wraps onto the next line when narrow, so no button is ever hidden."""

from __future__ import annotations

from PySide6.QtCore import QMargins, QPoint, QRect, QSize, Qt
from PySide6.QtGui import QAction, QResizeEvent
from PySide6.QtWidgets import QFrame, QLayout, QLayoutItem, QToolButton, QWidget

GAP = 2
GROUP_GAP = 10  # between groups (where a toolbar would draw a separator)


class FlowLayout(QLayout):
    """Items left to right, wrapped to a new line at the right edge (Qt's flow layout example)."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self._items: list[QLayoutItem] = []
        self.setContentsMargins(QMargins(0, 0, 0, 0))

    def addItem(self, item: QLayoutItem) -> None:
        self._items.append(item)

    def count(self) -> int:
        return len(self._items)

    def itemAt(self, index: int) -> QLayoutItem | None:
        return self._items[index] if 0 <= index < len(self._items) else None

    def takeAt(self, index: int) -> QLayoutItem | None:
        return self._items.pop(index) if 0 <= index < len(self._items) else None

    def expandingDirections(self) -> Qt.Orientation:
        return Qt.Orientation(0)

    def hasHeightForWidth(self) -> bool:
        return True

    def heightForWidth(self, width: int) -> int:
        return self._place(QRect(0, 0, width, 0), move=False)

    def setGeometry(self, rect: QRect) -> None:
        super().setGeometry(rect)
        self._place(rect, move=True)

    def sizeHint(self) -> QSize:
        return self.minimumSize()

    def minimumSize(self) -> QSize:
        size = QSize()
        for item in self._items:
            size = size.expandedTo(item.minimumSize())
        return size

    def _place(self, rect: QRect, *, move: bool) -> int:
        x, y, line = rect.x(), rect.y(), 0
        for item in self._items:
            hint = item.sizeHint()
            if x + hint.width() > rect.right() + 1 and line > 0:
                x, y, line = rect.x(), y + line + GAP, 0
            if move:
                item.setGeometry(QRect(QPoint(x, y), hint))
            x += hint.width() + GAP
            line = max(line, hint.height())
        return y + line - rect.y()


class ButtonFlow(QWidget):
    """Tool buttons for actions, in groups, wrapping like words in a paragraph."""

    def __init__(self, parent: QWidget | None = None) -> None:
        super().__init__(parent)
        self.flow = FlowLayout(self)
        self.buttons: dict[str, QToolButton] = {}

    def resizeEvent(self, event: QResizeEvent) -> None:
        """Ask for the height the wrapped lines need at this width (a dock does not ask)."""
        super().resizeEvent(event)
        needed = self.flow.heightForWidth(self.width())
        if needed != self.minimumHeight():
            self.setMinimumHeight(needed)

    def add_action(self, action: QAction) -> QToolButton:
        """A button for `action` (its text, tooltip and enabled state follow the action)."""
        button = QToolButton(self)
        button.setDefaultAction(action)
        button.setAutoRaise(True)
        button.setToolButtonStyle(Qt.ToolButtonStyle.ToolButtonTextOnly)
        self.flow.addWidget(button)
        self.buttons[action.objectName()] = button
        return button

    def add_widget(self, widget: QWidget) -> None:
        """Another widget in the flow (a labelled field that wraps with the buttons)."""
        widget.setParent(self)
        self.flow.addWidget(widget)

    def add_separator(self) -> None:
        """A gap between two groups of buttons."""
        gap = QFrame(self)
        gap.setFixedSize(GROUP_GAP, 1)
        self.flow.addWidget(gap)

    def hidden_buttons(self) -> list[str]:
        """The actions whose button does not lie wholly inside the widget (none, by design)."""
        inside = self.rect()
        return [name for name, button in self.buttons.items()
                if not inside.contains(button.geometry())]
