"""A WPLSoft `.dvp` project opens in the console as ladder; Save never writes over the project:
it says why and offers Save As in the Delta instruction-list form."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.core.dialects import parse_target
from ladderworks.core.ladder.model import Contact
from ladderworks.gui import file_dialogs
from ladderworks.gui.main_window import MainWindow
from tests.core.dialects.dvp_samples import make_dvp


def test_a_project_opens_as_ladder_and_is_saved_as_an_instruction_list(
        window: MainWindow, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    project = tmp_path / "machine.dvp"
    data = make_dvp(comments=b"X0$&start\n")
    project.write_bytes(data)
    assert window.load(project)
    assert window.model.dialect == "delta" and not window.model.showing_text
    contact = window.model.networks[0].cells[(0, 0)]
    assert isinstance(contact, Contact) and contact.address == parse_target("X0", "delta")[0]
    offered: list[tuple[str, str]] = []
    target = tmp_path / "machine.il"

    def ask(_parent: object, _caption: str, name: str, filters: str) -> str:
        offered.append((name, filters))
        return str(target)

    monkeypatch.setattr(file_dialogs, "save_file_name", ask)
    assert window.save()  # Save: refused over the .dvp, Save As in the text form instead
    assert project.read_bytes() == data  # the project is untouched
    assert ".dvp" in window.last_warning
    assert offered == [(str(tmp_path / "machine.il"),
                        "Delta DVP instruction lists (*.il *.IL *.txt *.TXT);;All files (*)")]
    assert target.read_bytes().decode().split() == [
        "LD", "X0", "TMR", "T0", "K5", "LD", "T0", "OUT", "Y0", "LD", "X1", "RST", "T0", "END"]
    assert window.load(target)  # the instruction list reads back as the same program
    assert window.model.dialect == "delta"


def test_a_damaged_project_shows_its_error_and_is_never_overwritten(
        window: MainWindow, tmp_path: Path) -> None:
    project = tmp_path / "cut.dvp"
    data = make_dvp()[:-40]
    project.write_bytes(data)
    assert window.load(project)
    assert window.model.showing_text
    assert [d.code for d in window.errors.diagnostics()] == ["dvp-truncated"]
    assert not window.save_to(project)
    assert project.read_bytes() == data


def test_a_project_with_damaged_words_shows_the_instructions_read_before_them(
        window: MainWindow, tmp_path: Path) -> None:
    project = tmp_path / "damaged.dvp"
    data = make_dvp((0xA400, 0x4500, 0xA401, 0xA700, 0x4501, 0x800F))
    project.write_bytes(data)
    assert window.load(project)
    assert window.model.showing_text
    assert window.text_view.toPlainText().split() == ["LD", "X0", "OUT", "Y0", "LD", "X1"]
    assert [(d.code, d.line) for d in window.errors.diagnostics()] == [("dvp-unknown-device", 4)]
    assert not window.save_to(project)
    assert project.read_bytes() == data
