#!/usr/bin/env python3
"""Write the CoolRunner-II ZIA maps of xc2bit, and the package pins of merkur's
CoolRunner-II targets, from Project Combine's database.

xc2bit 0.0.4 (third_party/xc2bit) knows how each ZIA row's configuration
bits encode its choices (`decode_<N>_zia_choice`: the choice index of each
bit pattern) but, for the XC2C128, 256, 384 and 512, not which signal each
choice selects: its `ZIA_MAP_<N>` tables are placeholders. Project Combine
(github.com/prjunnamed/prjcombine, databases/coolrunner2.txt; 0BSD or
Apache-2.0) lists, for every die and every ZIA row (`IM[r].MUX` of the
`IMUX_BITS` tile), each choice's bit pattern and the signal it selects.

This script joins the two on the bit pattern (xc2bit lists a row's bits in
the reverse of Project Combine's order) and rewrites the four tables in
third_party/xc2bit/src/zia.rs. It first regenerates the XC2C32A and XC2C64A
tables, which xc2bit has from hardware fuzzing, and stops unless they come
out entry for entry as xc2bit has them.

It also writes cli/src/synth/xc2_pins.rs: for each device, the package pin
of every pad (function block, macrocell) in the device's largest package,
where every pad of the die is bonded; `merkur synth` reports the open
fitter's pin placement with it.

Usage: scripts/gen-xc2-zia.py COOLRUNNER2_TXT
  COOLRUNNER2_TXT  Project Combine's databases/coolrunner2.txt
Run from the repository's root; both files are rewritten in place.
"""

import os
import re
import sys

# xc2bit table size -> (Project Combine chip, choices a row)
DIES = {32: ("CHIP1", 6), 64: ("CHIP3", 12), 128: ("CHIP4", 22),
        256: ("CHIP5", 40), 384: ("CHIP6", 62), 512: ("CHIP7", 78)}
ROWS = 40


def fail(msg):
    print(f"gen-xc2-zia: {msg}", file=sys.stderr)
    sys.exit(2)


def read_chips(text):
    """Per chip: the macrocells with a pad, and every ZIA row's choices."""
    chips = {}
    chip = None
    row = None
    in_imux = False
    for line in text.splitlines():
        m = re.match(r"^chip (CHIP\d+) \{", line)
        if m:
            chip = {"pads": [], "rows": {}}
            chips[m.group(1)] = chip
            continue
        if line.startswith("}"):
            chip = None
            continue
        if chip is None:
            continue
        m = re.match(r"^\tio IOB_C0B(\d+)MC(\d+) =", line)
        if m:
            chip["pads"].append((int(m.group(1)), int(m.group(2))))
            continue
        if re.match(r"^\tbstile ", line):
            in_imux = line.strip().startswith("bstile IMUX_BITS")
            row = None
            continue
        if not in_imux:
            continue
        m = re.match(r"^\tIM\[(\d+)\]\.MUX:", line)
        if m:
            row = {}
            chip["rows"][int(m.group(1))] = row
            continue
        m = re.match(r"^\t\t([01]+): (\S+)$", line)
        if m and row is not None:
            row[m.group(1)] = m.group(2)
        elif not line.startswith("\t\t"):
            row = None
    return chips


def iob_numbers(pads):
    """xc2bit numbers a die's I/O buffers in function block, macrocell order."""
    return {fbmc: i for i, fbmc in enumerate(sorted(pads))}


def xc2bit_choice(name, iobs):
    m = re.match(r"^MC_C0B(\d+)MC(\d+)$", name)
    if m:
        return f"XC2ZIAInput::Macrocell{{fb: {m.group(1)}, mc: {m.group(2)}}}"
    m = re.match(r"^IOB_C0B(\d+)MC(\d+)$", name)
    if m:
        fbmc = (int(m.group(1)), int(m.group(2)))
        if fbmc not in iobs:
            fail(f"{name} is a ZIA choice but the die lists no such pad")
        return f"XC2ZIAInput::IBuf{{ibuf: {iobs[fbmc]}}}"
    if re.match(r"^IPAD\d*$", name):
        return "XC2ZIAInput::DedicatedInput"
    fail(f"unknown ZIA source {name}")


def decode_patterns(zia_rs, n):
    """xc2bit's bit pattern of each choice index of the N-macrocell ZIA."""
    m = re.search(rf"fn decode_{n}_zia_choice.*?\n    }}\n", zia_rs, re.S)
    if not m:
        fail(f"decode_{n}_zia_choice not found")
    pats = {}
    for arm in re.finditer(rf"\[([TF, ]+)\] => ZIA_MAP_{n}\[row\]\[(\d+)\]", m.group(0)):
        bits = "".join("1" if b.strip() == "T" else "0" for b in arm.group(1).split(","))
        pats[int(arm.group(2))] = bits
    return pats


def table(chips, zia_rs, n):
    chip, width = DIES[n]
    die = chips[chip]
    iobs = iob_numbers(die["pads"])
    pats = decode_patterns(zia_rs, n)
    if sorted(pats) != list(range(width)):
        fail(f"decode_{n}_zia_choice has choices {sorted(pats)}, expected 0..{width}")
    rows = []
    for r in range(ROWS):
        choices = die["rows"].get(r)
        if choices is None:
            fail(f"{chip} has no IM[{r}]")
        entries = []
        for k in range(width):
            name = choices.get(pats[k][::-1])
            if name is None:
                fail(f"{chip} IM[{r}]: no choice has xc2bit's pattern {k}")
            entries.append(xc2bit_choice(name, iobs))
        named = {v for v in choices.values() if v not in ("VCC", "GND")}
        if len(named) != width:
            fail(f"{chip} IM[{r}] has {len(named)} signal choices, xc2bit {width}")
        rows.append(entries)
    return rows


def render(n, rows):
    out = [f"/// merkur: generated by scripts/gen-xc2-zia.py from Project Combine's database",
           f"/// (the choices of each row's `decode_{n}_zia_choice` patterns); do not edit.",
           f"pub static ZIA_MAP_{n}: [[XC2ZIAInput; {len(rows[0])}]; INPUTS_PER_ANDTERM] = ["]
    for r, entries in enumerate(rows):
        out.append(f"    // Row {r}")
        out.append("    [" + ",\n     ".join(entries) + "],")
    out.append("];")
    return "\n".join(out) + "\n"


def existing(zia_rs, n):
    m = re.search(rf"(?:/// merkur: [^\n]*\n/// [^\n]*\n)?pub static ZIA_MAP_{n}:.*?\n\];\n", zia_rs, re.S)
    if not m:
        fail(f"ZIA_MAP_{n} not found")
    return m


# merkur target -> (Project Combine device, package; its Cpld.package)
PACKAGES = {"XC2C32A": ("xc2c32a", "vq44"), "XC2C64A": ("xc2c64a", "vq100"),
            "XC2C128": ("xc2c128", "tq144"), "XC2C256": ("xc2c256", "ft256"),
            "XC2C384": ("xc2c384", "fg324"), "XC2C512": ("xc2c512", "fg324")}


def read_bonds(text):
    """Per (device, package): pin name of each (fb, mc) pad."""
    bonds, devices = {}, {}
    cur = None
    for line in text.splitlines():
        m = re.match(r"^bond (BOND\d+) \{", line)
        if m:
            cur = bonds.setdefault(m.group(1), {})
            continue
        m = re.match(r"^device (\w+) \{", line)
        if m:
            cur = None
            dev = devices.setdefault(m.group(1), {})
            continue
        if line.startswith("}"):
            cur = None
            continue
        m = re.match(r"^\tpin (\w+) = IOB_C0B(\d+)MC(\d+);", line)
        if m and cur is not None:
            cur[(int(m.group(2)), int(m.group(3)))] = m.group(1)
            continue
        m = re.match(r"^\tbond (\w+) = (BOND\d+);", line)
        if m and cur is None and devices:
            dev[m.group(1)] = m.group(2)
    return {(d, p): bonds[b] for d, pk in devices.items() for p, b in pk.items()}


def pins_rs(chips, bonds):
    out = ["//! The package pin of every CoolRunner-II pad: generated by",
           "//! scripts/gen-xc2-zia.py from Project Combine's database",
           "//! (github.com/prjunnamed/prjcombine, databases/coolrunner2.txt); do not",
           "//! edit. One table per device, for its largest package, in which every",
           "//! pad of the die is bonded: (function block, macrocell, pin), both",
           "//! counted from 0 as the fitter's `FBn_m` locations are.", ""]
    sizes = {"XC2C32A": 32, "XC2C64A": 64, "XC2C128": 128, "XC2C256": 256,
             "XC2C384": 384, "XC2C512": 512}
    for dev, (pc_dev, pkg) in PACKAGES.items():
        pads = sorted(chips[DIES[sizes[dev]][0]]["pads"])
        bond = bonds.get((pc_dev, pkg))
        if bond is None:
            fail(f"no bond {pc_dev} {pkg}")
        if sorted(bond) != pads:
            fail(f"{dev} {pkg} bonds {len(bond)} of the die's {len(pads)} pads")
        out.append(f"/// {dev} in the {pkg.upper()}: {len(pads)} pads.")
        out.append(f"pub const {dev}_{pkg.upper()}: &[(u8, u8, &str)] = &[")
        for fb, mc in pads:
            out.append(f'    ({fb}, {mc}, "{bond[(fb, mc)]}"),')
        out.append("];")
        out.append("")
    return "\n".join(out)


def write_file(path, text):
    tmp = path + ".tmp"
    with open(tmp, "w") as f:
        f.write(text)
    os.replace(tmp, path)


def main():
    if len(sys.argv) != 2:
        print(__doc__, file=sys.stderr)
        sys.exit(2)
    db_path = sys.argv[1]
    rs_path = "third_party/xc2bit/src/zia.rs"
    with open(db_path) as f:
        text = f.read()
    chips = read_chips(text)
    pins = pins_rs(chips, read_bonds(text))
    with open(rs_path) as f:
        zia_rs = f.read()
    for n in (32, 64):
        have = re.findall(r"XC2ZIAInput::\w+(?:\{[^}]*\})?", existing(zia_rs, n).group(0))
        want = [e for row in table(chips, zia_rs, n) for e in row]
        norm = [re.sub(r"\s+", " ", e) for e in have]
        if norm != want:
            diff = sum(1 for a, b in zip(norm, want) if a != b)
            fail(f"the XC2C{n} table from Project Combine differs from xc2bit's in {diff} entries")
        print(f"XC2C{n}: all {len(want)} choices agree with xc2bit's fuzzed table")
    for n in (128, 256, 384, 512):
        m = existing(zia_rs, n)
        rows = table(chips, zia_rs, n)
        zia_rs = zia_rs[: m.start()] + render(n, rows) + zia_rs[m.end():]
        print(f"XC2C{n}: {ROWS * len(rows[0])} choices written")
    write_file(rs_path, zia_rs)
    write_file("cli/src/synth/xc2_pins.rs", pins)
    print("cli/src/synth/xc2_pins.rs written")


if __name__ == "__main__":
    main()
