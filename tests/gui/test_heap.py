"""The open program's objects are frozen once laid out, and released when another is read."""

from __future__ import annotations

import gc
import weakref
from pathlib import Path

import pytest

from ladderworks.core.collector import release_frozen
from ladderworks.gui.editor import progressive
from ladderworks.gui.main_window import MainWindow
from ladderworks.paths import EXAMPLES
from tests.real_programs import real_bytes


class _Cycle:
    """An object in a reference cycle: only the cycle collector frees it."""

    def __init__(self) -> None:
        self.me = self


def test_a_laid_out_program_is_frozen_and_released_by_the_next_one(
        window: MainWindow, tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(progressive, "AT_ONCE", 5)  # laid out in the background, as a large one
    source = tmp_path / "dressing.LAD"
    source.write_bytes(real_bytes("FANUC_X22_FRAG_fc62224_DRESSING"))
    try:
        held = _Cycle()  # alive while the program is laid out: frozen with it
        alive = weakref.ref(held)
        assert window.load(source)
        window.editor.finish_loading()
        assert gc.get_freeze_count() > 0
        del held  # now garbage, but in the permanent generation
        gc.collect()
        assert alive() is not None  # the collector no longer walks the frozen objects
        assert window.load(source)  # released, then collected and frozen again
        window.editor.finish_loading()
        assert alive() is None
    finally:
        release_frozen()


def test_an_edit_compares_networks_as_the_saved_drawing_does(window: MainWindow) -> None:
    assert window.load(EXAMPLES / "or_double.LAD")
    network = window.editor.networks[0]
    copy = network.copy()
    assert copy == network and copy.state() == network.state()
    copy.comments.append("changed")
    assert copy != network and copy.state() != network.state()
    copy = network.copy()
    copy.links.add((0, 1)) if (0, 1) not in copy.links else copy.links.discard((0, 1))
    assert copy != network and copy.state() != network.state()
