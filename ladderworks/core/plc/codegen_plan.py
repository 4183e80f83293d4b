"""The generated scan's frame: how a unit is cut into chunk functions, the compiled module kept
per source, and the exceptions the generated code raises (`codegen.py` uses them)."""

from __future__ import annotations

from collections.abc import Callable
from functools import lru_cache
from types import CodeType

from ladderworks.core.compiler.binary import Op
from ladderworks.core.compiler.structure import LOOP_LIMIT, Unit
from ladderworks.core.diagnostics import Diagnostic, DiagnosticError

CHUNK_OPS = 1500  # ops per generated function (keeps every function small for Python)


class ScanLoopError(DiagnosticError):
    """A backward label jump repeated more than LOOP_LIMIT times in one scan (run stopped)."""

    def __init__(self, label: int, line: int) -> None:
        super().__init__([Diagnostic("endless-loop", {"label": label, "limit": LOOP_LIMIT},
                                     line, 0)])


class JumpToMain(Exception):
    """JMPC: leave the subprograms and continue at a label of the level's main program."""

    def __init__(self, label: int) -> None:
        super().__init__(label)
        self.label = label


def chunk_plan(ops: tuple[Op, ...], unit: Unit, most: int = CHUNK_OPS,
               network_at: int = CHUNK_OPS * 3 // 4) -> tuple[set[int], dict[int, int]]:
    """Where a unit's chunks start (op indices), and the chunk each of its labels starts.

    A chunk ends after `most` ops (at a network start once it has `network_at`: by default
    in the last quarter); in a unit with labels every LBL starts a chunk (the dispatch loop's
    jump targets). The native scan plans its chunks here too, with its own sizes.
    """
    starts = {unit.start}
    chunk_of_label: dict[int, int] = {}
    by_index = {index: label for label, index in unit.labels.items()}
    size = 0
    for index in range(unit.start, unit.end):
        network_start = index == unit.start or \
            ops[index].source.network != ops[index - 1].source.network
        if index != unit.start and (index in by_index or size >= most or (
                network_start and size >= network_at)):
            starts.add(index)
            size = 0
        if index in by_index:
            chunk_of_label[by_index[index]] = len(starts) - 1
        size += 1
    return starts, chunk_of_label


def loop_stop(ops: tuple[Op, ...], units: list[Unit]) -> Callable[..., None]:
    """The dispatch loop's stop: raise ScanLoopError naming the label jumped to."""

    def loop(unit: int, chunk: int, labels: dict[int, int]) -> None:
        label = next((k for k, v in labels.items() if v == chunk), 0)
        index = units[unit].labels.get(label, 0)
        raise ScanLoopError(label, ops[index].source.line if index < len(ops) else 0)

    return loop


@lru_cache(maxsize=4)
def compiled(source: str) -> CodeType:
    """The compiled scan module of `source`; kept for a program loaded again (F9 of an
    unchanged program, a second engine): compiling 38k ops takes ~0.5 s. A code object holds
    no state: each exec makes new functions over the engine's own namespace."""
    return compile(source, "<ladder scan>", "exec")
