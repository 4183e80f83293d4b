"""Issue 25: a Delta DVP program opens in the console, is drawn in Delta's spelling, compiles
into the PLC and runs (an output changes), and is saved back byte for byte."""

from __future__ import annotations

from pathlib import Path

from PySide6.QtCore import Qt
from PySide6.QtGui import QAction
from pytestqt.qtbot import QtBot

from ladderworks import paths
from ladderworks.core.dialects import parse_target
from ladderworks.core.ladder.model import Coil, Contact
from ladderworks.gui.main_window import MainWindow

EXAMPLE = paths.EXAMPLES / "delta" / "timer_t0.txt"


def _action(window: MainWindow, name: str) -> QAction:
    action = window.findChild(QAction, name)
    assert action is not None, name
    return action


def test_a_delta_program_opens_draws_and_runs(qtbot: QtBot, window: MainWindow) -> None:
    assert window.load(EXAMPLE)
    assert window.model.dialect == "delta"
    networks = window.model.networks
    contact = networks[0].cells[(0, 0)]
    assert isinstance(contact, Contact)
    assert contact.address == parse_target("X0", "delta")[0]
    window.editor.make_visible_items()
    items = [item for _index, item in window.editor.network_items.made()]
    assert items
    first = min(items, key=lambda item: item.number)
    assert first.label_lines(contact)[0] == "X0"  # Delta's spelling, not X0.0
    coil = next(cell for cell in networks[1].cells.values() if isinstance(cell, Coil))
    second = next(item for item in items if item.number == 2)
    assert second.label_lines(coil)[0] == "Y0"
    session = window.plc_docks.session
    session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)
    assert session.run.engine is not None
    _action(window, "action_plc_start").trigger()
    x0, y0 = parse_target("X0", "delta")[0], parse_target("Y0", "delta")[0]
    session.run_scans(2)
    assert session.run.bit(y0) == 0
    session.set_bit(x0, 1)
    session.run_scans(1100 // session.run.engine.period_ms + 2)
    assert session.run.bit(y0) == 1
    session.set_bit(x0, 0)
    session.run_scans(2)
    assert session.run.bit(y0) == 0


def test_an_unchanged_delta_program_saves_as_it_was(window: MainWindow, tmp_path: Path) -> None:
    copy = tmp_path / "motor.txt"
    data = (paths.EXAMPLES / "delta" / "motor_flip_flop.txt").read_bytes().replace(b"\n", b"\r\n")
    copy.write_bytes(data)
    assert window.load(copy)
    other = tmp_path / "other.txt"
    assert window.save_to(other)  # written afresh from the console's networks
    assert other.read_bytes() == data


def test_docks_take_delta_spelling(qtbot: QtBot, window: MainWindow) -> None:
    assert window.load(paths.EXAMPLES / "delta" / "counter_reset.txt")
    session = window.plc_docks.session
    session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)
    assert session.run.engine is not None and session.run.program_dialect == "delta"
    result = window.plc_docks.scenario.run_file(
        paths.EXAMPLES / "delta" / "counter_reset.scenario.csv")
    assert result is not None and result.passed
    bits = window.plc_docks.bit_display
    bits.set_address(0, "M8")
    assert bits.rows[0].address == parse_target("M8", "delta")[0].byte_address()
    assert bits.rows[0].edit.text() == "M8"
    bits.set_address(1, "D100")
    assert bits.rows[1].edit.text() == "D100"
    bits.set_address(2, "X8")
    assert bits.rows[2].address is None  # octal: an error in the row, no address


def test_an_address_typed_in_a_delta_program_is_a_delta_device(
        qtbot: QtBot, window: MainWindow, tmp_path: Path) -> None:
    copy = tmp_path / "t.txt"
    copy.write_bytes((paths.EXAMPLES / "delta" / "timer_t0.txt").read_bytes())
    assert window.load(copy)
    editor = window.editor
    editor.inline.open_address(0, 0, 0)
    assert editor.inline_editor.text() == "X0"
    editor.inline_editor.setText("X8")
    qtbot.keyClick(editor.inline_editor, Qt.Key.Key_Return)
    assert "octal" in editor.inline_message.text()
    editor.inline_editor.setText("X17")
    qtbot.keyClick(editor.inline_editor, Qt.Key.Key_Return)
    contact = window.model.networks[0].cells[(0, 0)]
    assert isinstance(contact, Contact)
    assert contact.address == parse_target("X17", "delta")[0]
    other = tmp_path / "saved.txt"
    assert window.save_to(other)
    lines = other.read_text(encoding="utf-8").splitlines()
    # the changed rung written in Delta, the others as they were
    assert lines[1:] == ["LD\tX17", "TMR\tT0\tK10", "LD     T0", "OUT    Y0", "END"]


def test_cross_reference_and_force_list_in_delta_spelling(qtbot: QtBot,
                                                          window: MainWindow) -> None:
    assert window.load(paths.EXAMPLES / "delta" / "motor_flip_flop.txt")
    dock = window.cross_reference
    dock.show_address("D500")
    model = dock.model
    assert model.rowCount() == 3
    assert {model.data(model.index(row, 0)) for row in range(3)} == {"D500"}
    assert model.data(model.index(0, 1)) == ""  # no FANUC signal name
    session = window.plc_docks.session
    session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)
    session.force(parse_target("X3", "delta")[0], 1)
    forces = window.plc_docks.force_list
    forces.show_entries(session.run.forces())
    assert forces.describe(forces.entries[0])[1] == "X3"


def test_a_delta_file_with_an_error_is_fixed_in_the_text_view(window: MainWindow,
                                                               tmp_path: Path) -> None:
    broken = tmp_path / "broken.txt"
    broken.write_text("LD X0\nANI X8\nOUT Y0\nEND\n", encoding="utf-8")
    window.load(broken)
    assert window.model.showing_text  # it has an error: shown as text, the error listed
    assert window.errors.tree.topLevelItemCount() == 1
    assert "octal" in window.errors.tree.topLevelItem(0).text(window.errors.tree.columnCount() - 1)
    window.text_view.setPlainText("LD X0\nANI X7\nOUT Y0\nEND\n")
    assert window.show_as_ladder()
    assert window.model.dialect == "delta"
    assert [type(cell).__name__ for cell in window.model.networks[0].cells.values()].count(
        "Contact") == 2


def test_the_plc_control_screen_compiles_delta_text(window: MainWindow) -> None:
    control = window.plc_docks.control
    assert control.open_file(EXAMPLE)
    control.stripe_ms = 0
    result = control.compile()
    assert result.ok and result.binary is not None


def test_a_wplsoft_export_opens_drawn_and_names_what_it_does_not_simulate(
        qtbot: QtBot, window: MainWindow, tmp_path: Path) -> None:
    """Issue 36: WPLSoft's CSV export opens as ladder; the PLC control screen lists the
    instructions the scan passes by; the file saves back byte for byte."""
    example = paths.EXAMPLES / "delta" / "wplsoft_outputs.csv"
    assert window.load(example)
    assert window.model.dialect == "delta"
    assert all(network.listing is None for network in window.model.networks)
    control = window.plc_docks.control
    program, _diagnostics = window.model.program()
    assert program is not None
    assert window.plc_docks.session.load_program(program).ok
    control.show()
    qtbot.waitUntil(lambda: control.skipped.isVisible(), timeout=3000)
    assert "PID D0 D10 D100 D200 (line 20)" in control.skipped.text()
    other = tmp_path / "again.csv"
    assert window.save_to(other)
    assert other.read_bytes() == example.read_bytes()


def test_the_real_lathe_export_opens_as_ladder_and_saves_as_it_was(
        window: MainWindow, tmp_path: Path) -> None:
    """The WPLSoft export of a real machine (read from ../shared, never copied)."""
    from tests.real_programs import real_programs_dir

    path = real_programs_dir() / "delta" / "METALURGICA_c91257f_proejto_clp.csv"
    assert window.load(path)
    assert window.model.dialect == "delta"
    assert sum(1 for network in window.model.networks if network.cells) == 71  # + a new one
    assert all(network.listing is None for network in window.model.networks)
    other = tmp_path / "again.csv"
    assert window.save_to(other)
    assert other.read_bytes() == path.read_bytes()


def test_an_example_scenario_names_its_program_in_the_ide(qtbot: QtBot,
                                                          window: MainWindow) -> None:
    """Issue 38 item 10: PLC › Run scenario of a Delta example names its PROGRAM: run on
    another program, the dock says which program the scenario is for."""
    assert window.load(paths.EXAMPLES / "delta" / "counter_reset.txt")
    session = window.plc_docks.session
    session.run.realtime = False
    qtbot.keyClick(window, Qt.Key.Key_F9)
    dock = window.plc_docks.scenario
    own = dock.run_file(paths.EXAMPLES / "delta" / "counter_reset.scenario.csv")
    assert own is not None and own.passed
    assert not own.scenario.diagnostics  # its PROGRAM line names the program in the PLC
    other = dock.run_file(paths.EXAMPLES / "delta" / "timer_t0.scenario.csv")
    assert other is not None
    assert [d.code for d in other.scenario.diagnostics] == ["scenario-other-program"]
    assert other.scenario.program == "timer_t0.txt"
