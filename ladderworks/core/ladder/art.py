"""Ladder networks as plain-text drawings (for the command line and for reading in tests)."""

from __future__ import annotations

from ladderworks.core.dialects.spelling import Spelling, spelling
from ladderworks.core.ladder import row_contacts
from ladderworks.core.ladder.model import (
    Coil,
    Contact,
    FunctionBox,
    LadderDocument,
    LadderNetwork,
    Wire,
    coil_mark,
)
from ladderworks.core.symbols import SymbolTable

CELL = 9  # characters per cell; nodes sit between cells


def _x(node: int) -> int:
    return node * (CELL + 1)


def _symbol(element: Contact | Coil | Wire) -> str:
    if isinstance(element, Wire):
        return "-" * CELL
    mark = "/" if element.negated else " "
    if isinstance(element, Coil) and coil_mark(element):  # SET / RST: (S) / (R); OUT L: (L)
        mark = coil_mark(element)
    if isinstance(element, Coil) and element.mark:  # a source's own coil: (P), (JMP)
        mark = element.mark
    if isinstance(element, Contact) and (element.function or element.mark):  # |↑|, |>=|
        mark = row_contacts.shown_mark(element).split("\n")[0]
        return f"{'-' * (3 - len(mark) // 2)}|{mark}|{'-' * (3 - (len(mark) - 1) // 2)}"
    return f"---{'|' if isinstance(element, Contact) else '('}{mark}" \
           f"{'|' if isinstance(element, Contact) else ')'}---"


def _label(element: Contact | Coil, spell: Spelling) -> str:
    if element.texts or (isinstance(element, Coil) and element.mark):  # as the source
        return (element.texts or ("",))[0][:CELL].center(CELL)  # writes it ("Start")
    if isinstance(element, Contact) and element.function:
        text = " ".join(row_contacts.operand_texts(element, spell))
        return text[:CELL].center(CELL)
    text = spell.address(element.address) if element.address is not None else "?"
    return text[:CELL].center(CELL)


def _named_rows(box: FunctionBox) -> list[tuple[str, str, str, str]]:
    """(label line, symbol line, operand left of it, operand right of it) for each row of a
    box with named pins: the instance in its top edge, the title and type inside."""
    inner = 2 * CELL - 1
    rows: list[tuple[str, str, str, str]] = []
    for i in range(box.height):
        left = next((p for p in box.named if p.row == i and not p.output), None)
        right = next((p for p in box.named if p.row == i and p.output), None)
        middle = box.title if i == 0 else box.type_name if i == 1 else ""
        names = (("/" if left and left.negated else "") + (left.name if left else ""),
                 right.name if right else "")
        body = names[0] + middle.center(inner - len(names[0]) - len(names[1]))[
            :max(0, inner - len(names[0]) - len(names[1]))] + names[1]
        top = ("+" + box.instance[:inner].center(inner, "-") + "+") if i == 0 else \
            "|" + " " * inner + "|"
        rows.append((top, "|" + body + "|", left.text if left else "",
                     right.text if right else ""))
    if box.height == 1 and box.type_name:
        rows[0] = (rows[0][0], rows[0][1], rows[0][2], rows[0][3])
    return rows


def _box_rows(box: FunctionBox, spell: Spelling) -> list[tuple[str, str]]:
    """(label line, symbol line) texts for each row of a box, each 2*CELL+1 wide."""
    width = 2 * CELL + 1
    inner = width - 2
    words = " ".join(spell.params(box.spec, box.params)).split()
    rows: list[tuple[str, str]] = []
    pin_names = {p: name for p, name in zip(box.pins, box.inputs, strict=False)}
    outputs = {offset: box.output_label(contact) for offset, contact in box.outputs}
    for i in range(box.height):
        pin = pin_names.get(i, "")
        if i == 0:
            title = spell.name(box.spec) if box.spec.known else f"SUB {box.spec.sub}"
            label = "+" + f" {title} ".center(inner, "-") + "+"
        else:
            label = "|" + " " * inner + "|"
        param = words[i] if i < len(words) else ""
        if i == box.height - 1 and len(words) > box.height:
            param = " ".join(words[i:])
        out = "W1" if i == 0 and box.has_output else outputs.get(i, "")
        body = (pin.ljust(7) + param).ljust(inner - len(out))[:inner - len(out)] + out
        rows.append((label, "|" + body + "|"))
    return rows


def _symbol_notes(network: LadderNetwork, symbols: SymbolTable | None,
                  spell: Spelling | None = None) -> list[str]:
    """`   X21.7 ESKIP` for each element whose address has a program symbol."""
    if symbols is None or not len(symbols):
        return []
    seen: list[str] = []
    for _cell, element in network.elements():
        if isinstance(element, Contact | Coil) and element.address is not None:
            name = symbols.symbol(element.address)
            shown = spell.address(element.address) if spell is not None else element.address
            note = f"   {shown} {name}"  # in the program's spelling (Fatek's `S3`)
            if name and note not in seen:
                seen.append(note)
    return seen


def draw_network(network: LadderNetwork, symbols: SymbolTable | None = None,
                 spell: Spelling | None = None) -> list[str]:
    """The network as text lines: two lines per grid row (addresses, then symbols), then each
    element's program symbol with its address (`X21.7 ESKIP`) when `symbols` has them.
    `spell`: the program's dialect's spelling (Delta's `X17`), the PMC's by default."""
    spell = spell or spelling(None)
    lines = ["// " + text for text in network.comments]
    if network.label:
        lines.append(network.label + ":")
    if network.listing is not None:
        lines.append("  (kept as instruction list: it has no ladder picture)")
        texts = (spell.instruction(ins) for ins in network.listing)
        lines.extend("    " + text for text in texts if text)  # (a row its line writes: none)
        return lines
    width = _x(network.columns + 1) + 1
    covered: dict[tuple[int, int], bool] = {}
    for anchor, element in network.elements():
        for cell in network.footprint(anchor, element):
            covered[cell] = True
    notes: list[str] = []
    for r in range(network.used_rows()):
        label = [" "] * width
        symbol = [" "] * width
        label[0] = "|"
        symbol[0] = "|"
        for k in range(1, network.columns + 1):
            if (r, k) in network.links or (r - 1, k) in network.links:
                symbol[_x(k)] = "+"
            elif covered.get((r, k - 1)) and covered.get((r, k)):
                symbol[_x(k)] = "-"
            if (r - 1, k) in network.links:
                label[_x(k)] = "|"
        for c in range(network.columns + 1):
            item = network.cells.get((r, c))
            if isinstance(item, Contact | Coil | Wire):
                symbol[_x(c) + 1:_x(c) + 1 + CELL] = _symbol(item)
                if isinstance(item, Contact | Coil):
                    label[_x(c) + 1:_x(c) + 1 + CELL] = _label(item, spell)
        for (br, bc), element in network.elements():
            if isinstance(element, FunctionBox) and element.named and br <= r < br + \
                    element.height:
                top, body, left, right = _named_rows(element)[r - br]
                label[_x(bc) + 1:_x(bc) + 1 + len(top)] = top
                symbol[_x(bc) + 1:_x(bc) + 1 + len(body)] = body
                if left and bc > 0:
                    text = (left[:CELL - 1] + "-").rjust(CELL)
                    symbol[_x(bc - 1) + 1:_x(bc)] = text
                if right:
                    end = _x(bc + element.width)
                    symbol[end:end + CELL] = ("-" + right[:CELL - 1]).ljust(CELL)
            elif isinstance(element, FunctionBox) and br <= r < br + element.height:
                top, body = _box_rows(element, spell)[r - br]
                label[_x(bc) + 1:_x(bc) + 1 + len(top)] = top
                symbol[_x(bc) + 1:_x(bc) + 1 + len(body)] = body
        lines.append("".join(label).rstrip())
        lines.append("".join(symbol).rstrip())
    for (r, c), element in network.elements():
        if isinstance(element, Wire):
            continue
        name = (spell.address(element.address) if isinstance(element, Contact | Coil)
                and element.address
                else " ".join(row_contacts.operand_texts(element, spell))
                if isinstance(element, Contact) and element.function
                else element.name if isinstance(element, FunctionBox) else "?")
        notes.extend(f"   ({r},{c}) {name}: // {text}" for text in element.lead)
        notes.extend(_text_notes((r, c), element))
        if element.comment:
            notes.append(f"   ({r},{c}) {name}  {element.comment}")
    return lines + notes + _symbol_notes(network, symbols, spell)


def _text_notes(cell: tuple[int, int], element: Contact | Coil | FunctionBox) -> list[str]:
    """`(0,1) TON "IEC_Timer_0_DB": IN, PT=T#10s -> Q, ET="Geçen Süre"` for an element drawn
    from a source's graph: every operand as written, in full."""
    where = f"   ({cell[0]},{cell[1]})"
    if isinstance(element, FunctionBox) and element.named:
        head = " ".join(t for t in (element.title, element.type_name, element.instance) if t)
        ins = [f"{p.name}={p.text}" if p.text else p.name for p in element.named
               if not p.output and (p.name or p.text)]
        outs = [f"{p.name}={p.text}" if p.text else p.name for p in element.named
                if p.output and (p.name or p.text)]
        return [f"{where} {head}: {', '.join(ins)} -> {', '.join(outs)}"]
    if isinstance(element, Contact | Coil) and element.texts:
        mark = element.mark.replace("\n", " ") if element.mark else (
            "/" if element.negated else "")
        kind = "contact" if isinstance(element, Contact) else "coil"
        return [f"{where} {kind}{' ' + mark if mark else ''}: {' '.join(element.texts)}"]
    return []


def draw_document(doc: LadderDocument) -> str:
    """Every network, one after another, numbered from 1 (symbols from the program's %@2)."""
    symbols = doc.origin.symbols if doc.origin is not None else None
    spell = spelling(doc.origin.dialect if doc.origin is not None else None)
    out: list[str] = ["// " + text for text in doc.header]
    for index, network in enumerate(doc.networks, start=1):
        out.append(f"== network {index} " + "=" * 40)
        out.extend(draw_network(network, symbols, spell))
    out.extend("// " + text for text in doc.trailer)
    return "\n".join(out) + "\n"
