"""LadderWorks: a FANUC-PMC-style ladder IDE and PLC simulator for CNC technicians."""

__version__ = "0.1.0"


def version() -> str:
    """The installed package's version (this source's own when it is not installed)."""
    from importlib import metadata  # loaded when asked: `ladderworks-cli check` starts faster

    try:
        return metadata.version("ladderworks")
    except metadata.PackageNotFoundError:
        return __version__
