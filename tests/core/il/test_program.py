"""The program model's Instruction and Network keep a frozen dataclass's meaning: equality and
hash without line/column, immutable, no tuple behaviour leaking into comparisons."""

from __future__ import annotations

import copy
import operator
import pickle
from unittest.mock import ANY

import pytest

from ladderworks.core.address import Address, Area
from ladderworks.core.il.program import Instruction, Network, new_instruction

X00 = Address(Area.X, 0, 0)
Y00 = Address(Area.Y, 0, 0)
FULL = Instruction("RD", X00, (), "start", ("lead 1", "lead 2"), 12, 5)


def test_new_instruction_is_the_same_as_the_constructor() -> None:
    made = new_instruction("RD", X00, (), "start", ("lead 1", "lead 2"), 12, 5)
    assert type(made) is Instruction
    assert made == FULL
    assert (made.name, made.operand, made.params, made.comment, made.lead, made.line,
            made.column) == ("RD", X00, (), "start", ("lead 1", "lead 2"), 12, 5)


def test_keyword_construction_and_defaults() -> None:
    made = Instruction("TMR", params=(101,), line=3)
    assert (made.name, made.operand, made.params, made.comment, made.lead, made.line,
            made.column) == ("TMR", None, (101,), "", (), 3, 0)
    assert Instruction(name="RD", operand=X00, comment="c", lead=("l",), line=1, column=2) == (
        Instruction("RD", X00, (), "c", ("l",)))


def test_equality_and_hash_ignore_line_and_column() -> None:
    moved = Instruction("RD", X00, (), "start", ("lead 1", "lead 2"), 99, 1)
    assert moved == FULL
    assert not operator.ne(moved, FULL)  # `!=` too: a tuple's own `!=` would see the line
    assert hash(moved) == hash(FULL)
    assert len({FULL, moved}) == 1
    # the same number as the frozen dataclass's hash of its compared fields
    assert hash(FULL) == hash(("RD", X00, (), "start", ("lead 1", "lead 2")))


@pytest.mark.parametrize("changed", [
    FULL._replace(name="RD.NOT"),
    FULL._replace(operand=Y00),
    FULL._replace(operand=None),
    FULL._replace(params=(1,)),
    FULL._replace(comment="other"),
    FULL._replace(lead=("lead 1",)),
])
def test_every_compared_field_counts(changed: Instruction) -> None:
    assert changed != FULL
    assert not operator.eq(changed, FULL)
    assert len({FULL, changed}) == 2


def test_never_equal_to_a_plain_tuple() -> None:
    plain = tuple(FULL)
    for left, right in ((FULL, plain), (plain, FULL), (FULL, ("RD",)), (FULL, object())):
        assert not operator.eq(left, right)
        assert operator.ne(left, right)
    assert operator.eq(FULL, ANY)  # another type still decides for itself, as with a dataclass


@pytest.mark.parametrize("other", [FULL, tuple(FULL), ("ZZZ",)])
def test_instructions_have_no_order(other: object) -> None:
    for compare in (operator.lt, operator.le, operator.gt, operator.ge):
        with pytest.raises(TypeError):
            compare(FULL, other)
        with pytest.raises(TypeError):
            compare(other, FULL)
    with pytest.raises(TypeError):
        sorted([FULL, FULL._replace(name="AND")])


def test_immutable() -> None:
    with pytest.raises(AttributeError):
        FULL.name = "WRT"  # type: ignore[misc]
    with pytest.raises(AttributeError):
        FULL.line = 1  # type: ignore[misc]
    with pytest.raises(AttributeError):
        FULL.extra = 1  # type: ignore[attr-defined]
    with pytest.raises(AttributeError):
        del FULL.comment  # type: ignore[misc]
    assert FULL.name == "RD" and FULL.line == 12


def test_replace_keeps_the_other_fields() -> None:
    moved = FULL._replace(operand=Y00)
    assert (moved.name, moved.operand, moved.comment, moved.lead, moved.line, moved.column) == (
        "RD", Y00, "start", ("lead 1", "lead 2"), 12, 5)
    assert FULL.operand == X00


def test_pickle_and_copy_keep_every_field() -> None:
    for twin in (pickle.loads(pickle.dumps(FULL)), copy.copy(FULL), copy.deepcopy(FULL)):
        assert type(twin) is Instruction
        assert twin == FULL and (twin.line, twin.column) == (12, 5)


def test_repr_names_every_field() -> None:
    assert repr(Instruction("TMR", params=(1,), line=3, column=2)) == (
        "Instruction(name='TMR', operand=None, params=(1,), comment='', lead=(), line=3, "
        "column=2)")


def test_class_pattern() -> None:
    match FULL:
        case Instruction("RD", operand, line=line):
            assert (operand, line) == (X00, 12)
        case _:
            pytest.fail("no match")


def test_spec_and_param_map() -> None:
    timer = Instruction("TMR", params=(101,))
    assert timer.is_function and timer.spec.name == "TMR"
    assert timer.param_map() == {"timer": 101}
    table = Instruction("COD", params=(2, X00, Y00, 10, 20))
    assert table.param_map() == {"size": 2, "index": X00, "output": Y00, "table": (10, 20)}
    assert not FULL.is_function


def test_network_defaults_are_fresh_lists() -> None:
    first, second = Network(), Network()
    first.instructions.append(FULL)
    first.comments.append("note")
    assert second.instructions == [] and second.comments == [] and second.label == ""
    assert first == Network([FULL], ["note"])


def test_network_construction_keeps_the_lists_given() -> None:
    body, notes = [FULL], ["a"]
    network = Network(comments=notes, label="N00012")
    network.instructions.extend(body)
    assert network.comments is notes
    assert Network(body, notes, "N00012") == network
    assert Network(instructions=body).instructions is body
    empty: list[Instruction] = []
    assert Network(empty, empty).instructions is empty  # an empty list given is kept too
    assert repr(Network(label="N1")) == "Network(instructions=[], comments=[], label='N1')"


def test_network_equality_and_key_ignore_positions() -> None:
    here = Network([FULL], ["c"], "N1")
    there = Network([FULL._replace(line=400, column=9)], ["c"], "N1")
    assert here == there and here.key() == there.key()
    assert hash(here.key()) == hash(there.key())
    assert here != Network([FULL], ["c"], "N2")
    assert here != Network([FULL._replace(comment="")], ["c"], "N1")
    assert here.line == 12 and Network().line == 0
    with pytest.raises(TypeError):
        hash(here)  # a network is mutable, so unhashable
