"""Where the examples, signal tables, icons, help pages and translations are read from.

An installed wheel carries them inside the package: the build maps the checkout's top-level
`resources/`, `translations/` (compiled to `.qm`) and `docs/instructions*.md` to the package
folders named in PACKAGE_DATA. A source checkout or an editable install has no such folders in
the package, so the same functions fall back to the top-level folders of the checkout.
"""

from __future__ import annotations

from importlib import resources
from pathlib import Path

CHECKOUT = Path(__file__).resolve().parent.parent
# package folder -> the checkout's top-level folder it is built from
PACKAGE_DATA: dict[str, str] = {"resources": "resources", "translations": "translations",
                                "help": "docs"}
HELP_PAGES: dict[str, str] = {"en": "instructions.md", "tr": "instructions_tr.md"}
DIALECT_HELP = ("delta", "fatek", "s7")  # docs/instructions_<dialect>.md and its _tr.md


def data_dir(kind: str) -> Path:
    """The package folder `kind` of PACKAGE_DATA, or its checkout folder when not packaged."""
    packaged = resources.files("ladderworks") / kind
    if isinstance(packaged, Path) and packaged.is_dir():  # wheels install as plain folders
        return packaged
    return CHECKOUT / PACKAGE_DATA[kind]


def resources_dir() -> Path:
    """Examples, signal tables, icons and the sample AlarmMsg.dat."""
    return data_dir("resources")


def examples_dir() -> Path:
    """The example `.LAD` programs."""
    return resources_dir() / "examples"


def signals_dir() -> Path:
    """The signal tables (one CSV per area)."""
    return resources_dir() / "signals"


def icons_dir() -> Path:
    """The SVG icons."""
    return resources_dir() / "icons"


def alarm_file() -> Path:
    """The sample AlarmMsg.dat."""
    return resources_dir() / "AlarmMsg.dat"


def translations_dir() -> Path:
    """The compiled `.qm` files (packaged) or the `.ts` sources (checkout)."""
    return data_dir("translations")


def help_page(language: str) -> Path:
    """The instruction reference in `language` (English when there is none)."""
    return data_dir("help") / HELP_PAGES.get(language, HELP_PAGES["en"])


def dialect_help_pages(language: str) -> list[str]:
    """The file names of the dialects' own instruction pages in `language`."""
    suffix = "_tr" if language == "tr" else ""
    return [f"instructions_{name}{suffix}.md" for name in DIALECT_HELP]


def help_pages(language: str) -> list[Path]:
    """The instruction reference in `language` and each dialect's own page beside it."""
    main = help_page(language)
    return [main, *(main.parent / name for name in dialect_help_pages(
        "tr" if main.name == HELP_PAGES["tr"] else "en"))]


# The same folders resolved once, for the callers that name them as constants.
RESOURCES = resources_dir()
EXAMPLES = examples_dir()
SIGNALS = signals_dir()
ICONS = icons_dir()
