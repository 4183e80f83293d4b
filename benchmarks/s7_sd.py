"""Prints ms to read a generated SIMATIC SD block of 750 networks (the counters example's
three networks over and over, each copy on its own instances), to save it back unchanged, and
to compile it and run 1,000 scans (no GUI)."""

from __future__ import annotations

import time
from pathlib import Path

from ladderworks.core.compiler import compile_program
from ladderworks.core.il.printer import print_faithful
from ladderworks.core.il.reading import parse_bytes
from ladderworks.core.plc.engine import ScanEngine

EXAMPLE = Path(__file__).resolve().parents[1] / "resources" / "examples" / "s7" / "counters"


def block(copies: int) -> bytes:
    """The example's networks `copies` times over, each copy with instances of its own."""
    text = (EXAMPLE / "Main.s7dcl").read_text("utf-8-sig")
    head, _, rest = text.partition('ORGANIZATION_BLOCK "Main"\n')
    body = rest.rsplit("END_ORGANIZATION_BLOCK", 1)[0]
    body = body.replace('"Say"', "%I0.0").replace('"Sıfırla"', "%I0.1")
    for name in ("Geri Say", "Yükle", "İleri", "Geri", "CTU Q", "CTD Q", "CTUD QU", "CTUD QD",
                 "CTU Değer", "CTD Değer", "CTUD Değer"):
        body = body.replace(f'"{name}"', {"CTU Değer": "%MW10", "CTD Değer": "%MW12",
                                          "CTUD Değer": "%MW14"}.get(name, "%M20.0"))
    copies_text = [body.replace('"Sayıcı_', f'"K{n}_') for n in range(copies)]
    return (head + 'ORGANIZATION_BLOCK "Main"\n' + "".join(copies_text)
            + "END_ORGANIZATION_BLOCK\n").encode("utf-8")


def _best(fn, repeat: int = 3) -> tuple[float, object]:  # type: ignore[no-untyped-def]
    best, result = float("inf"), None
    for _ in range(repeat):
        start = time.perf_counter()
        result = fn()
        best = min(best, time.perf_counter() - start)
    return best * 1000, result


def main() -> None:
    data = block(250)
    read_ms, result = _best(lambda: parse_bytes(data, "s7"))
    program = result.program  # type: ignore[attr-defined]
    assert not result.diagnostics  # type: ignore[attr-defined]
    save_ms, text = _best(lambda: print_faithful(program))
    assert text.encode("utf-8") == data
    compile_ms, compiled = _best(lambda: compile_program(program))
    engine = ScanEngine(compiled.binary)  # type: ignore[attr-defined]
    start = time.perf_counter()
    for _ in range(1000):
        engine.scan()
    scans_ms = (time.perf_counter() - start) * 1000
    print(f"S7 SD block, {len(data) // 1024} KiB, 750 networks -> "
          f"{len(program.networks)} engine networks")
    print(f"read {read_ms:.0f} ms, save unchanged {save_ms:.1f} ms, compile {compile_ms:.0f} ms, "
          f"1000 scans {scans_ms:.0f} ms ({scans_ms / 1000:.2f} ms a scan)")


if __name__ == "__main__":
    main()
