"""Test help for issue 7's docks: the console window's PLC docks on the virtual clock."""

from __future__ import annotations

from ladderworks.core.address import parse_address
from ladderworks.gui.docks.plc_docks import PlcDocks
from ladderworks.gui.main_window import MainWindow
from ladderworks.gui.plc_session import PlcSession

SWITCH = ("X2.1", "X2.3", "X2.5")


def plc_docks(window: MainWindow) -> PlcDocks:
    """The window's PLC docks, their session switched to the virtual clock."""
    docks = window.plc_docks
    docks.session.run.realtime = False
    return docks


def set_switch(session: PlcSession, position: int) -> None:
    """Turn the spindle-override rotary switch: X2.1, X2.3, X2.5 carry the position's bits."""
    for bit, address in enumerate(SWITCH):
        session.set_bit(parse_address(address), position >> bit & 1)


def override_code(position: int) -> int:
    """G30 for a switch position, from the seed's BIN 1 … BIN 128 equations."""
    r = [position == k for k in range(8)]
    bits = [r[6], r[0] or r[7], r[1] or r[3] or r[5] or r[6] or r[7],
            r[0] or r[2] or r[3] or r[6],
            (r[1] or r[3] or r[4] or r[6] or r[7]) and not r[5],
            (r[2] or r[3] or r[5] or r[6]) and not r[1],
            (r[4] or r[5] or r[6]) and not r[1], r[7] and not r[1]]
    return sum(1 << k for k, on in enumerate(bits) if on)
