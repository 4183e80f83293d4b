"""Issue 26: a Fatek `OUT L` (retentive) coil in a network the user changes is saved as
`OUT L`, not `OUT` (every value a user sets is kept); NOT makes it a plain inverted coil."""

from __future__ import annotations

from pathlib import Path

from ladderworks import paths
from ladderworks.core.dialects.fatek import DEVICES
from ladderworks.core.il.reading import parse_file
from ladderworks.core.ladder.model import Coil
from ladderworks.gui.main_window import MainWindow


def _retentive(window: MainWindow) -> tuple[int, int, int]:
    """The network and cell of the coil on Y10, Y11 or Y12 (the listing's `OUT L`)."""
    wanted = {DEVICES.bit(name) for name in ("Y10", "Y11", "Y12")}
    return next((index, *cell) for index, network in enumerate(window.model.networks)
                for cell, element in network.cells.items()
                if isinstance(element, Coil) and element.address in wanted)


def _copy(tmp_path: Path) -> Path:
    copy = tmp_path / "conveyor.lst"
    copy.write_bytes((paths.EXAMPLES / "fatek" / "conveyor.lst").read_bytes())
    return copy


def test_out_l_in_a_changed_network_is_saved_as_out_l(window: MainWindow,
                                                       tmp_path: Path) -> None:
    copy = _copy(tmp_path)
    assert "OUT L    Y10" in copy.read_text(encoding="utf-8")
    assert window.load(copy)
    last, row, col = _retentive(window)
    # the network changes: its coil gets another output
    assert window.editor.edits.set_address(last, row, col, str(DEVICES.bit("Y11")))
    assert window.save_to(copy)
    lines = copy.read_text(encoding="utf-8").splitlines()
    assert "OUT L    Y11" in lines, lines[-6:]
    assert not any(line.split() == ["OUT", "Y11"] for line in lines)
    result = parse_file(copy)
    assert result.ok, result.diagnostics
    assert window.load(copy)  # read back: still retentive, saved so again
    last, row, col = _retentive(window)
    assert window.editor.edits.set_address(last, row, col, str(DEVICES.bit("Y12")))
    assert window.save_to(copy)
    assert "OUT L    Y12" in copy.read_text(encoding="utf-8").splitlines()


def test_not_on_an_out_l_coil_makes_out_not(window: MainWindow, tmp_path: Path) -> None:
    copy = _copy(tmp_path)
    assert window.load(copy)
    last, row, col = _retentive(window)
    assert window.editor.edits.invert(last, row, col)
    assert window.save_to(copy)
    assert "OUT NOT  Y10" in copy.read_text(encoding="utf-8").splitlines()
