"""A box's further output pins chosen in the editor: which bits of its output byte (Fatek's
FO1 … FO7) the box shows on its right side, each on a row of its own."""

from __future__ import annotations

from dataclasses import replace

from ladderworks.core.ladder.edits import Edit, EditRefused
from ladderworks.core.ladder.model import MAX_ROWS, Contact, FunctionBox, LadderNetwork

PIN_BITS = range(1, 8)  # FO1 … FO7 (FO0 is the box's W1)


def shown_pins(box: FunctionBox) -> tuple[int, ...]:
    """The bits of the output byte the box shows as pins, in row order."""
    return tuple(contact.address.bit for _offset, contact in box.outputs
                 if contact.address is not None and contact.address.bit is not None)


def set_output_pins(network: LadderNetwork, row: int, col: int, bits: tuple[int, ...]) -> Edit:
    """Show the pins `bits` on the box covering (row, col): a pin kept stays on its row, a new
    one takes the first free row from the box's second; the box grows to its last pin (its
    coils and contacts are drawn by the user). EditRefused when there is no box with an output
    byte there, or when the grown box would cover another element."""
    found = network.element_at(row, col)
    box = found[1] if found is not None else None
    byte = box.output_byte() if isinstance(box, FunctionBox) else None
    if found is None or not isinstance(box, FunctionBox) or byte is None:
        raise EditRefused("edit-no-pins", (row, col), row=row, col=col)
    anchor = found[0]
    wanted = sorted({bit for bit in bits if bit in PIN_BITS})
    kept = {contact.address.bit: (offset, contact) for offset, contact in box.outputs
            if contact.address is not None and contact.address.bit in wanted}
    taken = {offset for offset, _ in kept.values()}
    outputs = []
    offset = 1
    for bit in wanted:
        if bit in kept:
            outputs.append(kept[bit])
            continue
        while offset in taken:
            offset += 1
        taken.add(offset)
        outputs.append((offset, Contact(byte.with_bit(bit))))
    outputs.sort(key=lambda item: item[0])
    height = max(1, max(box.pins, default=0) + 1, *(o + 1 for o, _ in outputs))
    grown = replace(box, outputs=tuple(outputs), height=height)
    last = anchor[0] + height - 1
    if last >= MAX_ROWS:
        raise EditRefused("edit-outside", (last, anchor[1]), row=last, col=anchor[1])
    for cell in network.footprint(anchor, grown):
        other = network.element_at(*cell)
        if other is not None and other[0] != anchor:
            raise EditRefused("edit-box-room", cell, name=box.name)
    work = network.copy()
    work.rows = max(work.rows, last + 1)
    work.cells[anchor] = grown
    return Edit(work.state()).apply(network)
