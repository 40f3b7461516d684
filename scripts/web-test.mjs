// The browser test of the page: drives headless Chromium over the DevTools
// protocol (Node's built-in WebSocket) against web/dist served on a
// loopback port. Usage:
//   node web-test.mjs <chromium> <page url> <tmm binary> <out dir> <dist dir>
// Writes <out dir>/results.json and one screenshot per view; exits 1 on the
// first failed check.
import { spawn, execFileSync } from "node:child_process";
import { writeFileSync, readFileSync, mkdtempSync, readdirSync } from "node:fs";
import { gzipSync } from "node:zlib";
import { join } from "node:path";
import { tmpdir } from "node:os";

const [chromiumBin, url, tmmBin, outDir, distDir] = process.argv.slice(2);
const results = { checks: [], figures: {}, screenshots: [] };
const check = (name, ok, detail = "") => {
  results.checks.push({ name, ok, detail });
  console.log(`${ok ? "ok  " : "FAIL"} ${name}${detail ? " — " + detail : ""}`);
  if (!ok) { finish(1); }
};
const sleep = (ms) => new Promise((r) => setTimeout(r, ms));

// ---------- Chromium and the protocol ----------
const profile = mkdtempSync(join(tmpdir(), "tmm-chromium-"));
const browser = spawn(chromiumBin, ["--headless=new", "--no-sandbox", "--disable-gpu", "--no-first-run",
  "--remote-debugging-port=0", `--user-data-dir=${profile}`, "--window-size=1500,1000", "about:blank"], { stdio: ["ignore", "ignore", "pipe"] });
function finish(code) {
  writeFileSync(join(outDir, "results.json"), JSON.stringify(results, null, 2));
  browser.kill();
  process.exit(code);
}
setTimeout(() => { console.log("FAIL timed out"); finish(1); }, 240000).unref();
process.on("uncaughtException", (e) => { console.log("FAIL", e.message); finish(1); });
process.on("unhandledRejection", (e) => { console.log("FAIL", e && e.message); finish(1); });
const wsUrl = await new Promise((resolve, reject) => {
  let buf = "";
  browser.stderr.on("data", (d) => { buf += d; const m = buf.match(/DevTools listening on (ws:\/\/\S+)/); if (m) resolve(m[1]); });
  browser.on("exit", (c) => reject(new Error("chromium exited " + c + "\n" + buf)));
});
const port = new URL(wsUrl).port;
const targets = await (await fetch(`http://127.0.0.1:${port}/json/list`)).json();
const pageTarget = targets.find((t) => t.type === "page");
const ws = new WebSocket(pageTarget.webSocketDebuggerUrl);
await new Promise((r) => ws.addEventListener("open", r));
let nextId = 1; const pending = new Map(); const events = [];
ws.addEventListener("message", (m) => {
  const msg = JSON.parse(m.data);
  if (msg.id && pending.has(msg.id)) { const { resolve, reject } = pending.get(msg.id); pending.delete(msg.id); msg.error ? reject(new Error(JSON.stringify(msg.error))) : resolve(msg.result); }
  else if (msg.method) events.push(msg);
});
const send = (method, params = {}) => new Promise((resolve, reject) => { const id = nextId++; pending.set(id, { resolve, reject }); ws.send(JSON.stringify({ id, method, params })); });
async function js(expr) {
  const r = await send("Runtime.evaluate", { expression: expr, awaitPromise: true, returnByValue: true });
  if (r.exceptionDetails) throw new Error(expr + ": " + JSON.stringify(r.exceptionDetails));
  return r.result.value;
}
async function until(expr, ms = 20000) {
  const t0 = Date.now();
  while (Date.now() - t0 < ms) { if (await js(expr)) return true; await sleep(50); }
  return false;
}

// ---------- load ----------
await send("Page.enable"); await send("Runtime.enable");
const tNav = Date.now();
await send("Page.navigate", { url });
check("page is ready (wasm loaded, default task analysed)", await until("document.body && document.body.dataset.ready === '1'"));
results.figures.ready_ms = Date.now() - tNav;
const paint = await js("JSON.stringify(performance.getEntriesByType('paint').map(e => [e.name, e.startTime]))");
results.figures.paint = Object.fromEntries(JSON.parse(paint));
results.figures.first_paint_ms = results.figures.paint["first-contentful-paint"] ?? results.figures.paint["first-paint"];
results.figures.ready_after_navigation_start_ms = await js("performance.now()");
check("first contentful paint under 2 s", results.figures.first_paint_ms < 2000, `${results.figures.first_paint_ms?.toFixed(0)} ms`);

// ---------- key numbers equal the CLI's ----------
const expected = JSON.parse(execFileSync(tmmBin, ["run", "--json"], { maxBuffer: 64 << 20 }).toString());
const shown = await js("[...document.querySelectorAll('[data-key]')].map(e => [e.dataset.key, +e.dataset.value])");
check("key numbers are shown", shown.length >= 8, `${shown.length} numbers`);
for (const [path, v] of shown) {
  const want = path.split(".").reduce((o, k) => o?.[k], expected);
  check(`${path} equals tmm run --json`, typeof want === "number" && Math.abs(v - want) <= 1e-12 * Math.max(1, Math.abs(want)), `page ${v}, cli ${want}`);
}

// ---------- editing a length updates the numbers ----------
const defaultText = await js("document.getElementById('editor').value");
const lines = defaultText.split("\n");
const lineNo = lines.findIndex((l) => /^length = "480 mm"/.test(l)) + 1;
check("the default task has the coupler length 480 mm", lineNo > 0, `line ${lineNo}`);
const setText = (t) => js(`(() => { const e = document.getElementById('editor'); e.value = ${JSON.stringify(t)}; e.dispatchEvent(new Event('input')); return true; })()`);
const kv0 = shown.find(([p]) => p === "linkage.kv")[1];
const edited = lines.map((l, i) => (i === lineNo - 1 ? 'length = "470 mm"' : l)).join("\n");
await setText(edited);
check("editing a length changes Kv", await until(`+document.querySelector('[data-key="linkage.kv"]').dataset.value !== ${kv0}`));
const editedDir = mkdtempSync(join(tmpdir(), "tmm-web-task-"));
writeFileSync(join(editedDir, "edited.toml"), edited);
const expEdited = JSON.parse(execFileSync(tmmBin, ["run", "--json", join(editedDir, "edited.toml")], { maxBuffer: 64 << 20 }).toString());
const kv1 = await js(`+document.querySelector('[data-key="linkage.kv"]').dataset.value`);
check("the edited Kv equals the CLI's for the edited file", Math.abs(kv1 - expEdited.linkage.kv) <= 1e-12, `page ${kv1}, cli ${expEdited.linkage.kv}`);
check("the edited task is kept in the URL", await until("location.hash.startsWith('#task=') && !location.hash.includes('undefined')"));
await sleep(500);
const editedUrl = await js("location.href");

// ---------- a bad value shows the CLI's error at its line ----------
const bad = lines.map((l, i) => (i === lineNo - 1 ? 'length = "-480 mm"' : l)).join("\n");
writeFileSync(join(editedDir, "task.toml"), bad);
await setText(bad);
check("a bad length shows an error", await until("!document.getElementById('error').hidden"));
const errLine = await js("+document.getElementById('error').dataset.line");
const errText = await js("document.getElementById('error').textContent");
const gutterErr = await js("document.querySelector('#gutter .err')?.dataset.line");
check("the error is at the edited line", errLine === lineNo && +gutterErr === lineNo, `error line ${errLine}, gutter ${gutterErr}, edited ${lineNo}`);
let cliErr = "";
try { execFileSync(tmmBin, ["run", "--out", join(editedDir, "out"), join(editedDir, "task.toml")], { stdio: "pipe" }); } catch (e) { cliErr = e.stderr.toString(); }
const firstLine = errText.split("\n")[0].replace(/^task\.toml/, "");
check("the page's message is the CLI's", cliErr.length > 0 && cliErr.includes(firstLine.slice(firstLine.indexOf(": ") + 2)), `page: ${errText.split("\n")[0]}`);

// ---------- performance of re-analysis ----------
await setText(defaultText);
await until("document.getElementById('error').hidden");
// 20 edits of the coupler's length (480 ↔ 470 mm): each reruns the
// sections that read [linkage] (synthesis, linkage, forces, dynamics)
const timed = await js(`window.tmmPage.timeAnalyse(20, ${JSON.stringify([edited, defaultText])})`);
results.figures.reanalysis_ms = timed.call;
results.figures.reanalysis_with_reply_ms = timed.with_reply;
console.log("re-analysis after an edit of the default task (median of 20):", timed.call.toFixed(1), "ms;", timed.with_reply.toFixed(1), "ms with the reply read");

// ---------- screenshots ----------
async function shot(view, name = view) {
  await js(`document.querySelector('#tabs [data-view="${view}"]').click(), true`);
  await sleep(300);
  const { data } = await send("Page.captureScreenshot", { format: "png" });
  const file = join(outDir, `web-${name}.png`);
  writeFileSync(file, Buffer.from(data, "base64"));
  const colours = await js(`new Promise(res => { const i = new Image(); i.onload = () => { const c = document.createElement('canvas'); c.width = i.width; c.height = i.height; const g = c.getContext('2d'); g.drawImage(i, 0, 0); const d = g.getImageData(0, 0, c.width, c.height).data; const s = new Set(); for (let k = 0; k < d.length; k += 4 * 7) s.add((d[k] << 16) | (d[k + 1] << 8) | d[k + 2]); res(s.size); }; i.src = 'data:image/png;base64,${data}'; })`);
  results.screenshots.push({ view: name, file, colours });
  check(`screenshot of ${name} is not blank`, colours >= 16, `${colours} colours, ${file}`);
}

// ---------- the crank slider changes the angle and the plan ----------
await js(`document.querySelector('#tabs [data-view="mechanism"]').click(), true`);
const before = await js("[document.getElementById('angle-out').dataset.phi, document.querySelector('#plans svg').outerHTML]");
await js("(() => { const a = document.getElementById('angle'); a.value = 90; a.dispatchEvent(new Event('input')); return true; })()");
const after = await js("[document.getElementById('angle-out').dataset.phi, document.querySelector('#plans svg').outerHTML]");
check("the slider changes the displayed angle", before[0] !== after[0], `${before[0]} → ${after[0]}`);
check("the slider changes the velocity plan", before[1] !== after[1]);
await shot("mechanism");
await shot("numbers");
await shot("diagrams");
check("the diagrams carry a cursor", (await js("document.querySelectorAll('#diagrams .cursor').length")) > 0);

// ---------- clicking the contour changes x1, x2 ----------
await js(`document.querySelector('#tabs [data-view="gear"]').click(), true`);
const g0 = await js(`[+document.querySelector('[data-gear="x1"]').dataset.value, +document.querySelector('[data-gear="x2"]').dataset.value]`);
const target = await js(`(() => { const cells = document.querySelectorAll('#contour g#allowed polygon, #contour g#allowed polyline, #contour g#allowed path'); const c = cells[Math.floor(cells.length * 0.3)]; c.scrollIntoView({block: 'center'}); const r = c.getBoundingClientRect(); return [r.x + r.width / 2, r.y + r.height / 2, cells.length]; })()`);
check("the contour has allowed cells", target[2] > 0, `${target[2]} cells`);
for (const type of ["mousePressed", "mouseReleased"]) await send("Input.dispatchMouseEvent", { type, x: target[0], y: target[1], button: "left", clickCount: 1 });
await sleep(300);
const g1 = await js(`[+document.querySelector('[data-gear="x1"]')?.dataset.value, +document.querySelector('[data-gear="x2"]')?.dataset.value, document.getElementById('gear-numbers').textContent]`);
check("clicking the contour changes x1 and x2", g1[0] !== g0[0] && g1[1] !== g0[1] && Number.isFinite(g1[0]), `(${g0[0]}, ${g0[1]}) → (${g1[0]}, ${g1[1]}) ${Number.isFinite(g1[0]) ? "" : g1[2]}`);
await js("window.scrollTo(0, 0), true");
await shot("gear");
await shot("planetary");
await shot("cam");
await shot("files");

// ---------- animation of the seed-003 six-bar with its plans ----------
await js(`(() => { const s = document.getElementById('task-select'); s.value = 'seed-003-sixbar.toml'; s.dispatchEvent(new Event('change')); return true; })()`);
check("seed-003 six-bar analysed", await until("document.getElementById('error').hidden && window.tmmPage.frames && window.tmmPage.frames.names.length >= 6"));
await js(`document.querySelector('#tabs [data-view="mechanism"]').click(), true`);
await js("(window.tmmPage.fpsFrames = 0, document.getElementById('play').click(), true)");
const t0 = Date.now();
await sleep(3000);
const nFrames = await js("window.tmmPage.fpsFrames");
results.figures.animation_fps = nFrames / ((Date.now() - t0) / 1000);
await shot("mechanism", "mechanism-seed-003-playing");
await js("(document.getElementById('play').click(), true)");
results.figures.at_angle_ms = await js("window.tmmPage.lastAngleMs");
console.log("animation of seed-003 with plans:", results.figures.animation_fps.toFixed(1), "frames/s");
await shot("mechanism", "mechanism-seed-003");

// ---------- a link reproduces the task ----------
await send("Page.navigate", { url: "about:blank" });
await sleep(200);
await send("Page.navigate", { url: editedUrl });
check("the page opened from the link is ready", await until("document.body && document.body.dataset.ready === '1'"));
const kvLink = await js(`+document.querySelector('[data-key="linkage.kv"]').dataset.value`);
check("the link reproduces the edited task", Math.abs(kvLink - expEdited.linkage.kv) <= 1e-12, `Kv ${kvLink}`);

// The first difference of two JSON values (numbers to 1e-12 relative), or null.
function jsonDiff(a, b, path = "") {
  if (typeof a === "number" && typeof b === "number") return Math.abs(a - b) <= 1e-12 * Math.max(1e-3, Math.abs(a), Math.abs(b)) ? null : `${path}: ${a} and ${b}`;
  if (Array.isArray(a) !== Array.isArray(b) || typeof a !== typeof b || (a === null) !== (b === null)) return `${path}: ${JSON.stringify(a)?.slice(0, 40)} and ${JSON.stringify(b)?.slice(0, 40)}`;
  if (a === null || typeof a !== "object") return a === b ? null : `${path}: ${a} and ${b}`;
  const ka = Object.keys(a), kb = Object.keys(b);
  if (ka.length !== kb.length || ka.some((k, i) => k !== kb[i])) return `${path}: keys ${ka.slice(0, 5)} and ${kb.slice(0, 5)}`;
  for (const k of ka) { const d = jsonDiff(a[k], b[k], `${path}.${k}`); if (d) return d; }
  return null;
}

// ---------- the files: the list, a download, save and load ----------
// (the page now holds the edited task, from the link)
// every download goes through an anchor's click: catch them instead
// (the list's own links are clicked by an event, which the catch lets through)
await js(`(window.__downloads = [], HTMLAnchorElement.prototype.click = function () { window.__downloads.push([this.download, this.href]); }, URL.revokeObjectURL = () => {}, true)`);
await js(`document.querySelector('#tabs [data-view="files"]').click(), true`);
await until("document.querySelectorAll('#file-list li').length > 1");
const listed = await js("[...document.querySelectorAll('#file-list li')].map((li) => li.textContent.replace(/ \\(.*$/, ''))");
const cliOut = join(editedDir, "out-files");
execFileSync(tmmBin, ["run", "--no-pdf", "--out", cliOut, join(editedDir, "edited.toml")], { stdio: "pipe" });
const walk = (d, pre = "") => readdirSync(d, { withFileTypes: true }).flatMap((e) => e.isDirectory() ? walk(join(d, e.name), pre + e.name + "/") : [pre + e.name]);
const cliFiles = walk(cliOut).filter((f) => f !== ".tmm-out").sort();
const pageFiles = listed.filter((f) => !f.startsWith("task.toml")).sort();
const missing = cliFiles.filter((f) => !pageFiles.includes(f));
check("the page offers every file tmm run writes", missing.length === 0 && pageFiles.length === cliFiles.length, `${pageFiles.length} files on the page, ${cliFiles.length} written by the CLI${missing.length ? "; missing " + missing.slice(0, 5).join(", ") : ""}`);
const fetchDownload = async (i) => js(`fetch(window.__downloads[${i}][1]).then((r) => r.text())`);
for (const want of ["report.json", "linkage/positions.svg", "gear/mesh.dxf"]) {
  const n0 = await js("window.__downloads.length");
  await js(`[...document.querySelectorAll('#file-list li')].find((li) => li.textContent.startsWith(${JSON.stringify(want + " ")})).querySelector('a').dispatchEvent(new MouseEvent('click', { bubbles: true, cancelable: true })), true`);
  await until(`window.__downloads.length > ${n0}`);
  const got = await fetchDownload(n0);
  const cli = readFileSync(join(cliOut, want), "utf8");
  if (want.endsWith(".json")) {
    // the page's floating point runs on WebAssembly's own libm: numbers
    // agree to 1e-12, not always to the last bit
    const diff = jsonDiff(JSON.parse(got), JSON.parse(cli));
    check(`the downloaded ${want} is the CLI's (numbers to 1e-12)`, diff === null, diff ?? `${got.length} bytes`);
  } else {
    // text with numbers printed to many places (the DXF's 12 decimals): every
    // word equal, every number to 1e-9 of its size
    const words = (t) => t.split(/[\s,"<>=]+/);
    const [wa, wb] = [words(got), words(cli)];
    let bad = wa.length === wb.length ? -1 : Math.min(wa.length, wb.length);
    for (let i = 0; bad < 0 && i < wa.length; i++) {
      const [x, y] = [Number(wa[i]), Number(wb[i])];
      const same = wa[i] === wb[i] || (wa[i] !== "" && Number.isFinite(x) && Number.isFinite(y) && Math.abs(x - y) <= 1e-9 * Math.max(1, Math.abs(x)));
      if (!same) bad = i;
    }
    check(`the downloaded ${want} is the CLI's (numbers to 1e-9)`, bad < 0, bad < 0 ? `${got.length} bytes, ${wa.length} words` : `word ${bad}: page ${wa[bad]}, cli ${wb[bad]}`);
  }
}
{
  const n0 = await js("window.__downloads.length");
  await js("(document.getElementById('save').click(), true)");
  await until(`window.__downloads.length > ${n0}`);
  const saved = await fetchDownload(n0);
  check("Save task downloads the editor's text", saved === (await js("document.getElementById('editor').value")), `${saved.length} bytes`);
}
{
  const example = new URL("../examples/seed-001-fourbar.toml", import.meta.url).pathname;
  const { root } = await send("DOM.getDocument");
  const { nodeId } = await send("DOM.querySelector", { nodeId: root.nodeId, selector: "#load" });
  await send("DOM.setFileInputFiles", { nodeId, files: [example] });
  const text = readFileSync(example, "utf8");
  check("Load puts the file into the editor", await until(`document.getElementById('editor').value === ${JSON.stringify(text)}`));
  const exp = JSON.parse(execFileSync(tmmBin, ["run", "--json", example], { maxBuffer: 64 << 20 }).toString());
  await js(`document.querySelector('#tabs [data-view="numbers"]').click(), true`);
  check("the loaded task is analysed", await until(`Math.abs(+document.querySelector('[data-key="linkage.kv"]').dataset.value - ${exp.linkage.kv}) <= 1e-12`), `Kv ${exp.linkage.kv}`);
}

// ---------- bundle size ----------
const wasm = readFileSync(join(distDir, "tmm_web_bg.wasm"));
const glue = ["tmm_web.js", "app.js", "index.html", "style.css"].map((f) => readFileSync(join(distDir, f)));
results.figures.wasm_bytes = wasm.length;
results.figures.wasm_gzip_bytes = gzipSync(wasm, { level: 9 }).length;
results.figures.bundle_gzip_bytes = results.figures.wasm_gzip_bytes + glue.reduce((s, b) => s + gzipSync(b, { level: 9 }).length, 0);
check("bundle under 3 MB compressed", results.figures.bundle_gzip_bytes < 3e6, `${(results.figures.bundle_gzip_bytes / 1e6).toFixed(2)} MB gzip (wasm ${(wasm.length / 1e6).toFixed(2)} MB raw)`);
console.log(JSON.stringify(results.figures, null, 2));
finish(0);
