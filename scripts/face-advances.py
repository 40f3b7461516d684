#!/usr/bin/env python3
"""Print the advance table of crates/tmm-draw/src/face.rs: the advance
widths (font units) of osifont (the system's osifont.ttf) and, for the
characters it draws, tmm's GOST supplement. Needs fontTools.

    python3 scripts/face-advances.py [/usr/share/fonts/truetype/osifont/osifont.ttf]
"""
import sys
from fontTools.ttLib import TTFont

osi = TTFont(sys.argv[1] if len(sys.argv) > 1 else "/usr/share/fonts/truetype/osifont/osifont.ttf")
sup = TTFont("crates/tmm-note/fonts/tmm-gost-supplement.ttf")
SUPPLEMENT = "ЭэЁё−′″…→₀"
chars = [chr(c) for c in range(0x20, 0x7F)] + [chr(c) for c in range(0x391, 0x3CA)] + [chr(c) for c in range(0x400, 0x460)]
chars += list("ҐґϑϕϵΔ°±×·−′″…→₀₁₂₃₄₅₆₇₈₉²³√∑∫∆∂⊥∥←↑↓≈≤≥≠«»–—№")
rows = []
for ch in sorted(set(chars)):
    if ch in SUPPLEMENT and ord(ch) in sup.getBestCmap():
        rows.append((ord(ch), sup["hmtx"][sup.getBestCmap()[ord(ch)]][0]))
    elif ord(ch) in osi.getBestCmap():
        rows.append((ord(ch), osi["hmtx"][osi.getBestCmap()[ord(ch)]][0]))
for i in range(0, len(rows), 6):
    print("    " + " ".join(f"('\\u{{{c:04X}}}', {a})," for c, a in rows[i : i + 6]))

# The ink bounds (xMin, xMax, yMin, yMax) of the same characters, font
# units, for crates/tmm-draw/src/face.rs's BOUNDS (a blank glyph is all 0).
print()
bounds = []
for ch in sorted(set(chars)):
    font = sup if ch in SUPPLEMENT and ord(ch) in sup.getBestCmap() else osi
    cmap = font.getBestCmap()
    if ord(ch) not in cmap:
        continue
    g = font["glyf"][cmap[ord(ch)]]
    b = (g.xMin, g.xMax, g.yMin, g.yMax) if g.numberOfContours != 0 else (0, 0, 0, 0)
    bounds.append((ord(ch), b))
for i in range(0, len(bounds), 3):
    print("    " + " ".join(f"('\\u{{{c:04X}}}', {b[0]}, {b[1]}, {b[2]}, {b[3]})," for c, b in bounds[i : i + 3]))
