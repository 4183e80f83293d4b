"""A drawn S7 network edited with the ladder edit operations is saved into its file in its own
form: the drawing read back as a network (from_grid.py) names the file's network it replaces,
only that network's text changes (SD spliced, XML's FlgNet replaced), the file read again gives
the edited graph and compiles to the same program; back as read it saves byte for byte."""

from __future__ import annotations

import difflib
import shutil
from collections.abc import Callable
from dataclasses import replace
from pathlib import Path

import pytest

from ladderworks.core.compiler import compile_program, disassemble
from ladderworks.core.diagnostics import Refused
from ladderworks.core.dialects.s7 import opening
from ladderworks.core.dialects.s7.graph_shape import shape
from ladderworks.core.dialects.s7.source import S7Model, match_drawn
from ladderworks.core.dialects.spelling import spelling
from ladderworks.core.il.printer import encode_program
from ladderworks.core.il.program import Program
from ladderworks.core.ladder import edits
from ladderworks.core.ladder.convert import ladder_to_program, program_to_ladder
from ladderworks.core.ladder.find_replace import (
    find,
    parse_query,
    replacement_address,
    replacements,
)
from ladderworks.core.ladder.model import Coil, Contact, FunctionBox, LadderDocument, LadderNetwork

ROOT = Path(__file__).resolve().parents[4] / "resources" / "examples"
FORMS = (("s7", ".s7dcl"), ("s7-xml", ".xml"))
Edit = Callable[[LadderDocument, S7Model], None]


def _model(program: Program) -> S7Model:
    assert isinstance(program.model, S7Model)
    return program.model


def _open(path: Path) -> Program:
    program, diagnostics, _encoding = opening.open_path(path, None)
    assert not [d for d in diagnostics if d.is_error], diagnostics
    return program


def _copy(tmp_path: Path, form: str, name: str, suffix: str) -> Path:
    shutil.copytree(ROOT / form / name, tmp_path / name)
    return tmp_path / name / f"Main{suffix}"


def _saved(path: Path, edit: Edit) -> tuple[bytes, bytes, Program]:
    """The file as read, as saved after `edit` (written over the copy) and the edited program."""
    program = _open(path)
    doc = program_to_ladder(program)
    edit(doc, _model(program))
    rebuilt, found = ladder_to_program(doc)
    assert not [d for d in found if d.is_error], found
    before = path.read_bytes()
    out = encode_program(rebuilt)
    path.write_bytes(out)
    return before, out, rebuilt


def _changed_lines(before: bytes, after: bytes) -> list[int]:
    """The 1-based lines of `before` that `after` changes (an insertion: the line after)."""
    old = before.decode("utf-8-sig").splitlines()
    new = after.decode("utf-8-sig").splitlines()
    found: list[int] = []
    for tag, i1, i2, _j1, _j2 in difflib.SequenceMatcher(None, old, new,
                                                         autojunk=False).get_opcodes():
        if tag != "equal":
            found += list(range(i1 + 1, i2 + 1)) or [i1 + 1]
    return found


def _region(program: Program, index: int) -> range:
    """The lines of the file's network `index` (to the next network's first line)."""
    lines = [n.line for n in _model(program).entry.networks]
    stop = lines[index + 1] if index + 1 < len(lines) else 1 << 30
    return range(lines[index] - 3, stop)  # its pragma (SD) or its unit's head (XML)


def _same_program(path: Path, edited: Program) -> None:
    """The file read again: the edited graph, compiled to the same operations."""
    again = _open(path)
    assert [shape(n) for n in _model(again).entry.networks] == \
        [shape(n) for n in _model(edited).entry.networks]
    first, second = compile_program(again).binary, compile_program(edited).binary
    assert first is not None and second is not None
    # the same operations (a binary also holds each one's source line, which the save moved)
    assert disassemble(first).instructions() == disassemble(second).instructions()
    assert encode_program(again) == path.read_bytes()  # read back: byte for byte


def _operand(doc: LadderDocument, model: S7Model, index: int, cell: tuple[int, int],
             text: str) -> None:
    found = model.operand(text)
    assert isinstance(found, tuple), found
    edits.set_operand(doc.networks[index], *cell, found[0], found[1])


@pytest.mark.parametrize(("form", "suffix"), FORMS)
@pytest.mark.parametrize(("name", "index", "cell", "text"), [
    ("timers", 0, (0, 0), '"Lamba 2"'), ("timers", 1, (0, 10), '"Lamba 1"'),
    ("jumps", 1, (0, 0), '"Start"'), ("counters", 0, (0, 0), "%I0.5")])
def test_an_operand_changed_in_the_drawing_rewrites_only_its_network(
        tmp_path: Path, form: str, suffix: str, name: str, index: int, cell: tuple[int, int],
        text: str) -> None:
    path = _copy(tmp_path, form, name, suffix)
    read = _open(path)
    before, out, edited = _saved(path, lambda doc, model: _operand(doc, model, index, cell,
                                                                  text))
    assert out != before
    changed = _changed_lines(before, out)
    assert changed and all(line in _region(read, index) for line in changed), changed
    assert suffix == ".xml" or text.encode() in out  # XML: an absolute address's attributes
    _same_program(path, edited)


@pytest.mark.parametrize(("form", "suffix"), FORMS)
def test_a_contact_in_series_and_a_coil_in_parallel_are_saved(tmp_path: Path, form: str,
                                                              suffix: str) -> None:
    path = _copy(tmp_path, form, "timers", suffix)

    def edit(doc: LadderDocument, model: S7Model) -> None:
        second = doc.networks[1]
        shown, address = model.operand("%I0.7")  # type: ignore[misc]
        edits.replace_element(second, 0, 1, Contact(texts=(shown,), address=address,
                                                    negated=True))
        coil = model.operand('"Lamba 1"')
        assert isinstance(coil, tuple)
        edits.place(second, 1, second.coil_column, Coil(texts=(coil[0],), address=coil[1]))
        second.links.add((0, second.coil_column))

    before, out, edited = _saved(path, edit)
    parts = [p.name for p in _model(edited).entry.networks[1].parts]
    assert parts.count("Contact") == 1 and parts.count("Coil") == 2
    assert all(line in _region(_open_bytes(before, path), 1)
               for line in _changed_lines(before, out))
    _same_program(path, edited)


def _open_bytes(data: bytes, path: Path) -> Program:
    program, _diagnostics, _encoding = opening.open_path(path, data)
    return program


@pytest.mark.parametrize(("form", "suffix"), FORMS)
def test_a_network_added_and_one_deleted_are_saved(tmp_path: Path, form: str,
                                                   suffix: str) -> None:
    path = _copy(tmp_path, form, "jumps", suffix)

    def edit(doc: LadderDocument, model: S7Model) -> None:
        fresh = LadderNetwork()
        start, lamp = model.operand('"Start"'), model.operand("%Q0.5")
        assert isinstance(start, tuple) and isinstance(lamp, tuple)
        edits.place_wired(fresh, 0, 0, Contact(texts=(start[0],), address=start[1]))
        edits.place_wired(fresh, 0, 0, Coil(texts=(lamp[0],), address=lamp[1]))
        del doc.networks[1]
        doc.networks.insert(0, fresh)

    read = _open(path)
    _before, out, edited = _saved(path, edit)
    entry = _model(edited).entry.networks
    assert len(entry) == len(_model(read).entry.networks)
    assert not entry[0].line and entry[1:] == [n for i, n in enumerate(_model(read).entry.networks)
                                               if i != 1]
    assert suffix == ".xml" or b"%Q0.5" in out
    _same_program(path, edited)


@pytest.mark.parametrize(("form", "suffix"), FORMS)
def test_a_box_operand_changed_in_the_operand_dialog_is_saved(tmp_path: Path, form: str,
                                                              suffix: str) -> None:
    path = _copy(tmp_path, form, "timers", suffix)

    def edit(doc: LadderDocument, model: S7Model) -> None:
        first = doc.networks[0]
        anchor, box = next((c, e) for c, e in first.cells.items() if isinstance(e, FunctionBox))
        texts = [t if t != "T#10s" else "T#3s" for _n, t in model.operands(box)]
        edits.replace_element(first, *anchor, model.with_operands(box, texts))

    before, out, edited = _saved(path, edit)
    assert b"T#3s" in out and b"T#10s" not in out
    assert all(line in _region(_open_bytes(before, path), 0)
               for line in _changed_lines(before, out))
    _same_program(path, edited)


@pytest.mark.parametrize(("form", "suffix"), FORMS)
def test_an_edit_undone_saves_byte_for_byte(tmp_path: Path, form: str, suffix: str) -> None:
    path = _copy(tmp_path, form, "compare", suffix)
    before = path.read_bytes()

    def edit(doc: LadderDocument, model: S7Model) -> None:
        network = doc.networks[2]
        cell = next(c for c, e in network.cells.items() if isinstance(e, Coil))
        element = network.cells[cell]
        assert isinstance(element, Coil)
        undo = edits.set_operand(network, *cell, "%Q1.1", None)
        undo.apply(network)  # back as drawn

    _before, out, _edited = _saved(path, edit)
    assert out == before


def test_an_operand_written_another_way_for_the_same_address_is_saved(tmp_path: Path) -> None:
    """"Start" and %I0.0 lower alike: the file still gets the text as typed."""
    path = _copy(tmp_path, "s7", "timers", ".s7dcl")
    before, out, edited = _saved(path, lambda doc, model: _operand(doc, model, 0, (0, 0),
                                                                  "%I0.0"))
    assert edited.networks == _open_bytes(before, path).networks
    assert b"Contact( %I0.0 )" in out and b'Contact( "Start" )' not in out


@pytest.mark.parametrize(("form", "suffix"), FORMS)
def test_a_drawing_that_is_no_s7_network_is_refused_and_nothing_written(
        tmp_path: Path, form: str, suffix: str) -> None:
    path = _copy(tmp_path, form, "timers", suffix)
    program = _open(path)
    doc = program_to_ladder(program)
    doc.networks[1].cells[(0, 3)] = FunctionBox.new("ADDB", (2, 0, 0, 0))
    rebuilt, found = ladder_to_program(doc)
    assert [d.code for d in found] == ["s7-grid-element"]
    with pytest.raises(Refused) as refused:
        encode_program(rebuilt)
    assert refused.value.diagnostic.code == "s7-save-drawing"
    assert refused.value.diagnostic.args["network"] == 2


def test_a_change_of_the_engine_networks_alone_is_refused() -> None:
    program = _open(ROOT / "s7" / "timers" / "Main.s7dcl")
    edited = replace(program, networks=program.networks[:-1])
    with pytest.raises(Refused) as refused:
        encode_program(edited)
    assert refused.value.diagnostic.code == "s7-save-changed"


def test_a_changed_drawing_names_the_network_it_replaces() -> None:
    a, b, c, d = (LadderNetwork(rows=n) for n in (1, 2, 3, 4))
    changed = LadderNetwork(rows=9)
    assert match_drawn([a, b, c], [a, changed, c]) == ([0, None, 2], [None, 1, None])
    assert match_drawn([a, b, c], [a, c]) == ([0, 2], [None, None])  # b removed
    assert match_drawn([a, b], [changed, a, b]) == ([None, 0, 1], [None, None, None])  # new
    assert match_drawn([a, b, c], [changed, d, c]) == ([None, None, 2], [0, 1, None])
    # a network changed to look like an earlier one: the others stay in place
    assert match_drawn([a, b, a, c, a], [a, b, a, a, a]) == \
        ([0, 1, 2, None, 4], [None, None, None, 3, None])
    assert match_drawn([a, b, c], [b, a, c])[0] == [1, 0, 2]  # moved: kept as read


@pytest.mark.parametrize(("form", "suffix"), FORMS)
def test_find_and_replace_by_a_tag_name_is_saved_as_typed(tmp_path: Path, form: str,
                                                          suffix: str) -> None:
    """Find "Lamba 1" (a tag as written) and the TON's ET, Geçen Süre; replace them: the coil
    and the box pin show the replacement as typed, and the file gets it."""
    path = _copy(tmp_path, form, "timers", suffix)

    def edit(doc: LadderDocument, model: S7Model) -> None:
        symbols = _open(path).symbols
        for typed, written in (('"Lamba 1"', "%Q0.7"), ("Geçen Süre", "%MD20")):
            query = parse_query(typed, symbols, "s7")
            assert query is not None and query.address is not None
            hits = find(doc.networks, query, symbols)
            assert [h.network for h in hits] == [0]
            new = replacement_address(written, query, symbols, "s7")
            for index, change in replacements(doc.networks, hits, query, new, written,
                                              spelling("s7").address):
                change.apply(doc.networks[index])

    before, out, edited = _saved(path, edit)
    assert suffix == ".xml" or (b"Coil( %Q0.7 )" in out and b"et => %MD20" in out)
    assert all(line in _region(_open_bytes(before, path), 0)
               for line in _changed_lines(before, out))
    _same_program(path, edited)
