"""PLC TEŞHİS: read-only ladder of the running program, search, where written, box values."""

from __future__ import annotations

import pytest
from PySide6.QtCore import QPoint, QPointF, Qt
from PySide6.QtGui import QWheelEvent
from PySide6.QtWidgets import QApplication, QWidget
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.il import parse
from ladderworks.gui.docks import diagnostic
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.settings import Settings
from tests.gui.plc_docks_help import plc_docks

TIMER = """%@3
RD X0.0
TMRB 9 80
WRT R1.7
RD X0.1
SUB 8
1111
1111
R0100
R0300
RD X0.0
WRT Y0.0
%
"""


def loaded(window: MainWindow, text: str):
    """Docks with `text` compiled, started and the diagnostic shown."""
    docks = plc_docks(window)
    result = parse(text)
    assert docks.session.load_program(result.program).ok
    docks.session.start()
    docks.diagnostic.show()
    docks.diagnostic.raise_()
    return docks


def test_box_values_and_power(qtbot: QtBot, window: MainWindow) -> None:
    docks = loaded(window, TIMER)
    session, view = docks.session, docks.diagnostic.view
    session.write(parse_address("R100"), 123)
    session.set_bit(parse_address("X0.0"), 1)
    session.step(120)
    overlay = view.live.overlays[0]
    box_cell = next(cell for cell, e in view.networks[0].cells.items()
                    if type(e).__name__ == "FunctionBox")
    assert overlay.power.box_pins[box_cell] == [True]
    assert box_cell in overlay.power.box_out  # 120 ms > 80 ms: the timer is up
    assert overlay.values[box_cell] == []  # TMRB has no address parameters
    add_cell = next(cell for cell, e in view.networks[1].cells.items()
                    if type(e).__name__ == "FunctionBox")
    assert view.live.overlays[1].values[add_cell] == ["R100=123", "R300=0"]
    session.set_bit(parse_address("X0.1"), 1)
    session.step(8)
    assert view.live.overlays[1].values[add_cell] == ["R100=123", "R300=123"]


def test_find_and_where_written(qtbot: QtBot, window: MainWindow) -> None:
    docks = loaded(window, TIMER)
    dock = docks.diagnostic
    dock.search.setText("X0.0")
    dock.find_next()
    assert dock.hits == [(0, (0, 0)), (2, (0, 0))]
    assert "1 of 2" in dock.message.text()
    dock.find_next()
    assert "2 of 2" in dock.message.text()
    dock.search.setText("Y0.0")
    dock.where_written()
    assert dock.hits == [(2, (0, dock.view.networks[2].coil_column))]
    assert (0, dock.view.networks[2].coil_column) in dock.view.live.overlays[2].marked
    dock.search.setText("Q9")
    dock.find_next()
    assert "not an address" in dock.message.text()
    dock.search.setText("R5.5")
    dock.where_written()
    assert "No coil writes R5.5" in dock.message.text()


def test_passive_element_is_tagged(qtbot: QtBot, window: MainWindow) -> None:
    docks = loaded(window, TIMER)
    session, view = docks.session, docks.diagnostic.view
    session.set_bit(parse_address("X0.0"), 1)
    op = session.disable((2, 0))  # RD X0.0 of the last network
    session.step(8)
    assert session.run.bit(parse_address("Y0.0")) == 0
    assert (0, 0) in view.live.overlays[2].power.disabled
    assert (0, 0) not in view.live.overlays[2].power.closed
    session.enable(op)
    session.step(8)
    assert session.run.bit(parse_address("Y0.0")) == 1
    assert view.live.overlays[2].power.coils


def test_element_names_choice_restacks_the_diagnostic_view(qtbot: QtBot,
                                                           window: MainWindow) -> None:
    from PySide6.QtGui import QAction

    docks = loaded(window, TIMER)
    view = docks.diagnostic.view
    window.findChild(QAction, "action_names_comment").trigger()
    tall = list(view.layout_.tops)
    window.findChild(QAction, "action_names_address").trigger()
    assert view.layout_.tops[1] < tall[1] and view.layout_.tops[2] < tall[2]
    for item, overlay, top in zip(view.network_items, view.live.overlays, view.layout_.tops,
                                  strict=True):
        assert item.pos().y() == overlay.pos().y() == top  # the live power stays on its rung
        assert item.boundingRect() == overlay.boundingRect()


def test_a_long_state_does_not_widen_the_dock(qtbot: QtBot, window: MainWindow) -> None:
    """The state (RUNNING — scan N, PAST — scan N at T ms) grows with the run; in Turkish on
    a long run it must not push the dock, and the ladder beside it, wider."""
    from dataclasses import replace

    window.set_language("tr")
    docks = loaded(window, TIMER)
    dock = docks.diagnostic
    docks.session.run_scans(3)
    qtbot.waitUntil(lambda: dock.state.text() != "")
    narrow = dock.minimumSizeHint().width()
    assert narrow <= 520, narrow
    dock.show_past(replace(docks.session.run.snapshot(), scan_count=12345678, now_ms=98765432))
    assert "12345678" in dock.state.text()
    assert dock.minimumSizeHint().width() <= 520
    assert dock.state.isVisible()
    dock.back_to_live()
    window.set_language("en")


def _wheel(view: QWidget, notches: int, modifiers: Qt.KeyboardModifier) -> None:
    """Turn the mouse wheel over the middle of `view` by `notches` (positive: away)."""
    middle = QPointF(view.width() / 2, view.height() / 2)
    event = QWheelEvent(middle, QPointF(view.mapToGlobal(middle.toPoint())), QPoint(),
                        QPoint(0, 120 * notches), Qt.MouseButton.NoButton, modifiers,
                        Qt.ScrollPhase.NoScrollPhase, False)
    QApplication.sendEvent(view, event)


def test_zoom_buttons_wheel_limits_and_settings(qtbot: QtBot, window: MainWindow,
                                                settings: Settings) -> None:
    docks = loaded(window, TIMER)
    dock, view = docks.diagnostic, docks.diagnostic.view
    assert view.zoom() == pytest.approx(diagnostic.VIEW_SCALE)
    assert dock.zoom_label.text() == "62 %"
    before = view.mapFromScene(view.cell_rect(0, (0, 1)).topLeft()).x()
    dock.zoom_in_button.click()
    assert view.zoom() == pytest.approx(diagnostic.VIEW_SCALE * diagnostic.ZOOM_STEP)
    assert view.mapFromScene(view.cell_rect(0, (0, 1)).topLeft()).x() > before  # drawn larger
    assert dock.zoom_label.text() == "78 %"
    _wheel(view.viewport(), 1, Qt.KeyboardModifier.ControlModifier)
    assert view.zoom() == pytest.approx(diagnostic.VIEW_SCALE * diagnostic.ZOOM_STEP ** 2)
    _wheel(view.viewport(), -1, Qt.KeyboardModifier.NoModifier)  # the wheel alone scrolls
    assert view.zoom() == pytest.approx(diagnostic.VIEW_SCALE * diagnostic.ZOOM_STEP ** 2)
    for _step in range(12):
        dock.zoom_in_button.click()
    assert view.zoom() == pytest.approx(diagnostic.ZOOM_MAX)
    assert not dock.zoom_in_button.isEnabled() and dock.zoom_out_button.isEnabled()
    for _step in range(20):
        _wheel(view.viewport(), -1, Qt.KeyboardModifier.ControlModifier)
    assert view.zoom() == pytest.approx(diagnostic.ZOOM_MIN)
    assert not dock.zoom_out_button.isEnabled() and dock.zoom_in_button.isEnabled()
    dock.zoom_in_button.click()
    assert settings.diagnostic_zoom(1.0) == pytest.approx(diagnostic.ZOOM_MIN
                                                          * diagnostic.ZOOM_STEP)
    again = MainWindow(settings, window.language)  # the next start: the zoom remembered
    qtbot.addWidget(again)
    assert again.plc_docks.diagnostic.view.zoom() == pytest.approx(diagnostic.ZOOM_MIN
                                                                  * diagnostic.ZOOM_STEP)
    window.set_language("tr")
    assert dock.zoom_in_button.toolTip() == "Yakınlaştır (Ctrl+tekerlek)"
    assert dock.zoom_label.text() == f"%{round(view.zoom() * 100)}"  # the Turkish way
    window.set_language("en")
