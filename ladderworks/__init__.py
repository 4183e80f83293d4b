"""LadderWorks: a FANUC-PMC-style ladder IDE and PLC simulator for CNC technicians."""

from importlib import metadata

__version__ = "0.1.0"


def version() -> str:
    """The installed package's version (this source's own when it is not installed)."""
    try:
        return metadata.version("ladderworks")
    except metadata.PackageNotFoundError:
        return __version__
