"""ROT and ROTB: the seed's 12-station turret, every (current, target) pair, and edge cases."""

from __future__ import annotations

import itertools

import pytest
from hypothesis import given
from hypothesis import strategies as st

from ladderworks.core.plc.functions import FunctionContext
from ladderworks.core.plc.functions.rotation import rotate
from tests.core.functions.conftest import at

STATIONS = 12


def walk(current: int, target: int, step: int) -> list[int]:
    """Stations passed turning one station at a time from current to target (1..12)."""
    path = [current]
    while path[-1] != target:
        path.append((path[-1] - 1 + step) % STATIONS + 1)
    return path


PAIRS = list(itertools.product(range(1, STATIONS + 1), repeat=2))


@pytest.mark.parametrize(("current", "target"), PAIRS)
def test_turret_dir1_takes_the_shorter_way(ctx: FunctionContext, box, current: int,
                                           target: int) -> None:
    forward, backward = walk(current, target, 1), walk(current, target, -1)
    reverse = len(backward) < len(forward)  # a tie goes forward
    path = backward if reverse else forward
    steps = len(path) - 1
    mem = ctx.memory
    mem.write_bcd(at("X41"), current, 1)
    mem.write_bcd(at("R200"), target, 1)
    # RN0=1 (stations 1..12), BYT=0, DIR=1; the four POS/INC combinations
    for pos, inc, want in [
        (0, 0, target),
        (0, 1, steps),
        (1, 0, path[-2] if steps else (target - 2) % STATIONS + 1),
        (1, 1, max(steps - 1, 0)),
    ]:
        rot = box("ROT", STATIONS, "X41", "R200", "R230")
        assert rot(1, 0, 1, pos, inc, 1) is reverse, (current, target, pos, inc)
        assert mem.read_bcd(at("R230"), 1) == want, (current, target, pos, inc)
    # the shorter way is never longer than half the turret
    assert steps <= STATIONS // 2


def test_turret_seed_example_one_before(ctx: FunctionContext, box) -> None:
    """From 2 to 11 the short way is backwards (3 steps); slow down at 12, one before."""
    ctx.memory.write_bcd(at("X41"), 2, 1)
    ctx.memory.write_bcd(at("R200"), 11, 1)
    rot = box("ROT", 12, "X41", "R200", "R230")
    assert rot(1, 0, 1, 1, 0, 1) is True
    assert ctx.memory.read_bcd(at("R230"), 1) == 12
    rot(1, 0, 1, 0, 1, 1)
    assert ctx.memory.read_bcd(at("R230"), 1) == 3


def test_dir0_always_forward(ctx: FunctionContext, box) -> None:
    ctx.memory.write_bcd(at("R0"), 2, 1)
    ctx.memory.write_bcd(at("R1"), 11, 1)
    rot = box("ROT", 12, "R0", "R1", "R2")
    assert rot(1, 0, 0, 0, 1, 1) is False
    assert ctx.memory.read_bcd(at("R2"), 1) == 9


def test_tie_goes_forward() -> None:
    assert rotate(12, 1, 1, 7, shortest=True, before=False, steps=True).reverse is False
    assert rotate(12, 1, 7, 1, shortest=True, before=False, steps=True).reverse is False


def test_rn0_zero_numbers_from_zero() -> None:
    assert rotate(8, 0, 0, 7, shortest=True, before=False, steps=True) is not None
    assert rotate(8, 0, 0, 8, shortest=True, before=False, steps=True) is None
    assert rotate(8, 0, 7, 0, shortest=True, before=True, steps=False).value == 7
    assert rotate(8, 0, 1, 0, shortest=True, before=True, steps=False).value == 1
    assert rotate(8, 1, 0, 3, shortest=True, before=False, steps=True) is None  # 0 with RN0=1


def test_act_off_keeps_w1_and_result(ctx: FunctionContext, box) -> None:
    ctx.memory.write_bcd(at("R0"), 2, 1)
    ctx.memory.write_bcd(at("R1"), 11, 1)
    rot = box("ROT", 12, "R0", "R1", "R2")
    assert rot(1, 0, 1, 0, 1, 1) is True
    ctx.memory.write_bcd(at("R1"), 3, 1)
    assert rot(1, 0, 1, 0, 1, 0) is True  # W1 unchanged with ACT = 0
    assert ctx.memory.read_bcd(at("R2"), 1) == 3  # result from the last execution
    assert rot(1, 0, 1, 0, 1, 1) is False


def test_invalid_bcd_or_out_of_range_keeps_everything(ctx: FunctionContext, box) -> None:
    ctx.memory.write_bcd(at("R0"), 2, 1)
    ctx.memory.write_bcd(at("R1"), 11, 1)
    rot = box("ROT", 12, "R0", "R1", "R2")
    assert rot(1, 0, 1, 0, 1, 1) is True
    ctx.memory.write(at("R1"), 0x1A)  # not BCD
    assert rot(1, 0, 1, 0, 1, 1) is True
    assert ctx.memory.read_bcd(at("R2"), 1) == 3
    ctx.memory.write_bcd(at("R1"), 13, 1)  # no station 13
    assert rot(1, 0, 1, 0, 1, 1) is True
    assert ctx.memory.read_bcd(at("R2"), 1) == 3


def test_rot_four_digit_bcd(ctx: FunctionContext, box) -> None:
    ctx.memory.write_bcd(at("D0"), 1, 2)
    ctx.memory.write_bcd(at("D2"), 90, 2)
    rot = box("ROT", 200, "D0", "D2", "D4")
    assert rot(1, 1, 1, 0, 1, 1) is False
    assert ctx.memory.read_bcd(at("D4"), 2) == 89
    ctx.memory.write_bcd(at("D2"), 160, 2)
    assert rot(1, 1, 1, 0, 1, 1) is True
    assert ctx.memory.read_bcd(at("D4"), 2) == 41


@pytest.mark.parametrize("width", [1, 2, 4])
def test_rotb_binary_positions_from_memory(ctx: FunctionContext, box, width: int) -> None:
    mem = ctx.memory
    mem.write(at("D0"), 12, width)
    mem.write(at("D4"), 2, width)
    mem.write(at("D8"), 11, width)
    rotb = box("ROTB", width, "D0", "D4", "D8", "D12")
    assert rotb(1, 1, 0, 1, 1) is True
    assert mem.read(at("D12"), width) == 3
    mem.write(at("D0"), 24, width)  # the turret size can change while running
    assert rotb(1, 1, 0, 1, 1) is False
    assert mem.read(at("D12"), width) == 9
    mem.write(at("D0"), 0, width)  # zero positions: nothing is computed
    assert rotb(1, 1, 0, 1, 1) is False
    assert mem.read(at("D12"), width) == 9


@given(positions=st.integers(1, 400), first=st.integers(0, 1), data=st.data())
def test_property_turning_the_result_reaches_the_target(positions: int, first: int,
                                                        data: st.DataObject) -> None:
    """Turning `steps` stations in the W1 direction from current lands on the target."""
    current = data.draw(st.integers(first, first + positions - 1))
    target = data.draw(st.integers(first, first + positions - 1))
    rotation = rotate(positions, first, current, target, shortest=True, before=False,
                      steps=True)
    assert rotation is not None
    sign = -1 if rotation.reverse else 1
    assert first + (current - first + sign * rotation.value) % positions == target
    assert rotation.value <= positions // 2
    before = rotate(positions, first, current, target, shortest=True, before=True,
                    steps=False)
    assert before is not None and before.reverse == rotation.reverse
    if rotation.value >= 1:  # the station one before is one step short of the target
        assert first + (current - first + sign * (rotation.value - 1)) % positions \
            == before.value
