"""Issues 25/26: the palette of a Delta program offers its program structure (CJ, CALL, P,
SRET, FEND, MC/MCR) and its edge and comparison contacts, a Fatek program its FUN boxes, RST
and TU/TD contacts; each placed element is drawn, compiled, run, saved in the dialect's text
(the rest byte for byte) and read back."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt
from PySide6.QtGui import QAction
from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core.address import Address
from ladderworks.core.dialects import parse_target
from ladderworks.core.il.reading import parse_file
from ladderworks.core.ladder.model import Coil, Contact, FunctionBox, LadderNetwork, Wire
from ladderworks.core.ladder.row_contacts import mark
from ladderworks.gui.main_window import MainWindow


def _entries(window: MainWindow) -> list[str]:
    combo = window.tool_palette.functions
    return [combo.itemText(i) for i in range(combo.count())]


def _device(text: str, dialect: str) -> Address:
    return parse_target(text, dialect)[0]


def _end(window: MainWindow) -> int:
    """The index of the blank network new networks are drawn in: before a Delta program's END
    (kept last); a Fatek listing's END is its trailer, not a network: the end of the list."""
    return window.model.blank_index()


def _rung(dialect: str, contact: str | None, coil: str | None, first: int = 1) -> LadderNetwork:
    """A network with a contact at (0, 0) (or none), wires from `first` and a coil."""
    network = LadderNetwork()
    if contact is not None:
        network.cells[(0, 0)] = Contact(_device(contact, dialect))
    if coil is not None:
        for col in range(first, network.columns):
            network.cells[(0, col)] = Wire()
        network.cells[(0, network.columns)] = Coil(_device(coil, dialect))
    return network


def _place(qtbot: QtBot, window: MainWindow, index: int, cell: tuple[int, int], name: str,
           values: list[str]) -> None:
    """Choose `name` in the palette, click the cell with the function tool, fill the table."""
    window.tool_palette.set_function(name)
    assert window.current_tool().name == "FUNCTION"
    window.editor.edits.open_function_dialog(index, *cell, window.tool_palette.current_function())
    dialog = window.editor.edits.function_dialog
    assert dialog is not None
    assert dialog.table.rowCount() == len(values)
    for row, text in enumerate(values):
        dialog.table.item(row, 1).setText(text)
    with qtbot.waitSignal(dialog.accepted):
        dialog.accept()


def _compile_and_start(qtbot: QtBot, window: MainWindow) -> None:
    session = window.plc_docks.session
    session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)
    assert session.run.engine is not None, window.errors.diagnostics()
    start = window.findChild(QAction, "action_plc_start")
    assert start is not None
    start.trigger()


def _copy(tmp_path: Path, *parts: str) -> Path:
    copy = tmp_path / parts[-1]
    copy.write_bytes(paths.EXAMPLES.joinpath(*parts).read_bytes())
    return copy


def test_delta_palette_offers_structure_and_contacts(window: MainWindow) -> None:
    assert window.load(paths.EXAMPLES / "delta" / "timer_t0.txt")
    entries = _entries(window)
    assert "— Delta DVP program structure —" in entries
    assert "— Delta DVP contacts —" in entries
    assert any(e.startswith("CJ — ") for e in entries)
    assert any(e.startswith("FEND — ") for e in entries)
    assert any(e.startswith("LD= / AND= / OR= — ") for e in entries)
    assert any(e.startswith("LDP / ANDP / ORP — ") for e in entries)
    window.set_language("tr")
    entries = _entries(window)
    assert "— Delta DVP program yapısı —" in entries and "— Delta DVP kontakları —" in entries
    window.set_language("en")
    assert window.load(paths.EXAMPLES / "fatek" / "conveyor.lst")
    entries = _entries(window)
    assert "— Fatek FBs contacts —" in entries
    for start in ("FUN 8 MOV — ", "FUN 11 (+) — ", "FUN 12 (-) — ", "FUN 13 (*) — ",
                  "FUN 14 (/) — ", "FUN 15 (+1) — ", "FUN 16 (-1) — ", "FUN 17 CMP — ",
                  "FUN 7 UDCTR — ", "FUN 94 ASCWR — ", "RST — ", "TU — ", "TD — "):
        assert any(e.startswith(start) for e in entries), start


def test_delta_contacts_placed_run_and_save(qtbot: QtBot, window: MainWindow,
                                            tmp_path: Path) -> None:
    copy = _copy(tmp_path, "delta", "timer_t0.txt")
    original = copy.read_text(encoding="utf-8")
    assert window.load(copy)
    end = _end(window)
    window.model.insert_network(end, _rung("delta", None, "Y1"))
    _place(qtbot, window, end, (0, 0), "DVP.LD=", ["D0", "K5"])  # on the rail: LD=
    window.model.insert_network(end + 1, _rung("delta", "X1", "Y2", first=2))
    _place(qtbot, window, end + 1, (0, 1), "DVP.LDP", ["X2"])  # in series: ANDP
    assert window.model.undo_stack.undoText() == "Place LDP"  # the dialect's spelling
    contact = window.model.networks[end + 1].cells[(0, 1)]
    assert isinstance(contact, Contact) and contact.function == "DVP.LDP"
    window.editor.make_visible_items()
    item = next(i for n, i in window.editor.network_items.made() if n == end + 1)
    assert item.label_lines(contact)[0] == "X2"  # drawn with its device
    _compile_and_start(qtbot, window)
    session = window.plc_docks.session
    y1, y2 = _device("Y1", "delta"), _device("Y2", "delta")
    session.run_scans(2)
    assert session.run.bit(y1) == 0
    session.write(_device("D0", "delta"), 5, 2)
    session.run_scans(1)
    assert session.run.bit(y1) == 1
    session.set_bit(_device("X1", "delta"), 1)
    session.set_bit(_device("X2", "delta"), 1)
    session.run_scans(1)
    assert session.run.bit(y2) == 1  # one scan after X2 rose
    session.run_scans(1)
    assert session.run.bit(y2) == 0
    window.plc_docks.session.stop()
    assert window.save_to(copy)
    text = copy.read_text(encoding="utf-8")
    head = original[:original.rindex("END")]
    assert text == head + "LD=\tD0\tK5\nOUT\tY1\nLD\tX1\nANDP\tX2\nOUT\tY2\nEND\n"
    result = parse_file(copy)
    assert result.ok and {"DVP.LD=", "DVP.ANDP"} <= {i.name for i in result.program.instructions()}
    assert window.load(copy)  # re-opened: drawn as contacts again
    again = window.model.networks[_end(window) - 1].cells[(0, 1)]
    assert isinstance(again, Contact) and again.function == "DVP.ANDP"


def test_delta_structure_placed_runs_and_saves(qtbot: QtBot, window: MainWindow,
                                               tmp_path: Path) -> None:
    copy = _copy(tmp_path, "delta", "timer_t0.txt")
    assert window.load(copy)
    end = _end(window)
    model = window.model
    model.insert_network(end, _rung("delta", "X3", None))
    _place(qtbot, window, end, (0, 1), "DVP.CJ", ["P1"])
    model.insert_network(end + 1, _rung("delta", "X4", "Y3"))  # skipped by the jump
    model.insert_network(end + 2, LadderNetwork())
    _place(qtbot, window, end + 2, (0, 0), "DVP.P", ["P1"])
    model.insert_network(end + 3, _rung("delta", "X5", None))
    _place(qtbot, window, end + 3, (0, 1), "DVP.CALL", ["P2"])
    model.insert_network(end + 4, LadderNetwork())
    _place(qtbot, window, end + 4, (0, 0), "DVP.FEND", [])
    model.insert_network(end + 5, LadderNetwork())
    _place(qtbot, window, end + 5, (0, 0), "DVP.P.SUB", ["P2"])
    model.insert_network(end + 6, _rung("delta", "M1000", "Y4"))
    model.insert_network(end + 7, LadderNetwork())
    _place(qtbot, window, end + 7, (0, 0), "DVP.SRET", [])
    names = [c.name for n in model.networks[end:end + 8] for c in n.cells.values()
             if isinstance(c, FunctionBox)]
    assert names == ["DVP.CJ", "DVP.P", "DVP.CALL", "DVP.FEND", "DVP.P.SUB", "DVP.SRET"]
    _compile_and_start(qtbot, window)
    session = window.plc_docks.session
    x3, x4, x5 = (_device(t, "delta") for t in ("X3", "X4", "X5"))
    y3, y4 = _device("Y3", "delta"), _device("Y4", "delta")
    session.set_bit(x4, 1)
    session.run_scans(1)
    assert session.run.bit(y3) == 1 and session.run.bit(y4) == 0
    session.set_bit(x3, 1)  # CJ P1: the rung of Y3 is skipped, Y3 keeps its state
    session.set_bit(x4, 0)
    session.run_scans(2)
    assert session.run.bit(y3) == 1
    session.set_bit(x5, 1)  # CALL P2: the subroutine turns Y4 on
    session.run_scans(1)
    assert session.run.bit(y4) == 1
    session.stop()
    assert window.save_to(copy)
    text = copy.read_text(encoding="utf-8")
    assert text.endswith("LD\tX3\nCJ\tP1\nLD\tX4\nOUT\tY3\nP1\nLD\tX5\nCALL\tP2\nFEND\nP2\n"
                         "LD\tM1000\nOUT\tY4\nSRET\nEND\n")
    result = parse_file(copy)
    assert result.ok, result.diagnostics
    read = [i.name for i in result.program.instructions()]
    assert {"DVP.CJ", "DVP.P", "DVP.CALL", "DVP.FEND", "DVP.P.SUB", "DVP.SRET"} <= set(read)


def test_delta_master_control_placed_gates_its_coils(qtbot: QtBot, window: MainWindow,
                                                     tmp_path: Path) -> None:
    copy = _copy(tmp_path, "delta", "timer_t0.txt")
    assert window.load(copy)
    end = _end(window)
    model = window.model
    model.insert_network(end, _rung("delta", "X6", None))
    _place(qtbot, window, end, (0, 1), "DVP.MC", ["N0"])
    model.insert_network(end + 1, _rung("delta", "X7", "Y5"))
    model.insert_network(end + 2, LadderNetwork())
    _place(qtbot, window, end + 2, (0, 0), "DVP.MCR", ["N0"])
    _compile_and_start(qtbot, window)
    session = window.plc_docks.session
    session.set_bit(_device("X7", "delta"), 1)
    session.run_scans(1)
    assert session.run.bit(_device("Y5", "delta")) == 0  # MC off: its coils are written 0
    session.set_bit(_device("X6", "delta"), 1)
    session.run_scans(1)
    assert session.run.bit(_device("Y5", "delta")) == 1
    session.stop()
    assert window.save_to(copy)
    assert copy.read_text(encoding="utf-8").endswith(
        "LD\tX6\nMC\tN0\nLD\tX7\nOUT\tY5\nMCR\tN0\nEND\n")


def test_fatek_boxes_and_contacts_placed_run_and_save(qtbot: QtBot, window: MainWindow,
                                                      tmp_path: Path) -> None:
    copy = _copy(tmp_path, "fatek", "conveyor.lst")
    original = copy.read_bytes()
    assert window.load(copy)
    end = _end(window)
    model = window.model
    model.insert_network(end, _rung("fatek", "X10", None))
    _place(qtbot, window, end, (0, 1), "FBS.ADD", ["", "R10", "5", "R11"])
    model.insert_network(end + 1, _rung("fatek", "X11", None))
    _place(qtbot, window, end + 1, (0, 1), "FBS.INC", ["P", "R12"])  # pulse form: FUN 15P
    model.insert_network(end + 2, _rung("fatek", "X12", None))
    _place(qtbot, window, end + 2, (0, 1), "FBS.RST", ["C0"])
    model.insert_network(end + 3, _rung("fatek", "X13", "Y20", first=2))
    _place(qtbot, window, end + 3, (0, 1), "FBS.TU.ORG", ["X14"])  # the palette's TU entry
    contact = model.networks[end + 3].cells[(0, 1)]
    assert isinstance(contact, Contact) and mark(contact.function) == "↑"
    model.insert_network(end + 4, _rung("fatek", None, "Y21"))
    _place(qtbot, window, end + 4, (0, 0), "FBS.TD.ORG", ["X15"])  # on the rail: no SHORT
    falling = model.networks[end + 4].cells[(0, 0)]
    assert isinstance(falling, Contact) and mark(falling.function) == "↓"
    fo_bytes = [dict(zip((p.name for p in c.spec.params), c.params, strict=False)).get("fo")
                for n in model.networks for c in n.cells.values() if isinstance(c, FunctionBox)]
    fo_bytes = [fo for fo in fo_bytes if fo is not None]
    assert len(fo_bytes) == len(set(fo_bytes)) > 4  # each placed box its own FO byte
    _compile_and_start(qtbot, window)
    session = window.plc_docks.session
    r10, r11, r12 = (_device(t, "fatek") for t in ("R10", "R11", "R12"))
    session.write(r10, 30, 2)
    session.set_bit(_device("X10", "fatek"), 1)
    session.set_bit(_device("X11", "fatek"), 1)
    session.run_scans(3)
    assert session.run.read(r11, 2) == 35
    assert session.run.read(r12, 2) == 1  # +1 once: on the rising edge only
    x2 = _device("X2", "fatek")  # the conveyor's counter C0 counts X2's rising edges
    for _ in range(2):
        session.set_bit(x2, 1)
        session.run_scans(1)
        session.set_bit(x2, 0)
        session.run_scans(1)
    c0 = _device("C0", "fatek")
    assert session.run.read(c0, 2) == 2
    session.set_bit(_device("X12", "fatek"), 1)
    session.run_scans(1)
    assert session.run.read(c0, 2) == 0  # RST C0
    x15, y21 = _device("X15", "fatek"), _device("Y21", "fatek")
    session.set_bit(x15, 1)
    session.run_scans(1)
    session.set_bit(x15, 0)
    session.run_scans(1)
    assert session.run.bit(y21) == 1  # TD: one scan after X15 fell
    session.run_scans(1)
    assert session.run.bit(y21) == 0
    y20 = _device("Y20", "fatek")
    session.set_bit(_device("X13", "fatek"), 1)
    session.set_bit(_device("X14", "fatek"), 1)
    session.run_scans(1)
    assert session.run.bit(y20) == 1  # TU: one scan after X14 rose
    session.run_scans(1)
    assert session.run.bit(y20) == 0
    session.stop()
    assert window.save_to(copy)
    data = copy.read_bytes()
    head = original[:original.rindex(b"    41  END")]
    assert data.startswith(head)  # the rest byte for byte (CRLF/LF, headers, step numbers)
    text = data.decode("utf-8")
    for line in ("FUN 11   (+)", "    Sa: R10", "    Sb: 5", "    D : R11", "FUN 15P  (+1)",
                 "    D : R12", "RST      C0", "AND TU   X14", "ORG TD   X15"):
        assert line in text.splitlines(), line
    result = parse_file(copy)
    assert result.ok, result.diagnostics
    found = {i.name: i for i in result.program.instructions()}
    assert {"FBS.ADD", "FBS.INC", "FBS.RST", "FBS.TU", "FBS.TD.ORG"} <= set(found)
    assert found["FBS.INC"].param_map()["mode"] == 1
    assert window.load(copy)  # re-opened and drawn


def test_bad_operand_marks_its_row(qtbot: QtBot, window: MainWindow) -> None:
    assert window.load(paths.EXAMPLES / "fatek" / "conveyor.lst")
    end = _end(window)
    window.model.insert_network(end, _rung("fatek", "X10", None))
    window.tool_palette.set_function("FBS.MOV")
    window.editor.edits.open_function_dialog(end, 0, 1, "FBS.MOV")
    dialog = window.editor.edits.function_dialog
    assert dialog is not None
    for row, text in enumerate(["", "7", "X0"]):  # X0 is an input: not a destination
        dialog.table.item(row, 1).setText(text)
    dialog.accept()
    assert dialog.instruction is None and dialog.warning.isVisibleTo(dialog)
    assert "X0" in dialog.warning.text()
    assert dialog.table.currentRow() == 2  # the D row is marked
    dialog.reject()
    assert not any(isinstance(c, FunctionBox) for c in window.model.networks[end].cells.values())


def test_a_jump_to_a_missing_pointer_is_diagnosed_at_its_network(qtbot: QtBot, window: MainWindow,
                                                            tmp_path: Path) -> None:
    copy = _copy(tmp_path, "delta", "timer_t0.txt")
    assert window.load(copy)
    end = _end(window)
    window.model.insert_network(end, _rung("delta", "X3", None))
    _place(qtbot, window, end, (0, 1), "DVP.CJ", ["P9"])  # no P9 in the program
    qtbot.keyClick(window, Qt.Key.Key_F9)
    found = [d for d in window.errors.diagnostics() if d.is_error]
    assert [d.code for d in found] == ["dvp-pointer-missing"]
    assert found[0].network == end  # the compiler's structure check names the network
    assert window.plc_docks.session.run.engine is None  # not loaded
