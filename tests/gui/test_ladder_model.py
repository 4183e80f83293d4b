"""The ladder model: it owns the networks and the mode; undo commands change it in redo/undo."""

from __future__ import annotations

import pytest
from pytestqt.qtbot import QtBot

from ladderworks.core import ladder as core
from ladderworks.core.address import parse_address
from ladderworks.core.ladder import Coil, Contact, EditRefused, LadderNetwork
from ladderworks.gui.editor.commands import NetworkEditCommand, NetworkListCommand
from ladderworks.gui.editor.ladder_model import LadderModel, Mode
from ladderworks.gui.editor.step_name import editor_step
from ladderworks.gui.main_window import MainWindow
from ladderworks.paths import EXAMPLES


class Recorder:
    """Every signal the model sends, in order."""

    def __init__(self, model: LadderModel) -> None:
        self.seen: list[tuple[object, ...]] = []
        model.networks_inserted.connect(lambda first, count: self.seen.append(
            ("inserted", first, count)))
        model.network_removed.connect(lambda index: self.seen.append(("removed", index)))
        model.network_changed.connect(lambda index: self.seen.append(("changed", index)))
        model.modified_changed.connect(lambda modified: self.seen.append(("modified", modified)))
        model.mode_changed.connect(lambda mode: self.seen.append(("mode", mode)))


def _contact(text: str) -> Contact:
    return Contact(parse_address(text))


def test_pushing_an_edit_makes_it_and_undo_takes_it_back(qtbot: QtBot) -> None:
    model = LadderModel()
    first = model.networks[0]
    seen = Recorder(model)
    edit = model.prepare(0, lambda n: core.place(n, 0, 0, _contact("X1.0")))
    assert first.is_empty() and seen.seen == []  # worked out on a copy: nothing changed yet
    model.undo_stack.push(NetworkEditCommand(model, 0, edit, editor_step("Place contact")))
    assert first.cells == {(0, 0): _contact("X1.0")}
    assert len(model.networks) == 2 and model.networks[1].is_empty()  # room for the next one
    assert seen.seen == [("changed", 0), ("inserted", 1, 1), ("modified", True)]
    seen.seen.clear()
    model.undo_stack.undo()
    assert first.is_empty() and len(model.networks) == 1
    assert seen.seen == [("removed", 1), ("changed", 0), ("modified", False)]
    model.undo_stack.redo()
    assert first.cells == {(0, 0): _contact("X1.0")} and len(model.networks) == 2
    assert model.networks[0] is first  # the same network, changed in place


def test_an_edit_inside_the_program_appends_no_network(qtbot: QtBot) -> None:
    model = LadderModel()
    model.undo_stack.push(NetworkEditCommand(
        model, 0, model.prepare(0, lambda n: core.place(n, 0, 0, _contact("X1.0"))),
        editor_step("a")))
    model.undo_stack.push(NetworkEditCommand(
        model, 0, model.prepare(0, lambda n: core.place(n, 0, 10, Coil(parse_address("Y1.0")))),
        editor_step("b")))
    assert len(model.networks) == 2
    model.undo_stack.undo()
    assert len(model.networks) == 2 and (0, 10) not in model.networks[0].cells


def test_a_refused_edit_changes_nothing_and_pushes_nothing(qtbot: QtBot) -> None:
    model = LadderModel()
    seen = Recorder(model)
    with pytest.raises(EditRefused):
        model.prepare(0, lambda n: core.place(n, 0, n.columns, _contact("X1.0")))
    assert model.networks[0].is_empty() and model.undo_stack.count() == 0 and seen.seen == []


def test_deleting_a_network_is_undone_with_the_same_network(qtbot: QtBot) -> None:
    model = LadderModel()
    kept = LadderNetwork()
    core.place(kept, 0, 0, _contact("X2.0"))
    model.insert_network(0, kept)
    seen = Recorder(model)
    model.undo_stack.push(NetworkListCommand(model, 0, None, editor_step("Delete network")))
    assert kept not in model.networks and seen.seen[0] == ("removed", 0)
    model.undo_stack.undo()
    assert model.networks[0] is kept and seen.seen[-2] == ("inserted", 0, 1)


def test_the_mode_is_the_models_and_the_window_follows_it(window: MainWindow) -> None:
    model = window.model
    seen = Recorder(model)
    assert model.mode is Mode.LADDER and window.pages.currentWidget() is window.editor
    window.show_as_text()
    assert model.showing_text and window.pages.currentWidget() is window.text_view
    window.text_view.document().setModified(True)
    assert window.is_modified()  # in text mode the text's modified state counts
    window.text_view.document().setModified(False)
    assert window.show_as_ladder()
    assert model.mode is Mode.LADDER and window.pages.currentWidget() is window.editor
    assert [event for event in seen.seen if event[0] == "mode"] == [("mode", "text"),
                                                                   ("mode", "ladder")]


def test_the_view_draws_what_the_model_announces(window: MainWindow) -> None:
    assert window.load(EXAMPLES / "spindle_override.LAD")
    model, view = window.model, window.editor
    assert view.networks is model.networks
    count = len(model.networks)
    moved = view.network_items[1].pos().y()
    model.undo_stack.push(NetworkEditCommand(  # made on the model, not through the view
        model, 0, model.prepare(0, lambda n: core.insert_row(n, 0)), editor_step("Insert row")))
    assert view.network_items[1].pos().y() > moved  # the networks below moved down
    model.undo_stack.push(NetworkListCommand(model, 0, None, editor_step("Delete network")))
    assert len(view.network_items) == count - 1 == len(view.layout_.tops)
    assert view.network_items[0].number == 1 and view.network_items[0].network is model.networks[0]
    model.undo_stack.undo()
    model.undo_stack.undo()
    assert len(view.network_items) == count and view.network_items[1].pos().y() == moved
