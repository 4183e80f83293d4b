"""PLC › Native scan: the setting, the next load scanning natively, the screen saying so."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import QSettings
from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core.address import parse_address
from ladderworks.core.plc import engine as engine_module
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.scan_backend import ACTION
from ladderworks.gui.settings import Settings
from tests.gui.plc_docks_help import override_code, plc_docks, set_switch

SPINDLE = paths.EXAMPLES / "spindle_override.LAD"


@pytest.fixture(autouse=True)
def no_disk_cache(monkeypatch: pytest.MonkeyPatch) -> None:
    """The native code is not kept in the user's cache directory."""
    monkeypatch.setenv("LADDERWORKS_NATIVE_CACHE", "off")


def _compile_and_start(window: MainWindow) -> None:
    docks = plc_docks(window)
    control = docks.control
    control.show()
    control.stripe_ms = 0  # the stripes at once
    assert control.open_file(SPINDLE)
    assert control.compile().ok
    assert docks.session.run.engine is not None
    control.control_actions["action_plc_start"].trigger()
    assert docks.session.run.running


def test_native_scan_is_chosen_remembered_and_shown(qtbot: QtBot, window: MainWindow,
                                                     settings: Settings) -> None:
    action = window.actions_by_name[ACTION]
    assert action in window.menus.menus["menu_plc"].actions()
    assert not action.isChecked() and settings.scan_backend() == "python"
    action.trigger()
    assert action.isChecked() and settings.scan_backend() == "native"
    _compile_and_start(window)
    session, control = window.plc_docks.session, window.plc_docks.control
    assert session.run.engine is not None and session.run.engine.backend_used == "native"
    set_switch(session, 5)
    session.step(16)
    assert session.run.read(parse_address("G30")) == override_code(5)  # the native code ran
    assert "native scan (machine code)" in control.figures.text()
    window.set_language("tr")
    assert "yerel tarama (makine kodu)" in control.figures.text()
    assert action.text() == "Yerel tarama (makine kodu)"
    window.set_language("en")
    control.control_actions["action_plc_stop"].trigger()
    action.trigger()  # back to Python: from the next load on
    assert settings.scan_backend() == "python"
    assert control.compile().ok
    assert session.run.engine.backend_used == "python"
    assert "Python scan" in control.figures.text()
    assert "native" not in control.figures.text()


def test_the_setting_is_read_at_start(qtbot: QtBot, tmp_path: Path,
                                      monkeypatch: pytest.MonkeyPatch) -> None:
    store = QSettings(str(tmp_path / "native.ini"), QSettings.Format.IniFormat)
    Settings(store).set_scan_backend("native")
    from ladderworks.gui.translation import UiLanguage

    language = UiLanguage()
    language.apply("en")
    window = MainWindow(Settings(store), language)
    qtbot.addWidget(window)
    assert window.actions_by_name[ACTION].isChecked()
    assert window.plc_docks.session.run.backend == "native"
    monkeypatch.setattr(engine_module, "native_unavailable", lambda: "llvmlite is not here")
    _compile_and_start(window)
    control = window.plc_docks.control
    assert "Python scan (native not possible: llvmlite is not here)" in control.figures.text()
    window.plc_docks.control.control_actions["action_plc_stop"].trigger()
