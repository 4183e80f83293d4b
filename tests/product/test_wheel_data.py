"""The wheel's data: staged from the checkout, read by paths.py the way the code reads it."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

from PySide6.QtCore import QTranslator

from ladderworks import paths
from tools.package_data import data_files, stage_data, translation_files
from tools.product_check import missing_from, read_by_code, required_files

CHECKOUT = Path(__file__).resolve().parents[2]


def _listing(root: Path) -> list[str]:
    return [path.relative_to(root).as_posix() for path in root.rglob("*") if path.is_file()]


def _staged_package(tmp_path: Path) -> Path:
    """A copy of the package's modules with the data staged as the wheel build does."""
    package = tmp_path / "site" / "ladderworks"
    shutil.copytree(CHECKOUT / "ladderworks", package,
                    ignore=shutil.ignore_patterns("__pycache__"))
    stage_data(CHECKOUT, package)
    return package


def test_the_staged_package_holds_every_runtime_data_file(tmp_path: Path) -> None:
    package = _staged_package(tmp_path)
    assert missing_from(_listing(package.parent)) == []
    assert "ladderworks/translations/ladderworks_tr.qm" in required_files()
    assert "ladderworks/help/instructions_tr.md" in required_files()
    # each dialect's help (issue 38)
    for page in ("delta", "delta_tr", "fatek", "fatek_tr", "s7", "s7_tr"):
        assert f"ladderworks/help/instructions_{page}.md" in required_files()
    assert not (package / "translations" / "ladderworks_tr.ts").exists()  # only the .qm ships


def test_a_missing_data_file_is_named(tmp_path: Path) -> None:
    listing = _listing(_staged_package(tmp_path).parent)
    for name in ("ladderworks/resources/signals/f_signals.csv",
                 "ladderworks/resources/icons/zoom_in.svg",
                 "ladderworks/translations/ladderworks_tr.qm",
                 "ladderworks/core/il/grammar.lark"):
        assert missing_from(item for item in listing if item != name) == [name]


def test_the_code_names_files_that_exist_in_the_checkout() -> None:
    sources = {**data_files(CHECKOUT), **translation_files(CHECKOUT)}
    named = {name for name in read_by_code() if name != "core/il/grammar.lark"}
    assert {"resources/icons/ladderworks.svg", "resources/AlarmMsg.dat",
            "help/instructions.md", "translations/ladderworks_en.qm"} <= named
    assert sorted(named - set(sources)) == []


def test_the_packaged_turkish_qm_translates_the_menus(tmp_path: Path, qapp: object) -> None:
    package = _staged_package(tmp_path)
    translator = QTranslator()
    assert translator.load(str(package / "translations" / "ladderworks_tr.qm"))
    assert translator.translate("MainWindow", "&File") == "&Dosya"


def test_an_installed_package_reads_its_own_data(tmp_path: Path) -> None:
    package = _staged_package(tmp_path)
    script = ("from ladderworks import paths; "
              "print(paths.examples_dir()); print(paths.help_page('tr')); "
              "print(paths.translations_dir()); print(paths.alarm_file().is_file())")
    env = {**os.environ, "PYTHONPATH": str(package.parent)}
    result = subprocess.run([sys.executable, "-c", script], cwd=tmp_path, env=env,
                            capture_output=True, text=True, check=True, timeout=60)
    examples, help_tr, translations, alarm_exists = result.stdout.split("\n")[:4]
    assert Path(examples) == package / "resources" / "examples"
    assert Path(help_tr) == package / "help" / "instructions_tr.md"
    assert Path(translations) == package / "translations"
    assert alarm_exists == "True"


def test_a_checkout_reads_the_top_level_folders() -> None:
    assert paths.examples_dir() == CHECKOUT / "resources" / "examples"
    assert paths.translations_dir() == CHECKOUT / "translations"
    assert paths.help_page("tr") == CHECKOUT / "docs" / "instructions_tr.md"
    assert paths.help_page("xx") == CHECKOUT / "docs" / "instructions.md"
