"""Where the monitored scan writes the power flow: lists of 256 ops, each op at a small index.

Op n's result goes to `m<n // 256>[n % 256]`, a chunk function's default argument for each of
its blocks. A store `M[n]` into one list of every op needs a constant `n`: for 35,000 ops that
is 35,000 int objects whose reference counts every scan writes, about 1 MB of memory touched
beside the code; indices below 257 are Python's shared small ints.
"""

from __future__ import annotations

FLOW_BLOCK = 256  # ops per list (0..255 are small ints; so are their indices)


def flow_blocks(count: int) -> tuple[list[int], ...]:
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


def flow_bytes(blocks: tuple[list[int], ...], count: int) -> bytes:
    """The power flow of `count` ops, one byte per op, from the blocks."""
    return b"".join(map(bytes, blocks))[:count]
