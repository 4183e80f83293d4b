"""The entry block's file as read, kept in the S7 model (source.py) for Save (saving.py).

Its bytes and form ("sd" or "xml"), its path (None: read from a text) and the shape of each
network read, by the lines it was read from (`line`, `end_line`): a network of the current
block whose lines and shape are still as read is unchanged and kept byte for byte; any other
network is written afresh into the file (sd_save.py, xml_save.py).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

from ladderworks.core.dialects.s7.graph import Block, S7Network
from ladderworks.core.dialects.s7.graph_shape import Shape, shape

FORMS = ("sd", "xml")


@dataclass(frozen=True, slots=True)
class AsRead:
    """The entry block's file as read: bytes, form, path and each network's shape by lines."""

    data: bytes
    form: str
    path: Path | None = None
    shapes: dict[tuple[int, int], Shape] = field(default_factory=dict)

    @classmethod
    def of(cls, data: bytes, form: str, block: Block, path: Path | None = None) -> AsRead:
        """The file of a block just read, its networks' shapes remembered."""
        shapes = {(n.line, n.end_line): shape(n) for n in block.networks}
        return cls(data, form, path, shapes)

    def same(self, network: S7Network) -> bool:
        """True when `network` is one read from the file, as it was read."""
        key = (network.line, network.end_line)
        return bool(network.line) and key in self.shapes and self.shapes[key] == shape(network)

    def changed(self, block: Block) -> list[int]:
        """The indexes of `block`'s networks that are new or differ from what was read."""
        return [index for index, network in enumerate(block.networks) if not self.same(network)]

    def unchanged(self, block: Block, changed: list[int] | None = None) -> bool:
        """True when `block` holds the networks read, as read and in their order (`changed`:
        its `changed(block)` when known)."""
        keys = [(n.line, n.end_line) for n in block.networks]
        return keys == list(self.shapes) and not (
            self.changed(block) if changed is None else changed)
