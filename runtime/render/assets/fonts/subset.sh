#!/bin/sh
# Regenerates the fonts PNG pictures are drawn with (src/png.rs); run from this directory.
# Requires fontTools (pip install fonttools) and the Debian packages fonts-dejavu-core and
# fonts-droid-fallback.
set -e
# DejaVu Sans Bold (Debian fonts-dejavu-core) subset to printable ASCII (U+0020-U+007E) plus
# U+00B7 MIDDLE DOT and U+00D7 MULTIPLICATION SIGN: every label and the table's text.
pyftsubset /usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf --unicodes=U+0020-007E,U+00B7,U+00D7 --output-file=DejaVuSans-Bold-latin.ttf --layout-features='*' --no-hinting
# Droid Sans Fallback (Debian fonts-droid-fallback, Apache-2.0) subset for Japanese player names:
# CJK punctuation, hiragana, katakana (U+3000-30FF, U+31F0-31FF), full- and halfwidth forms
# (U+FF00-FFEF) and the 6,355 kanji of JIS X 0208 levels 1 and 2 (decoded from EUC-JP rows
# 16-84), gzipped (about 570 KB; 1 MB as it is).
python3 -c '
import sys
out = []
for row in range(16, 85):
    for cell in range(1, 95):
        try:
            out.append(bytes([0xA0 + row, 0xA0 + cell]).decode("euc_jp"))
        except UnicodeDecodeError:
            pass
sys.stdout.write("".join(out))
' > jis-x-0208-kanji.txt
pyftsubset /usr/share/fonts/truetype/droid/DroidSansFallbackFull.ttf --text-file=jis-x-0208-kanji.txt --unicodes=U+3000-30FF,U+31F0-31FF,U+FF00-FFEF --output-file=DroidSansFallback-names.ttf --layout-features='' --no-hinting
rm jis-x-0208-kanji.txt
gzip -9 -n -f DroidSansFallback-names.ttf
