"""Edit operations: what each does, that its returned edit undoes it exactly, and refusals."""

from __future__ import annotations

import random

import pytest

from ladderworks.core.address import parse_address
from ladderworks.core.ladder import (
    WIRE,
    Coil,
    Contact,
    EditRefused,
    FunctionBox,
    LadderNetwork,
    Selection,
    add_parallel,
    copy_text,
    cut,
    delete,
    delete_row,
    draw_line,
    erase_line,
    insert_row,
    invert,
    network_from_text,
    paste,
    place,
    replace_element,
    set_address,
    set_comment,
    set_lead,
    set_network_comments,
    set_params,
)
from ladderworks.core.ladder.decompose import network_to_instructions


def _a(text: str):
    return parse_address(text)


def _basic() -> LadderNetwork:
    network = LadderNetwork(4, 1)
    network.cells.update({(0, 0): Contact(_a("X0.0")), (0, 1): WIRE, (0, 2): WIRE,
                          (0, 3): WIRE, (0, 4): Coil(_a("Y0.0"))})
    return network


def _code(network: LadderNetwork) -> str:
    code, problems = network_to_instructions(network)
    assert problems == [], problems
    return " / ".join(f"{i.name} {i.operand or ''}".strip() for i in code or [])


def _undo_redo(network: LadderNetwork, undo) -> None:
    """The returned edit restores the old drawing; its inverse redoes the change."""
    after = network.copy()
    redo = undo.apply(network)
    before = network.copy()
    assert before != after
    undo_again = redo.apply(network)
    assert network == after
    undo_again.apply(network)
    assert network == before


def test_place_contact_and_undo() -> None:
    network = _basic()
    before = network.copy()
    undo = place(network, 0, 1, Contact(_a("X0.1"), negated=True))
    assert _code(network) == "RD X0.0 / AND.NOT X0.1 / WRT Y0.0"
    undo.apply(network)
    assert network == before


def test_place_grows_rows_and_undo_shrinks_them() -> None:
    network = _basic()
    undo = place(network, 3, 0, Contact(_a("X0.1")))
    assert network.rows == 4
    undo.apply(network)
    assert network.rows == 1


@pytest.mark.parametrize("op", [
    lambda n: replace_element(n, 0, 0, Contact(_a("X1.1"))),
    lambda n: delete(n, 0, 0),
    lambda n: invert(n, 0, 0),
    lambda n: invert(n, 0, 4),
    lambda n: set_address(n, 0, 0, "X3.3"),
    lambda n: set_comment(n, 0, 4, "çıkış"),
    lambda n: set_lead(n, 0, 0, ["önce"]),
    lambda n: set_network_comments(n, ["başlık"]),
    lambda n: add_parallel(n, 0, 0),
    lambda n: add_parallel(n, 0, 4),
    lambda n: insert_row(n, 0),
    lambda n: insert_row(n, 0, after=True),
    lambda n: draw_line(n, (1, 0), (1, 3)),
    lambda n: draw_line(n, (0, 2), (2, 2)),
    lambda n: erase_line(n, (0, 1), (0, 3)),
])
def test_every_operation_is_undone_exactly(op) -> None:
    network = _basic()
    _undo_redo(network, op(network))


def test_invert_gives_normally_closed_and_inverted_coil() -> None:
    network = _basic()
    invert(network, 0, 0)
    invert(network, 0, 4)
    assert _code(network) == "RD.NOT X0.0 / WRT.NOT Y0.0"


def test_or_tool_adds_a_parallel_contact_and_a_parallel_coil() -> None:
    network = _basic()
    add_parallel(network, 0, 0, Contact(_a("X0.1")))
    add_parallel(network, 0, 4, Coil(_a("Y0.1")))
    assert _code(network) == "RD X0.0 / OR X0.1 / WRT Y0.0 / WRT Y0.1"
    add_parallel(network, 0, 0, Contact(_a("X0.2")))  # the row below is taken: a row goes in
    assert network.rows == 3
    assert _code(network) == "RD X0.0 / OR X0.2 / OR X0.1 / WRT Y0.0 / WRT Y0.1"


def test_line_tool_draws_a_branch() -> None:
    network = _basic()
    place(network, 1, 1, Contact(_a("X0.1")))
    draw_line(network, (1, 0), (1, 1))  # a wire from the rail to the contact
    draw_line(network, (0, 2), (1, 2))
    assert network.cells[(1, 0)] == WIRE
    assert _code(network) == "RD X0.0 / OR X0.1 / WRT Y0.0"
    erase_line(network, (0, 2), (1, 2))
    assert (0, 2) not in network.links


def test_insert_row_inside_a_box_grows_it_and_keeps_links() -> None:
    network = LadderNetwork(4, 2)
    box = FunctionBox.new("SFT", (_a("R10"),))  # four inputs
    network.cells[(0, 2)] = box
    network.links.add((0, 1))
    undo = insert_row(network, 1)
    grown = network.cells[(0, 2)]
    assert isinstance(grown, FunctionBox)
    assert grown.height == 5 and grown.pins == (0, 2, 3, 4)
    assert network.links == {(0, 1), (1, 1)}
    undo.apply(network)
    assert network.cells[(0, 2)] == box


def test_delete_row_moves_rows_up() -> None:
    network = _basic()
    place(network, 2, 0, Contact(_a("X0.3")))
    undo = delete_row(network, 1)
    assert (1, 0) in network.cells and network.rows == 2
    undo.apply(network)
    assert (2, 0) in network.cells


def test_set_params_checks_texts_like_the_instruction_list() -> None:
    network = LadderNetwork(4, 1)
    network.cells[(0, 2)] = FunctionBox.new("TMRB")
    set_params(network, 0, 2, ["3", "1000"])
    assert network.cells[(0, 2)].params == (3, 1000)
    with pytest.raises(EditRefused) as refused:
        set_params(network, 0, 2, ["300", "1000"])
    assert refused.value.diagnostic.code == "param-range"
    assert refused.value.diagnostic.cell == (0, 2)


@pytest.mark.parametrize(("op", "code"), [
    (lambda n: place(n, 0, 4, Contact(_a("X0.1"))), "edit-coil-column"),
    (lambda n: place(n, 0, 3, FunctionBox.new("TMR", (1,))), "edit-box-room"),
    (lambda n: place(n, 0, 9, Contact(_a("X0.1"))), "edit-outside"),
    (lambda n: delete(n, 0, 1 + 9), "edit-no-element"),
    (lambda n: invert(n, 0, 1), "edit-no-element"),
    (lambda n: draw_line(n, (0, 0), (1, 1)), "edit-line"),
    (lambda n: set_address(n, 0, 0, "Q1.0"), "unknown-area"),
    (lambda n: set_address(n, 0, 0, "X1"), "bit-expected"),
    (lambda n: paste(n, 0, 0, "RD X0.0"), "grid-text"),
])
def test_refused_edits_change_nothing(op, code: str) -> None:
    network = _basic()
    before = network.copy()
    with pytest.raises(EditRefused) as refused:
        op(network)
    assert refused.value.diagnostic.code == code
    assert network == before


def test_copy_and_paste_a_selection() -> None:
    network = _basic()
    add_parallel(network, 0, 0, Contact(_a("X0.1"), comment="ikinci"))
    text = copy_text(network, Selection.spanning((0, 0), (1, 0)))
    undo = paste(network, 0, 1, text)
    assert network.cells[(1, 1)] == Contact(_a("X0.1"), comment="ikinci")
    assert (0, 1) in network.links and (0, 2) in network.links
    undo.apply(network)
    assert network.cells[(0, 1)] == WIRE


def test_cut_clears_and_paste_puts_back() -> None:
    network = _basic()
    before = network.copy()
    text, undo = cut(network, Selection(0, 0, 0, 4))
    assert network.cells == {}
    paste(network, 0, 0, text)
    assert network == before
    undo.apply(network)


def test_a_whole_network_as_text_and_back() -> None:
    network = _basic()
    place(network, 1, 1, FunctionBox.new("TMRB", (3, 96), comment="kutu"))
    set_network_comments(network, ["ağ", "// iki"])
    assert network_from_text(copy_text(network)) == network


ELEMENTS = [Contact(_a("X0.1")), Contact(_a("X0.2"), True), WIRE, FunctionBox.new("TMR", (1,))]


def _random_edit(network: LadderNetwork, rnd: random.Random):
    r, c = rnd.randrange(4), rnd.randrange(5)
    choice = rnd.randrange(10)
    if choice == 0:
        return place(network, r, c, rnd.choice(ELEMENTS))
    if choice == 1:
        return place(network, r, 4, Coil(_a("Y1.0")))
    if choice == 2:
        return delete(network, r, c)
    if choice == 3:
        return invert(network, r, c)
    if choice == 4:
        return add_parallel(network, r, c)
    if choice == 5:
        return insert_row(network, r, rnd.random() < 0.5)
    if choice == 6:
        return delete_row(network, min(r, network.rows - 1))
    if choice == 7:
        return draw_line(network, (r, c), (r, rnd.randrange(5)))
    if choice == 8:
        return draw_line(network, (r, c), (rnd.randrange(4), c))
    return cut(network, Selection.spanning((r, c), (r + 1, c)))[1]


def test_random_edit_sequences_undo_and_redo_exactly() -> None:
    rnd = random.Random(7)
    for _ in range(150):
        network = _basic()
        snapshots = [network.copy()]
        undos = []
        for _ in range(10):
            try:
                undos.append(_random_edit(network, rnd))
            except EditRefused:
                continue
            snapshots.append(network.copy())
        redos = []
        for undo, snapshot in zip(reversed(undos), reversed(snapshots[:-1]), strict=True):
            redos.append(undo.apply(network))
            assert network == snapshot
        for redo, snapshot in zip(reversed(redos), snapshots[1:], strict=True):
            redo.apply(network)
            assert network == snapshot
