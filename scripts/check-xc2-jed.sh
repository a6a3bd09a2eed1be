#!/usr/bin/env bash
# Cross-checks the open CoolRunner-II flow's .jed against Project Combine.
#
# The test `the_fitted_jed_computes_the_design` (cli/src/synth/xc2_fit.rs)
# fits a small design on the XC2C64A, XC2C256 and XC2C512, and
# `a_crowded_xc2c256_is_placed_and_computes` a crowded one, and runs each
# .jed as xc2bit reads it back. That read-back uses the tables that wrote
# the file, so it cannot see a wrong fuse position or ZIA map. This script
# reads the same files with Project Combine's own disassembler
# (`coolrunner2_dis`, from its database, derived from Xilinx's tools) and
# compares every field that xc2bit decodes: each function block's 40 ZIA
# rows, product terms and OR terms, each macrocell's and pad's settings,
# the global clock enables (docs/synthesis.md, "The open fitter").
#
# Usage: scripts/check-xc2-jed.sh PRJCOMBINE_CHECKOUT
#   PRJCOMBINE_CHECKOUT  a checkout of github.com/prjunnamed/prjcombine
#                        (public/ and databases/coolrunner2.zstd are used)
# Needs Yosys 0.23 on PATH (scripts/install-tools.sh). Exit 0 when every
# field agrees, 1 when one differs, 2 on bad usage.
set -euo pipefail
cd "$(dirname "$0")/.."
if [ $# -ne 1 ] || [ ! -f "$1/databases/coolrunner2.zstd" ] || [ ! -d "$1/public" ]; then
    echo "usage: $0 PRJCOMBINE_CHECKOUT (with public/ and databases/coolrunner2.zstd)" >&2
    exit 2
fi
pc=$(cd "$1" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
(cd "$pc/public" && cargo build --quiet --release -p prjcombine-coolrunner2 --bin coolrunner2_dis)
MERKUR_KEEP_XC2_FIT="$work" cargo test --quiet --release -p merkur --bin merkur xc2_fit \
    >/dev/null
cargo build --quiet --release -p merkur --example xc2_jed_fields
status=0
for jed in "$work"/*/top.jed; do
    name=$(basename "$(dirname "$jed")")
    "$pc/public/target/release/coolrunner2_dis" "$pc/databases/coolrunner2.zstd" "$jed" >"$work/$name.pc"
    target/release/examples/xc2_jed_fields "$jed" >"$work/$name.xc2bit"
    python3 - "$work/$name.pc" "$work/$name.xc2bit" "$name" <<'EOF' || status=1
import re, sys

def read(path):
    out = {}
    for line in open(path):
        m = re.match(r'^(GLOBAL|FB \d+|MC \d+ \d+|PT \d+ \d+|ST \d+ \d+):(.*)$', line.rstrip('\n'))
        if not m:
            continue
        key, rest = m.group(1), m.group(2).split()
        out[key] = ' '.join(rest) if key[:2] in ('PT', 'ST') else dict(x.split('=', 1) for x in rest)
    return out

pc, xb = read(sys.argv[1]), read(sys.argv[2])
fields, bad = 0, []
for key, v in xb.items():
    if isinstance(v, str):
        fields += 1
        if pc.get(key) != v:
            bad.append(f'{key}: Project Combine {pc.get(key)!r}, xc2bit {v!r}')
    else:
        for f, val in v.items():
            fields += 1
            got = pc.get(key, {}).get(f)
            if got != val:
                bad.append(f'{key} {f}: Project Combine {got}, xc2bit {val}')
for key in pc:
    if key[:2] in ('PT', 'ST') and key not in xb:
        bad.append(f'{key}: only Project Combine has it')
for b in bad[:20]:
    print('  differs:', b)
print(f'{sys.argv[3]}: {fields} fields compared, {len(bad)} differ')
sys.exit(1 if bad else 0)
EOF
done
exit $status
