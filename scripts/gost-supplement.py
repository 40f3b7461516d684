#!/usr/bin/env python3
"""Draw tmm's GOST type B supplement font, `tmm GOST supplement`.

The drawings' lettering is set in osifont (GOST 2.304 / ISO 3098 letter
shapes); Debian's osifont 0.1.20220224 draws Э э Ё ё as filled boxes and has
no − ′ ″ … →. This script draws those letters and signs anew from GOST
2.304's construction of type B — every stroke a centre line swept by a pen
of width d = h/10 with round ends, letters on the h/10 grid — at osifont's
metrics (2048 units per em, capital height h = 1510, x-height 1059, the same
advance widths), so they sit in a word set in osifont. No outline is taken
from osifont. The output is
`crates/tmm-note/fonts/tmm-gost-supplement.ttf` (MIT OR Apache-2.0, like
tmm), committed; run again only to change a letter:

    python3 -m venv /tmp/ft && /tmp/ft/bin/pip install fonttools==4.68.0
    /tmp/ft/bin/python scripts/gost-supplement.py

The output is deterministic (fixed timestamps).
"""

import math
import os
import sys

from fontTools.fontBuilder import FontBuilder
from fontTools.pens.ttGlyphPen import TTGlyphPen

UPEM = 2048
H = 1510  # capital height, osifont's
X = 1059  # x-height, osifont's
D = 151  # the stroke: GOST 2.304 type B, d = h/10
R = D / 2
STEPS = 12  # polygon sides per quarter circle (error under 1 unit)

FAMILY = "tmm GOST supplement"


def line(a, b):
    return [a, b]


def arc(c, rad, t0, t1):
    """Points on an arc about c from angle t0 to t1 (degrees)."""
    n = max(2, int(abs(t1 - t0) / 90 * STEPS) + 1)
    return [
        (c[0] + rad * math.cos(math.radians(t0 + (t1 - t0) * i / (n - 1))),
         c[1] + rad * math.sin(math.radians(t0 + (t1 - t0) * i / (n - 1))))
        for i in range(n)
    ]


def path(*pieces):
    """Pieces joined into one centre line (shared ends dropped)."""
    pts = []
    for p in pieces:
        for q in p:
            if not pts or math.dist(pts[-1], q) > 1e-6:
                pts.append(q)
    return pts


def stroke(pts, R=R):
    """The outline of a centre line swept by a round pen of width 2 R
    (D unless the line says otherwise)."""
    if isinstance(pts, tuple):
        pts, R = pts
    if len(pts) == 1 or all(math.dist(pts[0], q) < 1e-6 for q in pts):
        return arc(pts[0], R, 0, 360)[:-1]
    left, right = [], []
    n = len(pts)
    for i in range(n):
        # the normals of the segments before and after the point
        ns = []
        for a, b in ((i - 1, i), (i, i + 1)):
            if 0 <= a and b < n:
                dx, dy = pts[b][0] - pts[a][0], pts[b][1] - pts[a][1]
                ln = math.hypot(dx, dy)
                ns.append((-dy / ln, dx / ln))
        nx, ny = sum(v[0] for v in ns), sum(v[1] for v in ns)
        ln = math.hypot(nx, ny)
        nx, ny = nx / ln, ny / ln
        # miter: keep the offset R from both segments
        cos = nx * ns[0][0] + ny * ns[0][1]
        k = R / cos
        left.append((pts[i][0] + k * nx, pts[i][1] + k * ny))
        right.append((pts[i][0] - k * nx, pts[i][1] - k * ny))

    def cap(p, q, R=R):
        # half circle about p, from the left side round the end pointing away from q
        t = math.degrees(math.atan2(p[1] - q[1], p[0] - q[0]))
        return arc(p, R, t + 90, t - 90)

    out = left + cap(pts[-1], pts[-2])[1:-1] + right[::-1] + cap(pts[0], pts[1])[1:-1]
    return out


def dot(x, y):
    """A dot: a pen touch, as tall as 1.4 d (the type's period)."""
    return [(x, y - 0.2 * D), (x, y + 0.2 * D)]


def clockwise(poly):
    area = sum(poly[i][0] * poly[(i + 1) % len(poly)][1] - poly[(i + 1) % len(poly)][0] * poly[i][1]
               for i in range(len(poly)))
    return poly[::-1] if area > 0 else poly


# --- the letters: (advance, [centre lines]) -------------------------------

def e_reversed(x0, x1, top, rad):
    """Э and э: top and bottom strokes, the right side with rounded
    corners, the middle stroke from 0.3 of the width (GOST's Э)."""
    yt, yb, xl, xr = top - R, R, x0 + R, x1 - R
    ym = top / 2
    return [
        path(line((xl, yt), (xr - rad, yt)), arc((xr - rad, yt - rad), rad, 90, 0),
             line((xr, yt - rad), (xr, yb + rad)), arc((xr - rad, yb + rad), rad, 0, -90),
             line((xr - rad, yb), (xl, yb))),
        [(xl + 0.3 * (xr - xl), ym), (xr, ym)],
    ]


def cap_ie(x0, x1):
    """Е: the stem and three strokes, the middle one 0.9 of the top."""
    yt, yb, xl, xr = H - R, R, x0 + R, x1 - R
    return [
        [(xr, yt), (xl, yt), (xl, yb), (xr, yb)],
        [(xl, H / 2), (xl + 0.9 * (xr - xl), H / 2)],
    ]


def small_ie(x0, x1, rad):
    """е: the middle stroke, then round the bowl to the bottom right."""
    yt, yb, xl, xr = X - R, R, x0 + R, x1 - R
    ym = X / 2 + 0.02 * H
    return [
        path(line((xl, ym), (xr, ym)), line((xr, ym), (xr, yt - rad)),
             arc((xr - rad, yt - rad), rad, 0, 90), line((xr - rad, yt), (xl + rad, yt)),
             arc((xl + rad, yt - rad), rad, 90, 180), line((xl, yt - rad), (xl, yb + rad)),
             arc((xl + rad, yb + rad), rad, 180, 270), line((xl + rad, yb), (xr, yb))),
    ]


def diaeresis(cx, y, gap):
    return [dot(cx - gap / 2, y), dot(cx + gap / 2, y)]


def prime(x):
    # a short stroke leaning right, from the capital height down 0.3 h
    return [(x, H - 0.3 * H + R), (x + 0.08 * H, H - R)]


def sub_zero(x0, x1, y0, y1, pen):
    """₀: the figure 0 as osifont's superscripts are sized (0.47 h tall),
    lowered below the baseline; two half circles joined by straight
    sides, drawn with a pen of 0.7 d."""
    r = pen / 2
    xl, xr, yb, yt = x0 + r, x1 - r, y0 + r, y1 - r
    c = (xr - xl) / 2
    return (path(arc((xl + c, yt - c), c, 0, 180), line((xl, yt - c), (xl, yb + c)),
                 arc((xl + c, yb + c), c, 180, 360), line((xr, yb + c), (xr, yt - c))), r)


MID = H / 2 + 0.04 * H  # the signs' axis (osifont's + and − sit at 596)

GLYPHS = {
    # name: (code point, advance, centre lines)
    "uni042D": (0x042D, 920, e_reversed(84, 829, H, 0.17 * H)),
    "uni044D": (0x044D, 881, e_reversed(52, 808, X, 0.15 * H)),
    "uni0401": (0x0401, 1024, cap_ie(162, 915) + diaeresis((162 + 915) / 2, H + 0.18 * H, 0.27 * H)),
    "uni0451": (0x0451, 915, small_ie(80, 835, 0.15 * H) + diaeresis((80 + 835) / 2, X + 0.18 * H, 0.27 * H)),
    "uni2212": (0x2212, 952, [[(100 + R, 596), (852 - R, 596)]]),
    "uni2032": (0x2032, 420, [prime(120)]),
    "uni2033": (0x2033, 640, [prime(120), prime(340)]),
    "uni2026": (0x2026, 1240, [dot(131 + R + i * 413, 1.4 * R) for i in range(3)]),
    # an empty mark of no width that no other face has: the SVG writer puts
    # it after every run set in this font, so that a face substituted for
    # the rest of the text lacks one of its characters and replaces only
    # the characters it is asked for (usvg's font fallback)
    "u10FFFD": (0x10FFFD, 0, []),
    "uni2080": (0x2080, 593, [sub_zero(70, 523, -250, 465, 0.7 * D)]),
    "uni2192": (0x2192, 1240, [[(100 + R, 596), (1140 - R, 596)],
                               [(1140 - R - 0.25 * H, 596 + 0.2 * H), (1140 - R, 596),
                                (1140 - R - 0.25 * H, 596 - 0.2 * H)]]),
}


def draw(lines):
    pen = TTGlyphPen(None)
    for c in lines:
        poly = clockwise([(round(x), round(y)) for x, y in stroke(c)])
        clean = [poly[0]]
        for p in poly[1:]:
            if p != clean[-1]:
                clean.append(p)
        if clean[-1] == clean[0]:
            clean.pop()
        pen.moveTo(clean[0])
        for p in clean[1:]:
            pen.lineTo(p)
        pen.closePath()
    return pen.glyph()


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else os.path.join(
        os.path.dirname(os.path.abspath(__file__)), "..", "crates", "tmm-note", "fonts",
        "tmm-gost-supplement.ttf")
    order = [".notdef", "space"] + list(GLYPHS)
    fb = FontBuilder(UPEM, isTTF=True)
    fb.setupGlyphOrder(order)
    fb.setupCharacterMap({0x20: "space", **{v[0]: k for k, v in GLYPHS.items()}})
    notdef = TTGlyphPen(None)
    glyphs = {".notdef": notdef.glyph(), "space": TTGlyphPen(None).glyph()}
    metrics = {".notdef": (600, 0), "space": (600, 0)}
    for name, (_, adv, lines) in GLYPHS.items():
        g = draw(lines)
        glyphs[name] = g
    fb.setupGlyf(glyphs)
    glyf = fb.font["glyf"]
    for name, (_, adv, _) in GLYPHS.items():
        g = glyf[name]
        g.recalcBounds(glyf)
        metrics[name] = (adv, getattr(g, "xMin", 0))
    fb.setupHorizontalMetrics(metrics)
    fb.setupHorizontalHeader(ascent=2697, descent=-707)
    fb.setupNameTable({
        "familyName": FAMILY,
        "styleName": "Regular",
        "uniqueFontIdentifier": "tmm GOST supplement 1.0",
        "fullName": FAMILY,
        "psName": "tmmGOSTsupplement",
        "version": "Version 1.000",
        "copyright": "Copyright the tmm authors",
        "licenseDescription": "MIT OR Apache-2.0 (the licence of tmm)",
        "description": "GOST 2.304 type B letters drawn for tmm to go with osifont: "
                       "Э э Ё ё − ′ ″ … → ₀",
    })
    fb.setupOS2(sTypoAscender=1542, sTypoDescender=-693, sTypoLineGap=0,
                usWinAscent=2697, usWinDescent=709, sxHeight=X, sCapHeight=H,
                usWeightClass=400, fsType=0, achVendID="TMM ")
    fb.setupPost()
    fb.setupHead(unitsPerEm=UPEM, created=0, modified=0)
    fb.font["head"].created = 0
    fb.font["head"].modified = 0
    os.makedirs(os.path.dirname(os.path.abspath(out)), exist_ok=True)
    fb.font.recalcTimestamp = False
    fb.save(out)
    print(out, os.path.getsize(out), "bytes")


if __name__ == "__main__":
    main()
