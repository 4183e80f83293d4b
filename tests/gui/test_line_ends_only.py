"""Lines end only at LF, CR LF and CR (issue 30, item 7): VT, FS, GS, RS, NEL and the Unicode
line and paragraph separators in a comment move no diagnostic off the editor's line."""

from __future__ import annotations

from pathlib import Path

import pytest

from ladderworks.core.il.textform import split_lines
from ladderworks.core.plc.parameters import parse_parameters
from ladderworks.core.plc.scenario import parse_scenario
from ladderworks.gui.main_window import MainWindow

ODD = "a\x0bb\x1cc\x1dd\x1ee\x85f\u2028g\u2029h\u00a0i"  # none of these ends a line
PAD = "// " + "x" * 400 + "\n"  # enough text that the file reads as text, not binary
BROKEN = f"%@3\n{PAD}// {ODD}\nRD X0.0\nWRT Y0.1\nBADOP Y0.1\n%\n"
WRITES_INPUT = f"%@3\n{PAD}// {ODD}\nRD X0.0\nWRT Y0.1\n// {ODD}\nRD X0.0\nWRT X0.1\n%\n"


def _file(tmp_path: Path, text: str, newline: str = "\n") -> Path:
    path = tmp_path / "odd.LAD"
    path.write_bytes(text.replace("\n", newline).encode("utf-8"))
    return path


def _line_of(window: MainWindow, line: int) -> str:
    return window.text_view.document().findBlockByNumber(line - 1).text()


@pytest.mark.parametrize("newline", ["\n", "\r\n", "\r"])
def test_a_parse_error_is_on_its_line_in_the_text_view(window: MainWindow, tmp_path: Path,
                                                       newline: str) -> None:
    window.load(_file(tmp_path, BROKEN, newline))  # shown as text, with its error
    assert window.model.showing_text
    [error] = window.errors.diagnostics()
    assert error.code == "unknown-instruction" and error.line == 6
    assert _line_of(window, error.line) == "BADOP Y0.1"
    assert window.text_view.error_lines() == [6]
    assert not window.show_as_ladder()  # F5 reads the view's text: the same line
    assert [d.line for d in window.errors.diagnostics()] == [6]
    window.go_to_diagnostic(error)
    assert window.text_view.textCursor().block().text() == "BADOP Y0.1"


def test_a_check_diagnostic_goes_to_its_line(window: MainWindow, tmp_path: Path) -> None:
    assert window.load(_file(tmp_path, WRITES_INPUT))
    found = [d for d in window.check() if d.code == "write-input"]
    assert [d.line for d in found] == [8]
    window.actions_by_name["action_show_text"].trigger()  # F6: the file's lines
    window.text_view.go_to(found[0].line)
    assert window.text_view.textCursor().block().text() == "WRT X0.1"


def test_the_text_view_gives_the_odd_characters_back(window: MainWindow, tmp_path: Path
                                                     ) -> None:
    assert window.load(_file(tmp_path, WRITES_INPUT))
    window.show_as_text()
    assert window.text_view.document().blockCount() == len(split_lines(WRITES_INPUT)) + 1
    assert window.show_as_ladder()  # nothing changed: the same program, no error
    program = window.model.program()[0]
    assert program is not None
    assert program.networks[1].comments == [f" {ODD}"]


def test_parameter_and_scenario_lines_count_as_the_editor_does() -> None:
    parameters = parse_parameters(f"# {ODD}\nT0 = 5\nQ9 = 1\n")
    assert [d.line for d in parameters.diagnostics] == [3]
    scenario = parse_scenario(f"PMC SIGNAL DATA\nREMARK,{ODD}\nSET,0,Q9.9,1\n")
    assert [d.line for d in scenario.diagnostics] == [3]


def test_the_plc_control_screen_keeps_the_lines(window: MainWindow) -> None:
    control = window.plc_docks.control
    control.set_text(WRITES_INPUT)
    assert control.program_text() == WRITES_INPUT
    assert control.editor.blockCount() == len(split_lines(WRITES_INPUT)) + 1
    control.stripe_ms = 0
    result = control.compile()
    assert [(d.code, d.line) for d in result.diagnostics if d.is_error] == [("write-input", 8)]
