"""Rotation control: ROT (BCD) and ROTB (binary) — shortest way, steps, one before target."""

from __future__ import annotations

from dataclasses import dataclass

from ladderworks.core.plc.functions import FunctionContext, function


@dataclass(frozen=True, slots=True)
class Rotation:
    """What ROT computes: the value for the result address and the direction (W1)."""

    value: int
    reverse: bool


def rotate(positions: int, first: int, current: int, target: int, *, shortest: bool,
           before: bool, steps: bool) -> Rotation | None:
    """The ROT calculation; None when a position is outside first .. first + positions - 1.

    shortest = DIR, before = POS, steps = INC. Forward means increasing position numbers;
    a tie between the two ways goes forward.
    """
    last = first + positions - 1
    if positions < 1 or not (first <= current <= last and first <= target <= last):
        return None
    forward = (target - current) % positions
    backward = (current - target) % positions
    reverse = shortest and backward < forward
    distance = backward if reverse else forward
    if steps:
        return Rotation(max(distance - 1, 0) if before else distance, reverse)
    if not before:
        return Rotation(target, reverse)
    previous = target + 1 if reverse else target - 1
    return Rotation(first + (previous - first) % positions, reverse)


def _run(state: dict, rotation: Rotation | None) -> bool:
    if rotation is not None:
        state["w1"] = rotation.reverse
    return bool(state.get("w1", False))


@function("ROT")
def rot(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """BCD rotation control (2 digits with BYT=0, 4 with BYT=1); W1 = 1 means reverse."""
    rn0, byt, direction, pos, inc, act = inputs
    if not act:
        return bool(state.get("w1", False))
    positions, current_at, target_at, result_at = params
    width = 2 if byt else 1
    current = ctx.memory.read_bcd(current_at, width)
    target = ctx.memory.read_bcd(target_at, width)
    rotation = None
    if current is not None and target is not None:
        rotation = rotate(positions, int(rn0), current, target,
                          shortest=direction, before=pos, steps=inc)
    if rotation is not None and not ctx.memory.write_bcd(result_at, rotation.value, width):
        rotation = None
    return _run(state, rotation)


@function("ROTB")
def rotb(ctx: FunctionContext, state: dict, inputs: tuple[bool, ...], params: tuple) -> bool:
    """Binary rotation control; the number of positions is read from an address."""
    rn0, direction, pos, inc, act = inputs
    if not act:
        return bool(state.get("w1", False))
    width, positions_at, current_at, target_at, result_at = params
    memory = ctx.memory
    rotation = rotate(memory.read(positions_at, width, signed=True), int(rn0),
                      memory.read(current_at, width, signed=True),
                      memory.read(target_at, width, signed=True),
                      shortest=direction, before=pos, steps=inc)
    if rotation is not None:
        memory.write(result_at, rotation.value, width)
    return _run(state, rotation)
