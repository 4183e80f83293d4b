"""SimaticML's texts: a `Component` as a path element, an `Access` as TIA shows it, and an
SCL (`StructuredText`) or STL (`StatementList`) network's text rebuilt from its tokens."""

from __future__ import annotations

from ladderworks.core.dialects.s7.xml_forms import address_text
from ladderworks.core.dialects.s7.xml_safe import Element


def component(node: Element) -> str:
    """A `Component` as the graph's path element: its name, an array index in brackets."""
    name = node.attrs.get("Name", "")
    indices = [a for a in node.children if a.name == "Access"]
    if not indices:
        return name
    texts = []
    for access in indices:
        constant = access.child("Constant")
        if constant is not None:
            texts.append(constant.text_of("ConstantValue"))
        else:
            symbol = access.child("Symbol")
            components = symbol.all("Component") if symbol is not None else []
            prefix = "#" if access.attrs.get("Scope") == "LocalVariable" else ""
            texts.append(prefix + ".".join(component(c) for c in components))
    return f"{name}[{','.join(texts)}]"


def access_text(node: Element) -> str:
    """An `Access` inside SCL/STL text as TIA shows it: #local, "Global".member, %MW2, 5."""
    scope = node.attrs.get("Scope", "")
    constant = node.child("Constant")
    if constant is not None:
        return constant.text_of("ConstantValue") or constant.attrs.get("Name", "")
    symbol = node.child("Symbol")
    if symbol is None:
        address = node.child("Address")
        return address_text(address.attrs) if address is not None else ""
    names = [component(c) for c in symbol.all("Component")]
    if scope == "LocalVariable":
        return "#" + ".".join(names)
    head, *rest = names or [""]
    return ".".join([f'"{head}"', *rest])


def source_text(body: Element) -> str:
    """An SCL (`StructuredText`) or STL (`StatementList`) network's text from its tokens."""
    out: list[str] = []
    stack = list(reversed(body.children))
    while stack:
        node = stack.pop()
        name = node.name
        if name == "Access":
            out.append(access_text(node))
            continue
        if name in ("Token", "StlToken"):
            out.append(node.attrs.get("Text", ""))
            if name == "StlToken":
                out.append(" ")
        elif name == "Blank":
            out.append(" " * _count(node))
        elif name == "NewLine":
            out.append("\n" * _count(node))
        elif name == "LineComment":
            out.append("//" + "".join(t.text for t in node.walk() if t.name == "Text"))
            continue
        elif name == "Comment":
            out.append("(*" + "".join(t.text for t in node.walk() if t.name == "Text") + "*)")
            continue
        elif name == "StlStatement" and out and not out[-1].endswith("\n"):
            out.append("\n")
        stack.extend(reversed(node.children))
    lines = "".join(out).split("\n")
    return "\n".join(line.rstrip() for line in lines).strip("\n")


def _count(node: Element) -> int:
    text = node.attrs.get("Num", "1")
    return min(int(text), 1000) if text.isdigit() else 1


def graph_text(body: Element) -> str:
    """A GRAPH sequence (`Graph` network source) as text to show: its title, its steps (number,
    name, initial) and each transition with the steps it leads from and to (a `Jump` link
    marked); the actions, supervisions and interlocks are not shown [LW]."""
    sequence = body.child("Sequence")
    if sequence is None:
        return "GRAPH"
    title = sequence.find("Title", "MultiLanguageText")
    lines = [f"GRAPH {title.text.strip()}" if title is not None else "GRAPH"]
    steps = sequence.child("Steps")
    for step in steps.all("Step") if steps is not None else []:
        initial = " (initial)" if step.attrs.get("Init", "").lower() == "true" else ""
        lines.append(f"S{step.attrs.get('Number', '?')} {step.attrs.get('Name', '')}{initial}")
    before: dict[str, str] = {}
    after: dict[str, str] = {}
    connections = sequence.child("Connections")
    for link in connections.all("Connection") if connections is not None else []:
        start = (link.find("NodeFrom", "StepRef"), link.find("NodeFrom", "TransitionRef"))
        end = (link.find("NodeTo", "StepRef"), link.find("NodeTo", "TransitionRef"))
        jump = " (jump)" if link.text_of("LinkType") == "Jump" else ""
        if start[0] is not None and end[1] is not None:
            before[end[1].attrs.get("Number", "")] = "S" + start[0].attrs.get("Number", "?")
        elif start[1] is not None and end[0] is not None:
            after[start[1].attrs.get("Number", "")] = "S" + end[0].attrs.get("Number", "?") + jump
    transitions = sequence.child("Transitions")
    for transition in transitions.all("Transition") if transitions is not None else []:
        number = transition.attrs.get("Number", "?")
        lines.append(f"T{number} {transition.attrs.get('Name', '')}: "
                     f"{before.get(number, '?')} -> {after.get(number, '?')}")
    return "\n".join(lines)
