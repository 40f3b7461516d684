// The page: an editor for the task, the views and the downloads. All the
// mechanics runs in tmm_web.wasm (the same Rust code as the `tmm` command);
// this file only moves text between the editor, the WebAssembly module and
// the page. No dependencies.
import init, * as tmm from "./tmm_web.js";

const $ = (id) => document.getElementById(id);
const state = { reply: null, frames: null, frame: 0, playing: false, camPlaying: false, camIndex: 0, timings: [], name: "task.toml", words: {}, lists: {} };
window.tmmPage = state; // read by the browser test

// ---------- words ----------
// The page's words come from the word files of the drawings (the `[web]`
// area of crates/tmm-report/lang/*.toml), in the language chosen by the
// switch or, by default, by the task's `[project] lang`.
const W = (key, ...args) => (state.words[key] ?? key).replace(/\{(\d)\}/g, (_, i) => args[+i - 1]);
function uiLang() { return $("lang").value || state.taskLang || "en"; }
// A message of the solver (made in English) in the interface's language,
// from the page's word file crates/tmm-web/lang/messages.toml; null when a
// part of it has no wording there yet.
function sayOrNull(text) {
  if (!text || uiLang() === "en") return text;
  return JSON.parse(tmm.say(text, uiLang())).text;
}
const said = (text) => sayOrNull(text) ?? W("msg_untranslated");
function applyWords() {
  const lang = uiLang();
  if (state.wordsLang !== lang) {
    state.words = JSON.parse(tmm.words(lang)).words;
    state.wordsLang = lang;
  }
  document.documentElement.lang = lang;
  document.querySelectorAll("[data-w]").forEach((e) => (e.textContent = W(e.dataset.w)));
  document.querySelectorAll("[data-w-aria]").forEach((e) => e.setAttribute("aria-label", W(e.dataset.wAria)));
  $("play").textContent = W(state.playing ? "pause" : "play");
  $("cam-play").textContent = W(state.camPlaying ? "pause" : "play");
  const first = $("task-select").options[0];
  if (first) first.textContent = W("default_task");
}

// ---------- numbers on screen: mm and degrees (the JSON stays SI) ----------
// Numbers on screen as the interface's language writes them: a decimal comma
// in Russian and Ukrainian, a tiny value as m·10ⁿ (never "1.9e-14").
const decimal = (t) => (uiLang() === "en" ? t : t.replace(".", ","));
const SUP = { "-": "\u207b", "+": "", 0: "\u2070", 1: "\u00b9", 2: "\u00b2", 3: "\u00b3", 4: "\u2074", 5: "\u2075", 6: "\u2076", 7: "\u2077", 8: "\u2078", 9: "\u2079" };
const powerOfTen = (x) => {
  const [m, e] = x.toExponential(3).split("e");
  return `${decimal(+m + "")}\u00b710${[...e].map((c) => SUP[c]).join("")}`;
};
const nf = (x, digits = 6) => (Number.isFinite(x) ? (x !== 0 && Math.abs(x) < 1e-4 ? powerOfTen(x) : decimal(+x.toPrecision(digits) + "")) : String(x));
const fmt = (x) => (typeof x === "number" ? nf(x) : String(x));
const toMm = (m) => nf(m * 1000, 6);
const toDeg = (r) => nf((r * 180) / Math.PI, 6);
// Key numbers: [word key, path in report.json, kind]
const KEYS = [
  ["k_crank", "synthesis.lengths.OA", "len"],
  ["k_kv", "linkage.kv", ""],
  ["k_stroke", "linkage.stroke", "stroke"],
  ["k_theta", "linkage.theta", "ang"],
  ["k_forces_diff", "forces.max_relative_difference", ""],
  ["k_flywheel", "dynamics.flywheel_inertia", "inertia"],
  ["k_x1", "gear.x1", ""],
  ["k_x2", "gear.x2", ""],
  ["k_aw", "gear.aw", "len"],
  ["k_eps", "gear.eps_alpha", ""],
  ["k_planetary", "planetary.best.ratio", ""],
  ["k_r0", "cam.r0", "len"],
];
const get = (obj, path) => path.split(".").reduce((o, k) => (o == null ? undefined : o[k]), obj);
function shown(v, kind, report) {
  if (kind === "stroke") kind = get(report, "linkage.output.kind") === "angular" ? "ang" : "len";
  if (kind === "len") return [toMm(v), W("unit_mm")];
  if (kind === "ang") return [toDeg(v), "°"];
  if (kind === "inertia") return [fmt(v), W("unit_kgm2")];
  return [fmt(v), ""];
}

// ---------- the task in the address: #lang=ru&task=… ----------
async function packTask(text) {
  const s = new Blob([text]).stream().pipeThrough(new CompressionStream("deflate-raw"));
  const b = new Uint8Array(await new Response(s).arrayBuffer());
  let bin = ""; for (const c of b) bin += String.fromCharCode(c);
  return btoa(bin).replace(/\+/g, "-").replace(/\//g, "_").replace(/=+$/, "");
}
async function unpackTask(code) {
  const bin = atob(code.replace(/-/g, "+").replace(/_/g, "/"));
  const b = Uint8Array.from(bin, (c) => c.charCodeAt(0));
  const s = new Blob([b]).stream().pipeThrough(new DecompressionStream("deflate-raw"));
  return await new Response(s).text();
}
const hashParams = () => new URLSearchParams(location.hash.slice(1));
function setHash(params) {
  const h = [...params].map(([k, v]) => `${k}=${v}`).join("&");
  history.replaceState(null, "", h ? "#" + h : location.pathname + location.search);
}
let urlTimer = 0;
function keepTask(text) {
  // the browser's storage at once (a closed tab loses nothing), the address a moment later
  try { localStorage.setItem("tmm-task", JSON.stringify({ name: state.name, text, original: state.original })); } catch { /* storage full or refused */ }
  clearTimeout(urlTimer);
  urlTimer = setTimeout(async () => { const p = hashParams(); p.set("task", await packTask(text)); setHash(p); }, 300);
}
function keepLang() { const p = hashParams(); if ($("lang").value) p.set("lang", $("lang").value); else p.delete("lang"); setHash(p); }

// ---------- the editor, with its own undo history ----------
function gutter(errLine) {
  const n = $("editor").value.split("\n").length;
  let h = "";
  for (let i = 1; i <= n; i++) h += i === errLine ? `<span class="err" data-line="${i}">${i}</span>\n` : i + "\n";
  $("gutter").innerHTML = h;
  $("gutter").scrollTop = $("editor").scrollTop;
}
function showError(e) {
  const box = $("error");
  if (!e) { box.hidden = true; box.removeAttribute("data-line"); gutter(0); return; }
  box.hidden = false;
  box.dataset.line = e.line ?? "";
  const m = sayOrNull(e.message), h = e.help ? sayOrNull(e.help) : "";
  box.textContent = (m ?? W("msg_untranslated")) + (e.help ? `\n${W("help_label")}: ${h ?? W("msg_untranslated")}` : "");
  if (m == null || h == null) {
    // the English text stays out of sight until asked for
    const d = document.createElement("details"), s = document.createElement("summary"), p = document.createElement("pre");
    s.textContent = W("msg_original"); p.lang = "en"; p.textContent = e.message + (e.help ? "\nhelp: " + e.help : "");
    d.append(s, p); box.append(d);
  }
  gutter(e.line || 0);
}
const hist = { stack: [], i: -1 };
function record(text = $("editor").value) {
  if (hist.stack[hist.i] === text) return;
  hist.stack.length = hist.i + 1;
  hist.stack.push(text);
  if (hist.stack.length > 200) hist.stack.shift();
  hist.i = hist.stack.length - 1;
  undoButtons();
}
function undoButtons() {
  $("undo").disabled = !(hist.i > 0 || $("editor").value !== hist.stack[hist.i]);
  $("redo").disabled = hist.i >= hist.stack.length - 1;
}
function undo() {
  if ($("editor").value !== hist.stack[hist.i]) record();
  if (hist.i <= 0) return;
  hist.i--; $("editor").value = hist.stack[hist.i]; afterEdit();
}
function redo() {
  if (hist.i >= hist.stack.length - 1) return;
  hist.i++; $("editor").value = hist.stack[hist.i]; afterEdit();
}
// A new text from the page (an example, a loaded file, a pick, a drag):
// the old text stays one undo away.
function setEditor(text, { original } = {}) {
  record();
  $("editor").value = text;
  if (original !== undefined) state.original = original;
  record(text);
  afterEdit();
}
function afterEdit() { gutter(0); undoButtons(); analyse(); }
let recordTimer = 0;

// ---------- analysis ----------
function analyse() {
  const text = $("editor").value;
  keepTask(text);
  const t0 = performance.now();
  const out = tmm.analyse(state.name, text, $("lang").value);
  const t1 = performance.now();
  const r = JSON.parse(out);
  state.timings.push(t1 - t0);
  state.lists = {};
  if (state.pdfs && state.pdfs.key !== pdfKey(text)) { state.pdfs = null; $("pdf-status").textContent = ""; }
  state.contour = null;
  state.pick = null;
  state.dirty = new Set(Object.keys(VIEWS));
  if (!r.ok) {
    // nothing of the last task stays on screen: every view says why it is empty
    state.reply = null; state.frames = null; state.error = r.error;
    applyWords();
    showError(r.error);
    $("status").textContent = r.error.line ? W("error_status", r.error.line) : W("error_status_noline");
    $("status").classList.add("bad");
    render(activeView());
    return r;
  }
  state.error = null;
  state.goodText = text;
  state.taskLang = r.lang;
  applyWords();
  $("status").textContent = W("analysed", (t1 - t0).toFixed(0));
  $("status").classList.remove("bad");
  showError(null);
  state.reply = r;
  const f = JSON.parse(tmm.frames(360));
  state.frames = f.ok ? f : null;
  state.framesWhy = f.ok ? null : f.none ? W("no_linkage") : W("no_full_turn") + "\n" + said(f.error.message);
  state.bg = null;
  render(activeView());
  return r;
}
// The views, each drawn when shown after a new analysis; each first says
// why it is empty when the task has an error or lacks its section.
const VIEWS = {
  numbers: () => showNumbers(state.reply),
  mechanism: () => showMechanism(),
  diagrams: () => showDiagrams(),
  drawings: () => showDrawings(),
  gear: () => showGear(),
  planetary: () => showPlanetary(),
  cam: () => showCam(),
  files: () => showFiles(),
};
state.dirty = new Set();
const activeView = () => document.querySelector("#tabs button.active").dataset.view;
// Show the view's body, or hide it and say why (`why` non-empty).
function why(view, text) {
  const v = $("view-" + view);
  v.querySelector(".why").hidden = !text;
  v.querySelector(".why").textContent = text || "";
  v.querySelector(".body").hidden = !!text;
  v.dataset.state = text ? "empty" : "shown";
  return !!text;
}
function render(view) {
  if (!state.dirty.has(view)) return;
  state.dirty.delete(view);
  if (!state.reply) {
    const e = state.error;
    why(view, e ? W("blocked") + "\n" + (e.line ? `${W("error_status", e.line)}: ` : "") + said(e.message) : W("loading"));
    if (view === "mechanism") stopPlay();
    return;
  }
  VIEWS[view]();
}
// The median time of n edits (for the browser test): the analyses of the
// texts in turn, each a change from the one before, so the sections that
// read the changed table run each time. Returns the median of the module's
// call alone and with the page reading its reply; the editor's text is
// analysed again at the end.
state.timeAnalyse = (n, texts) => {
  const call = [], whole = [];
  for (let k = 0; k < n; k++) {
    const t0 = performance.now();
    const out = tmm.analyse(state.name, texts[k % texts.length], $("lang").value);
    const t1 = performance.now();
    JSON.parse(out);
    call.push(t1 - t0); whole.push(performance.now() - t0);
  }
  analyse();
  const med = (ts) => ts.sort((a, b) => a - b)[Math.floor(ts.length / 2)];
  return { call: med(call), with_reply: med(whole) };
};
let analyseTimer = 0;
function scheduleAnalyse() { clearTimeout(analyseTimer); analyseTimer = setTimeout(analyse, 150); }

function showNumbers(r) {
  why("numbers", null);
  let h = `<tr><th>${W("quantity")}</th><th>${W("value")}</th><th>${W("unit")}</th></tr>`;
  for (const [label, path, kind] of KEYS) {
    const v = get(r.report, path);
    if (typeof v !== "number") continue;
    const [text, unit] = shown(v, kind, r.report);
    h += `<tr><td>${W(label)}</td><td class="num" data-key="${path}" data-value="${v}">${text}</td><td>${unit}</td></tr>`;
  }
  $("key-numbers").innerHTML = h;
  if (uiLang() === "en") {
    $("texts").innerHTML = r.sections.map((s) => `<h3>${s.section}</h3><pre class="section-text"></pre>`).join("");
    $("texts").querySelectorAll("pre").forEach((p, i) => (p.textContent = r.sections[i].text));
  } else {
    // the plain-text summaries are English: not on a Russian or Ukrainian screen
    $("texts").innerHTML = `<p class="hint"></p>`;
    $("texts").firstChild.textContent = W("texts_note");
  }
}

// ---------- drawings, and a viewer that zooms and pans ----------
function drawing(title, svg) {
  const d = document.createElement("div");
  d.className = "drawing zoomable";
  d.innerHTML = `<h3></h3>` + (svg || "").replace(/^<\?xml[^>]*>\s*/, "");
  d.querySelector("h3").textContent = title;
  const s = d.querySelector("svg");
  if (s) { s.setAttribute("tabindex", "0"); s.setAttribute("role", "img"); s.setAttribute("aria-label", title); }
  return d;
}
function fill(id, items) {
  const el = $(id); el.replaceChildren(...items.map(([t, s]) => drawing(t, s)));
}
document.addEventListener("click", (e) => {
  const s = e.target.closest(".drawing.zoomable svg");
  if (s && !s.closest("#contour")) openViewer(s.closest(".drawing").querySelector("h3").textContent, s);
});
document.addEventListener("keydown", (e) => {
  const s = e.target.closest?.(".drawing.zoomable svg");
  if (s && (e.key === "Enter" || e.key === " ") && !s.closest("#contour")) { e.preventDefault(); openViewer(s.closest(".drawing").querySelector("h3").textContent, s); }
});
const viewer = { vb: null, svg: null, back: null };
function openViewer(title, svg) {
  const c = svg.cloneNode(true);
  c.removeAttribute("width"); c.removeAttribute("height"); c.removeAttribute("tabindex");
  const vb = svg.viewBox.baseVal;
  viewer.vb = [vb.x, vb.y, vb.width, vb.height]; viewer.full = [...viewer.vb]; viewer.svg = c; viewer.back = document.activeElement;
  $("viewer-title").textContent = title;
  $("viewer-stage").replaceChildren(c);
  $("viewer").hidden = false;
  $("viewer-stage").focus();
}
function viewerSet() { viewer.svg.setAttribute("viewBox", viewer.vb.join(" ")); }
function viewerZoom(k, fx = 0.5, fy = 0.5) {
  const [x, y, w, h] = viewer.vb, nw = w * k, nh = h * k;
  viewer.vb = [x + (w - nw) * fx, y + (h - nh) * fy, nw, nh]; viewerSet();
}
function closeViewer() { $("viewer").hidden = true; $("viewer-stage").replaceChildren(); viewer.back?.focus?.(); }
$("viewer-close").onclick = closeViewer;
$("viewer-stage").addEventListener("wheel", (e) => {
  e.preventDefault();
  const r = $("viewer-stage").getBoundingClientRect();
  viewerZoom(e.deltaY > 0 ? 1.2 : 1 / 1.2, (e.clientX - r.left) / r.width, (e.clientY - r.top) / r.height);
}, { passive: false });
{
  let pan = null;
  const st = $("viewer-stage");
  st.addEventListener("pointerdown", (e) => { pan = [e.clientX, e.clientY, [...viewer.vb]]; st.setPointerCapture(e.pointerId); });
  st.addEventListener("pointermove", (e) => {
    if (!pan) return;
    const r = st.getBoundingClientRect(), [x, y, w, h] = pan[2], k = Math.max(w / r.width, h / r.height);
    viewer.vb = [x - (e.clientX - pan[0]) * k, y - (e.clientY - pan[1]) * k, w, h]; viewerSet();
  });
  st.addEventListener("pointerup", () => (pan = null));
  $("viewer").addEventListener("keydown", (e) => {
    const [x, y, w, h] = viewer.vb, step = 0.1;
    const keys = {
      Escape: closeViewer, "+": () => viewerZoom(1 / 1.2), "=": () => viewerZoom(1 / 1.2), "-": () => viewerZoom(1.2),
      "0": () => { viewer.vb = [...viewer.full]; viewerSet(); },
      ArrowLeft: () => { viewer.vb = [x - w * step, y, w, h]; viewerSet(); }, ArrowRight: () => { viewer.vb = [x + w * step, y, w, h]; viewerSet(); },
      ArrowUp: () => { viewer.vb = [x, y - h * step, w, h]; viewerSet(); }, ArrowDown: () => { viewer.vb = [x, y + h * step, w, h]; viewerSet(); },
    };
    if (keys[e.key] && !(e.key === "Escape" && false)) { e.preventDefault(); keys[e.key](); }
    if (e.key === "Tab") { e.preventDefault(); (document.activeElement === $("viewer-close") ? $("viewer-stage") : $("viewer-close")).focus(); }
  });
}

// The files of one section of the last run ("report" for report.json),
// asked for once per analysis: the module makes the section's drawings then.
function sectionFiles(section) {
  if (!state.reply) return [];
  if (!(section in state.lists)) {
    const l = JSON.parse(tmm.files(section));
    if (!l.ok) { $("status").textContent = said(l.error.message); $("status").classList.add("bad"); }
    state.lists[section] = l.ok ? l.files : [];
  }
  return state.lists[section];
}
const files = (prefix, ext = ".svg") => sectionFiles(prefix.split("/")[0]).map((f) => f.path).filter((p) => p.startsWith(prefix) && p.endsWith(ext));
const allSections = () => ["report", ...state.reply.sections.map((s) => s.section), "sheets"];

function showDrawings() {
  why("drawings", null);
  const box = $("all-drawings"); box.replaceChildren();
  for (const sec of allSections().slice(1)) {
    const svgs = files(sec + "/");
    if (!svgs.length) continue;
    const h = document.createElement("h2"); h.textContent = sec + "/";
    const g = document.createElement("div"); g.className = "grid";
    g.append(...svgs.map((p) => drawing(p, tmm.file_text(p))));
    box.append(h, g);
  }
}

// ---------- downloads ----------
function download(name, bytes, type) {
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([bytes], { type }));
  a.download = name; a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}
function showFiles() {
  why("files", null);
  const ul = $("file-list"); ul.replaceChildren();
  const add = (label, fn) => { const li = document.createElement("li"); const b = document.createElement("a"); b.href = "#"; b.textContent = label; b.onclick = (e) => { e.preventDefault(); fn(); }; li.append(b); ul.append(li); };
  add(`task.toml (${W("task_file")})`, () => download(state.name, $("editor").value, "text/plain"));
  for (const f of pdfFiles()) add(`${f.path} (${(f.bytes.length / 1024).toFixed(1)} KB)`, () => download(f.path.replace(/\//g, "-"), f.bytes, "application/pdf"));
  for (const f of allSections().flatMap(sectionFiles)) add(`${f.path} (${(f.size / 1024).toFixed(1)} KB)`, () => download(f.path.replace(/\//g, "-"), tmm.file_bytes(f.path), "application/octet-stream"));
}
// The note and the sheets as PDF, typeset in a worker by the page's second
// module (tmm_web_pdf: typst and its fonts) with the drawings' GOST font
// osifont served beside it, both loaded on the first click only.
// The PDFs belong to the task text and language they were made from.
const pdfKey = (text) => $("lang").value + "\n" + text;
const pdfFiles = () => (state.pdfs && state.pdfs.key === pdfKey($("editor").value) ? state.pdfs.files : []);
let pdfWorker = null;
$("pdf").onclick = () => {
  if (!state.reply || $("pdf").disabled) return;
  const text = $("editor").value, key = pdfKey(text), t0 = performance.now();
  $("pdf").disabled = true;
  $("pdf-status").classList.remove("bad");
  $("pdf-status").textContent = W(pdfWorker ? "pdf_typesetting" : "pdf_loading");
  pdfWorker ??= new Worker("pdf-worker.js", { type: "module" });
  pdfWorker.onmessage = (e) => {
    $("pdf").disabled = false;
    if (e.data.ok) {
      state.pdfs = { key, files: e.data.files, ms: performance.now() - t0 };
      // the drawings' lettering: osifont when the page serves it, else a
      // fallback face, said next to the count
      const font = e.data.font === "osifont" ? "" : " " + (e.data.font === "refused" ? W("pdf_font_refused") : W("pdf_font_absent"));
      $("pdf-status").dataset.font = e.data.font;
      $("pdf-status").textContent = W("pdf_done", e.data.files.length, ((performance.now() - t0) / 1000).toFixed(1)) + font;
    } else {
      $("pdf-status").textContent = W("pdf_failed") + " " + said(e.data.message);
      $("pdf-status").classList.add("bad");
    }
    if (activeView() === "files") showFiles();
  };
  pdfWorker.onerror = (e) => {
    $("pdf").disabled = false;
    $("pdf-status").textContent = W("pdf_failed") + " " + (e.message || "");
    $("pdf-status").classList.add("bad");
  };
  pdfWorker.postMessage({ name: state.name, text, lang: $("lang").value });
};
// A ZIP of every file with its folders (stored, not compressed: the
// drawings are small and the browser's own deflate stream has no raw
// CRC-32), made here from the module's bytes.
const CRC = (() => { const t = new Uint32Array(256); for (let n = 0; n < 256; n++) { let c = n; for (let k = 0; k < 8; k++) c = c & 1 ? 0xedb88320 ^ (c >>> 1) : c >>> 1; t[n] = c >>> 0; } return t; })();
function crc32(b) { let c = 0xffffffff; for (let i = 0; i < b.length; i++) c = CRC[(c ^ b[i]) & 255] ^ (c >>> 8); return (c ^ 0xffffffff) >>> 0; }
function zip(entries) {
  const enc = new TextEncoder(), parts = [], central = [];
  let off = 0;
  for (const [name, data] of entries) {
    const nm = enc.encode(name), crc = crc32(data);
    const h = new DataView(new ArrayBuffer(30));
    h.setUint32(0, 0x04034b50, true); h.setUint16(4, 20, true); h.setUint16(6, 0x0800, true);
    h.setUint32(14, crc, true); h.setUint32(18, data.length, true); h.setUint32(22, data.length, true); h.setUint16(26, nm.length, true);
    parts.push(new Uint8Array(h.buffer), nm, data);
    const c = new DataView(new ArrayBuffer(46));
    c.setUint32(0, 0x02014b50, true); c.setUint16(4, 20, true); c.setUint16(6, 20, true); c.setUint16(8, 0x0800, true);
    c.setUint32(16, crc, true); c.setUint32(20, data.length, true); c.setUint32(24, data.length, true); c.setUint16(28, nm.length, true);
    c.setUint32(42, off, true);
    central.push(new Uint8Array(c.buffer), nm);
    off += 30 + nm.length + data.length;
  }
  const size = central.reduce((s, p) => s + p.length, 0);
  const e = new DataView(new ArrayBuffer(22));
  e.setUint32(0, 0x06054b50, true); e.setUint16(8, entries.length, true); e.setUint16(10, entries.length, true);
  e.setUint32(12, size, true); e.setUint32(16, off, true);
  return new Blob([...parts, ...central, new Uint8Array(e.buffer)], { type: "application/zip" });
}
$("zip").onclick = () => {
  if (!state.reply) return;
  const entries = [[state.name.replace(/^.*[\\/]/, ""), new TextEncoder().encode($("editor").value)]];
  for (const f of pdfFiles()) entries.push([f.path, f.bytes]);
  for (const f of allSections().flatMap(sectionFiles)) entries.push([f.path, tmm.file_bytes(f.path)]);
  download("tmm-" + state.name.replace(/\.toml$/, "").replace(/^.*[\\/]/, "") + ".zip", zip(entries), "application/zip");
};

// ---------- mechanism: animation, slider, dragging, plans at the angle ----------
function showMechanism() {
  if (why("mechanism", state.frames ? null : state.framesWhy)) { stopPlay(); clearMechanism(); return; }
  $("drag-why").hidden = true;
  sizeCanvas($("mech"), window.innerWidth < 760 ? 0.8 : 0.62);
  state.bg = null;
  setAngleIndex(state.frame);
}
function clearMechanism() {
  const c = $("mech"); c.getContext("2d").clearRect(0, 0, c.width, c.height);
  $("plans").replaceChildren(); $("force-plans").replaceChildren(); $("torque").textContent = "";
}
// A canvas as wide as its box, at the screen's pixel density.
function sizeCanvas(c, aspect, maxCss = 1100) {
  const w = Math.min(maxCss, Math.max(280, Math.round(c.parentElement.clientWidth - 2)));
  const dpr = window.devicePixelRatio || 1;
  const W_ = Math.round(w * dpr), H = Math.round(W_ * aspect);
  if (c.width !== W_ || c.height !== H) { c.width = W_; c.height = H; }
  c.style.width = w + "px"; c.style.height = H / dpr + "px";
}
const cssScale = (c) => c.width / c.getBoundingClientRect().width;
function setAngleIndex(i) {
  const F = state.frames;
  $("angle").value = i;
  if (!F) return;
  state.frame = ((i % F.phi.length) + F.phi.length) % F.phi.length;
  const phi = F.phi[state.frame];
  $("angle-out").textContent = `φ = ${((phi * 180) / Math.PI).toFixed(1)}°`;
  $("angle-out").dataset.phi = phi;
  drawMechanism();
  const t0 = performance.now();
  if (state.playing) {
    // a frame: the plans' vectors of the one solved position, drawn here;
    // the drawings (the CLI's SVG), the forces and the cursors when the
    // crank stops
    const a = JSON.parse(tmm.plan_vectors(phi));
    state.lastAngleMs = performance.now() - t0;
    if (a.ok) drawPlans(a);
    return;
  }
  const a = JSON.parse(tmm.at_angle(phi, true));
  state.lastAngleMs = performance.now() - t0;
  if (!a.ok) { $("plans").replaceChildren(); $("torque").textContent = said(a.error?.message ?? ""); return; }
  fill("plans", [[W("velocity_plan"), a.velocity_plan], [W("acceleration_plan"), a.acceleration_plan]]);
  if (a.forces) {
    fill("force-plans", Object.entries(a.forces.files));
    $("torque").textContent = W("mb", nf(a.forces.balancing_moment), nf(a.forces.zhukovsky_moment));
  } else { $("force-plans").replaceChildren(); $("torque").textContent = ""; }
  moveCursors(a.psi);
}
// The velocity and acceleration plans of a frame of the animation on two
// canvases: each vector from its start to its end, the pole p (π) at the
// origin, the points' images named; the scale fits each plan to its box.
function drawPlans(a) {
  let cs = [...document.querySelectorAll("#plans canvas")];
  if (cs.length !== 2) {
    fill("plans", [[W("velocity_plan"), ""], [W("acceleration_plan"), ""]]);
    cs = [...document.querySelectorAll("#plans .drawing")].map((d) => { const c = document.createElement("canvas"); c.width = 420; c.height = 320; d.append(c); return c; });
  }
  [[a.velocity, "p"], [a.acceleration, "π"]].forEach(([vs, pole], i) => {
    const c = cs[i], g = c.getContext("2d");
    g.clearRect(0, 0, c.width, c.height);
    let r = 1e-12;
    for (const v of vs) r = Math.max(r, Math.abs(v.from[0]), Math.abs(v.from[1]), Math.abs(v.to[0]), Math.abs(v.to[1]));
    const s = (Math.min(c.width, c.height) / 2 - 24) / r, cx = c.width / 2, cy = c.height / 2;
    const to = ([x, y]) => [cx + s * x, cy - s * y];
    g.font = "12px sans-serif"; g.lineCap = "round";
    for (const v of vs) {
      const [u1, v1] = to(v.from), [u2, v2] = to(v.to), L = Math.hypot(u2 - u1, v2 - v1);
      if (L < 0.5) continue;
      g.strokeStyle = g.fillStyle = v.kind === "Absolute" ? "#1f4e9c" : "#555";
      g.lineWidth = v.kind === "Absolute" ? 2 : 1;
      g.beginPath(); g.moveTo(u1, v1); g.lineTo(u2, v2); g.stroke();
      const ux = (u2 - u1) / L, uy = (v2 - v1) / L, k = Math.min(8, L / 2);
      g.beginPath(); g.moveTo(u2, v2); g.lineTo(u2 - k * ux - k * 0.35 * uy, v2 - k * uy + k * 0.35 * ux); g.lineTo(u2 - k * ux + k * 0.35 * uy, v2 - k * uy - k * 0.35 * ux); g.closePath(); g.fill();
      if (v.kind === "Absolute") { g.fillStyle = "#000"; g.fillText(v.label.replace(/^[Va]_?/, "").toLowerCase(), u2 + 4, v2 - 4); }
    }
    g.fillStyle = "#000"; g.fillText(pole, cx - 12, cy + 14);
    g.beginPath(); g.arc(cx, cy, 3, 0, 2 * Math.PI); g.fill();
  });
}
function mechTransform() {
  const F = state.frames, c = $("mech"), pad = 30 * (window.devicePixelRatio || 1);
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  for (const fr of F.xy) for (const [x, y] of fr) { x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y); }
  for (const gd of (F.guides || []).filter((g) => g.fixed)) for (const [x, y] of [gd.from, gd.to]) { x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y); }
  const s = Math.min((c.width - 2 * pad) / (x1 - x0 || 1), (c.height - 2 * pad) / (y1 - y0 || 1));
  const ox = (c.width - s * (x1 - x0)) / 2 - s * x0, oy = (c.height + s * (y1 - y0)) / 2 + s * y0;
  return { s, ox, oy, to: ([x, y]) => [ox + s * x, oy - s * y], from: (u, v) => [(u - ox) / s, (oy - v) / s] };
}
// The scale and the traced paths of every point, drawn once per set of
// frames onto a canvas of their own; a frame copies it and draws the links.
function mechBackground() {
  const F = state.frames, c = $("mech");
  if (state.bg && state.bg.frames === F && state.bg.canvas.width === c.width && state.bg.canvas.height === c.height) return state.bg;
  const T = state.dragT || mechTransform();
  const canvas = document.createElement("canvas"); canvas.width = c.width; canvas.height = c.height;
  const g = canvas.getContext("2d"), dpr = window.devicePixelRatio || 1;
  g.lineWidth = dpr;
  F.names.forEach((_, j) => {
    g.strokeStyle = `hsl(${(j * 67) % 360} 60% 60%)`;
    g.beginPath();
    F.xy.forEach((fr, k) => { const [u, v] = T.to(fr[j]); k ? g.lineTo(u, v) : g.moveTo(u, v); });
    g.closePath(); g.stroke();
  });
  // the fixed guides of the sliders, hatched on one side
  g.strokeStyle = "#333"; g.lineWidth = 1.5 * dpr;
  for (const gd of F.guides || []) {
    if (!gd.fixed) continue;
    const [u1, v1] = T.to(gd.from), [u2, v2] = T.to(gd.to), L = Math.hypot(u2 - u1, v2 - v1) || 1;
    g.beginPath(); g.moveTo(u1, v1); g.lineTo(u2, v2); g.stroke();
    const nx = (v2 - v1) / L, ny = -(u2 - u1) / L, ux = (u2 - u1) / L, uy = (v2 - v1) / L, hs = 6 * dpr;
    g.lineWidth = dpr;
    for (let t = 0; t < L; t += 10 * dpr) { const a = u1 + ux * t, b = v1 + uy * t; g.beginPath(); g.moveTo(a, b); g.lineTo(a + nx * hs - ux * hs, b + ny * hs - uy * hs); g.stroke(); }
    g.lineWidth = 1.5 * dpr;
  }
  // the frame's pivots: the points that do not move over the cycle
  const half = F.xy[Math.floor(F.xy.length / 2)];
  const quarter = F.xy[Math.floor(F.xy.length / 4)];
  const still = (a, b, j) => Math.hypot(a[j][0] - b[j][0], a[j][1] - b[j][1]) <= 1e-9;
  const fixed = F.names.map((_, j) => still(F.xy[0], half, j) && still(F.xy[0], quarter, j));
  state.bg = { frames: F, canvas, T, fixed };
  return state.bg;
}
function drawMechanism() {
  const F = state.frames, c = $("mech"), g = c.getContext("2d"), dpr = window.devicePixelRatio || 1;
  g.clearRect(0, 0, c.width, c.height);
  if (!F) return;
  const bg = mechBackground(), T = bg.T; state.T = T;
  g.drawImage(bg.canvas, 0, 0);
  const fr = F.xy[state.frame];
  g.strokeStyle = "#1f4e9c"; g.lineWidth = 4 * dpr; g.lineCap = "round";
  for (const [a, b] of F.segments) { const [u1, v1] = T.to(fr[a]), [u2, v2] = T.to(fr[b]); g.beginPath(); g.moveTo(u1, v1); g.lineTo(u2, v2); g.stroke(); }
  // the moving guides (on a rocker: the slotted link) and the sliders' blocks
  for (const gd of F.guides || []) {
    if (gd.fixed) continue;
    const a = gd.frames[state.frame];
    const [u1, v1] = T.to(a[0]), [u2, v2] = T.to(a[1]);
    g.strokeStyle = "#1f4e9c"; g.lineWidth = 2 * dpr; g.beginPath(); g.moveTo(u1, v1); g.lineTo(u2, v2); g.stroke();
  }
  for (const sl of F.sliders || []) {
    const [u, v] = T.to(fr[sl.point]), ang = sl.angle[state.frame], w = 16 * dpr, h = 10 * dpr;
    g.save(); g.translate(u, v); g.rotate(-ang);
    g.fillStyle = "#fff"; g.strokeStyle = "#000"; g.lineWidth = 1.5 * dpr;
    g.fillRect(-w / 2, -h / 2, w, h); g.strokeRect(-w / 2, -h / 2, w, h); g.restore();
  }
  g.font = `${13 * dpr}px sans-serif`;
  F.names.forEach((n, j) => {
    const [u, v] = T.to(fr[j]);
    const big = j === F.pin; // the crank pin: a handle a finger can take (≥ 24 px across)
    g.beginPath(); g.arc(u, v, (big ? 12 : 4) * dpr, 0, 2 * Math.PI); g.fillStyle = big ? "rgba(240,160,0,.35)" : "#fff"; g.fill(); g.lineWidth = 1.5 * dpr; g.strokeStyle = "#000"; g.stroke();
    if (big) { g.beginPath(); g.arc(u, v, 4 * dpr, 0, 2 * Math.PI); g.fillStyle = "#fff"; g.fill(); g.stroke(); }
    g.fillStyle = "#000"; g.fillText(n, u + 8 * dpr, v - 8 * dpr);
  });
  F.names.forEach((_, j) => {
    if (!bg.fixed[j]) return;
    const [pu, pv] = T.to(fr[j]), k = dpr;
    g.beginPath(); g.moveTo(pu, pv + 4 * k); g.lineTo(pu - 8 * k, pv + 14 * k); g.lineTo(pu + 8 * k, pv + 14 * k); g.closePath(); g.stroke();
    g.beginPath(); g.moveTo(pu - 12 * k, pv + 14 * k); g.lineTo(pu + 12 * k, pv + 14 * k); g.stroke();
  });
  if (state.dragging?.edit) {
    const [u, v] = state.dragging.at;
    g.strokeStyle = "#f0a000"; g.lineWidth = 2 * dpr; g.beginPath(); g.arc(u, v, 10 * dpr, 0, 2 * Math.PI); g.stroke();
  }
}
function nearestFrame(phi) {
  const F = state.frames; let best = 0, bd = Infinity;
  F.phi.forEach((p, k) => { const d = Math.abs(Math.atan2(Math.sin(p - phi), Math.cos(p - phi))); if (d < bd) { bd = d; best = k; } });
  return best;
}
// The point under the pointer (within 24 CSS px), the crank pin first.
function pointAt(e) {
  const F = state.frames, c = $("mech"), r = c.getBoundingClientRect(), k = cssScale(c);
  const u = (e.clientX - r.left) * k, v = (e.clientY - r.top) * k, fr = F.xy[state.frame];
  let best = -1, bd = 24 * k;
  F.names.forEach((_, j) => { const [pu, pv] = state.T.to(fr[j]); const d = Math.hypot(pu - u, pv - v) - (j === F.pin ? 4 * k : 0); if (d < bd) { bd = d; best = j; } });
  return { j: best, u, v };
}
$("mech").addEventListener("pointerdown", (e) => {
  if (!state.frames || !state.T) return;
  const { j, u, v } = pointAt(e);
  if (j < 0) return;
  const edit = $("edit-drag").checked;
  if (!edit && j !== state.frames.pin) return;
  e.preventDefault();
  if (edit) { stopPlay(); record(); state.dragT = state.T; }
  state.dragging = { j, name: state.frames.names[j], edit, at: [u, v], phi: state.frames.phi[state.frame], frame: state.frame };
  $("mech").setPointerCapture(e.pointerId);
});
$("mech").addEventListener("pointermove", (e) => {
  const d = state.dragging;
  if (!d) return;
  const c = $("mech"), r = c.getBoundingClientRect(), k = cssScale(c);
  const u = (e.clientX - r.left) * k, v = (e.clientY - r.top) * k;
  const [x, y] = state.T.from(u, v);
  if (!d.edit) {
    const pv = state.frames.xy[0][state.frames.pivot];
    setAngleIndex(nearestFrame(Math.atan2(y - pv[1], x - pv[0])));
    return;
  }
  d.at = [u, v];
  const out = JSON.parse(tmm.drag(state.goodText, d.name, x, y, d.phi));
  if (!out.ok) { $("drag-why").hidden = false; $("drag-why").textContent = W("cannot_assemble") + " " + said(out.error.message); drawMechanism(); return; }
  if (out.text === $("editor").value) { drawMechanism(); return; }
  $("editor").value = out.text; gutter(0);
  const last = { frames: state.frames, bg: state.bg };
  const res = analyse();
  if (!res.ok) {
    // the dragged mechanism does not assemble: the view stays, showing the
    // last mechanism that did with the pointer marked, and saying why
    state.dirty.delete("mechanism"); why("mechanism", null);
    state.frames = last.frames; state.bg = last.bg;
    $("plans").replaceChildren(); $("force-plans").replaceChildren(); $("torque").textContent = "";
    $("drag-why").hidden = false; $("drag-why").textContent = W("cannot_assemble") + " " + said(res.error.message);
    drawMechanism();
  } else $("drag-why").hidden = true;
});
const endDrag = () => {
  const d = state.dragging; state.dragging = null;
  if (d?.edit) { state.dragT = null; state.bg = null; record(); undoButtons(); if (state.frames) drawMechanism(); }
};
$("mech").addEventListener("pointerup", endDrag);
$("mech").addEventListener("pointercancel", endDrag);
$("mech").addEventListener("keydown", (e) => {
  if (!state.frames) return;
  const step = { ArrowRight: 1, ArrowUp: 1, ArrowLeft: -1, ArrowDown: -1, PageUp: 30, PageDown: -30 }[e.key];
  if (step) { e.preventDefault(); setAngleIndex(state.frame + step); }
});
$("angle").addEventListener("input", () => setAngleIndex(+$("angle").value));
function playLoop() {
  if (!state.playing || !state.frames) return;
  state.fpsFrames = (state.fpsFrames || 0) + 1;
  setAngleIndex(state.frame + 1);
  requestAnimationFrame(playLoop);
}
function stopPlay() { if (state.playing) { state.playing = false; $("play").textContent = W("play"); } }
$("play").onclick = () => {
  state.playing = !state.playing;
  $("play").textContent = W(state.playing ? "pause" : "play");
  if (state.playing) { $("torque").textContent = ""; $("force-plans").replaceChildren(); requestAnimationFrame(playLoop); }
  else setAngleIndex(state.frame);
};

// ---------- diagrams with a cursor ----------
function showDiagrams() {
  const list = [...files("linkage/diagram-"), ...files("dynamics/"), ...files("forces/strength-"), ...files("forces/balancing-torque")];
  if (why("diagrams", list.length ? null : W("no_diagrams"))) return;
  fill("diagrams", list.map((p) => [p, tmm.file_text(p)]));
  moveCursors(state.frames ? cursorPsi() : null);
}
function cursorPsi() {
  const F = state.frames; const p = F.phi[state.frame];
  return (((F.direction * (p - F.start)) % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI);
}
// The diagrams run over one revolution: the longest curve (polyline or
// path) spans ψ = 0…2π.
function moveCursors(psi) {
  document.querySelectorAll("#diagrams .drawing").forEach((d) => {
    if (!/diagram-|dynamics\//.test(d.querySelector("h3").textContent)) return;
    const svg = d.querySelector("svg");
    svg.querySelector(".cursor")?.remove();
    if (psi == null) return;
    let best = null, bl = 0;
    svg.querySelectorAll("polyline, path").forEach((pl) => { const n = (pl.getAttribute("points") || pl.getAttribute("d") || "").length; if (n > bl) { bl = n; best = pl; } });
    if (!best) return;
    const bb = best.getBBox();
    const x = bb.x + (bb.width * psi) / (2 * Math.PI);
    const vb = svg.viewBox.baseVal;
    const l = document.createElementNS("http://www.w3.org/2000/svg", "line");
    l.setAttribute("class", "cursor"); l.setAttribute("x1", x); l.setAttribute("x2", x);
    l.setAttribute("y1", vb.y); l.setAttribute("y2", vb.y + vb.height);
    l.setAttribute("stroke", "#e67e00"); l.setAttribute("stroke-width", 0.5);
    svg.append(l);
  });
}

// ---------- gear: the contour picks (x1, x2) ----------
function gearNumbers(g, err, at) {
  const box = $("gear-numbers");
  box.dataset.pickX1 = at ? at[0] : ""; box.dataset.pickX2 = at ? at[1] : "";
  if (err) { box.innerHTML = `<p class="bad"></p>`; box.firstChild.textContent = err; $("gear-checks").replaceChildren(); $("gear-write").hidden = true; return; }
  const rows = [["x1", g.x1, nf(g.x1)], ["x2", g.x2, nf(g.x2)], [`aw, ${W("unit_mm")}`, g.aw, toMm(g.aw)], ["αw, °", g.alpha_w, toDeg(g.alpha_w)], ["εα", g.eps_alpha, nf(g.eps_alpha)],
    [`sa1, ${W("unit_mm")}`, g.sa1, toMm(g.sa1)], [`sa2, ${W("unit_mm")}`, g.sa2, toMm(g.sa2)], [W("gear_all"), g.all_checks_pass, W(g.all_checks_pass ? "yes" : "no")]];
  box.innerHTML = "<table>" + rows.map(([k, v, t]) => `<tr><td>${k}</td><td class="num" data-gear="${k.split(",")[0]}" data-value="${v}">${t}</td></tr>`).join("") + "</table>";
  // each check's verdict
  const mmKeys = /^(interference|pointing)/;
  let h = `<h3>${W("gear_checks")}</h3><table><tr><th></th><th>${W("value")}</th><th>${W("limit")}</th><th></th></tr>`;
  for (const [k, c] of Object.entries(g.checks || {})) {
    const v = mmKeys.test(k) ? toMm(c.value) + " " + W("unit_mm") : nf(c.value), l = mmKeys.test(k) ? toMm(c.limit) + " " + W("unit_mm") : nf(c.limit);
    h += `<tr data-check="${k}" data-pass="${c.pass}"><td>${W("chk_" + k)}</td><td class="num">${v}</td><td class="num">${l}</td><td class="${c.pass ? "pass" : "fail"}">${W(c.pass ? "pass" : "fail")}</td></tr>`;
  }
  $("gear-checks").innerHTML = h + "</table>";
}
function showGear(svgs) {
  const g0 = state.reply.report.gear;
  if (why("gear", g0 ? null : W("no_gear"))) return;
  const text = (p) => (svgs ? svgs[p] : tmm.file_text(p));
  if (!svgs) { gearNumbers(g0, null, [g0.x1, g0.x2]); $("gear-write").hidden = true; }
  $("contour").replaceChildren(drawing("gear/contour.svg", text("gear/contour.svg")));
  $("contour").firstChild.classList.remove("zoomable");
  fill("gear-drawings", ["gear/mesh.svg", "gear/sliding.svg", "gear/profiles.svg"].map((p) => [p, text(p)]));
  const svg = $("contour").querySelector("svg");
  state.contour ??= JSON.parse(tmm.gear_contour());
  if (state.contour.ok) shadePasses(svg, state.contour);
  svg.addEventListener("click", (e) => {
    const A = state.contour; if (!A.ok) return;
    const pt = new DOMPoint(e.clientX, e.clientY).matrixTransform(svg.getScreenCTM().inverse());
    const x1 = +((pt.x - A.origin[0]) / A.scale).toFixed(3), x2 = +((A.origin[1] - pt.y) / A.scale).toFixed(3);
    const r = JSON.parse(tmm.gear_at(x1, x2));
    if (r.ok) { gearNumbers(r.gear, null, [x1, x2]); state.pick = [x1, x2]; showGear(r.files); $("gear-write").hidden = false; }
    else { gearNumbers(null, `x1 = ${nf(x1)}, x2 = ${nf(x2)}: ${said(r.error.message)}${r.error.help ? " — " + said(r.error.help) : ""}`, [x1, x2]); state.pick = null; }
  });
}
// The nodes where every check of the task passes, shaded over the drawing
// in the cells the drawing shades (all four corners inside), row by row.
function shadePasses(svg, A) {
  const n = A.n, ns = "http://www.w3.org/2000/svg";
  const g = document.createElementNS(ns, "g"); g.id = "passes";
  const at = (i, j) => [A.origin[0] + A.scale * (A.x1[0] + ((A.x1[1] - A.x1[0]) * i) / (n - 1)), A.origin[1] - A.scale * (A.x2[0] + ((A.x2[1] - A.x2[0]) * j) / (n - 1))];
  const ok = (i, j) => A.passes[j * n + i] === "1";
  for (let j = 0; j < n - 1; j++) {
    for (let i = 0; i < n - 1; i++) {
      if (!(ok(i, j) && ok(i + 1, j) && ok(i, j + 1) && ok(i + 1, j + 1))) continue;
      let k = i; while (k + 1 < n - 1 && ok(k + 1, j) && ok(k + 2, j) && ok(k + 1, j + 1) && ok(k + 2, j + 1)) k++;
      const [u0, v0] = at(i, j + 1), [u1, v1] = at(k + 1, j);
      const r = document.createElementNS(ns, "rect");
      r.setAttribute("x", u0); r.setAttribute("y", v0); r.setAttribute("width", u1 - u0 + 0.02); r.setAttribute("height", v1 - v0 + 0.02);
      g.append(r); i = k;
    }
  }
  const allowed = svg.querySelector("#allowed");
  allowed ? allowed.after(g) : svg.append(g);
}
$("gear-write").onclick = () => {
  if (!state.pick) return;
  const r = JSON.parse(tmm.gear_write($("editor").value, state.pick[0], state.pick[1]));
  if (r.ok) setEditor(r.text);
};

// ---------- planetary ----------
function showPlanetary() {
  const p = state.reply.report.planetary;
  if (why("planetary", p ? null : W("no_planetary"))) return;
  const best = JSON.stringify(p.best && p.best.z);
  let h = `<tr><th>${W("z")}</th><th>${W("ratio")}</th><th>${W("ratio_error")}</th><th>${W("radial_modules")}</th><th>${W("assembly_positions")}</th><th>${W("equal_spacing")}</th></tr>`;
  for (const c of p.candidates) h += `<tr class="${JSON.stringify(c.z) === best ? "best" : ""}"><td>${c.z.join(", ")}</td><td class="num">${fmt(c.ratio)}</td><td class="num">${fmt(c.error)}</td><td class="num">${fmt(c.radial_size)}</td><td class="num">${c.assembly_positions}</td><td>${W(c.equal_spacing ? "yes" : "no")}</td></tr>`;
  $("planetary-table").innerHTML = h;
  fill("planetary-drawings", files("planetary/").map((f) => [f, tmm.file_text(f)]));
}

// ---------- cam: animation and diagrams ----------
function showCam() {
  const c = state.reply.report.cam;
  if (why("cam", c ? null : W("no_cam"))) { state.camPlaying = false; return; }
  fill("cam-drawings", files("cam/").map((f) => [f, tmm.file_text(f)]));
  $("cam-slider").max = c.phi.length - 1;
  sizeCanvas($("cam-canvas"), 0.9, 600);
  drawCam();
}
// The cam turned to the angle φ_i and the follower where the profile puts
// it. The report gives the pitch point (the roller's centre, the flat
// face's point on the follower's axis, or an oscillating flat face's contact
// point) in the cam's own frame: turning the cam by φ (its sense of
// rotation) brings it to the follower in the frame of the machine.
function drawCam() {
  const c = state.reply && state.reply.report.cam, cv = $("cam-canvas"), g = cv.getContext("2d");
  g.clearRect(0, 0, cv.width, cv.height);
  if (!c) return;
  const i = ((state.camIndex % c.phi.length) + c.phi.length) % c.phi.length;
  $("cam-slider").value = i;
  const sg = c.rotation === "cw" ? -1 : 1, rot = sg * c.phi[i];
  const R = (x, y) => [x * Math.cos(rot) - y * Math.sin(rot), x * Math.sin(rot) + y * Math.cos(rot)];
  const follower = String(c.follower), osc = follower.startsWith("oscillating");
  // the box: the cam turning (a disc of its largest radius), the pitch
  // points' circle, the pivot with the arm or face around it, the stem
  let ext = 0;
  c.working_x.forEach((x, k) => (ext = Math.max(ext, Math.hypot(x, c.working_y[k]))));
  c.pitch_x.forEach((x, k) => (ext = Math.max(ext, Math.hypot(x, c.pitch_y[k]) + (c.roller_radius || 0))));
  let [x0, x1, y0, y1] = [-ext, ext, -ext, ext];
  const top = ext * 1.35;
  if (osc && c.pivot) {
    const reach = Math.max(c.arm || 0, (c.face_contact_max || 0) + (c.face_margin || 0)) + (c.roller_radius || 0);
    x0 = Math.min(x0, c.pivot[0] - reach); x1 = Math.max(x1, c.pivot[0] + reach);
    y0 = Math.min(y0, c.pivot[1] - reach); y1 = Math.max(y1, c.pivot[1] + reach);
  } else y1 = Math.max(y1, top);
  const pad = 12 * (window.devicePixelRatio || 1);
  const sc = Math.min((cv.width - 2 * pad) / (x1 - x0), (cv.height - 2 * pad) / (y1 - y0));
  const cx = (cv.width - sc * (x1 - x0)) / 2 - sc * x0, cy = (cv.height + sc * (y1 - y0)) / 2 + sc * y0;
  const to = ([x, y]) => [cx + sc * x, cy - sc * y];
  const dpr = window.devicePixelRatio || 1;
  g.beginPath(); c.working_x.forEach((x, k) => { const [u, v] = to(R(x, c.working_y[k])); k ? g.lineTo(u, v) : g.moveTo(u, v); });
  g.closePath(); g.fillStyle = "#dfe8f5"; g.fill(); g.strokeStyle = "#1f4e9c"; g.lineWidth = 2 * dpr; g.stroke();
  g.beginPath(); g.arc(cx, cy, 4 * dpr, 0, 2 * Math.PI); g.fillStyle = "#000"; g.fill();
  const P = R(c.pitch_x[i], c.pitch_y[i]), [pu, pv] = to(P);
  g.strokeStyle = "#000"; g.lineWidth = 3 * dpr; g.lineCap = "round";
  const line = (a, b) => { const [u1, v1] = to(a), [u2, v2] = to(b); g.beginPath(); g.moveTo(u1, v1); g.lineTo(u2, v2); g.stroke(); };
  if (follower === "translating-flat") {
    const m = c.face_margin || 0;
    line([P[0] + (c.face_contact_min ?? -0.5 * c.face_width) - m, P[1]], [P[0] + (c.face_contact_max ?? 0.5 * c.face_width) + m, P[1]]);
    line(P, [P[0], top]);
  } else if (follower.startsWith("translating")) {
    line(P, [P[0], top]);
    g.lineWidth = 1.5 * dpr; g.beginPath(); g.arc(pu, pv, Math.max(2, sc * (c.roller_radius || 0)), 0, 2 * Math.PI); g.fillStyle = "#fff"; g.fill(); g.stroke();
  } else if (follower === "oscillating-roller") {
    line(c.pivot, P);
    g.lineWidth = 1.5 * dpr; g.beginPath(); g.arc(pu, pv, Math.max(2, sc * (c.roller_radius || 0)), 0, 2 * Math.PI); g.fillStyle = "#fff"; g.fill(); g.stroke();
  } else {
    // oscillating flat: the face from the pivot through the contact point
    const dx = P[0] - c.pivot[0], dy = P[1] - c.pivot[1], L = Math.hypot(dx, dy) || 1, len = (c.face_contact_max ?? L) + (c.face_margin || 0);
    line(c.pivot, [c.pivot[0] + (dx / L) * len, c.pivot[1] + (dy / L) * len]);
  }
  if (c.pivot) { const [au, av] = to(c.pivot); g.lineWidth = 1.5 * dpr; g.beginPath(); g.arc(au, av, 5 * dpr, 0, 2 * Math.PI); g.fillStyle = "#fff"; g.fill(); g.stroke(); }
  const phiDeg = ((c.phi[i] * 180) / Math.PI).toFixed(1);
  $("cam-angle").textContent = osc ? W("cam_oscillating", phiDeg, ((c.s[i] * 180) / Math.PI).toFixed(2)) : W("cam_translating", phiDeg, (c.s[i] * 1000).toFixed(2));
  $("cam-angle").dataset.index = i;
}
function camLoop() { if (!state.camPlaying) return; state.camIndex += 2; drawCam(); requestAnimationFrame(camLoop); }
$("cam-play").onclick = () => { state.camPlaying = !state.camPlaying; $("cam-play").textContent = W(state.camPlaying ? "pause" : "play"); if (state.camPlaying) requestAnimationFrame(camLoop); };
$("cam-slider").addEventListener("input", () => { state.camIndex = +$("cam-slider").value; drawCam(); });

// ---------- tabs (arrow keys move between them) ----------
function selectTab(b, focus) {
  document.querySelectorAll("#tabs button").forEach((x) => { x.classList.remove("active"); x.setAttribute("aria-selected", "false"); x.tabIndex = -1; });
  document.querySelectorAll(".view").forEach((x) => x.classList.remove("active"));
  b.classList.add("active"); b.setAttribute("aria-selected", "true"); b.tabIndex = 0;
  if (focus) b.focus();
  $("view-" + b.dataset.view).classList.add("active");
  render(b.dataset.view);
  if (b.dataset.view === "diagrams" && state.frames) moveCursors(cursorPsi());
}
const tabs = [...document.querySelectorAll("#tabs button")];
tabs.forEach((b, k) => {
  b.onclick = () => selectTab(b);
  b.onkeydown = (e) => {
    const to = { ArrowRight: k + 1, ArrowLeft: k - 1, Home: 0, End: tabs.length - 1 }[e.key];
    if (to !== undefined) { e.preventDefault(); selectTab(tabs[(to + tabs.length) % tabs.length], true); }
  };
});

// ---------- start ----------
// The module is fetched with a progress bar (a slow link takes seconds);
// the editor takes typing meanwhile, and what was typed is kept.
async function loadModule() {
  const url = new URL("tmm_web_bg.wasm", import.meta.url);
  const res = await fetch(url);
  const total = +res.headers.get("content-length") || 0;
  if (!res.body || !total) return init({ module_or_path: res });
  const reader = res.body.getReader(), chunks = []; let got = 0;
  for (;;) {
    const { done, value } = await reader.read();
    if (done) break;
    chunks.push(value); got += value.length;
    $("loading-bar").value = got / total;
    $("loading-bytes").textContent = `${(got / 1e6).toFixed(1)} / ${(total / 1e6).toFixed(1)} MB`;
  }
  const bytes = new Uint8Array(got); let o = 0; for (const c of chunks) { bytes.set(c, o); o += c.length; }
  return init({ module_or_path: bytes });
}
async function main() {
  const params = hashParams();
  if (["ru", "uk", "en"].includes(params.get("lang"))) $("lang").value = params.get("lang");
  $("editor").addEventListener("input", () => {
    gutter(0); undoButtons();
    if (!state.ready) return;
    clearTimeout(recordTimer); recordTimer = setTimeout(() => { record(); undoButtons(); }, 600);
    keepTask($("editor").value);
    scheduleAnalyse();
  });
  $("editor").addEventListener("scroll", () => ($("gutter").scrollTop = $("editor").scrollTop));
  $("editor").addEventListener("keydown", (e) => {
    const k = e.key.toLowerCase();
    if ((e.ctrlKey || e.metaKey) && (k === "z" || k === "y")) { e.preventDefault(); (k === "y" || e.shiftKey ? redo : undo)(); }
  });
  await loadModule();
  $("loading").hidden = true;
  window.tmmWords = (l) => tmm.words(l); // read by the browser test
  const examples = JSON.parse(tmm.examples());
  const sel = $("task-select");
  sel.add(new Option("default course project", ""));
  for (const e of examples) sel.add(new Option(e.name, e.name));
  let shownExample = "";
  sel.onchange = () => {
    const e = examples.find((x) => x.name === sel.value);
    const edited = $("editor").value !== state.original;
    if (edited && !confirm(W("replace_confirm", e ? e.name : W("default_task")))) { sel.value = shownExample; return; }
    shownExample = sel.value;
    state.name = e ? e.name : "task.toml";
    setEditor(e ? e.text : tmm.default_task(), { original: e ? e.text : tmm.default_task() });
  };
  $("lang").onchange = () => { keepLang(); state.wordsLang = null; analyse(); };
  $("save").onclick = () => download(state.name, $("editor").value, "text/plain");
  $("load-btn").onclick = () => $("load").click();
  $("load").onchange = async (e) => { const f = e.target.files[0]; if (!f) return; state.name = f.name; const t = await f.text(); setEditor(t, { original: t }); e.target.value = ""; };
  $("undo").onclick = undo; $("redo").onclick = redo;
  // the text: typed while loading, else the link's, else the one kept in
  // the browser, else the default task
  const typed = $("editor").value;
  let kept = null;
  try { kept = JSON.parse(localStorage.getItem("tmm-task") || "null"); } catch { kept = null; }
  let text, note = "";
  if (typed.trim()) { text = typed; state.original = ""; }
  else if (params.get("task")) { text = await unpackTask(params.get("task")).catch(() => tmm.default_task()); state.original = text; }
  else if (kept && typeof kept.text === "string") { text = kept.text; state.name = kept.name || "task.toml"; state.original = kept.original ?? kept.text; note = "restored"; }
  else { text = tmm.default_task(); state.original = text; }
  $("editor").value = text;
  record(text);
  state.ready = true;
  analyse();
  if (note && state.reply) $("status").textContent += " · " + W(note);
  document.body.dataset.ready = "1";
}
main();
