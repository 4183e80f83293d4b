"""Issue 31 item 8: messages already shown follow a live language switch, and column titles
fit their words in both languages."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtWidgets import QHeaderView, QTableView, QTreeView
from pytestqt.qtbot import QtBot

from ladderworks.core.address import parse_address
from ladderworks.core.il import parse
from ladderworks.gui.main_window import MainWindow
from tests.gui.plc_docks_help import plc_docks
from tests.gui.test_cross_reference import _ask, _open

LATCH = "%@3\nRD X2.1\nOR Y0.0\nAND.NOT X2.2\nWRT Y0.0\n%\n"


def cut_titles(view: QTreeView | QTableView) -> list[str]:
    """The titles of the columns (a stretched last one aside) narrower than their words."""
    header = view.header() if isinstance(view, QTreeView) else view.horizontalHeader()
    model = header.model()
    last = header.count() - 1 if header.stretchLastSection() else header.count()
    return [str(model.headerData(column, header.orientation()))
            for column in range(last)
            if not header.isSectionHidden(column)
            and header.sectionResizeMode(column) == QHeaderView.ResizeMode.Interactive
            and header.sectionSize(column) < header.sectionSizeHint(column)]


def test_a_scenario_result_follows_the_switch_and_its_titles_fit(window: MainWindow,
                                                                  qtbot: QtBot) -> None:
    docks = plc_docks(window)
    assert docks.session.load_program(parse(LATCH).program).ok
    scenario = docks.scenario
    scenario.show()
    scenario.run_text("PMC SIGNAL DATA\nSET,0,X2.1,1\nEXPECT,16,Y0.0,1\n", "latch.csv")
    assert scenario.message.text() == "latch.csv: all 1 checks passed"
    assert scenario.checks.topLevelItem(0).text(5) == "passed"
    window.set_language("tr")
    assert scenario.message.text() == "latch.csv: 1 denetimin tümü geçti"
    assert scenario.checks.topLevelItem(0).text(5) == "geçti"
    assert cut_titles(scenario.checks) == []  # "Zaman (ms)", "Okunan" whole
    window.set_language("en")
    assert scenario.message.text() == "latch.csv: all 1 checks passed"
    assert cut_titles(scenario.checks) == []


def test_why_follows_the_switch(window: MainWindow, qtbot: QtBot) -> None:
    docks = plc_docks(window)
    session, diagnostic = docks.session, docks.diagnostic
    assert session.load_program(parse(LATCH).program).ok
    session.start()
    diagnostic.show()
    docks.time_travel.enable(True)
    session.step(16)
    session.set_bit(parse_address("X2.1"), 1)
    session.step(16)
    assert docks.time_travel.why(parse_address("Y0.0")) is not None
    assert diagnostic.message.text() == "Y0.0 went to 1 in scan 2 at 16 ms"
    window.set_language("tr")
    assert diagnostic.message.text() == "Y0.0, 2. taramada (16 ms) 1 oldu"
    window.set_language("en")


def test_the_cross_reference_columns_fit_after_a_switch(window: MainWindow, qtbot: QtBot,
                                                        tmp_path: Path) -> None:
    dock = _open(window, tmp_path)
    _ask(qtbot, dock, "R10.2")
    qtbot.waitUntil(lambda: dock.model.rowCount() > 0)
    dock.hide()  # closed while the language changes, opened again after
    window.set_language("tr")
    dock.show()
    dock.raise_()
    qtbot.waitUntil(dock.table.isVisible)
    assert cut_titles(dock.table) == []
    table = dock.table
    for column in range(dock.model.columnCount() - 1):  # "Okuma" whole, not "Oku…"
        widest = max(table.sizeHintForColumn(column), 0)
        assert table.columnWidth(column) >= widest, column
    window.set_language("en")


def test_every_dock_table_title_fits_in_turkish(window: MainWindow, qtbot: QtBot) -> None:
    docks = plc_docks(window)
    window.set_language("tr")
    views = [docks.scenario.checks, docks.alarms.tree, docks.force_list.table,
             window.errors.tree, window.signals_dock.table,
             *docks.tables.tables.values()]
    for view in views:
        assert cut_titles(view) == [], view.objectName()
    window.set_language("en")
