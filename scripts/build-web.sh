#!/usr/bin/env bash
# Build the browser page into web/dist/: tmm-web compiled to
# wasm32-unknown-unknown, bound with wasm-bindgen (the CLI pinned to the
# version in Cargo.lock), wasm-opt when present, and the page's own files.
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
echo "web/dist: $(du -sh web/dist | cut -f1); serve with: python3 -m http.server --bind 127.0.0.1 -d web/dist 8000"
