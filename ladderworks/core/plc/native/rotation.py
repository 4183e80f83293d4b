"""ROT (BCD) and ROTB (binary) as native code (core/plc/functions/rotation.py): the shortest
way, steps and one-before-target worked in i64 with RN0, DIR, POS and INC as run-time inputs;
W1 (reverse) kept in the call site's state, unchanged when a position is out of range (or,
for ROT, an operand is not BCD or the result does not fit)."""

from __future__ import annotations

from collections.abc import Callable, Sequence

from ladderworks.core.address import Address
from ladderworks.core.plc.native.bcd import _either, _encode
from ladderworks.core.plc.native.builtins import _fits, _load, _store
from ladderworks.core.plc.native.ir_text import FunctionText
from ladderworks.core.plc.native.state_block import HAS_W1, W1, Block


def _mod(f: FunctionText, value: str, positions: str) -> str:
    """Python's `value % positions` for -positions <= value < 2 * positions, positions >= 1."""
    low = f.value(f"add i64 {value}, {positions}")
    fixed = f.value(f"select i1 {f.value(f'icmp slt i64 {value}, 0')}, i64 {low}, "
                    f"i64 {value}")
    high = f.value(f"sub i64 {fixed}, {positions}")
    return f.value(f"select i1 {f.value(f'icmp sge i64 {fixed}, {positions}')}, i64 {high}, "
                   f"i64 {fixed}")


def _rotate(f: FunctionText, inputs: list[str], positions: str, current: str,
            target: str) -> tuple[str, str, str]:
    """`rotation.rotate`: (i1 inside, i64 value, i1 reverse); rn0, dir, pos, inc first."""
    rn0, shortest, before, steps = (f.truth(value) for value in inputs[:4])
    first = f.value(f"zext i1 {rn0} to i64")
    last = f.value(f"sub i64 {f.value(f'add i64 {first}, {positions}')}, 1")

    def within(value: str) -> str:
        return f.value(f"and i1 {f.value(f'icmp sle i64 {first}, {value}')}, "
                       f"{f.value(f'icmp sle i64 {value}, {last}')}")

    inside = f.value(f"and i1 {f.value(f'icmp sge i64 {positions}, 1')}, "
                     f"{f.value(f'and i1 {within(current)}, {within(target)}')}")
    safe = f.value(f"select i1 {inside}, i64 {positions}, i64 1")
    forward = _mod(f, f.value(f"sub i64 {target}, {current}"), safe)
    backward = _mod(f, f.value(f"sub i64 {current}, {target}"), safe)
    reverse = f.value(f"and i1 {shortest}, {f.value(f'icmp slt i64 {backward}, {forward}')}")
    distance = f.value(f"select i1 {reverse}, i64 {backward}, i64 {forward}")
    less = f.value(f"sub i64 {distance}, 1")
    positive = f.value(f"icmp sgt i64 {less}, 0")
    one_less = f.value(f"select i1 {positive}, i64 {less}, i64 0")
    counted = f.value(f"select i1 {before}, i64 {one_less}, i64 {distance}")
    previous = f.value(f"select i1 {reverse}, i64 {f.value(f'add i64 {target}, 1')}, "
                       f"i64 {f.value(f'sub i64 {target}, 1')}")
    wrapped = f.value(f"add i64 {first}, "
                      f"{_mod(f, f.value(f'sub i64 {previous}, {first}'), safe)}")
    placed = f.value(f"select i1 {before}, i64 {wrapped}, i64 {target}")
    value = f.value(f"select i1 {steps}, i64 {counted}, i64 {placed}")
    return inside, value, reverse


def _finish(b: Block, act: str, done: str, reverse: str, store: Callable[[], None]) -> str:
    """Store (when `done`) and keep W1 = reverse; W1 as i8."""
    f = b.f
    flags = b.flags()
    run = f.value(f"and i1 {f.truth(act)}, {done}")
    _, after = f.branch_if(run)
    store()
    f.join(after)
    now = f.value(f"or i32 {f.value(f'and i32 {flags}, {~W1}')}, {HAS_W1}")
    now = f.value(f"or i32 {now}, {f.value(f'select i1 {reverse}, i32 {W1}, i32 0')}")
    new = f.value(f"select i1 {run}, i32 {now}, i32 {flags}")
    b.set_flags(flags, new)
    held = f.value(f"icmp ne i32 {f.value(f'and i32 {new}, {W1}')}, 0")
    return f.value(f"zext i1 {held} to i8")


def rot(b: Block, params: Sequence[object], inputs: list[str]) -> str | None:
    """ROT: rn0, byt, dir, pos, inc, act; positions a constant, BCD of 2 or 4 digits."""
    if len(inputs) != 6 or len(params) != 4:
        return None
    positions, current_at, target_at, result_at = params
    if not (isinstance(positions, int) and -(1 << 62) < positions < 1 << 62
            and all(isinstance(a, Address) and _fits(a, 2)
                    for a in (current_at, target_at, result_at))):
        return None
    assert isinstance(result_at, Address)
    f = b.f
    wide = f.truth(inputs[1])
    current, current_ok = _either(f, wide, current_at)
    target, target_ok = _either(f, wide, target_at)
    control = [inputs[0], *inputs[2:5]]
    inside, value, reverse = _rotate(f, control, str(positions), current, target)
    limit = f.value(f"select i1 {wide}, i64 9999, i64 99")
    fits = f.value(f"and i1 {f.value(f'icmp sge i64 {value}, 0')}, "
                   f"{f.value(f'icmp sle i64 {value}, {limit}')}")
    done = f.value(f"and i1 {f.value(f'and i1 {current_ok}, {target_ok}')}, "
                   f"{f.value(f'and i1 {inside}, {fits}')}")

    def store() -> None:
        two, one, joined = f.label(), f.label(), f.label()
        f.add(f"br i1 {wide}, label %{two}, label %{one}")
        for label, width in ((two, 2), (one, 1)):
            f.start(label)
            _store(f, result_at, width, _encode(f, value, width))
            f.add(f"br label %{joined}")
        f.start(joined)

    return _finish(b, inputs[5], done, reverse, store)


def rotb(b: Block, params: Sequence[object], inputs: list[str]) -> str | None:
    """ROTB: rn0, dir, pos, inc, act; every operand signed binary of 1, 2 or 4 bytes."""
    if len(inputs) != 5 or len(params) != 5:
        return None
    width = params[0]
    places = [a for a in params[1:] if isinstance(a, Address)]
    if not (isinstance(width, int) and width in (1, 2, 4) and len(places) == 4
            and all(_fits(a, width) for a in places)):
        return None
    f = b.f
    positions, current, target = (f.value(f"sext i{8 * width} {_load(f, a, width)} to i64")
                                  for a in places[:3])
    inside, value, reverse = _rotate(f, inputs[:4], positions, current, target)
    result_at = places[3]
    return _finish(b, inputs[4], inside, reverse, lambda: _store(
        f, result_at, width, f.value(f"trunc i64 {value} to i{8 * width}")))
