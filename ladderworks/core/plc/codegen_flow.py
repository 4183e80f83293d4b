"""Where the monitored scan writes the power flow (lists of 256 ops, each op at a small index),
and the generated scan that holds them.

Op n's result goes to `m<n // 256>[n % 256]`, a chunk function's default argument for each of
its blocks. A store `M[n]` into one list of every op needs a constant `n`: for 35,000 ops that
is 35,000 int objects whose reference counts every scan writes, about 1 MB of memory touched
beside the code; indices below 257 are Python's shared small ints.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

ScanFunction = Callable[..., None]  # scan(ctx, M, full=True)
Blocks = tuple[list[int], ...]
FLOW_BLOCK = 256  # ops per list (0..255 are small ints; so are their indices)


def flow_blocks(count: int) -> Blocks:
    """Zeroed lists for the power flow of `count` ops (the last one full size too)."""
    return tuple([0] * FLOW_BLOCK for _ in range(max(1, -(-count // FLOW_BLOCK))))


def flow_slot(index: int) -> tuple[int, str]:
    """Op `index`'s block number and its place there, as generated code (`m3[17]`)."""
    block, place = divmod(index, FLOW_BLOCK)
    return block, f"m{block}[{place}]"


def zero_lines(start: int, end: int, indent: str) -> list[str]:
    """Lines setting the power flow of ops start..end-1 to 0 (`FB` the blocks, `Z` zeros)."""
    lines: list[str] = []
    whole: list[int] = []
    for k in range(start // FLOW_BLOCK, (end - 1) // FLOW_BLOCK + 1 if end > start else 0):
        low = max(start, k * FLOW_BLOCK) - k * FLOW_BLOCK
        high = min(end, (k + 1) * FLOW_BLOCK) - k * FLOW_BLOCK
        if (low, high) == (0, FLOW_BLOCK):
            whole.append(k)
        else:
            lines.append(f"{indent}FB[{k}][{low}:{high}] = Z[{low}:{high}]")
    if whole:  # consecutive: only the first and last block may be partial
        lines += [f"{indent}for b in FB[{whole[0]}:{whole[-1] + 1}]:", f"{indent}    b[:] = Z"]
    return lines


def flow_reset(level1: tuple[int, int] | None, count: int, by_op: bool) -> list[str]:
    """The scan function's first lines: every op's power flow 0, or level 1's only in a scan
    that runs level 1 only (`full` false); `by_op`: in the flat list `M` (`ZERO` zeros)."""
    if by_op:
        if level1 is None:
            return ["    M[:] = ZERO"]
        start, end = level1
        return ["    if not full:", f"        M[{start}:{end}] = ZERO[{start}:{end}]",
                "    else:", "        M[:] = ZERO"]
    if level1 is None:
        return zero_lines(0, count, "    ")
    return ["    if not full:", *zero_lines(*level1, "        "), "        pass",
            "    else:", *zero_lines(0, count, "        ")]


def flow_into(blocks: Blocks, out: bytearray) -> bytearray:
    """The power flow of `len(out)` ops written into `out`, one byte per op (a slice store
    per block: about twice as fast as joining the blocks' bytes)."""
    count = len(out)
    for number, block in enumerate(blocks):
        start = number * FLOW_BLOCK
        if start + FLOW_BLOCK <= count:
            out[start:start + FLOW_BLOCK] = block
        elif start < count:
            out[start:count] = block[:count - start]
    return out


@dataclass(slots=True)
class GeneratedScan:
    """The generated source and the compiled scan function `scan(ctx, M, full=True)`.

    The monitored mode's power flow is in `blocks` (one int per op, in lists of 256: storing
    into a list is about 3x faster than into a bytearray; `flow()` makes the bytes); `M` is
    the flat list of one int per op that the `flow_by_op` variant writes instead (None for
    the others); `full` False runs level 1 only (a scan between two level-2 passes).
    """

    source: str
    scan: ScanFunction
    blocks: Blocks = ()
    count: int = 0  # ops
    states: tuple[dict[str, Any], ...] = ()  # the state of each function call, in op order

    def flow(self) -> bytes:
        """The last scan's power flow, one byte per op (monitored variant; else all 0)."""
        return bytes(flow_into(self.blocks, bytearray(self.count)))

    def flow_into(self, out: bytearray) -> None:
        """Write the last scan's power flow into `out` (one byte for each of `count` ops)."""
        flow_into(self.blocks, out)

    def adopt(self, previous: object) -> None:
        """Go on from the states `previous` left (the dicts: nothing to do)."""

    def sync(self) -> None:
        """The call sites' states are in their dicts (always: the scan writes them there)."""

    def states_changed(self, moved: list[dict[str, Any]] | None = None) -> None:
        """The call sites' states were changed outside a scan (nothing to do: it reads them)."""

    def clear_flow(self) -> None:
        """Every op's power flow 0 (a cold start)."""
        for block in self.blocks:
            block[:] = [0] * len(block)
