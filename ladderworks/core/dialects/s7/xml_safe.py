"""A small element tree of an XML text, parsed with expat with every DTD feature refused.

A DOCTYPE, an ENTITY declaration (internal or external) or an external entity reference stops
the parse with a diagnostic: nothing is expanded, nothing fetched. A text over `MAX_BYTES` is
refused before parsing. Each element keeps its line, so diagnostics point at it.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from xml.parsers import expat

from ladderworks.core.diagnostics import Diagnostic

MAX_BYTES = 32 * 1024 * 1024  # TIA's block exports are a few MB at most
MAX_DEPTH = 200  # SimaticML nests some 20 levels deep


@dataclass(slots=True)
class Element:
    """One element: namespace URI, local name, attributes, text, children, 1-based line."""

    ns: str
    name: str
    attrs: dict[str, str]
    line: int
    children: list[Element] = field(default_factory=list)
    text: str = ""

    def child(self, name: str) -> Element | None:
        """The first child called `name`."""
        return next((c for c in self.children if c.name == name), None)

    def all(self, name: str) -> list[Element]:
        """The children called `name`."""
        return [c for c in self.children if c.name == name]

    def find(self, *path: str) -> Element | None:
        """The first element down a path of child names."""
        node: Element | None = self
        for name in path:
            node = node.child(name) if node is not None else None
        return node

    def walk(self) -> list[Element]:
        """This element and every descendant, in document order (iteratively)."""
        found: list[Element] = []
        stack = [self]
        while stack:
            node = stack.pop()
            found.append(node)
            stack.extend(reversed(node.children))
        return found

    def text_of(self, name: str) -> str:
        """The stripped text of the child `name` ("" when absent)."""
        node = self.child(name)
        return node.text.strip() if node is not None else ""


class XmlRefused(Exception):
    """The text is refused or not well-formed; `diagnostic` says why and where."""

    def __init__(self, diagnostic: Diagnostic) -> None:
        super().__init__(diagnostic.message())
        self.diagnostic = diagnostic


def parse(data: bytes | str) -> Element:
    """The root element of `data`; XmlRefused when it is too large, declares a DTD or an entity,
    or is not well-formed XML."""
    raw = data.encode("utf-8", "replace") if isinstance(data, str) else data
    if len(raw) > MAX_BYTES:
        raise XmlRefused(Diagnostic("s7xml-too-large", {"size": len(raw) // (1024 * 1024),
                                                        "limit": MAX_BYTES // (1024 * 1024)},
                                    0, 0))
    parser = expat.ParserCreate(namespace_separator=" ")
    parser.SetParamEntityParsing(expat.XML_PARAM_ENTITY_PARSING_NEVER)
    stack: list[Element] = []
    root: list[Element] = []
    texts: list[list[str]] = []

    def refuse(what: str) -> None:
        raise XmlRefused(Diagnostic("s7xml-dtd", {"what": what}, parser.CurrentLineNumber,
                                    parser.CurrentColumnNumber + 1))

    def start(name: str, attrs: dict[str, str]) -> None:
        if len(stack) >= MAX_DEPTH:
            raise XmlRefused(Diagnostic("s7xml-malformed", {"why": "elements nested too deep"},
                                        parser.CurrentLineNumber, 1))
        ns, _sep, local = name.rpartition(" ")
        node = Element(ns, local, {k.rpartition(" ")[2]: v for k, v in attrs.items()},
                       parser.CurrentLineNumber)
        if stack:
            stack[-1].children.append(node)
        else:
            root.append(node)
        stack.append(node)
        texts.append([])

    def end(_name: str) -> None:
        node = stack.pop()
        node.text = "".join(texts.pop())

    def chars(data: str) -> None:
        if texts:
            texts[-1].append(data)

    parser.StartElementHandler = start
    parser.EndElementHandler = end
    parser.CharacterDataHandler = chars
    parser.StartDoctypeDeclHandler = lambda *_a: refuse("DOCTYPE")
    parser.EntityDeclHandler = lambda *_a: refuse("ENTITY")
    parser.UnparsedEntityDeclHandler = lambda *_a: refuse("ENTITY")
    parser.NotationDeclHandler = lambda *_a: refuse("NOTATION")
    parser.ExternalEntityRefHandler = lambda *_a: refuse("an external entity")  # type: ignore[assignment]
    parser.SkippedEntityHandler = lambda *_a: refuse("an undeclared entity")
    try:
        parser.Parse(raw, True)
    except expat.ExpatError as error:
        raise XmlRefused(Diagnostic("s7xml-malformed", {"why": expat.errors.messages[error.code]
                                                        if error.code else str(error)},
                                    error.lineno, error.offset + 1)) from None
    except (LookupError, ValueError) as error:  # an unknown encoding in the declaration
        raise XmlRefused(Diagnostic("s7xml-malformed", {"why": str(error)},
                                    parser.CurrentLineNumber, 1)) from None
    except RecursionError:  # pragma: no cover - MAX_DEPTH keeps the stack small
        raise XmlRefused(Diagnostic("s7xml-malformed", {"why": "elements nested too deep"},
                                    0, 0)) from None
    if not root:
        raise XmlRefused(Diagnostic("s7xml-malformed", {"why": "no element"}, 1, 1))
    return root[0]
