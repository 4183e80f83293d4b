"""Save a changed S7 block in the form it was read: SIMATIC SD text or SimaticML XML.

`save_block(original, form, block, changed)` writes one block: the file's bytes with only the
networks at `changed` rewritten (sd_save.py, xml_save.py). A Program read from S7 exports keeps
an `S7Source` (`Program.graph`): the entry file's bytes, its form and the graph; Save calls
`write_changed`, which writes when the graph's networks lower to exactly the program's networks
(so every change made to the program is known as a change of the graph) and returns None
otherwise, so Save refuses the change (`Dialect.refuse_changes`). docs/dialects.md, "S7-1200:
saving a changed block".
"""

from __future__ import annotations

from collections.abc import Collection
from dataclasses import dataclass, field

from ladderworks.core.diagnostics import Refused
from ladderworks.core.dialects.s7.graph import Block, S7Network, S7Program
from ladderworks.core.dialects.s7.graph_shape import Shape, shape
from ladderworks.core.dialects.s7.sd_save import SaveRefused, save_sd
from ladderworks.core.dialects.s7.xml_save import save_xml
from ladderworks.core.il.program import Network, Program
from ladderworks.core.il.textform import decode_text

FORMS = ("sd", "xml")


def save_block(original: bytes, form: str, block: Block, changed: Collection[int],
               others: list[Block] | None = None) -> bytes:
    """The block's file as bytes: `original` (the file as read) with `block`'s networks at the
    indexes `changed` written afresh in `form` ("sd" or "xml"). A network of `block` names the
    one it replaces by `line`/`end_line` as read (0: a new network); a network of the file that
    no network of `block` names is removed. SaveRefused when it cannot be written."""
    if form == "sd":
        return save_sd(original, block, changed, others)
    if form == "xml":
        return save_xml(original, block, changed, others)
    raise SaveRefused("s7-save-unwritable", {"part": form})


@dataclass(slots=True)
class S7Source:
    """What Save needs of an S7 program read from a file: its bytes and form ("sd"/"xml"), the
    graph read (`program`, its entry `block`) and each network's shape as read."""

    data: bytes
    form: str
    program: S7Program
    block: Block
    read: dict[tuple[int, int], Shape] = field(default_factory=dict)

    @classmethod
    def of(cls, data: bytes, form: str, program: S7Program, block: Block) -> S7Source:
        """The source of a program just read, its networks' shapes remembered."""
        read = {(n.line, n.end_line): shape(n) for n in block.networks}
        return cls(data, form, program, block, read)

    def changed(self) -> list[int]:
        """The indexes of the block's networks that are new or differ from what was read."""
        return [index for index, network in enumerate(self.block.networks)
                if not self._same(network)]

    def _same(self, network: S7Network) -> bool:
        key = (network.line, network.end_line)
        return bool(network.line) and key in self.read and self.read[key] == shape(network)

    def unchanged(self) -> bool:
        """Whether the block holds the networks read, in their order."""
        keys = [(n.line, n.end_line) for n in self.block.networks]
        return not self.changed() and keys == list(self.read)


def lower_graph(source: S7Source) -> list[Network]:
    """The engine networks the current graph lowers to, as the reader builds them (a caller
    that changed the graph sets `Program.networks` to these)."""
    from ladderworks.core.dialects.s7.layout import Layout
    from ladderworks.core.dialects.s7.lowering import lower_block

    networks, _found = lower_block(source.block, Layout(source.program))
    return networks


def write_changed(program: Program) -> str | None:
    """The text Save writes for a changed S7 program, or None when its changes are not known as
    changes of its graph (Save then refuses them)."""
    source = program.graph
    if not isinstance(source, S7Source) or source.unchanged():
        return None
    if [n.key() for n in lower_graph(source)] != [n.key() for n in program.networks]:
        return None
    others = [b for b in source.program.blocks if b is not source.block]
    try:
        data = save_block(source.data, source.form, source.block, source.changed(), others)
    except SaveRefused as error:
        raise Refused(error.code, **error.args_) from None
    text, _form, _problems = decode_text(data)
    return text
