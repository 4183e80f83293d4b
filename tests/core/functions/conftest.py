"""Shared set-up for the functional-instruction tests: a fresh PLC memory and a call helper."""

from __future__ import annotations

from collections.abc import Callable

import pytest

from ladderworks.core.address import Address, parse_address
from ladderworks.core.plc.functions import FunctionContext, load_all
from ladderworks.core.plc.memory import Memory

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
