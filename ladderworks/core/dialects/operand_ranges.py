"""What each operand of a dialect's instruction accepts, as device ranges (`T0-T255`,
`K-32768–K32767`): found by asking the dialect's own reader (`check_params`), so the text the
function dialog shows is exactly what the reader takes."""

from __future__ import annotations

from collections.abc import Callable
from functools import cache

from ladderworks.core import dialects
from ladderworks.core.dialects.devices import Device
from ladderworks.core.dialects.functions import check_params, operand_params
from ladderworks.core.instructions import BY_NAME, InstructionSpec, ParamKind

FORMS = "mode"  # a Fatek row's forms (P, D, DP): not a device operand
FILLER = "D1"  # an operand after the one probed (the readers stop at the first bad one)
NOT_DEVICES = frozenset({"FO", "FOB"})  # the map's names of Fatek's box outputs, no devices


def _accepts(spec: InstructionSpec, dialect: str, texts: list[str], index: int) -> bool:
    """True when the reader takes `texts` with no error at operand `index` (0-based)."""
    params, problems = check_params(spec, texts, dialect)
    if params is not None:
        return True
    errors = [p for p in problems if p.is_error]  # none: read as another row (Delta RST Y0)
    return bool(errors) and not any(p.args.get("index", index + 1) == index + 1
                                    for p in errors)


def _span(device: Device, ok: Callable[[int], bool]) -> tuple[int, int] | None:
    """The numbers of `device` the reader takes: first to last, or the part it takes when it
    takes one end only (Delta CNT: C0-C199, DCNT: C200-C255); None when it takes neither."""
    low, high = device.first, device.last
    first, last = ok(low), ok(high)
    if first and last:
        return low, high
    if not first and not last:
        return None
    lo, hi = low, high  # the boundary between taken and refused, by halving
    while hi - lo > 1:
        middle = (lo + hi) // 2
        if ok(middle) == first:
            lo = middle
        else:
            hi = middle
    return (low, lo) if first else (hi, high)


def _joined(spans: list[tuple[Device, int, int]]) -> list[str]:
    """`D0-D9999` for D0-D4999 and D5000-D9999 (one letter's ranges that meet)."""
    merged: list[tuple[Device, int, int]] = []
    for device, low, high in spans:
        if merged and merged[-1][0].letter == device.letter and merged[-1][2] + 1 == low:
            merged[-1] = (merged[-1][0], merged[-1][1], high)
        else:
            merged.append((device, low, high))
    return [f"{d.spell(low)}–{d.spell(high)}" if low != high else d.spell(low)
            for d, low, high in merged]


@cache
def operand_ranges(name: str, dialect: str) -> tuple[tuple[str, ...], ...]:
    """For each operand of row `name` (as `operand_params` lists them) in a program of
    `dialect`, the device ranges and constants its reader takes; () for a form operand."""
    found = dialects.get(dialect)
    spec = BY_NAME.get(name)
    if found is None or spec is None:
        return ()
    params = operand_params(spec)
    good = ["" if p.name == FORMS else FILLER for p in params]
    result: list[tuple[str, ...]] = []
    for index, param in enumerate(params):
        if param.name == FORMS:
            result.append(())
            continue

        def ok(text: str, at: int = index) -> bool:
            texts = [*good[:at], text, *good[at + 1:]]
            return _accepts(spec, dialect, texts, at)

        spans: list[tuple[Device, int, int]] = []
        for device in found.devices.devices:
            if device.letter in NOT_DEVICES:
                continue
            def number_ok(number: int, kind: Device = device) -> bool:
                return ok(kind.spell(number))

            span = _span(device, number_ok)
            if span is not None:
                spans.append((device, *span))
        texts = _joined(spans)
        if param.kind in (ParamKind.VALUE, ParamKind.NUMBER):
            for prefix in ("K", ""):
                if ok(f"{prefix}{max(param.lo, 0)}"):
                    texts.insert(0, f"{prefix}{param.lo}–{prefix}{param.highest(dialect)}")
                    break
        if spans:
            good[index] = spans[0][0].spell(spans[0][1])
        elif texts:
            good[index] = texts[0].split("–")[0]
        result.append(tuple(texts))
    return tuple(result)
