"""Grid text: a selection (or a whole network) as text for the clipboard and for saved drafts."""

from __future__ import annotations

import json
from dataclasses import dataclass, replace
from typing import Any

from ladderworks.core.address import AddressError, parse_address
from ladderworks.core.il.program import ParamValue
from ladderworks.core.il.textform import split_lines
from ladderworks.core.instructions import Write, lookup, spec_for
from ladderworks.core.ladder.edits import (
    Edit,
    EditRefused,
    _change,
    _grow,
    _put,
    function_params,
)
from ladderworks.core.ladder.model import (
    DEFAULT_COLUMNS,
    MAX_COLUMNS,
    MAX_ROWS,
    WIRE,
    Cell,
    Coil,
    Contact,
    Element,
    FunctionBox,
    LadderNetwork,
    Pin,
    Wire,
)

MAGIC = "LADDERWORKS-GRID 1"


@dataclass(frozen=True, slots=True)
class Selection:
    """A rectangle of cells, rows `top`..`bottom` and columns `left`..`right` inclusive."""

    top: int
    left: int
    bottom: int
    right: int

    @classmethod
    def spanning(cls, a: Cell, b: Cell) -> Selection:
        """The rectangle with corners `a` and `b` (any order)."""
        return cls(min(a[0], b[0]), min(a[1], b[1]), max(a[0], b[0]), max(a[1], b[1]))

    @classmethod
    def whole(cls, network: LadderNetwork) -> Selection:
        """Every cell of a network, coil column included."""
        return cls(0, 0, network.used_rows() - 1, network.columns)

    def holds(self, cell: Cell) -> bool:
        """True when the cell is inside."""
        return self.top <= cell[0] <= self.bottom and self.left <= cell[1] <= self.right


def _element_record(element: Element) -> dict[str, Any]:
    if isinstance(element, Wire):
        return {"kind": "wire"}
    if isinstance(element, FunctionBox):
        record: dict[str, Any] = {
            "kind": "box", "name": element.name,
            "params": [p if isinstance(p, int) else str(p) for p in element.params],
            "pins": list(element.pins), "height": element.height}
        if element.outputs:  # its further output pins (Fatek's FO1 …): row and contact
            record["outputs"] = [[offset, _element_record(contact)]
                                 for offset, contact in element.outputs]
        if element.named:  # drawn from a source's model (S7): its pins and words
            record["named"] = [[p.name, p.row, p.output, p.text, p.negated]
                               for p in element.named]
            record.update(title=element.title, type=element.type_name,
                          instance=element.instance, origin=[list(o) for o in element.origin])
    else:
        record = {"kind": "contact" if isinstance(element, Contact) else "coil",
                  "address": str(element.address) if element.address else None,
                  "not": element.negated}
        if isinstance(element, Coil) and element.write is not Write.OUT:
            record["write"] = element.write.value
        if isinstance(element, Coil) and element.row:  # a dialect's own coil (OUT L)
            record["row"] = element.row
        if isinstance(element, Contact) and element.function:  # an edge / comparison contact
            record["function"] = element.function
            record["params"] = [p if isinstance(p, int) else str(p) for p in element.params]
        if element.texts or element.mark:  # operands as a source writes them (S7)
            record.update(texts=list(element.texts), mark=element.mark)
    if element.comment:
        record["comment"] = element.comment
    if element.lead:
        record["lead"] = list(element.lead)
    return record


def _parse_param(value: object) -> ParamValue:
    if isinstance(value, bool) or not isinstance(value, int | str):
        raise ValueError(value)
    if isinstance(value, int):
        return value
    return parse_address(value)


def _parse_params(name: str, values: list[object]) -> tuple[ParamValue, ...]:
    """A box's parameters as the parser reads them (`P5`, `L3` included); a draft's invalid
    parameters one by one (numbers and addresses)."""
    if all(isinstance(v, int | str) and not isinstance(v, bool) for v in values):
        params, problems = function_params(name, [str(v) for v in values])
        if params is not None and not problems:
            return params
    return tuple(_parse_param(p) for p in values)


def _element_from(record: dict[str, Any]) -> Element:
    kind = record.get("kind")
    comment = str(record.get("comment", ""))
    lead = tuple(str(x) for x in record.get("lead", []))
    if kind == "wire":
        return WIRE
    if kind == "box" and "named" in record:
        return _named_box(record, comment, lead)
    if kind == "box":
        name = str(record["name"])
        values = list(record.get("params", []))
        if spec_for(name, len(values)) is None:
            raise ValueError(name)
        params = _parse_params(name, values)
        pins = tuple(int(p) for p in record.get("pins", []))
        height = int(record.get("height", 1))
        default = FunctionBox.new(name, params)
        if (len(pins) != len(default.pins) or any(p >= height for p in pins)
                or not 1 <= height <= MAX_ROWS):  # a damaged draft must not fill the memory
            raise ValueError("pins")
        outputs: list[tuple[int, Contact]] = []
        for offset, item in record.get("outputs", []):
            contact = _element_from(dict(item))
            if not isinstance(contact, Contact) or not 0 < int(offset) < height:
                raise ValueError("outputs")
            outputs.append((int(offset), contact))
        return FunctionBox(default.name, params, comment, lead, pins, height, tuple(outputs))
    if kind in ("contact", "coil"):
        texts = tuple(str(t) for t in record.get("texts", []))
        return replace(_plain_element(kind, record, comment, lead), texts=texts,
                       mark=str(record.get("mark", "")))
    raise ValueError(kind)


def _named_box(record: dict[str, Any], comment: str, lead: tuple[str, ...]) -> FunctionBox:
    """A box with named pins (S7's), its sizes checked: a damaged draft must not fill memory."""
    named = tuple(Pin(str(n), int(r), bool(o), str(t), bool(g))
                  for n, r, o, t, g in record["named"])
    height = int(record.get("height", 1))
    pins = tuple(int(p) for p in record.get("pins", []))
    if not 1 <= height <= MAX_ROWS or any(not 0 <= p.row < height for p in named) \
            or any(not 0 <= p < height for p in pins):
        raise ValueError("pins")
    values = list(record.get("params", []))
    params = tuple(_parse_param(v) for v in values)
    origin = tuple((str(k), str(v)) for k, v in record.get("origin", []))
    return FunctionBox(str(record["name"]), params, comment, lead, pins, height, (), named,
                       str(record.get("title", "")), str(record.get("type", "")),
                       str(record.get("instance", "")), origin)


def _plain_element(kind: object, record: dict[str, Any], comment: str,
                   lead: tuple[str, ...]) -> Contact | Coil:
    if kind in ("contact", "coil"):
        text = record.get("address")
        address = parse_address(str(text), want_bit=True) if text else None
        if kind == "contact" and record.get("function"):
            name = str(record["function"])
            values = list(record.get("params", []))
            if spec_for(name, len(values)) is None:
                raise ValueError(name)
            return Contact(None, False, comment, lead, name, _parse_params(name, values))
        if kind == "contact":
            return Contact(address, bool(record.get("not", False)), comment, lead)
        write = Write(str(record.get("write", Write.OUT.value)))
        if write is Write.NONE:
            raise ValueError(write)
        row = str(record.get("row", ""))
        if row and lookup(row) is None:
            raise ValueError(row)
        return Coil(address, bool(record.get("not", False)), comment, lead, write, row)
    raise ValueError(kind)


def copy_text(network: LadderNetwork, selection: Selection | None = None) -> str:
    """The selected elements and links as text (the whole network when no selection)."""
    whole = selection is None
    sel = selection or Selection.whole(network)
    head: dict[str, Any] = {"columns": network.columns, "rows": sel.bottom - sel.top + 1,
                               "width": sel.right - sel.left + 1}
    if whole:
        head["rows"] = network.rows  # as set, even if an element reaches further
        if network.comments:
            head["comments"] = list(network.comments)
    lines = [f"{MAGIC} {json.dumps(head, ensure_ascii=False)}"]
    for (r, c), element in network.elements():
        cells = network.footprint((r, c), element)
        if not all(sel.holds(cell) for cell in cells):
            continue
        record = {"at": [r - sel.top, c - sel.left], **_element_record(element)}
        if c == network.coil_column:
            record["coil_column"] = True
        lines.append(json.dumps(record, ensure_ascii=False))
    for r, k in sorted(network.links):
        if sel.top <= r < sel.bottom and sel.left <= k <= sel.right + 1:
            lines.append(json.dumps({"link": [r - sel.top, k - sel.left]}))
    return "\n".join(lines) + "\n"


def _read(text: str) -> tuple[dict[str, Any], list[dict[str, Any]]]:
    lines = [line for line in split_lines(text) if line.strip()]
    if not lines or not lines[0].startswith(MAGIC):
        raise EditRefused("grid-text")
    try:
        head = json.loads(lines[0][len(MAGIC):])
        records = [json.loads(line) for line in lines[1:]]
    except json.JSONDecodeError:
        raise EditRefused("grid-text") from None
    if not isinstance(head, dict) or not all(isinstance(r, dict) for r in records):
        raise EditRefused("grid-text")
    return head, records


def network_from_text(text: str) -> LadderNetwork:
    """A whole network from `copy_text` output; EditRefused('grid-text') if it is not one."""
    head, records = _read(text)
    try:
        columns = int(head.get("columns", DEFAULT_COLUMNS))
        rows = int(head.get("rows", 1))
        if not (1 <= columns <= MAX_COLUMNS and 1 <= rows <= MAX_ROWS):
            raise ValueError("size")
        network = LadderNetwork(columns, rows,
                                comments=[str(x) for x in head.get("comments", [])])
        for record in records:
            if "link" in record:
                r, k = (int(x) for x in record["link"])
                if not (0 <= r < MAX_ROWS - 1 and 0 <= k <= columns):
                    raise ValueError("link")
                network.links.add((r, k))
                continue
            r, c = (int(x) for x in record["at"])
            _put(network, r, c, _element_from(record))
        network.rows = rows
    except (ValueError, KeyError, TypeError, AddressError, EditRefused):
        raise EditRefused("grid-text") from None
    return network


def cut(network: LadderNetwork, selection: Selection) -> tuple[str, Edit]:
    """Copy the selection as text and clear it; returns the text and the undo edit."""
    text = copy_text(network, selection)
    work = network.copy()
    for anchor, element in list(work.elements()):
        if all(selection.holds(cell) for cell in work.footprint(anchor, element)):
            del work.cells[anchor]
    work.links = {(r, k) for r, k in work.links
                  if not (selection.top <= r < selection.bottom
                          and selection.left <= k <= selection.right + 1)}
    return text, _change(network, work)


def paste(network: LadderNetwork, row: int, col: int, text: str) -> Edit:
    """Paste clipboard text with its top-left at a cell (coils copied from the coil column go
    to the coil column); what it covers is replaced. Returns the undo edit."""
    _, records = _read(text)
    work = network.copy()
    try:
        for record in records:
            if "link" in record:
                r, k = (int(x) for x in record["link"])
                if col + k > work.columns:
                    raise EditRefused("edit-outside", (row + r, col + k), row=row + r, col=col + k)
                _grow(work, row + r + 1)
                work.links.add((row + r, col + k))
                continue
            r, c = (int(x) for x in record["at"])
            element = _element_from(record)
            target = work.coil_column if record.get("coil_column") else col + c
            if target > work.columns:
                raise EditRefused("edit-outside", (row + r, target), row=row + r, col=target)
            _put(work, row + r, target, element)
    except (ValueError, KeyError, TypeError, AddressError):
        raise EditRefused("grid-text") from None
    return _change(network, work)
