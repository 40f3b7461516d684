#!/usr/bin/env bash
# The browser test: build the page (scripts/build-web.sh) and the CLI, serve
# web/dist on a loopback port and drive headless Chromium (Debian's
# `chromium`, installed when missing) over the DevTools protocol with
# scripts/web-test.mjs. Screenshots and results.json go to $1 (default
# ${TMPDIR:-/tmp}/tmm-web-test).
set -euo pipefail
cd "$(dirname "$0")/.."
out="${1:-${TMPDIR:-/tmp}/tmm-web-test}"
mkdir -p "$out"
target_dir="${CARGO_TARGET_DIR:-target}"

chromium_bin=$(command -v chromium || command -v chromium-browser || true)
if [ -z "$chromium_bin" ]; then
  apt-get update && apt-get install -y --no-install-recommends chromium
  chromium_bin=$(command -v chromium)
fi
# pdfinfo and pdftotext read the PDFs the page typesets
command -v pdftotext >/dev/null || { apt-get update && apt-get install -y --no-install-recommends poppler-utils; }
command -v node >/dev/null || { apt-get update && apt-get install -y --no-install-recommends nodejs; }
node_flags=()
[ "$(node -p 'process.versions.node.split(".")[0]')" -ge 22 ] || node_flags=(--experimental-websocket)

scripts/build-web.sh
cargo build --release --locked -p tmm-cli

port=$(python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')
python3 -m http.server --bind 127.0.0.1 --directory web/dist "$port" >"$out/server.log" 2>&1 &
server=$!
trap 'kill $server 2>/dev/null || true' EXIT
for _ in $(seq 50); do curl -sf "http://127.0.0.1:$port/" >/dev/null && break; sleep 0.1; done

node "${node_flags[@]}" scripts/web-test.mjs "$chromium_bin" "http://127.0.0.1:$port/" \
  "$target_dir/release/tmm" "$out" web/dist
