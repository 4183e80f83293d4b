"""Write the SimaticML (XML) twins of the SIMATIC SD examples: resources/examples/s7-xml/<name>.

Each SD example (resources/examples/s7/<name>/Main.s7dcl with its .s7res texts) is parsed into
the S7 graph and written with xml_writer (FlgNet/Interface v5, every culture of the titles);
the tag table and the scenario are copied. tests/core/dialects/s7/test_xml_reader.py checks
that both forms give the same graph and pass the same scenario.
"""

from __future__ import annotations

import shutil
import sys
from pathlib import Path

from ladderworks.core.dialects.s7.sd_parser import parse_sd
from ladderworks.core.dialects.s7.texts import read_texts
from ladderworks.core.dialects.s7.xml_writer import write_block

ROOT = Path(__file__).resolve().parent.parent
SOURCE = ROOT / "resources" / "examples" / "s7"
TARGET = ROOT / "resources" / "examples" / "s7-xml"


def main() -> int:
    """Write every example's XML twin: each block file, its texts, tags and scenarios."""
    for folder in sorted(p for p in SOURCE.iterdir() if (p / "Main.s7dcl").is_file()):
        parsed = {p.stem: parse_sd(p.read_text("utf-8-sig")) for p in folder.glob("*.s7dcl")}
        texts = read_texts((folder / "Main.s7res").read_text("utf-8-sig"))
        blocks = [p.block for p in parsed.values()]
        out = TARGET / folder.name
        out.mkdir(parents=True, exist_ok=True)
        for stem, one in sorted(parsed.items()):
            cultures = {}
            for index, (title, comment) in enumerate(one.title_ids, start=1):
                if title in texts:
                    cultures[(index, "title")] = texts[title]
                if comment in texts:
                    cultures[(index, "comment")] = texts[comment]
            (out / f"{stem}.xml").write_text(write_block(one.block, 5, cultures, blocks),
                                             "utf-8")
        for path in [folder / "PLC tags.xml", *folder.glob("*.scenario.csv")]:
            shutil.copyfile(path, out / path.name)
        print(out)
    return 0


if __name__ == "__main__":
    sys.exit(main())
