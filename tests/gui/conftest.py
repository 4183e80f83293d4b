"""GUI test set-up: offscreen platform, a main window on temporary settings, drawing helpers."""

from __future__ import annotations

import os
from collections.abc import Iterator
from pathlib import Path

os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")

import pytest
from PySide6.QtCore import QEvent, QPoint, QSettings, QStandardPaths, Qt
from PySide6.QtGui import QKeyEvent
from PySide6.QtWidgets import QApplication, QMessageBox, QWidget
from pytestqt.qtbot import QtBot

from ladderworks.gui import questions
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.refcount_guard import guard_singletons
from ladderworks.gui.settings import Settings
from ladderworks.gui.translation import UiLanguage

guard_singletons()  # PySide6 6.12.0 loses a reference to None on every void Qt call


@pytest.fixture(autouse=True)
def data_folder(tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> Path:
    """The user's data folder (recovery copies) in a temporary folder."""
    folder = tmp_path / "xdg-data"
    monkeypatch.setenv("XDG_DATA_HOME", str(folder))
    return folder


@pytest.fixture(autouse=True)
def qt_dialog_state(tmp_path_factory: pytest.TempPathFactory) -> Iterator[Path]:
    """Qt's own file dialog keeps its state in QtProject.conf: in a temporary folder (not in
    the test's own `tmp_path`, which tests list), so the user's is never read nor written."""
    folder = tmp_path_factory.mktemp("qt-config")
    native, scope = QSettings.Format.NativeFormat, QSettings.Scope.UserScope
    QSettings.setPath(native, scope, str(folder))
    yield folder
    QApplication.sendPostedEvents(None, QEvent.Type.DeferredDelete)  # dialogs save on deletion
    QSettings.setPath(native, scope, QStandardPaths.writableLocation(
        QStandardPaths.StandardLocation.GenericConfigLocation))


@pytest.fixture
def settings(tmp_path: Path) -> Settings:
    """Settings in a temporary INI file: tests never touch the user's settings."""
    return Settings(QSettings(str(tmp_path / "settings.ini"), QSettings.Format.IniFormat))


def _forget_changes(win: MainWindow) -> None:
    """Closing at the end of a test: nothing to save."""
    win.editor.undo_stack.setClean()
    win.text_view.document().setModified(False)
    win.parameters.saved = win.parameters.session.run.parameters.copy()


@pytest.fixture
def window(qtbot: QtBot, settings: Settings,
           monkeypatch: pytest.MonkeyPatch) -> Iterator[MainWindow]:
    """The main window in English, shown offscreen (an unexpected question fails the test)."""

    def no_question(*_args: object, **_kwargs: object) -> None:
        raise AssertionError("unexpected blocking question")

    monkeypatch.setattr(QMessageBox, "question", no_question)
    monkeypatch.setattr(questions, "ask", no_question)
    language = UiLanguage()
    language.apply("en")
    win = MainWindow(settings, language)
    qtbot.addWidget(win, before_close_func=_forget_changes)
    win.show()
    qtbot.waitExposed(win)
    yield win
    language.apply("en")


def type_text(qtbot: QtBot, widget: QWidget, text: str) -> None:
    """Key presses for each character (QTest only knows ASCII keys, so Turkish letters are
    sent as key events carrying their text, as a Turkish keyboard does)."""
    for char in text:
        if char.isascii():
            qtbot.keyClicks(widget, char)
            continue
        for kind in (QEvent.Type.KeyPress, QEvent.Type.KeyRelease):
            event = QKeyEvent(kind, Qt.Key.Key_unknown, Qt.KeyboardModifier.NoModifier, char)
            QApplication.sendEvent(widget, event)


class Drawer:
    """Draws in the grid editor with mouse clicks on the viewport and keystrokes only."""

    def __init__(self, qtbot: QtBot, window: MainWindow) -> None:
        self.qtbot = qtbot
        self.window = window
        self.view = window.editor

    def key(self, key: str | Qt.Key) -> None:
        """A key pressed in the grid (letters pick tools)."""
        self.qtbot.keyClick(self.view, key)

    def _click(self, point: QPoint) -> None:
        self.qtbot.mouseClick(self.view.viewport(), Qt.MouseButton.LeftButton, pos=point)

    def click(self, network: int, row: int, col: int) -> None:
        """Click a cell's centre."""
        self._click(self.view.cell_point(network, row, col))

    def click_node(self, network: int, row: int, node: int) -> None:
        """Click a grid node (the left edge of column `node` in `row`) — the line tool's points."""
        self._click(self.view.node_point(network, row, node))

    def type_inline(self, text: str) -> None:
        """Type into the in-place editor and press ENTER."""
        editor = self.view.inline_editor
        self.qtbot.waitUntil(editor.isVisible)
        type_text(self.qtbot, editor, text)
        self.qtbot.keyClick(editor, Qt.Key.Key_Return)

    def element(self, network: int, row: int, col: int, tool: str, text: str) -> None:
        """Pick a tool by its key, click a cell, type the address (and // comment)."""
        self.key(tool)
        self.click(network, row, col)
        self.type_inline(text)

    def line(self, network: int, start: tuple[int, int], end: tuple[int, int]) -> None:
        """The line tool: click a first node, then a second."""
        self.key("L")
        self.click_node(network, *start)
        self.click_node(network, *end)

    def comment(self, network: int, text: str) -> None:
        """The comment tool on the network's first (empty) row."""
        self.key("C")
        self.click(network, 0, 0)
        self.type_inline(text)


@pytest.fixture
def drawer(qtbot: QtBot, window: MainWindow) -> Drawer:
    """Drawing helper on the window's editor."""
    return Drawer(qtbot, window)


class Answers:
    """Answers to the file questions (`questions.ask`), in order; records each question."""

    def __init__(self) -> None:
        self.queue: list[str] = []
        self.asked: list[tuple[str, str, list[str]]] = []
        self.labels: list[list[str]] = []  # the buttons' texts of each question

    def __call__(self, _parent: object, title: str, text: str,
                 choices: list[tuple[str, str, object]]) -> str:
        keys = [key for key, _label, _role in choices]
        self.asked.append((title, text, keys))
        self.labels.append([label for _key, label, _role in choices])
        if not self.queue:
            raise AssertionError(f"unexpected question: {title}: {text}")
        answer = self.queue.pop(0)
        assert answer in keys, (answer, keys)
        return answer


@pytest.fixture
def answers(window: MainWindow, monkeypatch: pytest.MonkeyPatch) -> Answers:
    """Queue the answers a test gives to the window's file questions."""
    given = Answers()
    monkeypatch.setattr(questions, "ask", given)
    return given
