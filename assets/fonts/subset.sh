#!/usr/bin/env bash
# Regenerate the DejaVu subsets used by the game's UI.
#
# Sources: Debian package fonts-dejavu-core (/usr/share/fonts/truetype/dejavu/).
# Tool:    pyftsubset from fontTools (pip install fonttools brotli).
# Output:  DejaVuSans-subset.ttf and DejaVuSansMono-subset.ttf next to this script.
#
# The output is deterministic for a given DejaVu release and fontTools version
# (pyftsubset keeps the source's head.modified timestamp by default).
set -euo pipefail

SRC_DIR="${DEJAVU_DIR:-/usr/share/fonts/truetype/dejavu}"
OUT_DIR="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"

command -v pyftsubset >/dev/null || { echo "pyftsubset not found: pip install fonttools brotli" >&2; exit 1; }
for f in DejaVuSans.ttf DejaVuSansMono.ttf; do
  [[ -f "$SRC_DIR/$f" ]] || { echo "missing $SRC_DIR/$f: apt-get install fonts-dejavu-core" >&2; exit 1; }
done

# Character set:
#   U+0020-007E  printable ASCII
#   U+00A0-00FF  Latin-1 (incl. ² ³ ¹ × ·)
#   U+0391-03A9, U+03B1-03C9, U+03D1, U+03D5  Greek capitals, small letters, ϑ ϕ
#   U+2002-200A  en/em/thin/hair spaces
#   U+2010-2027, U+2030-203A  dashes, quotes, bullets, ellipsis, per mille, primes
#   U+2070-209F  superscripts and subscripts
#   U+2190-21FF  arrows
#   U+2200-22FF  mathematical operators (incl. − ≈ ≤ ≥ √ ∑ ∆)
#   U+25B4 U+25B8 U+25BE U+25C2  small triangles (fold markers)
#   U+25CB U+25CF  circles
#   U+2715 U+2716  crosses
UNICODES="U+0020-007E,U+00A0-00FF,U+00B2,U+00B3,U+00B9,U+00B7,U+00D7"
UNICODES+=",U+0391-03A9,U+03B1-03C9,U+03D1,U+03D5"
UNICODES+=",U+2002-200A,U+2010-2027,U+2030-203A,U+2070-209F"
UNICODES+=",U+2190-21FF,U+2200-22FF,U+2212,U+2248,U+2264,U+2265,U+221A,U+2211,U+2206"
UNICODES+=",U+25B4,U+25B8,U+25BE,U+25C2,U+25CB,U+25CF,U+2715,U+2716"

# --name-IDs='*' keeps the whole name table, including the copyright (ID 0)
# and licence description/URL (IDs 13/14) that the Bitstream Vera licence
# requires to travel with every copy.
subset() {
  pyftsubset "$SRC_DIR/$1" \
    --unicodes="$UNICODES" \
    --layout-features='kern,liga,tnum' \
    --no-hinting \
    --name-IDs='*' \
    --output-file="$OUT_DIR/$2"
}

subset DejaVuSans.ttf     DejaVuSans-subset.ttf
subset DejaVuSansMono.ttf DejaVuSansMono-subset.ttf

ls -l "$OUT_DIR"/DejaVuSans-subset.ttf "$OUT_DIR"/DejaVuSansMono-subset.ttf
