"""Shared set-up for the functional-instruction tests: a fresh PLC memory, a call helper and
engines running small programs in fast and monitored mode."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from ladderworks.core.address import Address, Area, parse_address
from ladderworks.core.plc.engine import ScanEngine
from ladderworks.core.plc.functions import FunctionContext, load_all
from ladderworks.core.plc.memory import Memory
from tests.core.plc.conftest import engine_for

REGISTRY = load_all()


def at(text: str) -> Address:
    """An address from its spelling."""
    return parse_address(text)


class Box:
    """One call site of a functional instruction: its own state, run against one memory."""

    def __init__(self, ctx: FunctionContext, name: str, *params: object) -> None:
        self.ctx = ctx
        self.impl = REGISTRY[name]
        self.params = tuple(at(p) if isinstance(p, str) else p for p in params)
        self.state: dict = {}

    def __call__(self, *inputs: bool | int) -> bool:
        """One scan with these control inputs (first -> last, ACT last); returns W1."""
        return self.impl(self.ctx, self.state, tuple(bool(i) for i in inputs), self.params)


@pytest.fixture
def ctx() -> FunctionContext:
    """A context over zeroed memory."""
    return FunctionContext(Memory())


@pytest.fixture
def box(ctx: FunctionContext) -> Callable[..., Box]:
    """Make a call site: box("ADD", 0, "R100", 5, "R102")."""
    return lambda name, *params: Box(ctx, name, *params)


# The 30i memory-B sizes of the areas whose FANUC layout lies past LadderWorks' seed map:
# T9000.. (timer precision) and C5000.. (CTRB values).
FANUC_SIZES = {Area.T: 9500, Area.C: 5200}


def fanuc_memory() -> Memory:
    """Zeroed memory with the T and C areas as large as on a 30i memory-B PMC."""
    memory = Memory()
    for area, size in FANUC_SIZES.items():
        memory.areas[area] = bytearray(size)
    return memory


def run_engine(text: str, monitored: bool, dialect: str = "seed",
               memory: Memory | None = None) -> ScanEngine:
    """An engine for ladder lines, in monitored or fast mode, for a program of `dialect`.

    Until the engine sets the dialect from the program, it is set on the engine's context here.
    """
    engine = engine_for(text, memory=memory) if memory is not None else engine_for(text)
    engine.monitored = monitored
    engine._ctx.dialect = dialect  # see the docstring
    return engine


@pytest.fixture(params=[False, True], ids=["fast", "monitored"])
def monitored(request: pytest.FixtureRequest) -> bool:
    """Run an engine test in fast and in monitored mode."""
    return bool(request.param)
