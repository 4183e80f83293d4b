"""Issues 25/26: the tool palette and the function property table offer a Delta or Fatek
program its own boxes (titles from the rows), check typed operands in its spelling, and a box
placed is saved as a line of the dialect's text that reads back."""

from __future__ import annotations

from pathlib import Path

from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core.dialects import parse_target
from ladderworks.core.il.reading import parse_file
from ladderworks.core.instructions import lookup
from ladderworks.core.ladder.model import Contact, FunctionBox, LadderNetwork
from ladderworks.gui.function_dialog import FunctionDialog
from ladderworks.gui.main_window import MainWindow


def _entries(window: MainWindow) -> list[str]:
    combo = window.tool_palette.functions
    return [combo.itemText(i) for i in range(combo.count())]


def test_palette_follows_the_program_dialect(window: MainWindow) -> None:
    assert window.load(paths.EXAMPLES / "delta" / "timer_t0.txt")
    entries = _entries(window)
    assert entries[0] == "— Delta DVP instructions —"
    assert "TMR — " + lookup("DVP.TMR").title in entries  # type: ignore[union-attr]
    assert not any(e.startswith("TMRB") for e in entries)  # no PMC row
    assert window.tool_palette.current_function() == "DVP.PLS"
    window.set_language("tr")
    assert _entries(window)[0] == "— Delta DVP komutları —"
    assert "TMR — " + lookup("DVP.TMR").title_tr in _entries(window)  # type: ignore[union-attr]
    window.set_language("en")
    assert window.load(paths.EXAMPLES / "fatek" / "conveyor.lst")
    assert _entries(window)[0] == "— Fatek FBs instructions —"
    window.tool_palette.set_function("FBS.TMR")
    assert window.load(paths.EXAMPLES / "mcode_decoder.LAD")  # back to the PMC's
    assert _entries(window)[0] == "— Seed manual instructions —"
    window.tool_palette.set_function("TMRB")


def test_function_dialog_checks_delta_operands(qtbot: QtBot) -> None:
    spec = lookup("DVP.MOV")
    assert spec is not None
    dialog = FunctionDialog(spec, dialect="delta")
    qtbot.addWidget(dialog)
    assert dialog.windowTitle().startswith("MOV — ")
    assert dialog.table.item(1, 2).text() == "T0–T255, C0–C255, D0–D9999"
    dialog.set_value("source", "K5")
    dialog.set_value("output", "X0")  # an input: not a place to write
    dialog.accept()
    assert dialog.instruction is None and dialog.warning.isVisibleTo(dialog)
    dialog.set_value("output", "D10")
    dialog.accept()
    assert dialog.instruction is not None
    assert FunctionDialog(spec, dialog.instruction, dialect="delta").values() == ["K5", "D10"]


def test_a_placed_delta_box_saves_and_reads_back(qtbot: QtBot, window: MainWindow,
                                                 tmp_path: Path) -> None:
    copy = tmp_path / "timer.txt"
    copy.write_bytes((paths.EXAMPLES / "delta" / "timer_t0.txt").read_bytes())
    assert window.load(copy)
    end = next(i for i, n in enumerate(window.model.networks)
               if any(isinstance(c, FunctionBox) and c.name == "END" for c in n.cells.values()))
    rung = LadderNetwork()
    rung.cells[(0, 0)] = Contact(parse_target("X1", "delta")[0])
    window.model.insert_network(end, rung)  # a rung with a contact, before END
    window.tool_palette.set_function("DVP.MOV")
    window.editor.edits.open_function_dialog(end, 0, 1, "DVP.MOV")
    dialog = window.editor.edits.function_dialog
    assert dialog is not None
    dialog.set_value("source", "K7")
    dialog.set_value("output", "D3")
    with qtbot.waitSignal(dialog.accepted):
        dialog.accept()
    boxes = [c for c in window.model.networks[end].cells.values()
             if isinstance(c, FunctionBox)]
    assert [b.name for b in boxes] == ["DVP.MOV"]
    assert window.save_to(copy)
    text = copy.read_text(encoding="utf-8")
    assert text.endswith("OUT    Y0\nLD\tX1\nMOV\tK7\tD3\nEND\n")  # the rest as it was
    result = parse_file(copy)
    assert result.ok and result.program.dialect == "delta"
    assert any(i.name == "DVP.MOV" for i in result.program.instructions())


def test_fatek_timer_takes_its_operands_and_not_its_fo_byte(qtbot: QtBot) -> None:
    spec = lookup("FBS.TMR")
    assert spec is not None
    dialog = FunctionDialog(spec, dialect="fatek")
    qtbot.addWidget(dialog)
    assert dialog.table.rowCount() == 2  # T50 and the preset; FO is not typed
    dialog.set_value("timer", "T50")
    dialog.set_value("preset", "R0")
    dialog.accept()
    assert dialog.instruction is not None
    again = FunctionDialog(spec, dialog.instruction, dialect="fatek")
    qtbot.addWidget(again)
    assert again.values() == ["T50", "R0"]
    dialog.set_value("timer", "C3")
    dialog.accept()
    assert dialog.warning.isVisibleTo(dialog)
