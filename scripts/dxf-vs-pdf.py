#!/usr/bin/env python3
"""Compare a sheet's DXF with its PDF by their renderings.

    python3 scripts/dxf-vs-pdf.py [--tol-mm 1.0] [--png DIR] SHEET.dxf SHEET.pdf [...]

Each DXF is drawn with ezdxf's drawing add-on (matplotlib) and each PDF
with poppler's `pdftoppm`, both at 60 dots per inch. The drawn part of
each picture (its ink: pixels with a channel under 200 of 255, so a
layer's light colour counts) is cut to its bounding
box, which is the sheet's frame in both; the two boxes must have the same
proportions within 0.5 % (the DXF is at the PDF's scale), and the DXF's box
is resampled onto the PDF's. Then, with a tolerance of `--tol-mm` (default
1 mm, about 2.4 pixels):

- coverage: the share of the DXF's ink that lies within the tolerance of
  the PDF's ink, and of the PDF's within the tolerance of the DXF's.

The lines, arcs, hatches and the frame coincide; text is drawn in the
fonts each renderer has (ezdxf falls back to its own face where the
DXF's style names a CAD font), so letters overlap in place but not stroke
for stroke. A file pair passes when both coverages are at least
`--min` (default 0.80). Prints one line per pair; exits 1 if any fails.
ezdxf, matplotlib and Pillow are not part of the Rust build: install them
in a throw-away venv (see scripts/dxf-audit.py). With --png DIR the two
renderings and their overlay (DXF red, PDF blue, both black) are saved.
"""
import os
import subprocess
import sys
import tempfile

import numpy as np
from PIL import Image

DPI = 60


def ink(img):
    # anything clearly not paper: a light colour of a layer counts as ink
    a = np.asarray(img.convert("RGB"), dtype=np.int16)
    return a.min(axis=2) < 200


def bbox(mask):
    ys, xs = np.nonzero(mask)
    return xs.min(), ys.min(), xs.max() + 1, ys.max() + 1


def dilate(mask, r):
    out = mask.copy()
    h, w = mask.shape
    for dy in range(-r, r + 1):
        for dx in range(-r, r + 1):
            if dx * dx + dy * dy > r * r:
                continue
            src = mask[max(0, -dy):h - max(0, dy), max(0, -dx):w - max(0, dx)]
            out[max(0, dy):h - max(0, -dy), max(0, dx):w - max(0, -dx)] |= src
    return out


def render_dxf(path, w_in, h_in, out_png):
    import ezdxf
    from ezdxf import recover
    from ezdxf.addons.drawing import matplotlib as mpl

    doc, _ = recover.readfile(path)
    mpl.qsave(doc.modelspace(), out_png, bg="#FFFFFF", dpi=DPI, size_inches=(w_in, h_in))


def render_pdf(path, out_prefix):
    subprocess.run(["pdftoppm", "-r", str(DPI), "-png", "-singlefile", path, out_prefix], check=True)
    return out_prefix + ".png"


def compare(dxf, pdf, tol_mm, min_cov, png_dir):
    with tempfile.TemporaryDirectory() as tmp:
        pdf_png = render_pdf(pdf, os.path.join(tmp, "pdf"))
        p_img = Image.open(pdf_png)
        w_in, h_in = p_img.width / DPI, p_img.height / DPI
        dxf_png = os.path.join(tmp, "dxf.png")
        render_dxf(dxf, w_in, h_in, dxf_png)
        d_img = Image.open(dxf_png)
        p, d = ink(p_img), ink(d_img)
        if not p.any() or not d.any():
            return False, "one rendering is blank"
        px0, py0, px1, py1 = bbox(p)
        dx0, dy0, dx1, dy1 = bbox(d)
        pw, ph, dw, dh = px1 - px0, py1 - py0, dx1 - dx0, dy1 - dy0
        aspect = (dw / dh) / (pw / ph) - 1
        crop = Image.fromarray(d[dy0:dy1, dx0:dx1].astype(np.uint8) * 255).resize((pw, ph), Image.BILINEAR)
        dd = np.asarray(crop) > 64
        pp = p[py0:py1, px0:px1]
        r = max(1, round(tol_mm / 25.4 * DPI * (pw / (pw if pw else 1))))
        cov_d = (dd & dilate(pp, r)).sum() / max(1, dd.sum())
        cov_p = (pp & dilate(dd, r)).sum() / max(1, pp.sum())
        if png_dir:
            os.makedirs(png_dir, exist_ok=True)
            name = os.path.splitext(os.path.basename(pdf))[0]
            rgb = np.full(pp.shape + (3,), 255, np.uint8)
            rgb[dd & ~pp] = (220, 0, 0)
            rgb[pp & ~dd] = (0, 0, 220)
            rgb[pp & dd] = (0, 0, 0)
            Image.fromarray(rgb).save(os.path.join(png_dir, name + "-overlay.png"))
            d_img.save(os.path.join(png_dir, name + "-dxf.png"))
            p_img.save(os.path.join(png_dir, name + "-pdf.png"))
        ok = abs(aspect) <= 0.005 and cov_d >= min_cov and cov_p >= min_cov
        return ok, (f"frame {pw}x{ph} px (PDF) vs {dw}x{dh} px (DXF), proportions differ {aspect * 100:+.2f} %; "
                    f"DXF ink within {tol_mm} mm of the PDF's {cov_d * 100:.1f} %, PDF ink within {tol_mm} mm of the DXF's {cov_p * 100:.1f} %")


def main(argv):
    tol, min_cov, png_dir, files = 1.0, 0.80, None, []
    it = iter(argv)
    for a in it:
        if a == "--tol-mm":
            tol = float(next(it))
        elif a == "--min":
            min_cov = float(next(it))
        elif a == "--png":
            png_dir = next(it)
        else:
            files.append(a)
    if not files or len(files) % 2:
        print(__doc__)
        return 2
    bad = 0
    for dxf, pdf in zip(files[::2], files[1::2]):
        ok, msg = compare(dxf, pdf, tol, min_cov, png_dir)
        print(f"{'ok  ' if ok else 'FAIL'} {os.path.basename(dxf)} vs {os.path.basename(pdf)}: {msg}")
        bad += not ok
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
