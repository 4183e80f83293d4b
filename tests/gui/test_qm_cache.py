"""A checkout's `.qm`: built once per `.ts` content, never rewritten under a running process."""

from __future__ import annotations

import hashlib
from pathlib import Path

from PySide6.QtCore import QTranslator

from ladderworks.gui.translation import build_qm, ts_file


def test_the_qm_is_named_by_the_ts_hash_and_built_once(tmp_path: Path, qapp: object) -> None:
    digest = hashlib.sha256(ts_file("tr").read_bytes()).hexdigest()[:16]
    first = build_qm("tr", tmp_path)
    assert first == tmp_path / f"ladderworks_tr-{digest}.qm"
    built = first.stat()
    assert build_qm("tr", tmp_path) == first
    assert (first.stat().st_ino, first.stat().st_mtime_ns) == (built.st_ino, built.st_mtime_ns)
    assert sorted(path.name for path in tmp_path.iterdir()) == [first.name]  # no .part left
    translator = QTranslator()
    assert translator.load(str(first))
    assert translator.translate("MainWindow", "&File") == "&Dosya"
