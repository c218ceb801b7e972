#!/bin/sh
# Regenerates DejaVuSans-Bold-latin.ttf: DejaVu Sans Bold (Debian fonts-dejavu-core)
# subset to printable ASCII (U+0020-U+007E) plus U+00D7 MULTIPLICATION SIGN.
# Requires fontTools (pip install fonttools); run from this directory.
set -e
pyftsubset /usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf --unicodes=U+0020-007E,U+00D7 --output-file=DejaVuSans-Bold-latin.ttf --layout-features='*' --no-hinting
