"""The S7 dialect's reader and opener: SimaticML XML (xml_open.py) or SIMATIC SD (reader.py),
chosen by content."""

from __future__ import annotations

from pathlib import Path

from ladderworks.core.diagnostics import Diagnostic
from ladderworks.core.dialects.s7 import reader, xml_open
from ladderworks.core.dialects.s7.xml_reader import is_simaticml
from ladderworks.core.il.program import Program
from ladderworks.core.il.textform import TextForm


def read(text: str, form: TextForm, lines: list[str],
         ends: list[str]) -> tuple[Program, list[Diagnostic]]:
    """One block's text: a SimaticML document or an SD block."""
    if is_simaticml(text) or text.lstrip().startswith("<SW."):
        return xml_open.read(text, form, lines, ends)
    return reader.read(text, form, lines, ends)


def open_path(path: Path, data: bytes | None) -> tuple[Program, list[Diagnostic], str]:
    """A block file with its folder's companions, or a folder of exports, as one program."""
    if xml_open.wants(path, data):
        return xml_open.open_path(path, data)
    return reader.open_path(path, data)
