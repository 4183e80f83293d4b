"""The core stays Qt-free: no module under ladderworks/core imports PySide6 or pyqtgraph."""

import ast
from pathlib import Path

import ladderworks.core

FORBIDDEN = ("PySide6", "pyqtgraph", "shiboken6")


def _imports(path: Path) -> list[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"))
    names: list[str] = []
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.extend(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom) and node.module:
            names.append(node.module)
    return names


def test_core_never_imports_qt() -> None:
    root = Path(ladderworks.core.__file__).parent
    files = sorted(root.rglob("*.py"))
    assert files
    offenders = [
        f"{path.relative_to(root)}: {name}"
        for path in files
        for name in _imports(path)
        if name.split(".")[0] in FORBIDDEN
    ]
    assert offenders == []
