// The browser test of the page: drives headless Chromium over the DevTools
// protocol (Node's built-in WebSocket) against web/dist served on a
// loopback port. Usage:
//   node web-test.mjs <chromium> <page url> <tmm binary> <out dir> <dist dir>
// Writes <out dir>/results.json and one screenshot per view; exits 1 on the
// first failed check.
import { spawn, execFileSync } from "node:child_process";
import { writeFileSync, readFileSync, mkdtempSync, readdirSync, existsSync, renameSync, rmSync } from "node:fs";
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
setTimeout(() => { console.log("FAIL timed out"); finish(1); }, 900000).unref();
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

// ---------- English words on a Russian or Ukrainian screen ----------
// The rule of crates/tmm-web/src/messages.rs (has_prose), written again:
// text in backticks, quotes and square brackets is the user's or the task
// file's own; a token with a digit, '.', '_', '/', '=', '-' or a letter
// outside ASCII is a symbol, and so is a key before ' = ', an option
// '--x', a file pattern or path ('*.txt', 'docs/web.md'), a word of capitals or with a capital inside (RRR, kPa), and the
// units, functions and section names below; 'e.g.' is English.
const NOT_WORDS = new Set(["mm", "cm", "dm", "km", "in", "ft", "rad", "deg", "rpm", "min", "max", "kg", "kgf", "Pa", "kPa", "MPa", "bar", "inv", "cos", "sin", "tan", "atan", "mod", "exp", "ln", "lg", "sqrt", "title", "project", "synthesis", "linkage", "forces", "dynamics", "gear", "planetary", "cam", "cylinder"]);
const SHORT_WORDS = new Set(["a", "an", "as", "at", "be", "by", "do", "go", "if", "in", "is", "it", "no", "of", "on", "or", "so", "to", "up", "we"]);
function englishWords(text) {
  const plain = text.replace(/`[^`]*`|"[^"]*"|«[^»]*»|\[[^\]]*\]/g, "0");
  const toks = plain.split(/\s+/).filter(Boolean);
  const found = [];
  toks.forEach((raw, i) => {
    if (toks[i + 1]?.startsWith("=") || /^(--|\*|\.)/.test(raw.replace(/^[("«]+/, "")) || raw.includes("/")) return;
    const tok = raw.replace(/^[^\p{L}\p{N}]+|[^\p{L}\p{N}]+$/gu, "");
    if (tok === "e.g" || tok === "i.e") { found.push(tok); return; }
    if (!tok || /[0-9._\/=<>+*·-]/.test(tok) || /[^\x00-\x7f]/.test(tok)) return;
    for (const w of tok.split(/['’]/)) {
      if (!/^[A-Za-z]+$/.test(w) || NOT_WORDS.has(w)) continue;
      if (w.length <= 2 ? SHORT_WORDS.has(w) : /^.[a-z]+$/.test(w)) found.push(w);
    }
  });
  return found;
}
const hasProse = (text) => englishWords(text).length > 0;

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
// (the module's message is English, as the CLI's; the box shows it in the interface's language)
const firstLine = (await js("window.tmmPage.error.message")).replace(/^task\.toml/, "");
check("the page's message is the CLI's", cliErr.length > 0 && cliErr.includes(firstLine.slice(firstLine.indexOf(": ") + 2)), `page: ${firstLine}`);
check("the error box shows it in the task's language (Russian)", /[а-я]/.test(errText) && errText.startsWith("task.toml:") && !hasProse(errText), errText.split("\n")[0]);

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

// ---------- the pick on the contour, against the drawing's own axes ----------
// The axes are read from the drawing itself: its grey grid lines and the
// numbers written at them (x1 under the plot, x2 to its left); a click at
// ten (x1, x2) of a spread over the plot must pick that pair to within the
// rounding (0.001) and a pixel of the drawing.
const drawingAxes = `(() => {
  const svg = document.querySelector('#contour svg');
  const lines = [...svg.querySelectorAll('line[stroke="#bbbbbb"]')];
  const vx = lines.filter((l) => l.getAttribute('x1') === l.getAttribute('x2')).map((l) => +l.getAttribute('x1'));
  const hy = lines.filter((l) => l.getAttribute('y1') === l.getAttribute('y2')).map((l) => +l.getAttribute('y1'));
  const near = (a, v) => a.reduce((b, x) => (Math.abs(x - v) < Math.abs(b - v) ? x : b), Infinity);
  const labels = [...svg.querySelectorAll('text')].map((t) => [t.textContent.replace(',', '.').replace('\u2212', '-'), +t.getAttribute('x'), +t.getAttribute('y')]).filter(([t]) => /^-?[0-9]+([.][0-9]+)?$/.test(t));
  const bottom = Math.max(...hy), left = Math.min(...vx);
  const xs = labels.filter((l) => l[2] > bottom && l[1] >= left - 0.5).map((l) => [+l[0], near(vx, l[1])]);
  const ys = labels.filter((l) => l[1] < left - 0.5 && l[2] <= bottom + 2).map((l) => [+l[0], near(hy, l[2])]);
  const fit = (p) => { const n = p.length, mx = p.reduce((s, q) => s + q[0], 0) / n, my = p.reduce((s, q) => s + q[1], 0) / n; const b = p.reduce((s, q) => s + (q[0] - mx) * (q[1] - my), 0) / p.reduce((s, q) => s + (q[0] - mx) ** 2, 0); return [my - b * mx, b]; };
  return { x: fit(xs), y: fit(ys), nx: xs.length, ny: ys.length, x1: [Math.min(...xs.map((q) => q[0])), Math.max(...xs.map((q) => q[0]))], x2: [Math.min(...ys.map((q) => q[0])), Math.max(...ys.map((q) => q[0]))] };
})()`;
async function clickShift(x1, x2) {
  const ax = await js(drawingAxes);
  const [cx, cy, px] = await js(`(() => { const svg = document.querySelector('#contour svg'); svg.scrollIntoView({ block: 'center' }); const m = svg.getScreenCTM(); const p = new DOMPoint(${ax.x[0] + ax.x[1] * x1}, ${ax.y[0] + ax.y[1] * x2}).matrixTransform(m); return [p.x, p.y, 1 / m.a]; })()`);
  for (const type of ["mousePressed", "mouseReleased"]) await send("Input.dispatchMouseEvent", { type, x: cx, y: cy, button: "left", clickCount: 1 });
  await until(`document.getElementById('gear-numbers').dataset.pickX1 !== ''`);
  const got = await js(`[+document.getElementById('gear-numbers').dataset.pickX1, +document.getElementById('gear-numbers').dataset.pickX2]`);
  return { got, tol: 0.0006 + 1.5 * px / Math.abs(ax.x[1]), ax };
}
const selectTask = async (name) => {
  await js(`(() => { window.confirm = () => true; const s = document.getElementById('task-select'); s.value = ${JSON.stringify(name)}; s.dispatchEvent(new Event('change')); return true; })()`);
  return until(`document.getElementById('error').hidden && window.tmmPage.reply && window.tmmPage.name === ${JSON.stringify(name || "task.toml")}`);
};
const openView = (v) => js(`document.querySelector('#tabs [data-view="${v}"]').click(), true`);
await openView("gear");
{
  const { got, ax, tol } = await clickShift(0.2, 0.85);
  check("the drawing's own axes are read (ticks on x1 and x2)", ax.nx >= 4 && ax.ny >= 4, `${ax.nx} and ${ax.ny} ticks`);
  check("a click on the task's point (0.2, 0.85) picks (0.2, 0.85) within a pixel", Math.abs(got[0] - 0.2) <= tol && Math.abs(got[1] - 0.85) <= tol, `picked (${got[0]}, ${got[1]}), a pixel is ${(tol / 1.5).toFixed(4)}`);
  results.figures.contour_pixel = tol / 1.5;
  const verdicts = await js(`[...document.querySelectorAll('#gear-checks [data-check]')].map((r) => [r.dataset.check, r.dataset.pass])`);
  check("each check's verdict is listed for the picked pair", verdicts.length >= 5 && verdicts.every(([, p]) => p === "true"), JSON.stringify(verdicts));
  check("the region where every check passes is shaded apart", (await js(`document.querySelectorAll('#contour #passes rect').length`)) > 0);
}
for (const task of ["", "gear-seed001.toml", "gear-seed003.toml", "gear-internal.toml"]) {
  if (task) { check(`${task} analysed`, await selectTask(task)); await openView("gear"); }
  let worst = 0, detail = "";
  for (let k = 0; k < 10; k++) {
    const ax = await js(drawingAxes);
    const x1 = ax.x1[0] + (ax.x1[1] - ax.x1[0]) * (0.08 + 0.84 * ((k * 0.37) % 1));
    const x2 = ax.x2[0] + (ax.x2[1] - ax.x2[0]) * (0.08 + 0.84 * ((k * 0.61 + 0.2) % 1));
    const { got, tol } = await clickShift(x1, x2);
    const err = Math.max(Math.abs(got[0] - x1), Math.abs(got[1] - x2)) / tol;
    if (err > worst) { worst = err; detail = `clicked (${x1.toFixed(4)}, ${x2.toFixed(4)}), picked (${got[0]}, ${got[1]}), tolerance ${tol.toFixed(4)}`; }
  }
  check(`the pick equals the clicked point at ten points (${task || "default task"})`, worst <= 1, detail);
}
await selectTask("");
await openView("gear");
{
  const { got: pk } = await clickShift(0.3, 0.7);
  await js("(document.getElementById('gear-write').click(), true)");
  await openView("numbers");
  check("a picked pair written into the task changes the numbers", await until(`+document.querySelector('[data-key="gear.x1"]')?.dataset.value === ${pk[0]} && +document.querySelector('[data-key="gear.x2"]')?.dataset.value === ${pk[1]}`), `(${pk[0]}, ${pk[1]})`);
  check("the written task holds the picked x1, x2", await js(`document.getElementById('editor').value.includes('\\nx1 = ${pk[0]}\\nx2 = ${pk[1]}\\n')`));
  await js("(document.getElementById('undo').click(), true)");
  check("undo brings the task back", await until(`+document.querySelector('[data-key="gear.x1"]')?.dataset.value === 0.2`));
  await js("(document.getElementById('redo').click(), true)");
  check("redo writes the pick again", await until(`+document.querySelector('[data-key="gear.x1"]')?.dataset.value === ${pk[0]}`));
  await js("(document.getElementById('undo').click(), true)");
  await until(`+document.querySelector('[data-key="gear.x1"]')?.dataset.value === 0.2`);
  await openView("gear");
  await clickShift(0.2, 0.85);
}
await js("window.scrollTo(0, 0), true");
await shot("gear");
await shot("planetary");
await shot("cam");
await shot("files");

// ---------- animation of the seed-003 six-bar with its plans ----------
check("seed-003 six-bar analysed", (await selectTask("seed-003-sixbar.toml")) && (await js("window.tmmPage.frames.names.length >= 6")));
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

// ---------- no stale view: every example, every view ----------
// Each view shows the current task or says why it cannot: after each
// example, a view with its section shows that section's numbers, one
// without says so and shows nothing of the task before.
const viewState = (v) => js(`(() => { document.querySelector('#tabs [data-view="${v}"]').click(); const e = document.getElementById('view-${v}'); return [e.dataset.state, e.querySelector('.why').textContent]; })()`);
const exampleNames = await js(`[...document.getElementById('task-select').options].map((o) => o.value).filter(Boolean)`);
let staleBad = [];
for (const name of exampleNames) {
  if (!(await selectTask(name))) { staleBad.push(`${name}: not analysed`); continue; }
  const rep = await js("window.tmmPage.reply.report");
  const hasFrames = await js("!!window.tmmPage.frames");
  const m = await viewState("mechanism");
  if (hasFrames !== (m[0] === "shown")) staleBad.push(`${name}: mechanism ${m[0]}`);
  if (!hasFrames && (!m[1] || (await js("document.querySelectorAll('#plans svg, #force-plans svg').length && !document.getElementById('view-mechanism').querySelector('.body').hidden")))) staleBad.push(`${name}: mechanism says nothing`);
  if (hasFrames && !(await js(`window.tmmPage.frames.phi.includes(+document.getElementById('angle-out').dataset.phi) && document.querySelectorAll('#plans svg').length === 2`))) staleBad.push(`${name}: plans not of this task`);
  const g = await viewState("gear");
  if (!!rep.gear !== (g[0] === "shown")) staleBad.push(`${name}: gear ${g[0]}`);
  if (rep.gear && (await js(`+document.querySelector('[data-gear="x1"]').dataset.value`)) !== rep.gear.x1) staleBad.push(`${name}: gear x1 not this task's`);
  const pl = await viewState("planetary");
  if (!!rep.planetary !== (pl[0] === "shown")) staleBad.push(`${name}: planetary ${pl[0]}`);
  if (rep.planetary && (await js("document.querySelectorAll('#planetary-table tr').length")) !== rep.planetary.candidates.length + 1) staleBad.push(`${name}: planetary table not this task's`);
  const c = await viewState("cam");
  if (!!rep.cam !== (c[0] === "shown")) staleBad.push(`${name}: cam ${c[0]}`);
  const d = await viewState("diagrams");
  if (!!(rep.linkage || rep.dynamics || rep.forces) !== (d[0] === "shown")) staleBad.push(`${name}: diagrams ${d[0]}`);
  const n = await viewState("numbers");
  const keys = await js(`[...document.querySelectorAll('[data-key]')].map((e) => [e.dataset.key, +e.dataset.value])`);
  if (n[0] !== "shown" || keys.some(([k, v]) => k.split(".").reduce((o, x) => o?.[x], rep) !== v)) staleBad.push(`${name}: numbers not this task's`);
  if (name === "gear-internal.toml") { await shot("mechanism", "no-linkage-gear-internal"); }
  if (name === "double-rocker.toml") { await shot("mechanism", "no-full-turn-double-rocker"); }
}
check(`no stale view over the ${exampleNames.length} examples`, staleBad.length === 0, staleBad.slice(0, 4).join("; "));
{
  await selectTask("");
  await setText(bad);
  await until("!document.getElementById('error').hidden");
  const st = await js("[document.getElementById('status').textContent, document.getElementById('status').classList.contains('bad')]");
  check("an error is in the status, not 'analysed in'", st[1] && !/analysed|расчёт за/.test(st[0]), st[0]);
  const views = ["numbers", "mechanism", "diagrams", "drawings", "gear", "planetary", "cam", "files"];
  const states = [];
  for (const v of views) states.push([v, ...(await viewState(v))]);
  check("after an error every view says why it is empty", states.every(([, s, w]) => s === "empty" && w.includes("> 0") && w.includes("49") && !hasProse(w)), JSON.stringify(states.map(([v, s, w]) => v + ":" + s + ":" + englishWords(w).join(","))));
  await shot("numbers", "error-numbers");
  await setText(defaultText);
  await until("document.getElementById('error').hidden");
}

// ---------- cams: every follower animates ----------
{
  const oscFlat = `title = "Cam, oscillating flat follower"\n\n[cam]\nfollower = "oscillating-flat"\nstroke = "15 deg"\npivot = "120 mm"\nphases = "rise 120 sine; dwell 30; return 120 sine; dwell 90"\nomega = "150 rpm"\n`;
  const cams = [["cam-seed-001-roller.toml", false], ["cam-seed-001-flat.toml", false], ["cam-oscillating-roller.toml", true], [null, true]];
  for (const [name, osc] of cams) {
    if (name) await selectTask(name); else { await setText(oscFlat); await until("window.tmmPage.reply && window.tmmPage.reply.report.cam && window.tmmPage.reply.report.cam.follower === 'oscillating-flat'"); }
    await openView("cam");
    const pix = (i) => js(`(() => { const s = document.getElementById('cam-slider'); s.value = ${i}; s.dispatchEvent(new Event('input')); const c = document.getElementById('cam-canvas'); const d = c.getContext('2d').getImageData(0, 0, c.width, c.height).data; let n = 0, h = 0; for (let k = 0; k < d.length; k += 4) if (d[k + 3] > 0) { n++; h = (h * 31 + d[k] + 7 * d[k + 1] + k) % 1000000007; } return [n, h, document.getElementById('cam-angle').textContent]; })()`);
    const a = await pix(0), b = await pix(150);
    const label = name || "oscillating flat";
    check(`the cam animates (${label})`, a[0] > 1000 && b[0] > 1000 && a[1] !== b[1], `${a[0]} and ${b[0]} drawn pixels`);
    check(`the follower's position reads in ${osc ? "degrees" : "mm"} (${label})`, osc ? /ψ = [-0-9.]+°/.test(b[2]) && !/mm|мм/.test(b[2]) : /s = [-0-9.]+ (mm|мм)/.test(b[2]), b[2]);
    await shot("cam", `cam-${(name || "oscillating-flat.toml").replace(/\.toml$/, "")}`);
  }
  await selectTask("");
}

// ---------- the interface in Russian, Ukrainian and English ----------
{
  // the default task is Russian ([project] lang = "ru")
  const uiTexts = `[...document.querySelectorAll('header, #tabs, .view.active')].map((e) => e.innerText).join('\\n')`;
  await openView("numbers");
  const ru = await js(uiTexts);
  check("the interface follows the task's language (Russian)", /Механизм/.test(ru) && /Результаты/.test(ru) && /коэффициент изменения средней скорости/.test(ru), ru.slice(0, 80));
  check("numbers on the Russian screen have a decimal comma and no exponent", /\d,\d/.test(ru) && !/\d\.\d/.test(ru.replace(/^.*\.(svg|toml|txt|json|dxf).*$/gm, "")) && !/\de[-+]?\d/.test(ru), ru.match(/[^\n]*\d[.,]\d[^\n]*/)?.[0]);
  const en = JSON.parse(await js("JSON.stringify(Object.values(JSON.parse(window.tmmWords('en')).words))"));
  const mixed = en.filter((w) => /[a-z]{4,}/.test(w) && w !== "English" && ru.includes(w));
  check("the Russian screen has no English words of the page", mixed.length === 0, mixed.slice(0, 3).join(" | "));
  check("lengths read in mm and angles in degrees", /мм/.test(ru) && /°/.test(ru));
  await shot("numbers", "numbers-ru");
  await shot("gear", "gear-ru");
  await js(`(() => { const s = document.getElementById('lang'); s.value = 'uk'; s.dispatchEvent(new Event('change')); return true; })()`);
  check("the switch turns the interface Ukrainian and is kept in the address", await until(`/Механізм/.test(document.getElementById('tabs').innerText) && location.hash.includes('lang=uk')`));
  await shot("numbers", "numbers-uk");
  await js(`(() => { const s = document.getElementById('lang'); s.value = 'en'; s.dispatchEvent(new Event('change')); return true; })()`);
  check("the switch turns the interface English", await until(`/Mechanism/.test(document.getElementById('tabs').innerText) && location.hash.includes('lang=en')`));
  const enText = await js(uiTexts);
  const ruWords = JSON.parse(await js("JSON.stringify(Object.values(JSON.parse(window.tmmWords('ru')).words))"));
  // (the language switch names each language in itself: Русский, Українська)
  const cyr = ruWords.filter((w) => w.length > 3 && /[а-я]/i.test(w) && w !== "Русский" && enText.includes(w));
  check("the English screen has no Cyrillic of the page's words", cyr.length === 0, cyr.slice(0, 3).join(" | "));
  await js(`(() => { const s = document.getElementById('lang'); s.value = ''; s.dispatchEvent(new Event('change')); return true; })()`);
  await until(`/Механизм/.test(document.getElementById('tabs').innerText)`);
}

// ---------- the solver's messages in Russian and Ukrainian ----------
// On each screen: bad TOML, a bad value, a mechanism that cannot be
// assembled, a crank that cannot turn fully, a gear pair picked where it
// is undercut and a bad pick outside the contour: no English word in the
// status, the message, the views' reasons, the gear's numbers and checks
// and the summaries.
{
  const root = join(distDir, "..", "..");
  const fourbar = readFileSync(join(root, "examples", "seed-001-fourbar.toml"), "utf8").split("\n");
  const at = fourbar.findIndex((l) => l.startsWith('length = "480 mm"'));
  const tooShort = fourbar.map((l, i) => (i === at ? 'length = "40 mm"' : l)).join("\n");
  const screen = `[document.getElementById('status').textContent, document.getElementById('error').hidden ? '' : document.getElementById('error').innerText, ...[...document.querySelectorAll('.view.active .why')].map((e) => e.textContent), document.getElementById('drag-why').hidden ? '' : document.getElementById('drag-why').textContent, document.getElementById('gear-numbers').innerText, document.getElementById('gear-checks').innerText, document.getElementById('texts').innerText].join('\\n')`;
  const cases = [
    ["toml", defaultText.replace("[gear]", "[gear"), "numbers"],
    ["value", defaultText.replace(/^length = "480 mm"/m, 'length = "abc"'), "numbers"],
    ["negative", bad, "numbers"],
    ["assembly", tooShort, "mechanism"],
  ];
  for (const lang of ["ru", "uk"]) {
    await js(`(() => { const s = document.getElementById('lang'); s.value = '${lang}'; s.dispatchEvent(new Event('change')); return true; })()`);
    await until(`document.documentElement.lang === '${lang}'`);
    for (const [kind, text, view] of cases) {
      const prev = await js("window.tmmPage.error ? window.tmmPage.error.message : ''");
      await setText(text);
      await until(`!document.getElementById('error').hidden && window.tmmPage.error && window.tmmPage.error.message !== ${JSON.stringify(prev)}`);
      await openView(view);
      const t = await js(screen);
      const untranslated = await js("!!document.querySelector('#error details')");
      const e = englishWords(t);
      check(`${lang}: the message of ${kind} is in the interface's language`, !untranslated && e.length === 0 && /[а-яіїє]/i.test(t), `${t.split("\n").find((l) => l.includes(":")) ?? ""} ${e.join(",")}`.slice(0, 300));
      await shot(view, `message-${lang}-${kind}`);
    }
    // a crank that cannot turn fully
    await setText(defaultText); await until("document.getElementById('error').hidden");
    await selectTask("double-rocker.toml");
    await openView("mechanism");
    const dr = await js(screen);
    check(`${lang}: a crank that cannot turn fully is said in the interface's language`, /[а-яіїє]/i.test(dr) && !hasProse(dr), englishWords(dr).join(","));
    await shot("mechanism", `message-${lang}-no-full-turn`);
    // the gear: a pick in the undercut corner, and the summaries
    await selectTask("");
    await openView("gear");
    const A = await js("window.tmmPage.contour");
    await clickShift(A.x1[0] + 0.02 * (A.x1[1] - A.x1[0]), A.x2[0] + 0.02 * (A.x2[1] - A.x2[0]));
    const g = await js(screen);
    const fails = await js("document.querySelectorAll('#gear-checks [data-pass=\"false\"], #gear-numbers .bad').length");
    check(`${lang}: a gear pair picked in the undercut corner fails its checks in the interface's language`, fails > 0 && !hasProse(g), `${fails} failed; ${englishWords(g).join(",")}`);
    await shot("gear", `message-${lang}-gear-undercut`);
    await openView("numbers");
    const sum = await js(screen);
    check(`${lang}: the numbers and the summaries have no English`, !hasProse(sum), englishWords(sum).join(","));
  }
  await js(`(() => { const s = document.getElementById('lang'); s.value = ''; s.dispatchEvent(new Event('change')); return true; })()`);
  await setText(defaultText);
  await until("document.getElementById('error').hidden && /Механизм/.test(document.getElementById('tabs').innerText)");
  await sleep(800); // the editor's history records the typed text 600 ms after the last keystroke
}

// ---------- the mechanism edited by dragging ----------
{
  await openView("mechanism");
  await js("(document.getElementById('edit-drag').checked = true, true)");
  const kvBefore = (await js("window.tmmPage.reply.report.linkage.kv"));
  const textBefore = await js("document.getElementById('editor').value");
  // the joint C: dragged 25 px right, the lengths BC and DC follow
  const at = (name) => js(`(() => { const F = window.tmmPage.frames, j = F.names.indexOf(${JSON.stringify(name)}), c = document.getElementById('mech'); c.scrollIntoView({ block: 'center' }); const [u, v] = window.tmmPage.T.to(F.xy[window.tmmPage.frame][j]); const r = c.getBoundingClientRect(), k = c.width / r.width; return [r.left + u / k, r.top + v / k]; })()`);
  const [cx, cy] = await at("C");
  await send("Input.dispatchMouseEvent", { type: "mousePressed", x: cx, y: cy, button: "left", clickCount: 1 });
  for (let k = 1; k <= 5; k++) await send("Input.dispatchMouseEvent", { type: "mouseMoved", x: cx + 5 * k, y: cy, button: "left", buttons: 1 });
  await send("Input.dispatchMouseEvent", { type: "mouseReleased", x: cx + 25, y: cy, button: "left", clickCount: 1 });
  await sleep(200);
  const textAfter = await js("document.getElementById('editor').value");
  const lens = (t) => [...t.matchAll(/^length = "([0-9.]+) mm"/gm)].map((m) => +m[1]);
  const [l0, l1] = [lens(textBefore), lens(textAfter)];
  check("dragging the joint C changes the links' lengths in the task, in whole mm", l1.length === l0.length && l1.some((v, i) => v !== l0[i]) && l1.every(Number.isInteger), `${l0} → ${l1}`);
  const kvAfter = await js("window.tmmPage.reply.report.linkage.kv");
  writeFileSync(join(editedDir, "dragged.toml"), textAfter);
  const expDrag = JSON.parse(execFileSync(tmmBin, ["run", "--json", join(editedDir, "dragged.toml")], { maxBuffer: 64 << 20 }).toString());
  check("the numbers follow the drag (Kv equals the CLI's for the dragged task)", kvAfter !== kvBefore && Math.abs(kvAfter - expDrag.linkage.kv) <= 1e-12, `Kv ${kvBefore} → ${kvAfter}, cli ${expDrag.linkage.kv}`);
  check("the assembly branch is kept", /assembly = \["C below AD"\]/.test(textAfter));
  await shot("mechanism", "mechanism-dragged");
  // an impossible drag: the coupler far too short to reach
  const [dx, dy] = await at("D");
  await send("Input.dispatchMouseEvent", { type: "mousePressed", x: dx, y: dy, button: "left", clickCount: 1 });
  await send("Input.dispatchMouseEvent", { type: "mouseMoved", x: dx + 400, y: dy, button: "left", buttons: 1 });
  const whyText = await js("document.getElementById('drag-why').hidden ? '' : document.getElementById('drag-why').textContent");
  await shot("mechanism", "mechanism-cannot-assemble");
  await send("Input.dispatchMouseEvent", { type: "mouseReleased", x: dx + 400, y: dy, button: "left", clickCount: 1 });
  check("an impossible drag says why it cannot assemble, in the interface's language", whyText.length > 10 && /[а-я]/.test(whyText) && !hasProse(whyText), whyText.slice(0, 160) + " " + englishWords(whyText).join(","));
  await js("(document.getElementById('undo').click(), true)");
  await js("(document.getElementById('undo').click(), true)");
  check("undo takes the drags back", await until(`document.getElementById('editor').value === ${JSON.stringify(textBefore)}`));
  await js("(document.getElementById('edit-drag').checked = false, true)");
}

// ---------- every drawing in a view that zooms and pans; a ZIP of all files ----------
{
  await openView("drawings");
  const names = await js("[...document.querySelectorAll('#all-drawings .drawing h3')].map((h) => h.textContent)");
  const want = ["linkage/positions.svg", "synthesis/", "forces/strength-M.svg", "sheets/sheet-1.svg"];
  check("the drawings view holds the construction, the 12 positions, N/Q/M and the sheets", want.every((w) => names.some((n) => n.startsWith(w))), `${names.length} drawings`);
  await js(`[...document.querySelectorAll('#all-drawings .drawing')].find((d) => d.querySelector('h3').textContent === 'linkage/positions.svg').querySelector('svg').dispatchEvent(new MouseEvent('click', { bubbles: true })), true`);
  const vb0 = await js("document.querySelector('#viewer-stage svg').getAttribute('viewBox')");
  await send("Input.dispatchKeyEvent", { type: "keyDown", key: "+", text: "+" });
  await send("Input.dispatchKeyEvent", { type: "keyDown", key: "ArrowRight", code: "ArrowRight", windowsVirtualKeyCode: 39 });
  const vb1 = await js("document.querySelector('#viewer-stage svg').getAttribute('viewBox')");
  check("a drawing opens in a viewer that zooms and pans", !(await js("document.getElementById('viewer').hidden")) && vb0 !== vb1, `${vb0} → ${vb1}`);
  await shot("drawings", "viewer");
  await send("Input.dispatchKeyEvent", { type: "keyDown", key: "Escape", code: "Escape", windowsVirtualKeyCode: 27 });
  check("Esc closes the viewer", await until("document.getElementById('viewer').hidden"));
  await shot("drawings");
}

// ---------- keyboard and contrast ----------
{
  await js("(document.activeElement?.blur(), window.scrollTo(0, 0), true)");
  const seen = [];
  for (let k = 0; k < 14; k++) {
    await send("Input.dispatchKeyEvent", { type: "keyDown", key: "Tab", code: "Tab", windowsVirtualKeyCode: 9 });
    await send("Input.dispatchKeyEvent", { type: "keyUp", key: "Tab", code: "Tab", windowsVirtualKeyCode: 9 });
    seen.push(await js("document.activeElement.id || document.activeElement.dataset.view || document.activeElement.tagName"));
  }
  check("Tab reaches the task, the language, Load…, Save, the editor and the tabs", ["task-select", "lang", "load-btn", "save", "editor"].every((id) => seen.includes(id)) && seen.some((v) => ["numbers", "mechanism", "diagrams", "drawings", "gear", "planetary", "cam", "files"].includes(v)), seen.join(" "));
  await js(`(document.getElementById('load-btn').focus(), window.__opened = 0, document.getElementById('load').click = () => { window.__opened++; }, true)`);
  await send("Input.dispatchKeyEvent", { type: "keyDown", key: "Enter", code: "Enter", windowsVirtualKeyCode: 13, text: "\r", unmodifiedText: "\r" });
  await send("Input.dispatchKeyEvent", { type: "keyUp", key: "Enter", code: "Enter", windowsVirtualKeyCode: 13 });
  await sleep(100);
  check("Enter on Load… opens the file chooser", (await js("window.__opened")) === 1);
  await js("(delete document.getElementById('load').click, true)");
  const tabKeys = await js(`(() => { const t = document.querySelector('#tabs [data-view="numbers"]'); t.focus(); t.dispatchEvent(new KeyboardEvent('keydown', { key: 'ArrowRight', bubbles: true })); return document.activeElement.dataset.view; })()`);
  check("the arrow keys move between the tabs", tabKeys === "mechanism", tabKeys);
  const contrast = `(() => { const rgb = (s) => s.match(/[0-9.]+/g).slice(0, 3).map(Number); const lum = ([r, g, b]) => { const f = (c) => { c /= 255; return c <= 0.03928 ? c / 12.92 : ((c + 0.055) / 1.055) ** 2.4; }; return 0.2126 * f(r) + 0.7152 * f(g) + 0.0722 * f(b); }; const st = getComputedStyle(document.getElementById('status')); const a = lum(rgb(st.color)), b = lum(rgb(st.backgroundColor)); return (Math.max(a, b) + 0.05) / (Math.min(a, b) + 0.05); })()`;
  const c1 = await js(contrast);
  await setText(bad); await until("!document.getElementById('error').hidden");
  const c2 = await js(contrast);
  await setText(defaultText); await until("document.getElementById('error').hidden");
  check("the status text has a contrast of at least 4.5:1 (normal and error)", c1 >= 4.5 && c2 >= 4.5, `${c1.toFixed(1)}:1, ${c2.toFixed(1)}:1`);
  results.figures.status_contrast = [c1, c2];
}

// ---------- phone and touch (390 × 844) ----------
{
  await send("Emulation.setDeviceMetricsOverride", { width: 390, height: 844, deviceScaleFactor: 2, mobile: true });
  await send("Emulation.setTouchEmulationEnabled", { enabled: true, maxTouchPoints: 1 });
  await sleep(300);
  await openView("mechanism");
  await js("(window.tmmPage.dirty.add('mechanism'), document.querySelector('#tabs [data-view=\"numbers\"]').click(), document.querySelector('#tabs [data-view=\"mechanism\"]').click(), true)");
  await sleep(200);
  const m = await js(`(() => { const r = document.getElementById('mech').getBoundingClientRect(); return { w: r.width, h: r.height, page: document.documentElement.scrollWidth, inner: window.innerWidth }; })()`);
  check("the phone layout clips nothing sideways", m.page <= m.inner, `page ${m.page} px in a ${m.inner} px window`);
  check("the mechanism drawing is usable on the phone", m.w >= 340 && m.h >= 250, `${m.w.toFixed(0)} × ${m.h.toFixed(0)} px`);
  results.figures.phone_mechanism_px = [m.w, m.h];
  const pin = await js(`(() => { const F = window.tmmPage.frames, c = document.getElementById('mech'); c.scrollIntoView({ block: 'center' }); const [u, v] = window.tmmPage.T.to(F.xy[window.tmmPage.frame][F.pin]); const r = c.getBoundingClientRect(), k = c.width / r.width; return [r.left + u / k, r.top + v / k, window.tmmPage.frame]; })()`);
  // a finger 10 px off the pin's centre still takes it (a target 24 px across)
  const touch = (type, x, y) => send("Input.dispatchTouchEvent", { type, touchPoints: type === "touchEnd" ? [] : [{ x, y, radiusX: 8, radiusY: 8 }] });
  await touch("touchStart", pin[0] + 10, pin[1]);
  for (let k = 1; k <= 6; k++) await touch("touchMove", pin[0] + 10 - 8 * k, pin[1] - 8 * k);
  await touch("touchEnd");
  await sleep(200);
  const frameAfter = await js("window.tmmPage.frame");
  check("a finger turns the crank", frameAfter !== pin[2], `frame ${pin[2]} → ${frameAfter}`);
  await shot("mechanism", "phone-mechanism");
  await js("window.scrollTo(0, 0), true");
  await shot("numbers", "phone-numbers");
  await shot("gear", "phone-gear");
  await send("Emulation.clearDeviceMetricsOverride");
  await send("Emulation.setTouchEmulationEnabled", { enabled: false });
  await js("window.scrollTo(0, 0), true");
}

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

// ---------- a ZIP of every file, with its folders ----------
{
  await js(`document.querySelector('#tabs [data-view="files"]').click(), true`);
  const nFiles = await js("document.querySelectorAll('#file-list li').length");
  const n0 = await js("window.__downloads.length");
  await js("(document.getElementById('zip').click(), true)");
  await until(`window.__downloads.length > ${n0}`);
  const z = await js(`fetch(window.__downloads[${n0}][1]).then((r) => r.arrayBuffer()).then((b) => { const d = new DataView(b); const e = b.byteLength - 22; const n = d.getUint16(e + 10, true); let o = d.getUint32(e + 16, true); const names = []; for (let i = 0; i < n; i++) { const l = d.getUint16(o + 28, true); names.push(new TextDecoder().decode(new Uint8Array(b, o + 46, l))); o += 46 + l; } return [window.__downloads[${n0}][0], names]; })`);
  check("the ZIP holds every file with its folders", z[1].length === nFiles && z[1].includes("linkage/positions.svg") && z[1].includes("report.json"), `${z[0]}: ${z[1].length} files, list ${nFiles}`);
}

// ---------- the note and the sheets as PDF, typeset in the page ----------
{
  // the typesetter is a second module, loaded only when asked for, and so
  // is the drawings' GOST font served beside it
  const early = await js("performance.getEntriesByType('resource').map((e) => e.name).filter((n) => /tmm_web_pdf|osifont/.test(n)).length");
  check("the first load does not fetch the PDF module nor the GOST font", early === 0, `${early} requests`);
  const taskText = await js("document.getElementById('editor').value");
  const t0 = Date.now();
  await js("(document.getElementById('pdf').click(), true)");
  const made = await until("/\\d/.test(document.getElementById('pdf-status').textContent) && !document.getElementById('pdf').disabled", 600000);
  results.figures.pdf_first_ms = Date.now() - t0;
  const status = await js("document.getElementById('pdf-status').textContent");
  check("the note and the sheets are typeset in the page", made && !(await js("document.getElementById('pdf-status').classList.contains('bad')")), `${status} (${results.figures.pdf_first_ms} ms with the module's load)`);
  // the GOST font: served when the build found osifont (scripts/build-web.sh)
  const served = existsSync(join(distDir, "osifont.ttf"));
  const fontState = await js("document.getElementById('pdf-status').dataset.font");
  check("the page's PDFs take the GOST font osifont when the page serves it", fontState === (served ? "osifont" : "absent"), `${fontState}; osifont.ttf ${served ? "served" : "not served"}`);
  const pdfNames = await js("[...document.querySelectorAll('#file-list li')].map((li) => li.textContent.replace(/ \\(.*$/, '')).filter((n) => n.endsWith('.pdf'))");
  const cliPdf = join(editedDir, "out-pdf");
  writeFileSync(join(editedDir, "pdf-task.toml"), taskText);
  // the command line reads osifont from the machine, the page was given the
  // same file by the build: both typeset with it. A page built without it
  // (no osifont, or no licence text to serve beside it) is compared with a
  // run kept off the machine's osifont (TMM_FONT_PATH naming a file that is
  // no font), so both use the fallback faces.
  const cliEnv = served ? process.env : { ...process.env, TMM_FONT_PATH: join(editedDir, "pdf-task.toml") };
  execFileSync(tmmBin, ["run", "--out", cliPdf, join(editedDir, "pdf-task.toml")], { stdio: "pipe", env: cliEnv });
  const cliPdfs = walk(cliPdf).filter((f) => f.endsWith(".pdf")).sort();
  check("the page offers the same PDFs as tmm run", JSON.stringify([...pdfNames].sort()) === JSON.stringify(cliPdfs), `page ${pdfNames.join(" ")}; cli ${cliPdfs.join(" ")}`);
  // the note's text and pages against the command line's (pdftotext, pdfinfo)
  const n0 = await js("window.__downloads.length");
  await js(`[...document.querySelectorAll('#file-list li')].find((li) => li.textContent.startsWith("note.pdf ")).querySelector('a').dispatchEvent(new MouseEvent('click', { bubbles: true, cancelable: true })), true`);
  await until(`window.__downloads.length > ${n0}`);
  const b64 = await js(`fetch(window.__downloads[${n0}][1]).then((r) => r.arrayBuffer()).then((b) => { let s = ''; const u = new Uint8Array(b); for (let i = 0; i < u.length; i += 32768) s += String.fromCharCode(...u.subarray(i, i + 32768)); return btoa(s); })`);
  const pagePdf = join(editedDir, "page-note.pdf");
  writeFileSync(pagePdf, Buffer.from(b64, "base64"));
  const pages = (f) => Number(/Pages:\s+(\d+)/.exec(execFileSync("pdfinfo", [f]).toString())[1]);
  const words = (f) => execFileSync("pdftotext", [f, "-"], { maxBuffer: 64 << 20 }).toString().split(/\s+/).filter(Boolean);
  const [wp, wc] = [words(pagePdf), words(join(cliPdf, "note.pdf"))];
  let differ = Math.abs(wp.length - wc.length);
  for (let i = 0; i < Math.min(wp.length, wc.length); i++) if (wp[i] !== wc[i]) differ++;
  // WebAssembly's libm may round a last printed digit differently: allow 1 word in 1000
  check("the page's note.pdf reads as the CLI's (pages, words)", pages(pagePdf) === pages(join(cliPdf, "note.pdf")) && differ <= wc.length / 1000, `${pages(pagePdf)} pages, ${wp.length} words, ${differ} differ`);
  // the fonts embedded (pdffonts; the subset prefix ABCDEF+ dropped)
  const fonts = (f) => [...new Set(execFileSync("pdffonts", [f]).toString().split("\n").slice(2).map((l) => l.split(/\s+/)[0]).filter(Boolean).map((n) => n.replace(/^[A-Z]{6}\+/, "")))].sort();
  const [fp, fc] = [fonts(pagePdf), fonts(join(cliPdf, "note.pdf"))];
  if (served) check("the page's note.pdf embeds osifont (pdffonts)", fp.includes("osifont"), fp.join(" "));
  check("the page's note.pdf embeds the CLI's fonts", JSON.stringify(fp) === JSON.stringify(fc), `page ${fp.join(" ")}; cli ${fc.join(" ")}`);
  // a second request reuses the loaded module
  await setText(taskText + "\n# again\n");
  await sleep(400);
  const t1 = Date.now();
  await js("(document.getElementById('pdf').click(), true)");
  await until("/\\d/.test(document.getElementById('pdf-status').textContent) && !document.getElementById('pdf').disabled", 600000);
  results.figures.pdf_again_ms = Date.now() - t1;
  const nZip = await js("document.querySelectorAll('#file-list li').length");
  const z0 = await js("window.__downloads.length");
  await js("(document.getElementById('zip').click(), true)");
  await until(`window.__downloads.length > ${z0}`);
  const zn = await js(`fetch(window.__downloads[${z0}][1]).then((r) => r.arrayBuffer()).then((b) => { const d = new DataView(b); return d.getUint16(b.byteLength - 22 + 10, true); })`);
  check("the ZIP then holds the PDFs too", zn === nZip, `${zn} files, list ${nZip}; typeset again in ${results.figures.pdf_again_ms} ms`);
  await shot("files", "files-pdf");
}

// ---------- the PDFs without the GOST font: said, and made all the same ----------
{
  // osifont.ttf is moved away, then replaced by bytes that are no font; the
  // file is put back before any check can end the test
  const font = join(distDir, "osifont.ttf"), kept = join(distDir, "osifont.ttf.kept");
  const had = existsSync(font);
  if (had) renameSync(font, kept);
  await send("Network.enable");
  const attempt = async (why) => {
    await send("Network.clearBrowserCache"); // the worker's fetch too
    await send("Page.navigate", { url: "about:blank" }); await sleep(100);
    await send("Page.navigate", { url });
    await until("document.body && document.body.dataset.ready === '1'");
    await js("(document.getElementById('pdf').click(), true)");
    const made = await until("/\\d/.test(document.getElementById('pdf-status').textContent) && !document.getElementById('pdf').disabled", 600000);
    const st = await js("[document.getElementById('pdf-status').dataset.font, document.getElementById('pdf-status').textContent, document.getElementById('pdf-status').classList.contains('bad'), document.documentElement.lang]");
    const said = JSON.parse(await js(`window.tmmWords(${JSON.stringify(st[3])})`)).words[`pdf_font_${why}`];
    await js(`document.querySelector('#tabs [data-view="files"]').click(), true`);
    const files = await js("[...document.querySelectorAll('#file-list li')].filter((li) => /\\.pdf /.test(li.textContent)).length");
    return [`the GOST font ${why === "absent" ? "not served" : "served as bytes that are no font"}: the PDFs are made with the fallback face and the page says so`, made && !st[2] && st[0] === why && !!said && st[1].includes(said) && files >= 1, `${st[0]}, ${files} PDFs listed, ${made ? "made" : "not made"}${st[2] ? ", marked as failed" : ""}${said && st[1].includes(said) ? "" : ", the words not said"}: ${st[1]}`];
  };
  const seen = [];
  try {
    seen.push(await attempt("absent"));
    writeFileSync(font, "not a font\n");
    seen.push(await attempt("refused"));
  } finally {
    if (had) renameSync(kept, font); else rmSync(font, { force: true });
  }
  await send("Network.clearBrowserCache");
  for (const [name, ok, detail] of seen) check(name, ok, detail);
}

// ---------- edits are never lost ----------
{
  // kept in the browser: a page opened without a link restores the task
  const mine = (await js("document.getElementById('editor').value")) + "\n# my note\n";
  await setText(mine);
  await sleep(100);
  const bare = url.replace(/#.*$/, "");
  await send("Page.navigate", { url: "about:blank" }); await sleep(100);
  await send("Page.navigate", { url: bare });
  check("the page is ready again", await until("document.body && document.body.dataset.ready === '1'"));
  check("the edited task is restored from the browser's storage", (await js("document.getElementById('editor').value")) === mine);
  // an example asks before it replaces an edited task
  await js(`(window.__asked = 0, window.confirm = () => { window.__asked++; return false; }, true)`);
  await js(`(() => { const s = document.getElementById('task-select'); s.value = 'gear-seed001.toml'; s.dispatchEvent(new Event('change')); return true; })()`);
  check("an example asks before it replaces an edited task, and 'no' keeps it", (await js("window.__asked")) === 1 && (await js("document.getElementById('editor').value")) === mine);
  // typed while the module loads on a slow link: kept, and a loading indicator shows
  await send("Network.enable");
  await send("Network.setCacheDisabled", { cacheDisabled: true });
  await send("Network.emulateNetworkConditions", { offline: false, latency: 150, downloadThroughput: 400 * 1024, uploadThroughput: 100 * 1024 });
  await js("(localStorage.clear(), true)");
  await send("Page.navigate", { url: "about:blank" }); await sleep(100);
  const tSlow = Date.now();
  await send("Page.navigate", { url: bare });
  await until("document.getElementById('editor') && !document.getElementById('loading').hidden", 10000);
  const typed = readFileSync(new URL("../examples/seed-001-fourbar.toml", import.meta.url), "utf8");
  const loadingShown = await js("!document.getElementById('loading').hidden && getComputedStyle(document.getElementById('loading')).display !== 'none'");
  await js(`(() => { const e = document.getElementById('editor'); e.value = ${JSON.stringify(typed)}; e.dispatchEvent(new Event('input')); return true; })()`);
  await sleep(1500);
  const progress = await js("document.getElementById('loading-bytes').textContent");
  await shot("numbers", "loading-slow-link");
  check("the page is ready on a slow link", await until("document.body.dataset.ready === '1'", 60000));
  results.figures.ready_slow_link_ms = Date.now() - tSlow;
  check("a loading indicator shows while the module loads", loadingShown && /MB/.test(progress), progress);
  check("text typed while the page loads is kept and analysed", (await js("document.getElementById('editor').value")) === typed && (await js("!!window.tmmPage.reply.report.linkage && !window.tmmPage.reply.report.cam")));
  await send("Network.emulateNetworkConditions", { offline: false, latency: 0, downloadThroughput: -1, uploadThroughput: -1 });
}

// ---------- opened from the disk: the page says how to serve it ----------
{
  await send("Page.navigate", { url: "file://" + join(process.cwd(), distDir, "index.html") });
  await sleep(800);
  check("index.html opened from the disk says how to serve it", await js("!document.getElementById('file-note').hidden && /http\\.server/.test(document.getElementById('file-note').textContent)"));
}

// ---------- bundle size ----------
const wasm = readFileSync(join(distDir, "tmm_web_bg.wasm"));
const glue = ["tmm_web.js", "app.js", "index.html", "style.css"].map((f) => readFileSync(join(distDir, f)));
results.figures.wasm_bytes = wasm.length;
results.figures.wasm_gzip_bytes = gzipSync(wasm, { level: 9 }).length;
results.figures.bundle_gzip_bytes = results.figures.wasm_gzip_bytes + glue.reduce((s, b) => s + gzipSync(b, { level: 9 }).length, 0);
check("bundle under 3 MB compressed", results.figures.bundle_gzip_bytes < 3e6, `${(results.figures.bundle_gzip_bytes / 1e6).toFixed(2)} MB gzip (wasm ${(wasm.length / 1e6).toFixed(2)} MB raw)`);
// the PDF module, loaded only when the PDFs are asked for
const pdfWasm = readFileSync(join(distDir, "tmm_web_pdf_bg.wasm"));
results.figures.pdf_module_bytes = pdfWasm.length;
results.figures.pdf_module_gzip_bytes = gzipSync(pdfWasm, { level: 9 }).length + gzipSync(readFileSync(join(distDir, "tmm_web_pdf.js")), { level: 9 }).length;
// the GOST font beside it, fetched with it
if (existsSync(join(distDir, "osifont.ttf"))) {
  const gost = readFileSync(join(distDir, "osifont.ttf"));
  results.figures.gost_font_bytes = gost.length;
  results.figures.gost_font_gzip_bytes = gzipSync(gost, { level: 9 }).length;
}
console.log(JSON.stringify(results.figures, null, 2));
finish(0);
