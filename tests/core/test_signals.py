"""Tests of the signal dictionary: the data files, lookup by address and search."""

from __future__ import annotations

import csv
from pathlib import Path

import pytest

from ladderworks import paths
from ladderworks.core.address import Address, Area, format_address, parse_address
from ladderworks.core.signals import (
    CSV_COLUMNS,
    SIGNAL_FILES,
    fold,
    load_signals,
    read_signal_file,
    search,
    signal_at,
    signals_in_byte,
)


def _rows(area: Area) -> list[dict[str, str]]:
    with (paths.SIGNALS / SIGNAL_FILES[area]).open(encoding="utf-8", newline="") as handle:
        return list(csv.DictReader(handle))


# ------------------------------------------------------------------ the data files

@pytest.mark.parametrize("area", list(SIGNAL_FILES))
def test_every_row_is_a_canonical_address_of_its_area(area: Area) -> None:
    rows = _rows(area)
    assert rows
    for row in rows:
        address = parse_address(row["address"])
        assert address.area is area, row
        assert format_address(address) == row["address"], "address not in canonical spelling"
        assert row["name"].strip(), row
        assert row["english"].strip() or row["turkish"].strip(), row


@pytest.mark.parametrize("area", list(SIGNAL_FILES))
def test_columns(area: Area) -> None:
    with (paths.SIGNALS / SIGNAL_FILES[area]).open(encoding="utf-8", newline="") as handle:
        header = next(csv.reader(handle))
    assert tuple(header) == CSV_COLUMNS


def test_no_duplicate_addresses() -> None:
    addresses = [signal.address for signal in load_signals()]
    assert len(addresses) == len(set(addresses))


def test_bits_only_except_documented_byte_signals() -> None:
    # The manual names a few whole bytes (binary M/S/T codes, user status data); no bit
    # signal may sit inside such a byte.
    bytes_ = [s for s in load_signals() if s.is_byte]
    assert {s.name for s in bytes_} >= {"MDC1", "MDC4", "SDC1", "TDC4", "USRD1", "USRD50"}
    assert all(s.address.area is Area.F for s in bytes_)
    for signal in bytes_:
        assert signals_in_byte(signal.address) == [signal]


def test_x_and_y_rows_name_their_board() -> None:
    for area in (Area.X, Area.Y):
        for row in _rows(area):
            assert row["board"], row
    for area in (Area.F, Area.G):
        assert all(not row["board"] for row in _rows(area))
    boards = {s.board for s in load_signals()}
    assert {"FP105/J1", "FP105/J2", "DC-155/IO-1"} <= boards


def test_size_of_the_dictionary() -> None:
    by_area: dict[Area, int] = {}
    for signal in load_signals():
        by_area[signal.address.area] = by_area.get(signal.address.area, 0) + 1
    # Manual section 6: ~400 table rows, many of them covering 8 bits each.
    assert sum(by_area.values()) > 1000
    assert by_area[Area.X] == 89
    assert by_area[Area.Y] == 32


def test_manual_rows_reassembled() -> None:
    spl = signal_at("F0.4")
    assert spl is not None
    assert (spl.name, spl.english, spl.turkish) == ("SPL", "CYCLE STOP", "PROGRAM DUR")
    assert spl.notes == "0: PROGRAM BAŞLADI VEYA RESET / 1: PROGRAM DURDU (FEED HOLD)"
    op = signal_at("F0.7")
    assert op is not None and op.english == "AUTO MODE RUNNING"
    assert op.turkish == "OTOMATİK MODE ÇALIŞIYOR"
    # a range row of the manual (F102.0-F102.7 MV1-MV8) is one signal per bit
    assert [s.name for s in signals_in_byte("F102")] == [f"MV{i}" for i in range(1, 9)]
    assert [s.name for s in signals_in_byte("F5")] == [f"MBDT{i}" for i in range(2, 10)]
    assert signal_at("F55.7").name == "UO15"  # type: ignore[union-attr]
    assert signal_at("F303.7").name == "PD01X31"  # type: ignore[union-attr]
    assert signal_at("G11.7").name == "*JV15"  # type: ignore[union-attr]
    assert signal_at("G102.0").name == "-J1"  # type: ignore[union-attr]
    hw = signal_at("X0.0")
    assert hw is not None and hw.name == "HW_ESTP" and hw.board == "FP105/J1"


def test_read_signal_file_rejects_wrong_area(tmp_path: Path) -> None:
    path = tmp_path / "g.csv"
    path.write_text(",".join(CSV_COLUMNS) + "\nF0.4,SPL,CYCLE STOP,PROGRAM DUR,,\n",
                    encoding="utf-8")
    with pytest.raises(ValueError, match="not in area G"):
        read_signal_file(path, Area.G)
    bad = tmp_path / "bad.csv"
    bad.write_text(",".join(CSV_COLUMNS) + "\nG9999.0,X,,,,\n", encoding="utf-8")
    with pytest.raises(ValueError, match="bad address"):
        read_signal_file(bad, Area.G)


# ------------------------------------------------------------------ lookup

@pytest.mark.parametrize("text", ["F0.4", "F00.4", "F000.4", "f0.4"])
def test_signal_at_accepts_leading_zeros(text: str) -> None:
    found = signal_at(text)
    assert found is not None and found.name == "SPL"


def test_signal_at_address_object_and_misses() -> None:
    assert signal_at(Address(Area.G, 8, 4)).name == "*ESP"  # type: ignore[union-attr]
    assert signal_at("F0.0") is None
    assert signal_at("R100.0") is None
    assert signal_at("not an address") is None
    assert signal_at("F0.9") is None


def test_bit_of_a_byte_signal_gives_the_byte() -> None:
    found = signal_at("F10.3")
    assert found is not None and found.name == "MDC1" and found.is_byte
    assert signal_at("F10") is found


def test_signals_in_byte() -> None:
    names = [s.name for s in signals_in_byte("G8.4")]
    assert names == ["*IT", "*ESP", "*SP", "ERS"]
    assert [s.address.bit for s in signals_in_byte("G8")] == [0, 4, 5, 7]
    assert signals_in_byte("R0") == []
    assert signals_in_byte("???") == []


def test_load_is_cached_and_ordered() -> None:
    first = load_signals()
    assert load_signals() is first
    areas = [s.address.area for s in first]
    assert areas.index(Area.G) > areas.index(Area.F)
    assert areas[-1] is Area.Y
    f_bytes = [(s.address.byte, s.address.bit or 0) for s in first if s.address.area is Area.F]
    assert f_bytes == sorted(f_bytes)


# ------------------------------------------------------------------ search

def test_fold_turkish_letters() -> None:
    assert fold("ACİL DUR") == "acil dur"
    assert fold("İŞ MİLİ") == "is mili"
    assert fold("ĞÜŞIÖÇ ğüşıöç") == "gusioc gusioc"


def test_search_by_name() -> None:
    assert [s.address for s in search("SPL")][:1] == [parse_address("F0.4")]
    assert search("spl")[0].name == "SPL"


def test_search_exact_name_before_prefix() -> None:
    results = search("MV1")
    assert results[0].name == "MV1"
    prefix = [s.name for s in search("MV")]
    assert set(prefix) >= {f"MV{i}" for i in range(1, 9)} | {f"MVD{i}" for i in range(1, 9)}


def test_search_by_address_and_byte() -> None:
    assert [s.name for s in search("G8.4")] == ["*ESP"]
    assert [s.name for s in search("G008.4")] == ["*ESP"]
    assert [str(s.address) for s in search("G8")][:4] == ["G8.0", "G8.4", "G8.5", "G8.7"]


def test_search_turkish_folding() -> None:
    names = [s.name for s in search("acil")]
    assert names[0] == "*ESP"  # ACİL DUR as a whole word comes before AÇILDI
    assert "HW_ESTP" in names
    assert [s.name for s in search("acil dur")] == ["*ESP", "HW_ESTP"]
    assert "*ESP" in [s.name for s in search("ACİL")]
    assert "ENB" in [s.name for s in search("is mili")]
    assert "ENB" in [s.name for s in search("İŞ MİLİ")]


def test_search_english_words_and_notes() -> None:
    assert [s.name for s in search("emergency stop")] == ["*ESP"]
    assert [s.name for s in search("feed hold")] == ["SPL"]
    assert "SA" in [s.name for s in search("servo ready")]


def test_search_all_and_nothing() -> None:
    assert len(search("")) == len(load_signals())
    assert search("no such signal qqq") == []


def test_search_has_no_duplicates() -> None:
    for query in ("G8", "is", "F1", "e-stop"):
        found = [s.address for s in search(query)]
        assert len(found) == len(set(found))


# ------------------------------------------------------------------ ladderworks-cli signals

def test_cli_signals_spl(capsys: pytest.CaptureFixture[str]) -> None:
    from ladderworks.cli import main

    assert main(["signals", "SPL"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert lines[0].startswith("F0.4  SPL  CYCLE STOP  PROGRAM DUR  0: PROGRAM BAŞLADI")


def test_cli_signals_esp(capsys: pytest.CaptureFixture[str]) -> None:
    from ladderworks.cli import main

    assert main(["signals", "G8.4"]) == 0
    out = capsys.readouterr().out
    assert out.splitlines() == [out.rstrip("\n")]
    assert out.startswith("G8.4  *ESP")
    assert "EMERGENCY STOP" in out and "ACİL DUR" in out


def test_cli_signals_all_and_words(capsys: pytest.CaptureFixture[str]) -> None:
    from ladderworks.cli import main

    assert main(["signals"]) == 0
    lines = capsys.readouterr().out.splitlines()
    assert len(lines) == len(load_signals())
    assert lines[0].startswith("F0.4 ")
    assert lines[-1].startswith("Y3.7 ") and lines[-1].endswith("[DC-155-2/IO-3,4]")
    assert main(["signals", "acil", "dur"]) == 0
    assert [line.split()[0] for line in capsys.readouterr().out.splitlines()] == ["G8.4", "X0.0"]


def test_cli_signals_no_match(capsys: pytest.CaptureFixture[str]) -> None:
    from ladderworks.cli import main

    assert main(["signals", "qqqq"]) == 1
    captured = capsys.readouterr()
    assert captured.out == ""
    assert "no signal matches 'qqqq'" in captured.err


# ------------------------------------------------------------------ FANUC's `*` names


def test_fanuc_star_names_replace_the_seeds_spelling_with_their_source() -> None:
    for address, fanuc, seed in (("G8.4", "*ESP", "ESP"), ("G8.0", "*IT", "IT"),
                                 ("G8.5", "*SP", "SP"), ("G114.0", "*+L1", "LMS1P")):
        signal = signal_at(address)
        assert signal is not None
        assert (signal.name, signal.seed_name) == (fanuc, seed)
        assert "FANUC_STUDER_X22_P036" in signal.source
    plain = signal_at("G8.7")
    assert plain is not None and (plain.name, plain.seed_name, plain.source) == ("ERS", "", "")


@pytest.mark.parametrize("query", ["*ESP", "ESP", "esp", "*esp"])
def test_a_starred_signal_is_found_by_either_spelling(query: str) -> None:
    assert str(search(query)[0].address) == "G8.4"


def test_the_star_names_are_the_real_exports_symbols() -> None:
    """Each row of fanuc_names.csv: the seed's name at that address, and the same FANUC
    name in the real programs' symbol tables it cites."""
    from tests.real_programs import real_programs_dir
    with (paths.SIGNALS / "fanuc_names.csv").open(encoding="utf-8", newline="") as handle:
        rows = list(csv.DictReader(handle))
    assert len(rows) >= 60
    texts = {name: (real_programs_dir() / f"{name}.txt").read_bytes().decode("utf-8")
             for name in ("FANUC_STUDER_X22_P036", "FANUC_STUDER_S41_F036")}
    seed = {str(s.address): s.seed_name for s in load_signals() if s.seed_name}
    for row in rows:
        assert row["fanuc"].startswith("*")
        assert seed[row["address"]] == row["seed"]
        for name in ("FANUC_STUDER_X22_P036", "FANUC_STUDER_S41_F036"):
            if name in row["source"]:
                assert f"\n{row['address']}" in texts[name] and row["fanuc"] in texts[name]
