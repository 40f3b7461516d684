// The PDF worker: loads the page's second module (tmm_web_pdf, the
// typesetter and its fonts) on the first request only and typesets the
// note and the sheets off the page's thread, so the page stays usable.
// Message in: { name, text, lang }; out: { ok, files: [{ path, bytes }] }
// or { ok: false, message }.
let ready = null;
self.onmessage = async (e) => {
  const { name, text, lang } = e.data;
  try {
    ready ??= import("./tmm_web_pdf.js").then(async (m) => { await m.default(); return m; });
    const m = await ready;
    const pdfs = m.typeset(name, text, lang);
    const names = pdfs.names();
    const files = names.map((path, i) => ({ path, bytes: pdfs.bytes(i) }));
    pdfs.free();
    self.postMessage({ ok: true, files }, files.map((f) => f.bytes.buffer));
  } catch (err) {
    self.postMessage({ ok: false, message: typeof err === "string" ? err : String(err && err.message || err) });
  }
};
