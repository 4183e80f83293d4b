"""A WinProladder project (.pdw) in the window: opened as a Fatek ladder with its comments as
names; Save never writes it and Save As offers its listing (.lst), saying why."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.gui import file_dialogs
from ladderworks.gui.main_window import MainWindow
from tests.core.dialects.pdw_builder import build
from tests.core.dialects.test_pdw_real import project

WORDS = [0x4000, 0x9001, 0xC100]  # ORG X0, AND NOT X1, OUT Y0


def _offered(monkeypatch: pytest.MonkeyPatch, target: Path | None) -> list[tuple[str, str]]:
    """Save dialogs answered with `target` (None: cancelled); their default names and filters."""
    offered: list[tuple[str, str]] = []

    def answer(_parent: object, _title: str, default: str, filters: str) -> str:
        offered.append((default, filters))
        return "" if target is None else str(target)

    monkeypatch.setattr(file_dialogs, "save_file_name", answer)
    return offered


def test_a_project_opens_and_saves_as_its_listing_only(
        window: MainWindow, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    path = tmp_path / "machine.pdw"
    data = build(WORDS, {"X0": b"START"})
    path.write_bytes(data)
    assert window.load(path)
    program, diagnostics = window.editor.program()
    assert program is not None and not diagnostics and program.dialect == "fatek"
    assert program.symbols is not None and len(program.symbols.by_address) == 1
    listing = tmp_path / "machine.lst"
    offered = _offered(monkeypatch, listing)
    assert window.save()
    assert "machine.pdw is a WinProladder project (.pdw)" in window.last_warning
    assert offered == [(str(listing), "Fatek WinProladder listings (*.lst *.LST);;All files (*)")]
    assert path.read_bytes() == data  # never written
    text = listing.read_bytes()
    assert text.startswith(b"Printed Item: Mnemonic - Main_unit1\r\n")
    assert b"00002M OUT Y0\r\n" in text
    assert window.path == listing


def test_save_as_onto_a_project_is_refused_too(
        window: MainWindow, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    other = tmp_path / "other.pdw"
    other.write_bytes(b"Fatek WinProladder, File Format 1 and more")
    source = tmp_path / "machine.pdw"
    source.write_bytes(build(WORDS))
    assert window.load(source)
    offered = _offered(monkeypatch, None)  # the listing offered, then cancelled
    assert not window.save_to(other)
    assert other.read_bytes() == b"Fatek WinProladder, File Format 1 and more"
    assert offered and offered[0][0].endswith("machine.lst")


def test_a_project_that_does_not_read_is_shown_as_its_listing_and_kept(
        window: MainWindow, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    path = tmp_path / "cut.pdw"
    data = build([*WORDS, 0x0123])  # a code not decoded: an error after the first steps
    path.write_bytes(data)
    assert window.load(path)
    text = window.text_view.toPlainText()
    assert "00002M OUT Y0" in text
    assert any(d.code == "pdw-code" for d in window.errors.diagnostics())
    _offered(monkeypatch, None)
    assert not window.save()
    assert path.read_bytes() == data


def test_the_real_project_opens_without_a_pdw_error(window: MainWindow) -> None:
    assert window.load(project())
    assert not [d for d in window.errors.diagnostics() if d.code.startswith("pdw-")]
