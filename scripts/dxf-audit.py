#!/usr/bin/env python3
"""Audit DXF files with ezdxf: exit 0 only if loading needed no recovery
fix and ezdxf's Auditor reports no fix and no error.

    python3 scripts/dxf-audit.py FILE.dxf [FILE.dxf ...]

ezdxf is not part of the Rust build; install it in a throw-away venv:

    python3 -m venv /tmp/ezdxf-venv && /tmp/ezdxf-venv/bin/pip install ezdxf==1.4.5
    TMM_EZDXF_PYTHON=/tmp/ezdxf-venv/bin/python cargo test --release -p tmm-draw --test all

With --png DIR each file is also drawn to DIR/NAME.png (ezdxf's drawing
add-on, needs matplotlib in the same venv).
"""
import os
import sys

import ezdxf
from ezdxf import recover


def main(argv):
    png = None
    files = []
    it = iter(argv)
    for a in it:
        if a == "--png":
            png = next(it)
        else:
            files.append(a)
    bad = 0
    for path in files:
        doc, loading = recover.readfile(path)
        audit = doc.audit()
        fixes = list(loading.fixes) + list(audit.fixes)
        errors = list(loading.errors) + list(audit.errors)
        print(f"{path}: {len(fixes)} fixes, {len(errors)} errors (ezdxf {ezdxf.__version__})")
        for f in fixes + errors:
            print(f"  {f.code}: {f.message}")
        if fixes or errors:
            bad += 1
        if png:
            from ezdxf.addons.drawing import matplotlib as mpl

            os.makedirs(png, exist_ok=True)
            name = os.path.splitext(os.path.basename(path))[0]
            mpl.qsave(doc.modelspace(), os.path.join(png, name + ".png"), bg="#FFFFFF", dpi=150)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
