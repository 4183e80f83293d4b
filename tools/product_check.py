"""CI's product check: build the wheel, install it in a fresh venv and use it from elsewhere.

Run with the project's environment (`python3 tools/dev.py product`): it lists the wheel's files
against the data the code reads, installs the wheel into a new virtual environment, and from a
folder outside the checkout runs `ladderworks-cli` on a shipped example, starts the installed
IDE offscreen for a few seconds and checks that its menus are Turkish from the packaged `.qm`.
"""

from __future__ import annotations

import os
import re
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET
import zipfile
from collections.abc import Iterable, Sequence
from pathlib import Path

CHECKOUT = Path(__file__).resolve().parent.parent
PACKAGE = "ladderworks"
IDE_SECONDS = 3
_ICON_CALL = re.compile(r'\bicon(?:\(\s*|=)"([a-z]\w*)"')  # icon("name"), or icon="name" in a table

TURKISH_MENUS = """
import sys
from PySide6.QtCore import QSettings
from PySide6.QtWidgets import QApplication
app = QApplication(sys.argv[:1])
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.settings import Settings
from ladderworks.gui.translation import UiLanguage, build_qm
language = UiLanguage()
language.apply("tr")
window = MainWindow(Settings(QSettings(sys.argv[1], QSettings.Format.IniFormat)), language)
print(build_qm("tr"))
print("|".join(action.text() for action in window.menuBar().actions()))
"""


class CheckFailed(Exception):
    """A product check that did not pass."""


def read_by_code() -> set[str]:
    """Package-relative names of the data files the code names one by one."""
    from ladderworks.core.signals import SIGNAL_FILES
    from ladderworks.gui.editor.interactions import INTERACTIONS
    from ladderworks.gui.settings import LANGUAGES
    from ladderworks.paths import HELP_PAGES, alarm_file, dialect_help_pages, resources_dir

    icons = {interaction.icon_name for interaction in INTERACTIONS}
    for source in (CHECKOUT / PACKAGE).rglob("*.py"):
        icons.update(_ICON_CALL.findall(source.read_text("utf-8")))
    names = {"core/il/grammar.lark",
             f"resources/{alarm_file().relative_to(resources_dir()).as_posix()}"}
    names.update(f"resources/signals/{name}" for name in SIGNAL_FILES.values())
    names.update(f"resources/icons/{name}.svg" for name in icons)
    names.update(f"translations/ladderworks_{language}.qm" for language in LANGUAGES)
    names.update(f"help/{page}" for page in HELP_PAGES.values())
    names.update(f"help/{page}" for language in HELP_PAGES
                 for page in dialect_help_pages(language))
    return names


def required_files(checkout: Path = CHECKOUT) -> set[str]:
    """Wheel names of every runtime data file: all of resources/ and what the code names."""
    resources = checkout / "resources"
    shipped = {f"resources/{path.relative_to(resources).as_posix()}"
               for path in resources.rglob("*") if path.is_file()}
    return {f"{PACKAGE}/{name}" for name in shipped | read_by_code()}


def missing_from(wheel_names: Iterable[str], checkout: Path = CHECKOUT) -> list[str]:
    """The required files a wheel listing lacks, sorted."""
    return sorted(required_files(checkout) - set(wheel_names))


def run(command: Sequence[str | Path], cwd: Path, env: dict[str, str] | None = None,
        timeout: float = 600) -> subprocess.CompletedProcess[str]:
    """Run `command`, echoing it; a non-zero exit fails the check with its output."""
    shown = ("<script>" if "\n" in str(part) else str(part) for part in command)
    print("+", " ".join(shown), flush=True)
    result = subprocess.run([str(part) for part in command], cwd=cwd, env=env, text=True,
                            capture_output=True, timeout=timeout)
    if result.returncode != 0:
        raise CheckFailed(f"exit {result.returncode}\n{result.stdout}{result.stderr}")
    return result


def scripts_dir(venv: Path) -> Path:
    """Where `venv` keeps its interpreter and entry points."""
    return venv / ("Scripts" if os.name == "nt" else "bin")


def build_wheel(workdir: Path) -> Path:
    """`pip wheel --no-deps` of the checkout (an isolated build, as a user's) into `workdir`."""
    run([sys.executable, "-m", "pip", "wheel", "--no-deps", "--quiet",
         "--disable-pip-version-check", "--wheel-dir", workdir / "dist", CHECKOUT], CHECKOUT)
    (wheel,) = (workdir / "dist").glob("ladderworks-*.whl")
    return wheel


def check_wheel_files(wheel: Path) -> None:
    """Every runtime data file is in the wheel."""
    with zipfile.ZipFile(wheel) as archive:
        names = archive.namelist()
    missing = missing_from(names)
    if missing:
        raise CheckFailed(f"{wheel.name} lacks runtime data files: {missing}")
    size = wheel.stat().st_size / 1024
    print(f"{wheel.name}: {len(names)} files, {size:.0f} KiB, every runtime data file in it")


def install_wheel(wheel: Path, workdir: Path) -> Path:
    """A fresh venv with the wheel (and its dependencies) installed; its scripts folder."""
    venv = workdir / "venv"
    run([sys.executable, "-m", "venv", venv], workdir)
    bin_dir = scripts_dir(venv)
    run([bin_dir / "python", "-m", "pip", "install", "--quiet", "--disable-pip-version-check",
         wheel], workdir)
    return bin_dir


def turkish_file_menu() -> str:
    """The committed Turkish of the File menu's title."""
    for context in ET.parse(CHECKOUT / "translations" / "ladderworks_tr.ts").getroot():
        for message in context.iter("message"):
            if context.findtext("name") == "MainWindow" and message.findtext("source") == "&File":
                return message.findtext("translation") or ""
    raise CheckFailed("no Turkish for MainWindow &File in translations/ladderworks_tr.ts")


def check_installed(bin_dir: Path, workdir: Path) -> None:
    """The installed CLI and IDE work from a folder outside the checkout."""
    elsewhere = workdir / "elsewhere"
    elsewhere.mkdir()
    env = {**os.environ, "QT_QPA_PLATFORM": "offscreen", "HOME": str(elsewhere),
           "XDG_CONFIG_HOME": str(elsewhere / "config"), "XDG_CACHE_HOME": str(elsewhere / "cache"),
           "LANG": "tr_TR.UTF-8", "LC_ALL": ""}
    env.pop("PYTHONPATH", None)
    cli, ide, python = bin_dir / "ladderworks-cli", bin_dir / "ladderworks", bin_dir / "python"
    version = run([cli, "--version"], elsewhere, env).stdout.strip()
    print(version)
    run([ide, "--version"], elsewhere, env)
    located = run([python, "-c", "from ladderworks.paths import examples_dir; "
                   "print(examples_dir() / 'spindle_override.LAD')"], elsewhere, env)
    example = Path(located.stdout.strip())
    if not example.is_relative_to(workdir / "venv"):
        raise CheckFailed(f"the example is read from {example}, not the installed package")
    run([cli, "check", example], elsewhere, env)
    scan = run([cli, "run", example, "--scans", "3", "--set", "X2.1=1", "--set", "X2.3=1",
                "--print", "G30"], elsewhere, env)
    if "G30 = 60" not in scan.stdout:
        raise CheckFailed(f"spindle_override.LAD gave {scan.stdout!r}, not G30 = 60")
    if "SPL" not in run([cli, "signals", "SPL"], elsewhere, env).stdout:
        raise CheckFailed("ladderworks-cli signals SPL found nothing")
    run([cli, "alarms"], elsewhere, env)
    started = time.monotonic()
    ide_run = run([ide, "--quit-after", str(IDE_SECONDS * 1000)], elsewhere, env, timeout=120)
    if "Traceback" in ide_run.stderr:
        raise CheckFailed(f"the IDE printed a traceback:\n{ide_run.stderr}")
    print(f"the installed IDE ran {time.monotonic() - started:.1f} s offscreen without a traceback")
    menus = run([python, "-c", TURKISH_MENUS, elsewhere / "settings.ini"], elsewhere, env)
    qm, titles = menus.stdout.strip().splitlines()[-2:]
    if not Path(qm).is_relative_to(workdir / "venv"):
        raise CheckFailed(f"the Turkish .qm came from {qm}, not the installed package")
    if turkish_file_menu() not in titles.split("|"):
        raise CheckFailed(f"the installed IDE's menus are not Turkish: {titles}")
    print(f"Turkish menus from {Path(qm).name}: {titles}")


def main() -> int:
    """Run every product check; 0 when all pass."""
    started = time.monotonic()
    with tempfile.TemporaryDirectory(prefix="ladderworks-product-") as name:
        workdir = Path(name)
        try:
            wheel = build_wheel(workdir)
            check_wheel_files(wheel)
            check_installed(install_wheel(wheel, workdir), workdir)
        except CheckFailed as failure:
            print(f"product check FAILED: {failure}", file=sys.stderr)
            return 1
    print(f"product check passed in {time.monotonic() - started:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
