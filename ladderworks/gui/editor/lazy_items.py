"""Network items (the editor's, the live ladder's and its overlays), made only when first
needed (shown on screen or asked for)."""

from __future__ import annotations

from collections.abc import Callable, Iterator
from typing import Generic, TypeVar

Item = TypeVar("Item")


class LazyItems(Generic[Item]):
    """One slot per network; `items[i]` makes network i's item on first use."""

    def __init__(self, make: Callable[[int], Item]) -> None:
        self._make = make
        self._slots: list[Item | None] = []

    def reset(self, count: int) -> None:
        """`count` networks, none made yet."""
        self._slots = [None] * count

    def __len__(self) -> int:
        return len(self._slots)

    def __getitem__(self, index: int) -> Item:
        if index < 0:
            index += len(self._slots)
        item = self._slots[index]
        if item is None:
            item = self._make(index)
            self._slots[index] = item
        return item

    def made(self, start: int = 0) -> Iterator[tuple[int, Item]]:
        """(index, item) of the items made so far, from network `start` on."""
        for index in range(start, len(self._slots)):
            item = self._slots[index]
            if item is not None:
                yield index, item

    def made_count(self) -> int:
        """How many items exist."""
        return sum(1 for item in self._slots if item is not None)

    def insert(self, index: int) -> None:
        """A network was inserted at `index` (its item is made when needed)."""
        self._slots.insert(index, None)

    def pop(self, index: int) -> Item | None:
        """A network was removed: its item, if it was made."""
        return self._slots.pop(index)
