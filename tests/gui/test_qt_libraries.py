"""Start-up without Qt's xcb libraries: the missing Debian/Ubuntu packages, in the UI language."""

from __future__ import annotations

from pathlib import Path

import pytest
from PySide6.QtCore import QSettings

from ladderworks import version
from ladderworks.gui import app
from ladderworks.gui.qt_libraries import (
    XCB_LIBRARIES,
    missing_libraries,
    missing_libraries_text,
    packages_for,
    uses_xcb,
)
from ladderworks.gui.settings import Settings
from ladderworks.gui.translation import UiLanguage

ABSENT = {"libxcb-cursor.so.0", "libxcb-icccm.so.4", "libxcb-keysyms.so.1"}


def test_the_missing_libraries_come_from_the_finder() -> None:
    assert missing_libraries(lambda soname: soname not in ABSENT) == [
        "libxcb-cursor.so.0", "libxcb-icccm.so.4", "libxcb-keysyms.so.1"]
    assert missing_libraries(lambda soname: True) == []
    assert len(missing_libraries(lambda soname: False)) == len(XCB_LIBRARIES)


def test_packages_are_the_debian_names_sorted_once() -> None:
    assert packages_for(sorted(ABSENT)) == ["libxcb-cursor0", "libxcb-icccm4", "libxcb-keysyms1"]
    assert packages_for(["libEGL.so.1", "libGL.so.1"]) == ["libegl1", "libgl1"]


def test_only_the_xcb_platform_needs_them() -> None:
    assert uses_xcb({}, "linux")
    assert uses_xcb({"QT_QPA_PLATFORM": "xcb"}, "linux")
    assert not uses_xcb({"QT_QPA_PLATFORM": "offscreen"}, "linux")
    assert not uses_xcb({"QT_QPA_PLATFORM": "wayland;xcb"}, "linux")
    assert not uses_xcb({"WAYLAND_DISPLAY": "wayland-0"}, "linux")
    assert not uses_xcb({}, "darwin") and not uses_xcb({}, "win32")


def test_the_message_in_english_and_turkish(qapp: object) -> None:
    language = UiLanguage()
    try:
        language.apply("en")
        english = missing_libraries_text(["libxcb-cursor.so.0"])
        language.apply("tr")
        turkish = missing_libraries_text(["libxcb-cursor.so.0"])
    finally:
        language.apply("en")
    assert english.startswith("LadderWorks cannot start")
    assert "missing: libxcb-cursor.so.0." in english
    assert english.endswith("\n    sudo apt-get install libxcb-cursor0")
    assert turkish.startswith("LadderWorks başlatılamıyor")
    assert "eksik: libxcb-cursor.so.0." in turkish and "Debian veya Ubuntu" in turkish
    assert turkish.endswith("\n    sudo apt-get install libxcb-cursor0")


def test_start_up_stops_with_the_packages_in_the_saved_language(
        qapp: object, tmp_path: Path, monkeypatch: pytest.MonkeyPatch,
        capsys: pytest.CaptureFixture[str]) -> None:
    store = Settings(QSettings(str(tmp_path / "s.ini"), QSettings.Format.IniFormat))
    store.set_language("tr")
    monkeypatch.setattr(app, "Settings", lambda: store)
    monkeypatch.setattr(app, "uses_xcb", lambda environ, platform: True)
    monkeypatch.setattr(app, "missing_libraries", lambda: ["libxcb-cursor.so.0"])
    try:
        assert app.main(["ladderworks"]) == 1
    finally:
        UiLanguage().apply("en")
    error = capsys.readouterr().err
    assert "LadderWorks başlatılamıyor" in error
    assert "sudo apt-get install libxcb-cursor0" in error


def test_version_and_options(capsys: pytest.CaptureFixture[str]) -> None:
    with pytest.raises(SystemExit) as stop:
        app.parse_arguments(["--version"])
    assert stop.value.code == 0
    assert capsys.readouterr().out.strip() == f"ladderworks {version()}"
    options = app.parse_arguments(["--quit-after", "3000", "a.LAD", "-style", "fusion"])
    assert options.quit_after == 3000 and options.files == ["a.LAD"]


def test_the_cli_version(capsys: pytest.CaptureFixture[str]) -> None:
    from ladderworks.cli import main

    with pytest.raises(SystemExit) as stop:
        main(["--version"])
    assert stop.value.code == 0
    assert capsys.readouterr().out.strip() == f"ladderworks-cli {version()}"
