"""PLC tag tables (TIA Openness XML: `SW.Tags.PlcTagTable` of `SW.Tags.PlcTag`) as `Tag`s.

Parsed with the standard library's expat with no DTD at all: a text with a DOCTYPE or an
ENTITY declaration is refused before parsing (no entity expansion, nothing fetched).
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.s7.graph import Tag

_DTD_RE = re.compile(r"<!\s*(DOCTYPE|ENTITY)", re.I)


def _local(tag: str) -> str:
    return tag.rsplit("}", 1)[-1]


def safe_xml(text: str) -> tuple[ET.Element | None, Diagnostic | None]:
    """The root element of an XML text, or the diagnostic why it is refused or unreadable."""
    found = _DTD_RE.search(text)
    if found is not None:
        line = text.count("\n", 0, found.start()) + 1
        return None, Diagnostic("s7-tags", {"why": "a DOCTYPE or ENTITY declaration is refused"},
                                line, 1)
    try:
        return ET.fromstring(text), None
    except ET.ParseError as error:
        line, column = getattr(error, "position", (1, 0))
        return None, Diagnostic("s7-tags", {"why": f"not well-formed XML ({error.msg})"
                                            if hasattr(error, "msg") else "not well-formed XML"},
                                line, column + 1)


def _text(element: ET.Element, name: str) -> str:
    for child in element.iter():
        if _local(child.tag) == name:
            return (child.text or "").strip()
    return ""


def _comment(tag: ET.Element) -> str:
    for child in tag.iter():
        if _local(child.tag) == "MultilingualText":
            for item in child.iter():
                if _local(item.tag) == "MultilingualTextItem":
                    text = _text(item, "Text")
                    if text:
                        return text
    return ""


def read_tag_table(text: str) -> tuple[list[Tag], list[Diagnostic]]:
    """The tags of a tag table export, and why it could not be read (if so)."""
    root, problem = safe_xml(text)
    if root is None:
        return [], [problem] if problem is not None else []
    tags: list[Tag] = []
    table = ""
    tables = 0
    for element in root.iter():
        name = _local(element.tag)
        if name == "SW.Tags.PlcTagTable":
            table = _text(element, "Name")
            tables += 1
        elif name in ("SW.Tags.PlcTag", "SW.Tags.PlcUserConstant"):  # a constant: its Value
            attributes = next((c for c in element if _local(c.tag) == "AttributeList"), element)
            tags.append(Tag(_text(attributes, "Name"), _text(attributes, "DataTypeName"),
                            _text(attributes, "LogicalAddress"), _comment(element), table,
                            _text(attributes, "Value")))
    if not tags and not tables:  # an empty table (no tag yet) is read as empty
        return [], [Diagnostic("s7-tags", {"why": "no SW.Tags.PlcTag in it"}, 1, 1)]
    return tags, []


def is_tag_table(text: str) -> bool:
    """True for a tag table export."""
    return "SW.Tags.PlcTagTable" in text[:5000] or "SW.Tags.PlcTag" in text[:5000]
