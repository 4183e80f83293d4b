"""Date, Time_Of_Day and LTime values as TIA's watch table writes them, and read back as typed.

A Date is the days since 1990-01-01 in a UInt (`D#1990-01-01` … `D#2169-06-06`), a
Time_Of_Day the milliseconds since midnight in a UDInt (`TOD#12:30:00.000`), an LTime the
nanoseconds in an LInt (`LT#1D_2H_3M_4S_5MS_6US_7NS`). S7-1200 system manual, "Data types".
"""

from __future__ import annotations

import re
from datetime import date, timedelta

EPOCH = date(1990, 1, 1)
LAST_DAY = 65_378  # D#2169-06-06, the last Date
DAY_MS = 86_400_000
LTIME_UNITS = (("D", 86_400 * 10**9), ("H", 3_600 * 10**9), ("M", 60 * 10**9), ("S", 10**9),
               ("MS", 10**6), ("US", 10**3), ("NS", 1))
_DATE_RE = re.compile(r"(?:(?:D|DATE)#)?(\d{4})-(\d{1,2})-(\d{1,2})", re.I)
_TOD_RE = re.compile(r"(?:(?:TOD|TIME_OF_DAY)#)?(\d{1,2}):(\d{1,2})(?::(\d{1,2})(?:\.(\d{1,3}))?)?",
                     re.I)
_LTIME_RE = re.compile(r"(\d+)(ns|us|ms|d|h|m|s)", re.I)
MAX_LTIME = 2**63 - 1


def date_text(days: int) -> str:
    """A Date's days as TIA writes it (`D#2024-01-31`)."""
    return f"D#{(EPOCH + timedelta(days=days)).isoformat()}"


def date_days(text: str) -> int | None:
    """A Date typed (`D#2024-01-31`, `DATE#2024-1-31`, `2024-01-31`) as its days; None when
    it is no date of the Date range."""
    match = _DATE_RE.fullmatch(text.strip())
    if match is None:
        return None
    try:
        days = (date(*(int(g) for g in match.groups())) - EPOCH).days
    except ValueError:  # no such day (2024-02-30)
        return None
    return days if 0 <= days <= LAST_DAY else None


def tod_text(ms: int) -> str:
    """A Time_Of_Day's milliseconds as TIA writes it (`TOD#12:30:00.000`)."""
    seconds, milli = divmod(ms, 1000)
    minutes, second = divmod(seconds, 60)
    hour, minute = divmod(minutes, 60)
    return f"TOD#{hour:02d}:{minute:02d}:{second:02d}.{milli:03d}"


def tod_ms(text: str) -> int | None:
    """A Time_Of_Day typed (`TOD#12:30:00.000`, `TIME_OF_DAY#8:05`, `23:59:59.999`) as its
    milliseconds; None when it is no time of a day."""
    match = _TOD_RE.fullmatch(text.strip())
    if match is None:
        return None
    hour, minute, second = (int(g or 0) for g in match.groups()[:3])
    milli = int((match.group(4) or "0").ljust(3, "0"))
    if hour > 23 or minute > 59 or second > 59:
        return None
    return ((hour * 60 + minute) * 60 + second) * 1000 + milli


def ltime_text(ns: int) -> str:
    """An LTime's nanoseconds as TIA writes it (`LT#1D_2H_3M_4S_5MS_6US_7NS`, `LT#0NS`)."""
    sign, rest = ("-", -ns) if ns < 0 else ("", ns)
    parts = []
    for unit, size in LTIME_UNITS:
        count, rest = divmod(rest, size)
        if count:
            parts.append(f"{count}{unit}")
    return f"LT#{sign}{'_'.join(parts) or '0NS'}"


def ltime_ns(text: str) -> int | None:
    """An LTime typed (`LT#1h30m`, `LTIME#-5s_300ms`, plain nanoseconds) as its nanoseconds;
    None when it is none or beyond LTime's range."""
    clean = text.strip().replace("_", "")
    if re.fullmatch(r"[+-]?\d+", clean):
        value = int(clean)
    else:
        head, sep, body = clean.partition("#")
        if not sep or head.upper() not in ("LT", "LTIME"):
            return None
        sign = -1 if body.startswith("-") else 1
        body = body.lstrip("+-")
        units = dict(LTIME_UNITS)
        total, at = 0, 0
        for match in _LTIME_RE.finditer(body):
            if match.start() != at:
                return None
            total += int(match.group(1)) * units[match.group(2).upper()]
            at = match.end()
        if not body or at != len(body):
            return None
        value = sign * total
    return value if -MAX_LTIME - 1 <= value <= MAX_LTIME else None
