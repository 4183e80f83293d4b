"""A WinProladder printout in the IDE: File › Import symbols (a comment export names its
addresses; the export beside the program is read with it; one that does not read changes
nothing), and a rung added saved in the printout's own form."""

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


def test_a_rung_added_to_a_printout_is_saved_in_the_printed_form(window: MainWindow,
                                                                  tmp_path: Path) -> None:
    """WinProladder's printed form kept on Save: the old lines byte for byte, the new rung
    with step numbers after the last and `SET( )` as the printout writes it."""
    from ladderworks.core.instructions import Write
    from ladderworks.core.ladder.model import Coil, Contact, LadderNetwork, Wire

    path = tmp_path / "capping.lst"
    original = EXAMPLE.read_bytes()
    path.write_bytes(original)
    assert window.load(path)
    rung = LadderNetwork()
    rung.cells[(0, 0)] = Contact(DEVICES.bit("X7"))
    for col in range(1, rung.columns):
        rung.cells[(0, col)] = Wire()
    rung.cells[(0, rung.columns)] = Coil(DEVICES.bit("S9"), write=Write.SET)
    end = len(window.model.networks) - 1  # before the empty rung at the end
    window.model.insert_network(end, rung)
    assert window.save_to(path)
    saved = path.read_text(encoding="utf-8").splitlines()
    assert path.read_bytes().startswith(original)
    assert saved[-2:] == ["00054M ORG      X7", "00055M SET( )   S9"]
