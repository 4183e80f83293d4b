"""The instruction table decides: no module that uses instructions compares or lists their names."""

from __future__ import annotations

import ast
from pathlib import Path

import ladderworks
from ladderworks.core.instructions import ALL, SUB_KEYWORD

PACKAGE = Path(ladderworks.__file__).parent
# The table itself, and the modules whose capital words are not instructions.
TABLES = {"core/instructions.py"}
NOT_INSTRUCTIONS = {
    "core/plc/scenario.py": "scenario commands (SET, FORCE, ...)",
    "core/plc/recorder.py": "scenario commands (SET, FORCE, ...)",
}
NAMES = {spec.name for spec in ALL} | {spec.text_name for spec in ALL} | {SUB_KEYWORD}


def _named(node: ast.AST) -> bool:
    return isinstance(node, ast.Constant) and node.value in NAMES


def name_uses(tree: ast.AST) -> list[tuple[int, str]]:
    """Instruction names compared (==, in), listed (tuple, list, set, dict) or looked up."""
    found: list[tuple[int, str]] = []
    for node in ast.walk(tree):
        items: list[ast.AST] = []
        if isinstance(node, ast.Compare):
            items = [node.left, *node.comparators]
            for side in node.comparators:
                if isinstance(side, ast.Tuple | ast.List | ast.Set):
                    items += side.elts
        elif isinstance(node, ast.Tuple | ast.List | ast.Set):
            items = list(node.elts)
        elif isinstance(node, ast.Dict):
            items = [key for key in node.keys if key is not None]
        elif isinstance(node, ast.Subscript):
            items = [node.slice]
        elif isinstance(node, ast.Call) and isinstance(node.func, ast.Name | ast.Attribute):
            called = node.func.id if isinstance(node.func, ast.Name) else node.func.attr
            if called in {"lookup", "spec_for", "get"}:
                items = list(node.args[:1])
        found += [(item.lineno, item.value) for item in items  # type: ignore[attr-defined]
                  if _named(item)]
    return found


def test_no_consumer_compares_or_lists_instruction_names() -> None:
    offences = []
    for path in sorted(PACKAGE.rglob("*.py")):
        relative = path.relative_to(PACKAGE).as_posix()
        if relative in TABLES or relative in NOT_INSTRUCTIONS \
                or relative.startswith("core/dialects/"):
            continue
        tree = ast.parse(path.read_text(encoding="utf-8"))
        offences += [f"{relative}:{line}: {name}" for line, name in name_uses(tree)]
    assert offences == []


def test_the_scan_finds_what_it_forbids() -> None:
    samples = ['x = spec.name == "TMR"', 'x = name in ("TMRC", "CTRC")',
               'T = {"SFT": 1}', 'x = BY_NAME["TMR"]', 'x = spec_for("RD")',
               'ORDER = ("ADD", "SUB")']
    for sample in samples:
        assert name_uses(ast.parse(sample)), sample
    assert name_uses(ast.parse('@function("TMR")\ndef tmr(): pass')) == []
