// The PDF worker: loads the page's second module (tmm_web_pdf, the
// typesetter and its fonts) on the first request only and typesets the
// note and the sheets off the page's thread, so the page stays usable.
// With the module it fetches, once, the drawings' GOST lettering font
// osifont (`osifont.ttf`, served unaltered beside the module under its own
// licence, never linked into it) and gives its bytes to the typesetter;
// without it the PDFs' drawings use the module's fallback faces.
// Message in: { name, text, lang }; out: { ok, files: [{ path, bytes }],
// font } or { ok: false, message }, where font is "osifont", "absent"
// (not served) or "refused" (served, but no osifont the typesetter reads).
let ready = null;
self.onmessage = async (e) => {
  const { name, text, lang } = e.data;
  try {
    ready ??= Promise.all([
      import("./tmm_web_pdf.js").then(async (m) => { await m.default(); return m; }),
      fetch("osifont.ttf").then((r) => (r.ok ? r.arrayBuffer() : null), () => null),
    ]).then(([m, font]) => {
      let fontState = "absent";
      if (font) {
        try {
          m.use_gost_font(new Uint8Array(font));
          fontState = "osifont";
        } catch (err) {
          fontState = "refused";
          console.warn(typeof err === "string" ? err : String(err && err.message || err));
        }
      }
      return { m, fontState };
    });
    const { m, fontState } = await ready;
    const pdfs = m.typeset(name, text, lang);
    const names = pdfs.names();
    const files = names.map((path, i) => ({ path, bytes: pdfs.bytes(i) }));
    pdfs.free();
    self.postMessage({ ok: true, files, font: fontState }, files.map((f) => f.bytes.buffer));
  } catch (err) {
    self.postMessage({ ok: false, message: typeof err === "string" ? err : String(err && err.message || err) });
  }
};
