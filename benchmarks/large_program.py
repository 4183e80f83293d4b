"""Shared generator of large programs for the benchmarks: mixed networks like a real PMC program."""

from __future__ import annotations


def large_program_text(networks: int = 2000) -> str:
    """A `.LAD` text with `networks` networks: series/parallel logic, stack ops, timers, coils."""
    lines = ["%@3"]
    for n in range(networks):
        byte = n % 900
        lines.append(f"// network {n}: İŞ MİLİ / EKSEN {n}")
        kind = n % 4
        if kind == 0:
            lines += [f"RD X{n % 120}.{n % 8}  // giriş", f"AND.NOT R{byte}.1",
                      f"OR R{byte}.2", f"WRT R{byte}.3"]
        elif kind == 1:
            lines += [f"RD.NOT F{n % 700}.{n % 8}", f"AND R{byte}.3",
                      f"RD.STK R{byte}.4", f"AND.NOT R{byte}.5", "OR.STK",
                      f"WRT R{byte}.6", f"WRT.NOT R{byte}.7"]
        elif kind == 2:
            lines += [f"RD R{byte}.6", f"TMRB {n % 100 + 1} {8 * (n % 50 + 1)}",
                      f"WRT Y{n % 120}.{n % 8}"]
        else:
            lines += [f"RD R{byte}.0", f"AND R{(byte + 1) % 900}.1",
                      f"RD.STK R{byte}.2", f"OR R{byte}.3", "AND.STK",
                      f"WRT G{n % 700}.{n % 8}"]
    lines.append("%")
    return "\n".join(lines) + "\n"
