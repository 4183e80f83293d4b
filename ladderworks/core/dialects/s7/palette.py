"""The S7 palette: what each S7 row of the palette places, as the drawing draws it.

A tool places the element `drawing.py` draws for that part — a contact, a coil, a box with
TIA's named pins — with TIA's placeholder `<???>` on each operand to fill in and `...` on an
optional output left unwired; `operand_names` / `with_operands` are what the operand dialog
shows and sets. An operand left `<???>` is an error when the block is lowered, as in TIA.
"""

from __future__ import annotations

from dataclasses import replace

from ladderworks.core.dialects.s7 import pins
from ladderworks.core.dialects.s7.drawing import COMPARES, CONTACT_ROWS
from ladderworks.core.ladder.model import Coil, Contact, Element, FunctionBox, Pin

PLACEHOLDER = "<???>"
UNWIRED = "..."  # an optional output wired to nothing (TIA's "...")
_OPTIONAL = frozenset(("ET", "CV", "QD", "ENO"))
# the template each box part says its type with, and the type a new one takes
_TYPES = {**{name: ("time_type", "Time") for name in ("TP", "TON", "TOF", "TONR")},
          **{name: ("countType", "Int") for name in ("CTU", "CTD", "CTUD")},
          **{name: ("SrcType", "Int") for name in ("InRange", "OutRange", "Add", "Sub", "Mul",
                                                  "Div", "Inc", "Dec")}}
_BOX_ROWS = {"S7.TP": "TP", "S7.TON": "TON", "S7.TOF": "TOF", "S7.TONR": "TONR",
             "S7.CTU": "CTU", "S7.CTD": "CTD", "S7.CTUD": "CTUD", "S7.IN_RANGE": "InRange",
             "S7.OUT_RANGE": "OutRange", "S7.MOVE": "Move", "S7.ADD": "Add", "S7.SUB": "Sub",
             "S7.MUL": "Mul", "S7.DIV": "Div", "S7.INC": "Inc", "S7.DEC": "Dec",
             "S7.CONVERT": "Convert", "S7.SR": "Sr", "S7.RS": "Rs", "S7.P_TRIG": "PTrig",
             "S7.N_TRIG": "NTrig"}
_COIL_ROWS = {"S7.P_COIL": "P", "S7.N_COIL": "N", "S7.PT": "PT", "S7.RT": "RT", "S7.JMP": "JMP",
              "S7.JMPN": "JMPN", "S7.RET": "RET"}


def _box(part: str) -> FunctionBox:
    ins, outs = pins.LAYOUTS[part]
    named = [Pin(name, row, text="" if row == 0 else PLACEHOLDER)
             for row, (name, _keys) in enumerate(ins)]
    named += [Pin(name, row, output=True, text="" if row == 0 else
                  UNWIRED if name in _OPTIONAL else PLACEHOLDER)
              for row, (name, _keys) in enumerate(outs)]
    key, type_name = _TYPES.get(part, ("", ""))
    instance = PLACEHOLDER if part in pins.INSTANCED or part in (
        "Sr", "Rs", "PTrig", "NTrig") else ""
    origin = (("part", part), *(((key, type_name),) if key else ()))
    height = max(p.row for p in named) + 1
    return FunctionBox("S7." + part.upper(), pins=(0,), height=height, named=tuple(named),
                       title=pins.TITLES.get(part, part.upper()), type_name=type_name,
                       instance=instance, origin=origin)


def new_element(row: str) -> Element | None:
    """The element a palette row places in an S7 program (None: a row it does not offer)."""
    if row in _BOX_ROWS:
        return _box(_BOX_ROWS[row])
    part = next((name for name, found in CONTACT_ROWS.items() if found == row), "")
    if part in COMPARES:
        return Contact(function=row, mark=COMPARES[part] + "\nInt",
                       texts=(PLACEHOLDER, PLACEHOLDER))
    if part:
        edge = part in ("PContact", "NContact")
        mark = {"PContact": "P", "NContact": "N", "Ok": "OK", "NotOk": "NOT_OK"}[part]
        return Contact(function=row, mark=mark,
                       texts=(PLACEHOLDER, PLACEHOLDER) if edge else (PLACEHOLDER,))
    if row in _COIL_ROWS:
        mark = _COIL_ROWS[row]
        return Coil(mark=mark, texts=(PLACEHOLDER,) * (2 if mark in ("P", "N", "PT") else 1))
    return None


def operand_names(element: Element) -> list[str]:
    """The names of an element's operands, in the order of its texts (the dialog's rows)."""
    if isinstance(element, FunctionBox):
        head = ["instance"] if element.instance else []
        return head + [p.name for p in element.named if p.text]
    if isinstance(element, Contact) and element.function in {CONTACT_ROWS[n] for n in COMPARES}:
        return ["IN1", "IN2"][:len(element.texts)]
    if isinstance(element, Coil) and element.mark == "PT":
        return ["instance", "PT"]
    if isinstance(element, Coil) and element.mark in ("JMP", "JMPN"):
        return ["label"]
    if isinstance(element, Coil) and element.mark == "RET":
        return ["value"]  # TIA's Return_Value: TRUE, FALSE or a Bool, the block's ENO
    return ["operand", "memory"][:len(element.texts) or 1] if isinstance(
        element, Contact | Coil) else []


def operand_texts(element: Element) -> list[str]:
    """An element's operand texts in the order of `operand_names`."""
    if isinstance(element, FunctionBox):
        head = [element.instance] if element.instance else []
        return head + [p.text for p in element.named if p.text]
    return list(element.texts) if isinstance(element, Contact | Coil) else []


def with_operands(element: Element, texts: list[str]) -> Element:
    """The element with its operands (in the order of `operand_names`) replaced; an emptied
    optional output shows `...` (unwired)."""
    if isinstance(element, FunctionBox):
        given = iter(texts)
        instance = next(given, element.instance) if element.instance else ""
        named = tuple(replace(p, text=(next(given, p.text).strip() or
                                       (UNWIRED if p.output else PLACEHOLDER)))
                      if p.text else p for p in element.named)
        return replace(element, instance=instance.strip() or PLACEHOLDER, named=named) \
            if element.instance else replace(element, named=named)
    if isinstance(element, Contact | Coil):
        return replace(element, texts=tuple(t.strip() or PLACEHOLDER for t in texts),
                       address=None)
    return element
