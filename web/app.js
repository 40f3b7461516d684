// The page: an editor for the task, the views and the downloads. All the
// mechanics runs in tmm_web.wasm (the same Rust code as the `tmm` command);
// this file only moves text between the editor, the WebAssembly module and
// the page. No dependencies.
import init, * as tmm from "./tmm_web.js";

const $ = (id) => document.getElementById(id);
const state = { reply: null, frames: null, frame: 0, playing: false, camPlaying: false, camIndex: 0, timings: [], name: "task.toml" };
window.tmmPage = state; // read by the browser test

// Key numbers: [label, path in report.json, unit]
const KEYS = [
  ["crank OA (synthesis)", "synthesis.lengths.OA", "m"],
  ["coefficient of speed change Kv", "linkage.kv", ""],
  ["output stroke", "linkage.stroke", "rad or m"],
  ["overlap angle θ", "linkage.theta", "rad"],
  ["max relative difference, force methods", "forces.max_relative_difference", ""],
  ["flywheel inertia", "dynamics.flywheel_inertia", "kg·m²"],
  ["shift x1", "gear.x1", ""],
  ["shift x2", "gear.x2", ""],
  ["centre distance aw", "gear.aw", "m"],
  ["contact ratio εα", "gear.eps_alpha", ""],
  ["planetary ratio (best)", "planetary.best.ratio", ""],
  ["cam base radius r0", "cam.r0", "m"],
];
const get = (obj, path) => path.split(".").reduce((o, k) => (o == null ? undefined : o[k]), obj);
const fmt = (x) => (typeof x === "number" ? (Math.abs(x) >= 1e-3 || x === 0 ? +x.toPrecision(6) + "" : x.toExponential(5)) : String(x));

// ---------- the task in the URL ----------
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
let urlTimer = 0;
function keepInUrl(text) {
  clearTimeout(urlTimer);
  urlTimer = setTimeout(async () => history.replaceState(null, "", "#task=" + (await packTask(text))), 300);
}

// ---------- the editor ----------
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
  box.textContent = e.message + (e.help ? "\nhelp: " + e.help : "");
  gutter(e.line || 0);
}

// ---------- analysis ----------
function analyse() {
  const text = $("editor").value;
  keepInUrl(text);
  const t0 = performance.now();
  const out = tmm.analyse(state.name, text, $("lang").value);
  const t1 = performance.now();
  const r = JSON.parse(out);
  state.timings.push(t1 - t0);
  $("status").textContent = `analysed in ${(t1 - t0).toFixed(0)} ms`;
  if (!r.ok) { showError(r.error); $("status").classList.add("bad"); return; }
  $("status").classList.remove("bad");
  showError(null);
  state.reply = r;
  state.lists = {};
  state.frames = JSON.parse(tmm.frames(360));
  if (!state.frames.ok) state.frames = null;
  // every view is drawn anew when it is next shown; the shown one now
  state.dirty = new Set(Object.keys(VIEWS));
  render(activeView());
}
// The views, each drawn only when shown after a new analysis (a section's
// drawings are made by the module only when a view or a download asks).
const VIEWS = {
  numbers: () => showNumbers(state.reply),
  mechanism: () => setAngleIndex(+$("angle").value),
  diagrams: () => showDiagrams(),
  gear: () => showGear(),
  planetary: () => showPlanetary(),
  cam: () => showCam(),
  files: () => showFiles(),
};
state.dirty = new Set();
const activeView = () => document.querySelector("#tabs button.active").dataset.view;
function render(view) {
  if (!state.reply || !state.dirty.has(view)) return;
  state.dirty.delete(view);
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
  let h = "<tr><th>quantity</th><th>value</th><th>unit</th></tr>";
  for (const [label, path, unit] of KEYS) {
    const v = get(r.report, path);
    if (typeof v !== "number") continue;
    h += `<tr><td>${label}</td><td class="num" data-key="${path}" data-value="${v}">${fmt(v)}</td><td>${unit}</td></tr>`;
  }
  $("key-numbers").innerHTML = h;
  $("texts").innerHTML = r.sections.map((s) => `<h3>${s.section}</h3><pre class="section-text"></pre>`).join("");
  $("texts").querySelectorAll("pre").forEach((p, i) => (p.textContent = r.sections[i].text));
}

function drawing(title, svg) {
  const d = document.createElement("div");
  d.className = "drawing";
  d.innerHTML = `<h3></h3>` + (svg || "").replace(/^<\?xml[^>]*>\s*/, "");
  d.querySelector("h3").textContent = title;
  return d;
}
function fill(id, items) {
  const el = $(id); el.replaceChildren(...items.map(([t, s]) => drawing(t, s)));
}
// The files of one section of the last run ("report" for report.json),
// asked for once per analysis: the module makes the section's drawings then.
function sectionFiles(section) {
  if (!state.reply) return [];
  if (!(section in state.lists)) {
    const l = JSON.parse(tmm.files(section));
    if (!l.ok) { $("status").textContent = l.error.message; $("status").classList.add("bad"); }
    state.lists[section] = l.ok ? l.files : [];
  }
  return state.lists[section];
}
const files = (prefix, ext = ".svg") => sectionFiles(prefix.split("/")[0]).map((f) => f.path).filter((p) => p.startsWith(prefix) && p.endsWith(ext));

// ---------- downloads ----------
function download(name, bytes, type) {
  const a = document.createElement("a");
  a.href = URL.createObjectURL(new Blob([bytes], { type }));
  a.download = name; a.click();
  setTimeout(() => URL.revokeObjectURL(a.href), 1000);
}
function showFiles() {
  const ul = $("file-list"); ul.replaceChildren();
  const add = (label, fn) => { const li = document.createElement("li"); const b = document.createElement("a"); b.href = "#"; b.textContent = label; b.onclick = (e) => { e.preventDefault(); fn(); }; li.append(b); ul.append(li); };
  add("task.toml (the task in the editor)", () => download(state.name, $("editor").value, "text/plain"));
  const all = ["report", ...state.reply.sections.map((s) => s.section), "sheets"].flatMap(sectionFiles);
  for (const f of all) add(`${f.path} (${(f.size / 1024).toFixed(1)} KB)`, () => download(f.path.replace(/\//g, "-"), tmm.file_bytes(f.path), "application/octet-stream"));
}

// ---------- mechanism: animation, slider, dragging, plans at the angle ----------
function setAngleIndex(i) {
  const F = state.frames;
  $("angle").value = i;
  if (!F) { $("angle-out").textContent = "no [linkage]"; return; }
  state.frame = ((i % F.phi.length) + F.phi.length) % F.phi.length;
  const phi = F.phi[state.frame];
  $("angle-out").textContent = `φ = ${(phi * 180 / Math.PI).toFixed(1)}°`;
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
  if (!a.ok) return;
  fill("plans", [["Velocity plan", a.velocity_plan], ["Acceleration plan", a.acceleration_plan]]);
  if (a.forces) {
    fill("force-plans", Object.entries(a.forces.files));
    $("torque").textContent = `Mb = ${fmt(a.forces.balancing_moment)} N·m (Zhukovsky: ${fmt(a.forces.zhukovsky_moment)} N·m)`;
  } else { $("force-plans").replaceChildren(); $("torque").textContent = ""; }
  moveCursors(a.psi);
}
// The velocity and acceleration plans of a frame of the animation on two
// canvases: each vector from its start to its end, the pole p (π) at the
// origin, the points' images named; the scale fits each plan to its box.
function drawPlans(a) {
  let cs = [...document.querySelectorAll("#plans canvas")];
  if (cs.length !== 2) {
    fill("plans", [["Velocity plan", ""], ["Acceleration plan", ""]]);
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
  const F = state.frames, c = $("mech");
  let x0 = Infinity, x1 = -Infinity, y0 = Infinity, y1 = -Infinity;
  for (const fr of F.xy) for (const [x, y] of fr) { x0 = Math.min(x0, x); x1 = Math.max(x1, x); y0 = Math.min(y0, y); y1 = Math.max(y1, y); }
  const s = Math.min((c.width - 40) / (x1 - x0 || 1), (c.height - 40) / (y1 - y0 || 1));
  const ox = (c.width - s * (x1 - x0)) / 2 - s * x0, oy = (c.height + s * (y1 - y0)) / 2 + s * y0;
  return { s, to: ([x, y]) => [ox + s * x, oy - s * y], from: (u, v) => [(u - ox) / s, (oy - v) / s] };
}
// The scale and the traced paths of every point, drawn once per set of
// frames onto a canvas of their own; a frame copies it and draws the links.
function mechBackground() {
  const F = state.frames, c = $("mech");
  if (state.bg && state.bg.frames === F && state.bg.canvas.width === c.width && state.bg.canvas.height === c.height) return state.bg;
  const T = mechTransform();
  const canvas = document.createElement("canvas"); canvas.width = c.width; canvas.height = c.height;
  const g = canvas.getContext("2d");
  g.lineWidth = 1;
  F.names.forEach((_, j) => {
    g.strokeStyle = `hsl(${(j * 67) % 360} 60% 60%)`;
    g.beginPath();
    F.xy.forEach((fr, k) => { const [u, v] = T.to(fr[j]); k ? g.lineTo(u, v) : g.moveTo(u, v); });
    g.closePath(); g.stroke();
  });
  // the frame's pivots: the points that do not move over the cycle
  const half = F.xy[Math.floor(F.xy.length / 2)];
  const quarter = F.xy[Math.floor(F.xy.length / 4)];
  const still = (a, b, j) => Math.hypot(a[j][0] - b[j][0], a[j][1] - b[j][1]) <= 1e-9;
  const fixed = F.names.map((_, j) => still(F.xy[0], half, j) && still(F.xy[0], quarter, j));
  state.bg = { frames: F, canvas, T, fixed };
  return state.bg;
}
function drawMechanism() {
  const F = state.frames, c = $("mech"), g = c.getContext("2d");
  g.clearRect(0, 0, c.width, c.height);
  if (!F) return;
  const bg = mechBackground(), T = bg.T; state.T = T;
  g.drawImage(bg.canvas, 0, 0);
  const fr = F.xy[state.frame];
  g.strokeStyle = "#1f4e9c"; g.lineWidth = 4; g.lineCap = "round";
  for (const [a, b] of F.segments) { const [u1, v1] = T.to(fr[a]), [u2, v2] = T.to(fr[b]); g.beginPath(); g.moveTo(u1, v1); g.lineTo(u2, v2); g.stroke(); }
  g.font = "13px sans-serif"; g.fillStyle = "#000";
  F.names.forEach((n, j) => {
    const [u, v] = T.to(fr[j]);
    g.beginPath(); g.arc(u, v, 4, 0, 2 * Math.PI); g.fillStyle = "#fff"; g.fill(); g.lineWidth = 1.5; g.strokeStyle = "#000"; g.stroke();
    g.fillStyle = "#000"; g.fillText(n, u + 6, v - 6);
  });
  F.names.forEach((_, j) => {
    if (!bg.fixed[j]) return;
    const [pu, pv] = T.to(fr[j]);
    g.beginPath(); g.moveTo(pu, pv + 4); g.lineTo(pu - 8, pv + 14); g.lineTo(pu + 8, pv + 14); g.closePath(); g.stroke();
    g.beginPath(); g.moveTo(pu - 12, pv + 14); g.lineTo(pu + 12, pv + 14); g.stroke();
  });
}
function nearestFrame(phi) {
  const F = state.frames; let best = 0, bd = Infinity;
  F.phi.forEach((p, k) => { const d = Math.abs(Math.atan2(Math.sin(p - phi), Math.cos(p - phi))); if (d < bd) { bd = d; best = k; } });
  return best;
}
let dragging = false;
$("mech").addEventListener("pointerdown", (e) => {
  if (!state.frames) return;
  const fr = state.frames.xy[state.frame], [u, v] = state.T.to(fr[state.frames.pin]);
  const r = $("mech").getBoundingClientRect(), k = $("mech").width / r.width;
  if (Math.hypot((e.clientX - r.left) * k - u, (e.clientY - r.top) * k - v) < 20) { dragging = true; $("mech").setPointerCapture(e.pointerId); }
});
$("mech").addEventListener("pointermove", (e) => {
  if (!dragging) return;
  const r = $("mech").getBoundingClientRect(), k = $("mech").width / r.width;
  const [x, y] = state.T.from((e.clientX - r.left) * k, (e.clientY - r.top) * k);
  const pv = state.frames.xy[0][state.frames.pivot];
  setAngleIndex(nearestFrame(Math.atan2(y - pv[1], x - pv[0])));
});
$("mech").addEventListener("pointerup", () => (dragging = false));
$("angle").addEventListener("input", () => setAngleIndex(+$("angle").value));
function playLoop() {
  if (!state.playing || !state.frames) return;
  state.fpsFrames = (state.fpsFrames || 0) + 1;
  setAngleIndex(state.frame + 1);
  requestAnimationFrame(playLoop);
}
$("play").onclick = () => {
  state.playing = !state.playing;
  $("play").textContent = state.playing ? "❚❚ Pause" : "▶ Play";
  if (state.playing) { $("torque").textContent = ""; $("force-plans").replaceChildren(); requestAnimationFrame(playLoop); }
  else setAngleIndex(state.frame);
};

// ---------- diagrams with a cursor ----------
function showDiagrams() {
  fill("diagrams", [...files("linkage/diagram-"), ...files("dynamics/")].map((p) => [p, tmm.file_text(p)]));
  moveCursors(state.frames ? cursorPsi() : null);
}
function cursorPsi() {
  const F = state.frames; const p = F.phi[state.frame];
  return (((F.direction * (p - F.start)) % (2 * Math.PI)) + 2 * Math.PI) % (2 * Math.PI);
}
// The diagrams run over one revolution: the longest curve (polyline or
// path) spans ψ = 0…2π.
function moveCursors(psi) {
  document.querySelectorAll("#diagrams svg").forEach((svg) => {
    svg.querySelector(".cursor")?.remove();
    if (psi == null) return;
    let best = null, bl = 0;
    svg.querySelectorAll("polyline, path").forEach((pl) => { const n = (pl.getAttribute("points") || pl.getAttribute("d") || "").length; if (n > bl) { bl = n; best = pl; } });
    if (!best) return;
    const bb = best.getBBox();
    const x = bb.x + bb.width * psi / (2 * Math.PI);
    const vb = svg.viewBox.baseVal;
    const l = document.createElementNS("http://www.w3.org/2000/svg", "line");
    l.setAttribute("class", "cursor"); l.setAttribute("x1", x); l.setAttribute("x2", x);
    l.setAttribute("y1", vb.y); l.setAttribute("y2", vb.y + vb.height);
    l.setAttribute("stroke", "#e67e00"); l.setAttribute("stroke-width", 0.5);
    svg.append(l);
  });
}

// ---------- gear: the contour picks (x1, x2) ----------
function gearNumbers(g, err) {
  if (err) { $("gear-numbers").innerHTML = `<p class="bad"></p>`; $("gear-numbers").firstChild.textContent = err; return; }
  const rows = [["x1", g.x1], ["x2", g.x2], ["aw, m", g.aw], ["αw, rad", g.alpha_w], ["εα", g.eps_alpha], ["sa1, m", g.sa1], ["sa2, m", g.sa2], ["all checks pass", g.all_checks_pass]];
  $("gear-numbers").innerHTML = "<table>" + rows.map(([k, v]) => `<tr><td>${k}</td><td class="num" data-gear="${k.split(",")[0]}" data-value="${v}">${fmt(v)}</td></tr>`).join("") + "</table>";
}
function showGear(svgs) {
  const has = state.reply && state.reply.report.gear;
  if (!has) { $("contour").replaceChildren(); $("gear-drawings").replaceChildren(); $("gear-numbers").textContent = "no [gear] in the task"; return; }
  const text = (p) => (svgs ? svgs[p] : tmm.file_text(p));
  if (!svgs) gearNumbers(state.reply.report.gear);
  if (!svgs) state.contourAxes = null; // a new task: its contour is computed on the first click
  $("contour").replaceChildren(drawing("gear/contour.svg", text("gear/contour.svg")));
  fill("gear-drawings", ["gear/mesh.svg", "gear/sliding.svg", "gear/profiles.svg"].map((p) => [p, text(p)]));
  const svg = $("contour").querySelector("svg");
  svg.style.cursor = "crosshair";
  svg.addEventListener("click", (e) => {
    const A = (state.contourAxes ??= JSON.parse(tmm.gear_contour())); if (!A.ok) return;
    const pt = new DOMPoint(e.clientX, e.clientY).matrixTransform(svg.getScreenCTM().inverse());
    const x1 = (pt.x - A.origin[0]) / A.scale, x2 = (A.origin[1] - pt.y) / A.scale;
    const r = JSON.parse(tmm.gear_at(+x1.toFixed(3), +x2.toFixed(3)));
    if (r.ok) { gearNumbers(r.gear); showGear(r.files); }
    else gearNumbers(null, `x1 = ${x1.toFixed(3)}, x2 = ${x2.toFixed(3)}: ${r.error.message}${r.error.help ? " — " + r.error.help : ""}`);
  });
}

// ---------- planetary ----------
function showPlanetary() {
  const p = state.reply && state.reply.report.planetary;
  if (!p) { $("planetary-table").innerHTML = "<tr><td>no [planetary] in the task</td></tr>"; $("planetary-drawings").replaceChildren(); return; }
  const best = JSON.stringify(p.best && p.best.z);
  let h = "<tr><th>z</th><th>ratio</th><th>error</th><th>radial size, m</th><th>assembly positions</th><th>equal spacing</th></tr>";
  for (const c of p.candidates) h += `<tr class="${JSON.stringify(c.z) === best ? "best" : ""}"><td>${c.z.join(", ")}</td><td class="num">${fmt(c.ratio)}</td><td class="num">${fmt(c.error)}</td><td class="num">${fmt(c.radial_size)}</td><td class="num">${c.assembly_positions}</td><td>${c.equal_spacing}</td></tr>`;
  $("planetary-table").innerHTML = h;
  fill("planetary-drawings", files("planetary/").map((f) => [f, tmm.file_text(f)]));
}

// ---------- cam: animation and diagrams ----------
function showCam() {
  const c = state.reply && state.reply.report.cam;
  fill("cam-drawings", files("cam/").map((f) => [f, tmm.file_text(f)]));
  drawCam();
  if (!c) $("cam-angle").textContent = "no [cam] in the task";
}
function drawCam() {
  const c = state.reply && state.reply.report.cam, cv = $("cam-canvas"), g = cv.getContext("2d");
  g.clearRect(0, 0, cv.width, cv.height);
  if (!c) return;
  const i = state.camIndex % c.phi.length;
  const R = Math.max(...c.working_x.map((x, k) => Math.hypot(x, c.working_y[k]))) + (c.roller_radius || 0) + c.stroke;
  const s = (cv.width / 2 - 20) / (R * 1.2), cx = cv.width / 2, cy = cv.height / 2 + R * 0.2 * s;
  // turn the cam so that its pitch point of this angle sits on the follower
  const px = c.pitch_x[i], py = c.pitch_y[i];
  const target = Math.atan2(c.s0 + c.s[i], c.e || 0), rot = target - Math.atan2(py, px);
  const to = (x, y) => [cx + s * (x * Math.cos(rot) - y * Math.sin(rot)), cy - s * (x * Math.sin(rot) + y * Math.cos(rot))];
  g.beginPath(); c.working_x.forEach((x, k) => { const [u, v] = to(x, c.working_y[k]); k ? g.lineTo(u, v) : g.moveTo(u, v); });
  g.closePath(); g.fillStyle = "#dfe8f5"; g.fill(); g.strokeStyle = "#1f4e9c"; g.lineWidth = 2; g.stroke();
  const [ru, rv] = to(px, py);
  g.strokeStyle = "#000"; g.beginPath(); g.arc(ru, rv, Math.max(2, s * (c.roller_radius || 0)), 0, 2 * Math.PI); g.stroke();
  if (String(c.follower).startsWith("translating")) { g.beginPath(); g.moveTo(ru, rv); g.lineTo(ru, 10); g.lineWidth = 4; g.stroke(); }
  g.beginPath(); g.arc(cx, cy, 4, 0, 2 * Math.PI); g.fillStyle = "#000"; g.fill();
  $("cam-angle").textContent = `φ = ${(c.phi[i] * 180 / Math.PI).toFixed(1)}°, s = ${(c.s[i] * 1000).toFixed(2)} mm`;
}
function camLoop() { if (!state.camPlaying) return; state.camIndex += 2; drawCam(); requestAnimationFrame(camLoop); }
$("cam-play").onclick = () => { state.camPlaying = !state.camPlaying; $("cam-play").textContent = state.camPlaying ? "❚❚ Pause" : "▶ Play"; if (state.camPlaying) requestAnimationFrame(camLoop); };

// ---------- start ----------
document.querySelectorAll("#tabs button").forEach((b) => (b.onclick = () => {
  document.querySelectorAll("#tabs button, .view").forEach((x) => x.classList.remove("active"));
  b.classList.add("active"); $("view-" + b.dataset.view).classList.add("active");
  render(b.dataset.view);
  if (b.dataset.view === "diagrams" && state.frames) moveCursors(cursorPsi());
}));
async function main() {
  await init();
  const examples = JSON.parse(tmm.examples());
  const sel = $("task-select");
  sel.add(new Option("default course project", ""));
  for (const e of examples) sel.add(new Option(e.name, e.name));
  sel.onchange = () => {
    const e = examples.find((x) => x.name === sel.value);
    state.name = e ? e.name : "task.toml";
    $("editor").value = e ? e.text : tmm.default_task();
    analyse();
  };
  const m = location.hash.match(/task=([A-Za-z0-9_-]+)/);
  $("editor").value = m ? await unpackTask(m[1]).catch(() => tmm.default_task()) : tmm.default_task();
  $("editor").addEventListener("input", () => { gutter(0); scheduleAnalyse(); });
  $("editor").addEventListener("scroll", () => ($("gutter").scrollTop = $("editor").scrollTop));
  $("lang").onchange = analyse;
  $("save").onclick = () => download(state.name, $("editor").value, "text/plain");
  $("load").onchange = async (e) => { const f = e.target.files[0]; if (!f) return; state.name = f.name; $("editor").value = await f.text(); analyse(); };
  analyse();
  state.ready = true;
  document.body.dataset.ready = "1";
}
main();
