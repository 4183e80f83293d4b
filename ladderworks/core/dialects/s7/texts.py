"""The `.s7res` companion of a `.s7dcl`: multilingual texts by id (titles, comments).

The form (public exports): `MultiLingualTexts:` then entries `- id: MLC_x` with one line per
culture `en-US: text` (a plain, single- or double-quoted scalar, or a `|` / `>` block). Only
this subset of YAML is read; anything else is skipped, never an error.
"""

from __future__ import annotations

import re

ENTRY_RE = re.compile(r"^(\s*)-\s+id:\s*(.*?)\s*$")
ITEM_RE = re.compile(r"^(\s*)([A-Za-z]{2,3}(?:-[A-Za-z0-9]+)*):\s?(.*)$")
PREFERRED = ("en-US", "en-GB", "tr-TR", "de-DE")


def scalar(text: str) -> str:
    text = text.strip()
    if len(text) >= 2 and text[0] == text[-1] == "'":
        return text[1:-1].replace("''", "'")
    if len(text) >= 2 and text[0] == text[-1] == '"':
        return bytes(text[1:-1], "utf-8").decode("unicode_escape", "replace") \
            if "\\" in text else text[1:-1]
    return text


def read_texts(text: str) -> dict[str, dict[str, str]]:
    """{id: {culture: text}} of an `.s7res` text."""
    found: dict[str, dict[str, str]] = {}
    current: dict[str, str] | None = None
    lines = text.lstrip("\ufeff").splitlines()
    index = 0
    while index < len(lines):
        line = lines[index]
        index += 1
        entry = ENTRY_RE.match(line)
        if entry is not None:
            current = found.setdefault(scalar(entry.group(2)), {})
            continue
        item = ITEM_RE.match(line)
        if item is None or current is None:
            continue
        indent, culture, value = len(item.group(1)), item.group(2), item.group(3)
        if value.strip() in ("|", "|-", "|+", ">", ">-", ">+"):
            block: list[str] = []
            while index < len(lines) and (not lines[index].strip() or
                                          len(lines[index]) - len(lines[index].lstrip()) > indent):
                block.append(lines[index].strip())
                index += 1
            joiner = " " if value.strip().startswith(">") else "\n"
            current[culture] = joiner.join(block).strip()
        else:
            current[culture] = scalar(value)
    return found


def pick(texts: dict[str, dict[str, str]], text_id: str, culture: str = "") -> str:
    """The text of an id in `culture`, else English, else the first culture; "" if none."""
    cultures = texts.get(text_id, {})
    for choice in (culture, *PREFERRED):
        if choice and cultures.get(choice):
            return cultures[choice]
    return next((value for value in cultures.values() if value), "")
