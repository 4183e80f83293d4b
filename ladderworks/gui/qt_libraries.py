"""Qt's xcb platform needs system libraries PySide6 does not ship: name the missing packages."""

from __future__ import annotations

import ctypes
from collections.abc import Callable, Mapping

from PySide6.QtCore import QCoreApplication

# What PySide6's platforms/libqxcb.so and libQt6XcbQpa need from the system (`ldd`), by soname,
# with the Debian/Ubuntu package that installs it.
XCB_LIBRARIES: dict[str, str] = {
    "libxcb-cursor.so.0": "libxcb-cursor0",
    "libxcb-icccm.so.4": "libxcb-icccm4",
    "libxcb-image.so.0": "libxcb-image0",
    "libxcb-keysyms.so.1": "libxcb-keysyms1",
    "libxcb-randr.so.0": "libxcb-randr0",
    "libxcb-render-util.so.0": "libxcb-render-util0",
    "libxcb-render.so.0": "libxcb-render0",
    "libxcb-shape.so.0": "libxcb-shape0",
    "libxcb-shm.so.0": "libxcb-shm0",
    "libxcb-sync.so.1": "libxcb-sync1",
    "libxcb-util.so.1": "libxcb-util1",
    "libxcb-xfixes.so.0": "libxcb-xfixes0",
    "libxcb-xkb.so.1": "libxcb-xkb1",
    "libxcb.so.1": "libxcb1",
    "libX11-xcb.so.1": "libx11-xcb1",
    "libX11.so.6": "libx11-6",
    "libxkbcommon.so.0": "libxkbcommon0",
    "libxkbcommon-x11.so.0": "libxkbcommon-x11-0",
    "libfontconfig.so.1": "libfontconfig1",
    "libfreetype.so.6": "libfreetype6",
    "libdbus-1.so.3": "libdbus-1-3",
    "libglib-2.0.so.0": "libglib2.0-0",
    "libGL.so.1": "libgl1",
    "libEGL.so.1": "libegl1",
}


def loadable(soname: str) -> bool:
    """True when the dynamic loader finds and loads `soname`."""
    try:
        ctypes.CDLL(soname)
    except OSError:
        return False
    return True


def uses_xcb(environ: Mapping[str, str], platform: str) -> bool:
    """True when Qt will start on its xcb (X11) platform plugin."""
    if not platform.startswith("linux"):
        return False
    chosen = environ.get("QT_QPA_PLATFORM", "").strip()
    if chosen:
        return chosen.split(";")[0].startswith("xcb")
    return not environ.get("WAYLAND_DISPLAY")


def missing_libraries(can_load: Callable[[str], bool] = loadable) -> list[str]:
    """The sonames of XCB_LIBRARIES that cannot be loaded."""
    return [soname for soname in XCB_LIBRARIES if not can_load(soname)]


def packages_for(sonames: list[str]) -> list[str]:
    """The Debian/Ubuntu packages that install `sonames`, sorted, each once."""
    return sorted({XCB_LIBRARIES[soname] for soname in sonames})


def missing_libraries_text(sonames: list[str]) -> str:
    """What is missing and the apt-get command that installs it, in the UI language."""
    missing = QCoreApplication.translate(
        "QtLibraries",
        "LadderWorks cannot start: Qt's X11 (xcb) platform needs system libraries that are "
        "missing: {0}.").format(", ".join(sonames))
    how = QCoreApplication.translate("QtLibraries", "On Debian or Ubuntu, install them with:")
    return f"{missing}\n{how}\n    sudo apt-get install {' '.join(packages_for(sonames))}"
