#!/usr/bin/env python3
"""Which crates the web build's code comes from: sums the size of each function body in a
.wasm file that still has its name section (cargo's output, before wasm-bindgen strips it),
by the crate its symbol names first, and prints the largest.

Run: python3 .ci/web/crate-sizes.py "$CARGO_TARGET_DIR/wasm32-unknown-unknown/wasm-release/rubber_band_box.wasm"
"""
import re
import sys
from collections import Counter


def leb(data, i):
    result, shift = 0, 0
    while True:
        byte = data[i]
        i += 1
        result |= (byte & 0x7F) << shift
        shift += 7
        if byte < 0x80:
            return result, i


def sections(data):
    i = 8
    while i < len(data):
        kind = data[i]
        size, i = leb(data, i + 1)
        yield kind, data[i:i + size]
        i += size


def crate_of(name):
    # Legacy mangling: _ZN<len><ident>...; a trait impl starts with _$LT$crate..path.
    m = re.match(r"_ZN\d+(.*)", name)
    if m:
        ident = m.group(1)
        ident = ident.replace("_$LT$", "").replace("$LT$", "")
        return re.split(r"\.\.|\$|\d", ident, maxsplit=1)[0] or "?"
    m = re.match(r"[<&\s]*([A-Za-z_][A-Za-z0-9_]*)", name)
    return m.group(1) if m else "?"


def main(path):
    data = open(path, "rb").read()
    imported = 0
    bodies = []
    names = {}
    for kind, body in sections(data):
        if kind == 2:  # imports: functions are numbered after the imported ones
            count, i = leb(body, 0)
            for _ in range(count):
                for _ in range(2):
                    length, i = leb(body, i)
                    i += length
                desc = body[i]
                i += 1
                if desc == 0:
                    _, i = leb(body, i)
                    imported += 1
                elif desc == 1:
                    i += 1
                    flags, i = leb(body, i)
                    _, i = leb(body, i)
                    if flags & 1:
                        _, i = leb(body, i)
                elif desc == 2:
                    flags, i = leb(body, i)
                    _, i = leb(body, i)
                    if flags & 1:
                        _, i = leb(body, i)
                elif desc == 3:
                    i += 2
                else:
                    _, i = leb(body, i)
        elif kind == 10:
            count, i = leb(body, 0)
            for _ in range(count):
                size, i = leb(body, i)
                bodies.append(size)
                i += size
        elif kind == 0:
            length, i = leb(body, 0)
            if body[i:i + length] != b"name":
                continue
            i += length
            while i < len(body):
                sub = body[i]
                size, i = leb(body, i + 1)
                end = i + size
                if sub == 1:
                    count, j = leb(body, i)
                    for _ in range(count):
                        index, j = leb(body, j)
                        length, j = leb(body, j)
                        names[index] = body[j:j + length].decode("utf-8", "replace")
                        j += length
                i = end
    if not names:
        sys.exit(f"{path} has no name section")
    by_crate = Counter()
    for n, size in enumerate(bodies):
        by_crate[crate_of(names.get(imported + n, "?"))] += size
    total = sum(bodies)
    print(f"{len(data)} bytes in all, {total} bytes of code in {len(bodies)} functions")
    for crate, size in by_crate.most_common(int(sys.argv[2]) if len(sys.argv) > 2 else 40):
        print(f"{size:>10} {100 * size / total:5.1f}%  {crate}")


main(sys.argv[1])
