"""Seed 002's listings (tab-separated as the seed prints them) with the [derived] function of
each output (docs/dialects.md, Fatek: the stack model), for the branch-logic tests."""

from __future__ import annotations

from collections.abc import Callable

Inputs = dict[str, int]
Case = tuple[str, str, dict[str, Callable[[Inputs], int]]]


def _t1(i: Inputs) -> int:
    return (i["X1"] & i["X2"]) | (i["X3"] & i["X4"])


# (seed lines, listing, {output: function of the inputs}); fragments that start inside a
# network get `ORG M100` (the incoming power p) in front.
CASES: list[Case] = [
    ("002:158-168", "ORG\tX\t0\nAND\tX\t1\nLD\tX\t2\nOR\tX\t3\nAND\tX\t4\nORLD\nAND\tX\t5\n"
     "OUT\tY\t0",
     {"Y0": lambda i: ((i["X0"] & i["X1"]) | ((i["X2"] | i["X3"]) & i["X4"])) & i["X5"]}),
    ("002:172-179", "ORG\tM\t0\nLD\tX\t0\nAND\tX\t1\nORLD\nOUT\tY\t0",
     {"Y0": lambda i: i["M0"] | (i["X0"] & i["X1"])}),
    ("002:181-190", "ORG\tM\t100\nAND\tY\t0\nLD\tM\t0\nAND\tM\t1\nLD\tX\t0\nAND\tX\t1\nORLD\n"
     "ANDLD\nOUT\tY\t1",
     {"Y1": lambda i: i["M100"] & i["Y0"] & ((i["M0"] & i["M1"]) | (i["X0"] & i["X1"]))}),
    ("002:215-222", "ORG\tX\t0\nAND\tX\t1\nOUT\tY\t0", {"Y0": lambda i: i["X0"] & i["X1"]}),
    ("002:224-232", "ORG\tX\t0\nOR\tX\t1\nAND\tX\t2\nOUT\tY\t0",
     {"Y0": lambda i: (i["X0"] | i["X1"]) & i["X2"]}),
    ("002:234-241", "ORG\tX\t0\nAND\tX\t1\nOR\tX\t2\nAND\tX\t3\nOUT\tY\t0",
     {"Y0": lambda i: ((i["X0"] & i["X1"]) | i["X2"]) & i["X3"]}),
    ("002:243-253", "ORG\tX\t2\nLD\tX\t0\nAND\tX\t1\nORLD\nAND\tX\t3\nOUT\tY\t0",
     {"Y0": lambda i: (i["X2"] | (i["X0"] & i["X1"])) & i["X3"]}),
    ("002:272-286", "ORG\tX\t1\nOR\tX\t2\nLD\tX\t3\nAND\tX\t4\nLD\tX\t5\nAND\tX\t6\nORLD\n"
     "ANDLD\nAND\tX\t7\nOUT\tY\t0",
     {"Y0": lambda i: (i["X1"] | i["X2"]) & ((i["X3"] & i["X4"]) | (i["X5"] & i["X6"]))
      & i["X7"]}),
    ("002:288-299", "ORG\tX\t0\nAND\tX\t1\nLD\tX\t2\nOR\tX\t3\nANDLD\nAND\tX\t4\nOUT\tY\t0",
     {"Y0": lambda i: i["X0"] & i["X1"] & (i["X2"] | i["X3"]) & i["X4"]}),
    ("002:301-317", "ORG\tX\t0\nLD\tX\t1\nOR\tX\t2\nANDLD\nLD\tX\t3\nAND\tX\t4\nLD\tX\t5\n"
     "AND\tX\t6\nORLD\nOR\tX\t7\nANDLD\nOUT\tY\t0",
     {"Y0": lambda i: i["X0"] & (i["X1"] | i["X2"])
      & ((i["X3"] & i["X4"]) | (i["X5"] & i["X6"]) | i["X7"])}),
    ("002:319-326", "ORG SHORT\nOUT\n\nY 0", {"Y0": lambda i: 1}),
    ("002:367-382", "ORG    M    100\nAND    X    0\nOUT TR 0\nAND    X    1\nOUT    Y    0\n"
     "LD TR  0 ← 2. sıradan başlar\nAND    X    2\nOUT    Y    1\n"
     "LD TR  0 ← 3. sıradan başlar\nOUT    Y    2",
     {"Y0": lambda i: i["M100"] & i["X0"] & i["X1"],
      "Y1": lambda i: i["M100"] & i["X0"] & i["X2"],
      "Y2": lambda i: i["M100"] & i["X0"]}),
    ("002:384-414", "ORG    X    1\nAND    X    2\nLD     X    3\nOUT TR 0\nAND    X    4\n"
     "ORLD\nOUT TR 1\nAND    X    5 ← AND komutu TR\nAND    X    6 ← Komutundan sonra\n"
     "LD TR 1 ← kullanılır.\nAND    X    7 ← LD TR komutu TR\nLD TR 0 ← branch hattına dönmek\n"
     "AND    X    9 ← için kullanılır.\nORLD\nAND    X    8\nORLD\nOUT    Y    0",
     {"Y0": lambda i: (_t1(i) & i["X5"] & i["X6"])
      | (((_t1(i) & i["X7"]) | (i["X3"] & i["X9"])) & i["X8"])}),
]

# 002:416-534: each pair of listings gives the same outputs (fragments completed as above)
PAIRS: list[tuple[str, str, str]] = [
    ("002:418-437", "ORG\tX\t0\nOR\tX\t9\nLD\tX\t1\nAND\tX\t2\nORLD\nOUT\tY\t0",
     "ORG\tX\t1\nAND\tX\t2\nOR\tX\t0\nOR\tX\t9\nOUT\tY\t0"),
    ("002:439-463", "ORG   X   0\nAND   X   1\nLD    X   2\nLD    X   3\nAND   X   4\nORLD\n"
     "ANDLD\nOUT Y 0",
     "ORG   X   3\nAND   X   4\nOR    X   2\nAND   X   0\nAND   X   1\nOUT Y 0"),
    ("002:465-485", "ORG M 100\nOUT TR 0\nAND   X   0\nOUT   Y   0\nLD TR 0\nOUT   Y   1",
     "ORG M 100\nOUT   Y   1\nAND   X   0\nOUT   Y   0"),
    ("002:487-515", "ORG   X   0\nLD    X   1\nOUT TR 0\nAND   X   2\nORLD\nOUT   Y   0\n"
     "LD TR 0\nAND   X   3\nOUT   Y   1",
     "ORG   X   1\nAND   X   2\nOR    X   0\nOUT   Y   0\nORG   X   1\nAND   X   3\n"
     "OUT   Y   1"),
]
