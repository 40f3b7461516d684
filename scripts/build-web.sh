#!/usr/bin/env bash
# Build the browser page into web/dist/: tmm-web compiled to
# wasm32-unknown-unknown, bound with wasm-bindgen (the CLI pinned to the
# version in Cargo.lock), wasm-opt when present, the page's own files, and
# the drawings' GOST lettering font osifont with its licence (below).
# Serve it with any static server on the loopback address, e.g.
# `python3 -m http.server --bind 127.0.0.1 -d web/dist 8000`.
set -euo pipefail
cd "$(dirname "$0")/.."
target_dir="${CARGO_TARGET_DIR:-target}"

rustup target list --installed 2>/dev/null | grep -qx wasm32-unknown-unknown \
  || rustup target add wasm32-unknown-unknown

# the wasm-bindgen version the crate was locked with
version=$(awk '/^name = "wasm-bindgen"$/ { getline; gsub(/"/, "", $3); print $3; exit }' Cargo.lock)
[ -n "$version" ] || { echo "wasm-bindgen is not in Cargo.lock" >&2; exit 1; }
if ! command -v wasm-bindgen >/dev/null || [ "$(wasm-bindgen --version | awk '{print $2}')" != "$version" ]; then
  echo "installing wasm-bindgen-cli $version (once; about 5 minutes on 2 cores)" >&2
  # --locked uses the tool's own lock file; when the registry no longer
  # serves one of its pinned dependencies (webpki-roots 1.0.11 for 0.2.130)
  # cargo refuses it: resolve afresh then, the tool itself staying =version.
  # The first attempt's refusal is kept out of the terminal and shown only
  # if the second attempt fails too.
  log=$(mktemp)
  if ! cargo install --quiet --locked wasm-bindgen-cli --version "=$version" 2>"$log"; then
    echo "the tool's lock file pins a dependency the registry no longer serves; resolving its dependencies afresh" >&2
    cargo install --quiet wasm-bindgen-cli --version "=$version" || { cat "$log" >&2; rm -f "$log"; exit 1; }
  fi
  rm -f "$log"
fi

# the page's module and its PDF module (the typesetter, loaded only when
# the PDFs are asked for), in one cargo invocation
cargo build --release --locked --target wasm32-unknown-unknown -p tmm-web -p tmm-web-pdf
rm -rf web/dist && mkdir -p web/dist
for module in tmm_web tmm_web_pdf; do
  wasm-bindgen --target web --no-typescript --out-dir web/dist \
    "$target_dir/wasm32-unknown-unknown/release/$module.wasm"
  if command -v wasm-opt >/dev/null; then
    wasm-opt -Oz --enable-bulk-memory --enable-nontrapping-float-to-int \
      -o "web/dist/${module}_bg.wasm.opt" "web/dist/${module}_bg.wasm" \
      && mv "web/dist/${module}_bg.wasm.opt" "web/dist/${module}_bg.wasm"
  fi
done
cp web/index.html web/app.js web/pdf-worker.js web/style.css web/dist/

# The drawings' GOST lettering font osifont, beside the PDF module: the PDF
# worker fetches it on the first PDF request and gives its bytes to the
# typesetter. It is found as `tmm run` finds it (tmm_note::fonts): the file
# or folder named by TMM_FONT_PATH, else the system's font folders, four
# folders deep, the first `osifont*.ttf` by name. The unaltered file is
# served as a file of its own under its own licence (GPL with the font
# exception), never linked into a module, so its licence text goes with it:
# Debian's /usr/share/doc/fonts-osifont/copyright, else a LICENSE* or
# COPYING* file beside the font. Without the font or a licence text the page
# is built without it, and its PDFs use the fallback faces (the page says so).
find_osifont() {
  local dirs=()
  if [ -n "${TMM_FONT_PATH:-}" ]; then
    if [ -f "$TMM_FONT_PATH" ]; then echo "$TMM_FONT_PATH"; return; fi
    dirs+=("$TMM_FONT_PATH")
  fi
  [ -n "${HOME:-}" ] && dirs+=("$HOME/.local/share/fonts" "$HOME/.fonts" "$HOME/Library/Fonts")
  [ -n "${XDG_DATA_HOME:-}" ] && dirs+=("$XDG_DATA_HOME/fonts")
  dirs+=(/usr/local/share/fonts /usr/share/fonts /Library/Fonts)
  local d f
  for d in "${dirs[@]}"; do
    [ -d "$d" ] || continue
    f=$(find -L "$d" -maxdepth 5 -type f -iname 'osifont*.ttf' 2>/dev/null | LC_ALL=C sort | head -n 1)
    if [ -n "$f" ]; then echo "$f"; return; fi
  done
}
font=$(find_osifont || true)
if [ -z "$font" ]; then
  echo "osifont not found (TMM_FONT_PATH, the system's font folders): the page is built without it, and its PDFs' drawings use the fallback faces; install it (Debian/Ubuntu: apt install fonts-osifont) for the GOST lettering" >&2
else
  licence=""
  for l in /usr/share/doc/fonts-osifont/copyright "$(dirname "$font")"/LICENSE* "$(dirname "$font")"/COPYING*; do
    [ -f "$l" ] && { licence="$l"; break; }
  done
  if [ -z "$licence" ]; then
    echo "osifont found at $font, but no licence text beside it (nor Debian's /usr/share/doc/fonts-osifont/copyright): the page is built without it, and its PDFs' drawings use the fallback faces" >&2
  else
    cp "$font" web/dist/osifont.ttf
    cp "$licence" web/dist/osifont-LICENSE.txt
    # the whole GPL's text too, when Debian's copyright file only names it
    gpl=/usr/share/common-licenses/GPL-3
    if [ "$licence" = /usr/share/doc/fonts-osifont/copyright ] && [ -f "$gpl" ]; then
      printf '\n\n----- %s (the GNU General Public License, version 3, named above) -----\n\n' "$gpl" >>web/dist/osifont-LICENSE.txt
      cat "$gpl" >>web/dist/osifont-LICENSE.txt
    fi
    echo "osifont: $font, unaltered, with its licence $licence, as web/dist/osifont.ttf and web/dist/osifont-LICENSE.txt" >&2
  fi
fi
echo "web/dist: $(du -sh web/dist | cut -f1); serve with: python3 -m http.server --bind 127.0.0.1 -d web/dist 8000"
