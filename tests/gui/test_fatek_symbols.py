"""File › Import symbols: a WinProladder comment export names a Fatek program's addresses; the
export beside the program is read with it; one that does not read changes nothing."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtGui import QAction

from ladderworks.core.dialects.fatek import DEVICES
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.symbol_import import import_symbols
from ladderworks.gui.translation import UiLanguage

EXAMPLE = Path(__file__).resolve().parents[2] / "resources" / "examples" / "fatek" / \
    "capping_printed.lst"


def test_import_symbols_names_the_programs_addresses(window: MainWindow, tmp_path: Path) -> None:
    UiLanguage().apply("en")
    assert window.findChild(QAction, "action_import_symbols") is not None
    path = tmp_path / "capping.lst"
    path.write_bytes(EXAMPLE.read_bytes())
    assert window.load(path) and window.editor.networks
    assert window.model.symbols is None
    export = tmp_path / "names.txt"
    export.write_bytes("REF\tCOMMENT\tDESCRIPTION\r\nS1\tPołożenie\t\r\nX0\tStart\t\r\n"
                       .encode("cp1250"))
    assert import_symbols(window, export)
    assert window.model.symbols is not None
    assert window.model.symbols.lookup(DEVICES.bit("S1")).symbol == "Położenie"  # type: ignore
    assert "2 symbols imported" in window.statusBar().currentMessage()
    bad = tmp_path / "bad.txt"
    bad.write_bytes(b"ORG X0\n")
    assert not import_symbols(window, bad)
    assert "bad.txt:1:1" in window.last_warning
    assert window.model.symbols.lookup(DEVICES.bit("X0")).symbol == "Start"  # type: ignore


def test_the_export_beside_the_program_is_read_with_it(window: MainWindow,
                                                        tmp_path: Path) -> None:
    path = tmp_path / "capping.lst"
    path.write_bytes(EXAMPLE.read_bytes())
    (tmp_path / "capping_comment.txt").write_bytes(b"REF\tCOMMENT\tDESCRIPTION\nY3\tReject\t\n")
    assert window.load(path)
    assert window.model.symbols is not None
    assert window.model.symbols.lookup(DEVICES.bit("Y3")).symbol == "Reject"  # type: ignore
