"""Save a changed S7 block in the form it was read: SIMATIC SD text or SimaticML XML.

`save_block(original, form, block, changed)` writes one block: the file's bytes with only the
networks at `changed` rewritten (sd_save.py, xml_save.py). A Program read from S7 exports keeps
its S7 model (`Program.model`, source.py): the graph, the layout, the entry block and its file
as read (as_read.py). Save calls `write_changed`, which writes when the entry block lowers
(with the model's layout) to exactly the program's networks — every change made to the program
is known as a change of the graph — and returns None otherwise, so Save refuses the change
(`Dialect.refuse_changes`). docs/dialects.md, "S7-1200: saving a changed block".
"""

from __future__ import annotations

from collections.abc import Collection

from ladderworks.core.diagnostics import Refused
from ladderworks.core.dialects.s7.as_read import FORMS
from ladderworks.core.dialects.s7.graph import Block, S7Network
from ladderworks.core.dialects.s7.palette import PLACEHOLDER
from ladderworks.core.dialects.s7.sd_save import SaveRefused, save_sd
from ladderworks.core.dialects.s7.source import S7Model
from ladderworks.core.dialects.s7.xml_save import save_xml
from ladderworks.core.il.program import Network, Program
from ladderworks.core.il.textform import decode_text

__all__ = ["FORMS", "changed_since_read", "lower_graph", "save_block", "write_changed"]


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


def lower_graph(model: S7Model) -> list[Network]:
    """The engine networks the model's entry block lowers to now, with the model's own layout
    (as `S7Model.rebuild` lowers it: the addresses stay put)."""
    from ladderworks.core.dialects.s7.source import lower

    return lower(model.entry, model.layout).networks


def changed_since_read(program: Program) -> bool:
    """True when the program's S7 graph differs from its file as read (a change the engine's
    networks may not show: an operand written another way for the same address)."""
    model = program.model
    return isinstance(model, S7Model) and model.read is not None and not model.unchanged()


def _placeholder(network: S7Network) -> bool:
    """True when an operand, instance or label of the network is still TIA's `<???>`."""
    ends = [end for wire in network.wires for end in (wire.source, *wire.targets)]
    operands = [e.operand for e in ends if e.operand is not None]
    operands += [p.instance for p in network.parts if p.instance is not None]
    return any(PLACEHOLDER in (o.text, *o.path) for o in operands) or \
        any(p.label == PLACEHOLDER for p in network.parts)


def write_changed(program: Program) -> str | None:
    """The text Save writes for a changed S7 program, or None when its changes are not known as
    changes of its graph (Save then refuses them); Refused when a network cannot be written."""
    model = program.model
    if not isinstance(model, S7Model) or model.read is None:
        return None
    changed = model.read.changed(model.entry)
    if model.read.unchanged(model.entry, changed):
        return None
    unfinished = [*model.unfinished, *(i for i in changed
                                       if _placeholder(model.entry.networks[i]))]
    if unfinished:
        raise Refused("s7-save-drawing", network=min(unfinished) + 1)
    if [n.key() for n in lower_graph(model)] != [n.key() for n in program.networks]:
        return None
    others = [b for b in model.graph.blocks if b is not model.entry]
    try:
        data = save_block(model.read.data, model.read.form, model.entry, changed, others)
    except SaveRefused as error:
        raise Refused(error.code, **error.args_) from None
    text, _form, _problems = decode_text(data)
    return text
