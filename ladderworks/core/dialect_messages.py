"""The Fatek (listings, .pdw projects) and S7-1200 (SD, SimaticML) readers' diagnostic templates
by code, in the "Diagnostic" context; `diagnostics.MESSAGES` holds them with the others."""

from __future__ import annotations

from ladderworks.core.translate_mark import QT_TRANSLATE_NOOP

DIALECT_MESSAGES: dict[str, str] = {
    # Fatek FBs programs (docs/dialects.md, Fatek)
    "fatek-ascii-quote": QT_TRANSLATE_NOOP(
        "Diagnostic", "ASCII format: the text opened by {quote} is never closed"),
    "fatek-ascii-repeat": QT_TRANSLATE_NOOP(
        "Diagnostic", "ASCII format: a repeat count must be 1 to 999, found {count}"),
    "fatek-ascii-item": QT_TRANSLATE_NOOP(
        "Diagnostic",
        "ASCII format: '{text}' is not an item (expected 'text', MX, hex codes,"
        " \"w.dRn\", / or \\)"),
    "fatek-ascii-variable": QT_TRANSLATE_NOOP(
        "Diagnostic",
        "ASCII format: \"{text}\" is not a variable (expected e.g. \"8.2R0\" or \"4R10H\")"),
    "fatek-ascii-after-end": QT_TRANSLATE_NOOP(
        "Diagnostic", "ASCII format: text after END: '{text}'"),
    "fatek-ascii-no-end": QT_TRANSLATE_NOOP("Diagnostic", "ASCII format: END is missing"),
    "fatek-unknown-instruction": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{name}' is not a Fatek instruction"),
    "fatek-stray-operand": QT_TRANSLATE_NOOP(
        "Diagnostic", "an operand line '{text}' without a FUN, TMR or CTR before it"),
    "fatek-missing-device": QT_TRANSLATE_NOOP("Diagnostic", "{name} needs a device"),
    "fatek-device": QT_TRANSLATE_NOOP("Diagnostic", "'{text}' is not a Fatek device"),
    "fatek-device-kind": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name} cannot take '{text}' (use {kinds})"),
    "fatek-device-range": QT_TRANSLATE_NOOP("Diagnostic", "'{text}' is out of range ({range})"),
    "fatek-no-input": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name} with nothing before it: a network starts with ORG"),
    "fatek-stack-empty": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name} needs two blocks: start the second one with LD"),
    "fatek-tr-reused": QT_TRANSLATE_NOOP(
        "Diagnostic", "TR{number} is set twice in this network"),
    "fatek-tr-count": QT_TRANSLATE_NOOP(
        "Diagnostic", "a network has at most {limit} TR points"),
    "fatek-tr-unset": QT_TRANSLATE_NOOP(
        "Diagnostic", "LD TR{number} before OUT TR{number} in this network"),
    "fatek-output-on-rail": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name} on the left rail: put ORG SHORT before it"),
    "fatek-open-block": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name}: {count} block(s) started with LD are not joined (ANDLD/ORLD)"),
    "fatek-unknown-fun": QT_TRANSLATE_NOOP(
        "Diagnostic", "FUN {number} is not a Fatek function LadderWorks knows"),
    "fatek-missing-operand": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name}: the operand line {param} is missing"),
    "fatek-extra-operand": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name} takes no more operands, found '{text}'"),
    "fatek-operand": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' cannot be the operand {param} (a register, or a constant)"),
    "fatek-bit-operand": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' cannot be the operand {param} (a bit device: Y0, M5 …)"),
    "fatek-not-simulated": QT_TRANSLATE_NOOP(
        "Diagnostic", "{name} is kept and drawn but not simulated: its outputs stay 0"),
    "fatek-timer-base": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is not the time base of {name} ({base})"),
    "fatek-fo": QT_TRANSLATE_NOOP(
        "Diagnostic", "FO {text}: no function output here (FO0-FO7 after a box)"),
    "fatek-long-number": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}…' is too long to be a Fatek number: the line is not read"),
    "fatek-comment-header": QT_TRANSLATE_NOOP(
        "Diagnostic",
        "not a WinProladder comment export: its first line must be REF, COMMENT, DESCRIPTION"
        " (tab-separated)"),
    "fatek-comment-ref": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is not a Fatek device: the line is skipped"),
    "fatek-comment-codepage": QT_TRANSLATE_NOOP(
        "Diagnostic",
        "the comments were read in code page {chosen}; they read as {others} too: check the"
        " names"),
    "fatek-comment-bytes": QT_TRANSLATE_NOOP(
        "Diagnostic",
        "byte {offset} (0x{byte}) is a character in no Windows code page tried: the comments"
        " are not read"),
    "fatek-ascii-section": QT_TRANSLATE_NOOP(
        "Diagnostic", "ASCII files: '{text}' is not a section header such as [R1000]"),
    # WinProladder projects (.pdw; docs/dialects.md, ".pdw projects"): byte offsets in the file
    "pdw-header": QT_TRANSLATE_NOOP(
        "Diagnostic", "not a WinProladder project: no 'Fatek WinProladder, File Format 1' header"),
    "pdw-truncated": QT_TRANSLATE_NOOP(
        "Diagnostic", "the .pdw file is cut short: its record at byte {offset} runs past the end"),
    "pdw-checksum": QT_TRANSLATE_NOOP(
        "Diagnostic", "the .pdw file is damaged: the record at byte {offset} fails its checksum"),
    "pdw-record": QT_TRANSLATE_NOOP(
        "Diagnostic", "the .pdw file is damaged: the record at byte {offset} is malformed"),
    "pdw-no-program": QT_TRANSLATE_NOOP(
        "Diagnostic", "the .pdw file holds no program (checked up to byte {offset})"),
    "pdw-key": QT_TRANSLATE_NOOP(
        "Diagnostic",
        "the program at byte {offset} cannot be unmasked: it has no erased memory block to"
        " recover the mask from"),
    "pdw-image": QT_TRANSLATE_NOOP(
        "Diagnostic", "the .pdw file is damaged: its program image is wrong at byte {offset}"),
    "pdw-program-checksum": QT_TRANSLATE_NOOP(
        "Diagnostic",
        "the .pdw file is damaged: the program's code does not match its checksum (byte"
        " {offset})"),
    "pdw-code": QT_TRANSLATE_NOOP(
        "Diagnostic",
        "instruction code {word} at byte {offset} is not one LadderWorks decodes yet: the"
        " program is read up to it"),
    "pdw-operand": QT_TRANSLATE_NOOP(
        "Diagnostic",
        "operand code {word} at byte {offset} is not a device LadderWorks decodes yet: the"
        " program is read up to it"),
    "pdw-cut": QT_TRANSLATE_NOOP(
        "Diagnostic", "the program ends inside an instruction at byte {offset}"),
    # Siemens S7-1200 (docs/dialects.md, S7-1200)
    "s7-address": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is not an S7 address (e.g. %I0.0, %MW2, %DB1.DBW4) or a tag"),
    "s7-syntax": QT_TRANSLATE_NOOP(
        "Diagnostic", "SIMATIC SD: expected {expected}, found '{found}'"),
    "s7-cut": QT_TRANSLATE_NOOP(
        "Diagnostic", "SIMATIC SD: the text ends inside {what} (cut off?)"),
    "s7-part-unknown": QT_TRANSLATE_NOOP(
        "Diagnostic", "network {network}: '{part}' is not an instruction LadderWorks simulates"),
    "s7-operand-unknown": QT_TRANSLATE_NOOP(
        "Diagnostic", "network {network}: '{text}' is neither a tag, a member of the block "
        "nor an address"),
    "s7-pin-missing": QT_TRANSLATE_NOOP(
        "Diagnostic", "network {network}: {part} needs its pin {pin}"),
    "s7-wire": QT_TRANSLATE_NOOP(
        "Diagnostic", "network {network}: the wiring of {part} cannot be followed ({why})"),
    "s7-label-unknown": QT_TRANSLATE_NOOP(
        "Diagnostic", "network {network}: there is no label '{label}' in this block"),
    "s7-not-simulated": QT_TRANSLATE_NOOP(
        "Diagnostic", "network {network}: a {language} network is shown, not simulated"),
    "s7-call-unknown": QT_TRANSLATE_NOOP(
        "Diagnostic", "network {network}: the block '{block}' it calls is not in the program"),
    "s7-tag-undeclared": QT_TRANSLATE_NOOP(
        "Diagnostic", "network {network}: {text} is in none of the tag tables read; "
        "LadderWorks gives it a place of its own ({type})"),
    "s7-type": QT_TRANSLATE_NOOP(
        "Diagnostic", "network {network}: {part} on the type '{type}' is not simulated"),
    "s7-memory-full": QT_TRANSLATE_NOOP(
        "Diagnostic", "network {network}: no room left for '{text}' (DB members and "
        "instances share 10000 bytes)"),
    "s7-too-large": QT_TRANSLATE_NOOP(
        "Diagnostic", "the file has {size} MB: S7 exports over {limit} MB are not read"),
    "s7-tags": QT_TRANSLATE_NOOP(
        "Diagnostic", "tag table: {why}"),
    "s7-grid-operand": QT_TRANSLATE_NOOP(
        "Diagnostic", "network {network}, row {row}, column {column}: the contact or coil has "
        "no operand"),
    "s7-grid-element": QT_TRANSLATE_NOOP(
        "Diagnostic", "network {network}, row {row}, column {column}: '{name}' is no S7 "
        "element (use the S7 palette)"),
    "s7-save-changed": QT_TRANSLATE_NOOP(
        "Diagnostic", "this change cannot be written into the S7 block's file: make it in "
        "TIA Portal"),
    "s7-db-syntax": QT_TRANSLATE_NOOP(
        "Diagnostic", "{file}, line {line}: expected {expected}, found '{found}': the source "
        "is not read"),
    "s7-db-cut": QT_TRANSLATE_NOOP(
        "Diagnostic", "{file}, line {line}: the text ends inside {what} (cut off?): the source "
        "is not read"),
    "s7-save-unreadable": QT_TRANSLATE_NOOP(
        "Diagnostic", "the S7 block's file no longer reads (line {line}): nothing is written"),
    "s7-save-unwritable": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{part}' cannot be written in the S7 block's file form: make this "
        "change in TIA Portal"),
    "s7-label-name": QT_TRANSLATE_NOOP(
        "Diagnostic", "'{text}' is no S7 jump label: letters, digits and _, not starting "
        "with a digit"),
    "s7-save-drawing": QT_TRANSLATE_NOOP(
        "Diagnostic", "network {network} is not a complete S7 network yet (an element S7 "
        "does not have, an operand missing or still <???>): the S7 block's file is not "
        "written"),
    # SimaticML XML (docs/dialects.md, SimaticML XML)
    "s7xml-too-large": QT_TRANSLATE_NOOP(
        "Diagnostic", "SimaticML: the file is {size} MB, more than the {limit} MB LadderWorks "
        "reads"),
    "s7xml-dtd": QT_TRANSLATE_NOOP(
        "Diagnostic", "SimaticML: {what} is refused (entities are never expanded or fetched)"),
    "s7xml-malformed": QT_TRANSLATE_NOOP("Diagnostic", "SimaticML: not well-formed XML ({why})"),
    "s7xml-empty": QT_TRANSLATE_NOOP(
        "Diagnostic", "SimaticML: the document holds no block (SW.Blocks.…) and no tag table"),
    "s7xml-namespace": QT_TRANSLATE_NOOP(
        "Diagnostic", "{block}, network {network}: the namespace '{uri}' is not TIA Openness's; "
        "the network is not read"),
    "s7xml-version": QT_TRANSLATE_NOOP(
        "Diagnostic", "{block}, network {network}: {kind} version v{version} is newer than the "
        "v5 LadderWorks knows; read as v5"),
    "s7xml-wire": QT_TRANSLATE_NOOP(
        "Diagnostic", "{block}, network {network}: wire {wire} goes to the part UId {uid}, "
        "which is not in the network"),
    "s7xml-loop": QT_TRANSLATE_NOOP(
        "Diagnostic", "{block}, network {network}: the wires from part UId {uid} loop back "
        "to it"),
    "s7xml-part": QT_TRANSLATE_NOOP(
        "Diagnostic", "{block}, network {network}: part UId {uid} '{part}' is not known to "
        "LadderWorks (kept, not simulated)"),
    "s7xml-too-many": QT_TRANSLATE_NOOP(
        "Diagnostic", "{block}, network {network}: more than {limit} parts; the network is "
        "not read"),
    "s7xml-access": QT_TRANSLATE_NOOP(
        "Diagnostic", "{block}, network {network}: access UId {uid} of scope '{scope}' names "
        "nothing LadderWorks reads; the parts wired to it are not simulated"),
    "s7xml-call-missing": QT_TRANSLATE_NOOP(
        "Diagnostic", "{block}, network {network}: part UId {uid} calls '{callee}', which is "
        "not in the program"),
}
