"""The F, G, X and Y signal dictionary of the seed manual (with FANUC's `*` spelling of the
active-low signals): lookup by address, search by text."""

from __future__ import annotations

import csv
import re
from dataclasses import dataclass, replace
from functools import cache
from pathlib import Path

from ladderworks import paths
from ladderworks.core.address import Address, AddressError, Area, parse_address

# Areas that have named signals, in the order the manual (and search results) list them.
SIGNAL_AREAS: tuple[Area, ...] = (Area.F, Area.G, Area.X, Area.Y)
SIGNAL_FILES: dict[Area, str] = {area: f"{area.value.lower()}_signals.csv" for area in SIGNAL_AREAS}
CSV_COLUMNS: tuple[str, ...] = ("address", "name", "english", "turkish", "notes", "board")
# FANUC's own names of the signals whose name has a `*` (active low), which the seed's F/G
# table drops; with where each comes from (docs/signals.md)
FANUC_NAMES_FILE = "fanuc_names.csv"
FANUC_COLUMNS: tuple[str, ...] = ("address", "fanuc", "seed", "source")

# Turkish letters and their ASCII spelling, so `acil` finds `ACİL` and `is mili` finds `İŞ MİLİ`.
# Both I and ı fold to i: a technician typing on an English keyboard cannot tell them apart.
_TURKISH_FOLD = str.maketrans({
    "İ": "i", "I": "i", "ı": "i",
    "Ş": "s", "ş": "s",
    "Ğ": "g", "ğ": "g",
    "Ç": "c", "ç": "c",
    "Ö": "o", "ö": "o",
    "Ü": "u", "ü": "u",
})
_WORD_RE = re.compile(r"[0-9a-z]+")
_QUERY_ADDRESS_RE = re.compile(r"^([A-Za-z])(\d+)(?:\.(\d))?$")


@dataclass(frozen=True, slots=True)
class Signal:
    """A named signal; `address` is a bit (`F0.4`) or, for whole-byte data such as F10, a byte."""

    address: Address
    name: str
    english: str
    turkish: str
    notes: str = ""
    board: str = ""
    seed_name: str = ""  # the seed manual's spelling when FANUC's differs (`ESP` for `*ESP`)
    source: str = ""  # where FANUC's spelling comes from, when it differs

    @property
    def is_byte(self) -> bool:
        """True for a whole-byte signal such as `F10 MDC1`."""
        return self.address.bit is None

    def text(self) -> str:
        """Every searchable text of the signal, folded."""
        return fold(" ".join((self.name, self.seed_name, self.english, self.turkish,
                              self.notes)))

    def names(self) -> tuple[str, ...]:
        """Every spelling of its name, folded: FANUC's, the seed's, and FANUC's without `*`."""
        spellings = (self.name, self.seed_name, self.name.lstrip("*"))
        return tuple(dict.fromkeys(fold(name) for name in spellings if name))


def fold(text: str) -> str:
    """Case- and Turkish-letter-insensitive form of `text` (`ACİL DUR` -> `acil dur`)."""
    return text.translate(_TURKISH_FOLD).lower()


def sort_key(address: Address) -> tuple[int, int, int]:
    """Listing order: area as in the manual, byte, then a whole byte before its bits."""
    area_rank = SIGNAL_AREAS.index(address.area) if address.area in SIGNAL_AREAS else 99
    return area_rank, address.byte, -1 if address.bit is None else address.bit


def read_signal_file(path: Path, area: Area) -> list[Signal]:
    """Read one signal CSV; a row that is not an address of `area` raises ValueError."""
    signals: list[Signal] = []
    with path.open(encoding="utf-8", newline="") as handle:
        reader = csv.DictReader(handle)
        if tuple(reader.fieldnames or ()) != CSV_COLUMNS:
            raise ValueError(f"{path}: columns must be {','.join(CSV_COLUMNS)}")
        for row in reader:
            where = f"{path.name}:{reader.line_num}"
            try:
                address = parse_address(row["address"])
            except AddressError as exc:
                raise ValueError(f"{where}: bad address {row['address']!r} ({exc.code})") from None
            if address.area is not area:
                raise ValueError(f"{where}: {row['address']} is not in area {area.value}")
            signals.append(Signal(
                address=address,
                name=row["name"].strip(),
                english=row["english"].strip(),
                turkish=row["turkish"].strip(),
                notes=row["notes"].strip(),
                board=row["board"].strip(),
            ))
    return signals


def read_fanuc_names(path: Path) -> dict[Address, tuple[str, str, str]]:
    """FANUC's spelling of each starred signal: address -> (FANUC name, seed name, source)."""
    names: dict[Address, tuple[str, str, str]] = {}
    with path.open(encoding="utf-8", newline="") as handle:
        reader = csv.DictReader(handle)
        if tuple(reader.fieldnames or ()) != FANUC_COLUMNS:
            raise ValueError(f"{path}: columns must be {','.join(FANUC_COLUMNS)}")
        for row in reader:
            names[parse_address(row["address"])] = (row["fanuc"].strip(), row["seed"].strip(),
                                                    row["source"].strip())
    return names


@cache
def load_signals() -> tuple[Signal, ...]:
    """Every signal of resources/signals/, ordered by address (read once, then cached); a
    signal FANUC names with a `*` has FANUC's name, the seed's kept as `seed_name`."""
    signals: list[Signal] = []
    for area, filename in SIGNAL_FILES.items():
        signals.extend(read_signal_file(paths.signals_dir() / filename, area))
    fanuc = read_fanuc_names(paths.signals_dir() / FANUC_NAMES_FILE)
    for index, signal in enumerate(signals):
        if signal.address in fanuc:
            name, seed, source = fanuc[signal.address]
            if seed != signal.name:
                raise ValueError(f"{FANUC_NAMES_FILE}: {signal.address} is {signal.name!r} in "
                                 f"the seed's table, not {seed!r}")
            signals[index] = replace(signal, name=name, seed_name=seed, source=source)
    return tuple(sorted(signals, key=lambda s: sort_key(s.address)))


@cache
def _by_address() -> dict[Address, Signal]:
    return {signal.address: signal for signal in load_signals()}


@cache
def _by_byte() -> dict[Address, tuple[Signal, ...]]:
    groups: dict[Address, list[Signal]] = {}
    for signal in load_signals():
        groups.setdefault(signal.address.byte_address(), []).append(signal)
    return {byte: tuple(group) for byte, group in groups.items()}


def _as_address(address: Address | str) -> Address | None:
    if isinstance(address, Address):
        return address
    try:
        return parse_address(address)
    except AddressError:
        return None


def signal_at(address: Address | str) -> Signal | None:
    """The signal at `address` (`F0.4`, `F00.4`, `F000.4` alike), or None.

    A bit of a whole-byte signal gives that byte's signal (`F10.3` -> `F10 MDC1`).
    Text that is not an address gives None.
    """
    where = _as_address(address)
    if where is None:
        return None
    found = _by_address().get(where)
    if found is None and where.bit is not None:
        found = _by_address().get(where.byte_address())
    return found


def signals_in_byte(address: Address | str) -> list[Signal]:
    """Every signal of the byte that holds `address`, in bit order (for the bit display)."""
    where = _as_address(address)
    if where is None:
        return []
    return list(_by_byte().get(where.byte_address(), ()))


def _address_matches(query: str) -> list[Signal]:
    match = _QUERY_ADDRESS_RE.match(query)
    if not match:
        return []
    where = _as_address(query)
    if where is None or where.area not in SIGNAL_AREAS:
        return []
    if where.bit is None:
        return signals_in_byte(where)
    found = signal_at(where)
    return [found] if found is not None else []


def _words(text: str) -> list[str]:
    return _WORD_RE.findall(text)


@cache
def _search_index() -> tuple[tuple[Signal, tuple[str, ...], tuple[str, ...]], ...]:
    """Each signal with its folded names (every spelling) and the folded words of its texts."""
    return tuple((s, s.names(), tuple(_words(s.text()))) for s in load_signals())


def _word_match(signal_words: tuple[str, ...], query_words: list[str]) -> int:
    """2 when every query word is a whole word of the signal, 1 when only as word starts, 0."""
    if all(q in signal_words for q in query_words):
        return 2
    if all(any(w.startswith(q) for w in signal_words) for q in query_words):
        return 1
    return 0


def search(query: str) -> list[Signal]:
    """Signals matching `query`, best first.

    Matches: an address (`G8.4`; a byte `G8` gives all of G8), a short name (exact or prefix;
    FANUC's `*ESP`, `ESP` or the seed's spelling alike),
    or words that each begin a word of the name, English, Turkish or notes text. Case and
    Turkish letters are folded (`acil` finds `ACİL`). An empty query gives every signal.
    Order: exact address or name; then name prefixes and whole-word text matches; then
    word-start text matches; by address within each group.
    """
    text = query.strip()
    if not text:
        return list(load_signals())
    folded = fold(text)
    query_words = _words(folded)
    groups: tuple[list[Signal], list[Signal], list[Signal]] = ([], [], [])
    groups[0].extend(_address_matches(text))
    seen = {signal.address for signal in groups[0]}
    bare = folded.lstrip("*")  # `*ESP` and `ESP` find the same signal
    for signal, names, signal_words in _search_index():
        if signal.address in seen:
            continue
        words = _word_match(signal_words, query_words) if query_words else 0
        if folded in names or (bare and bare in names):
            groups[0].append(signal)
        elif any(name.startswith(folded) or (bare and name.startswith(bare))
                 for name in names) or words == 2:
            groups[1].append(signal)
        elif words == 1:
            groups[2].append(signal)
    return groups[0] + groups[1] + groups[2]
