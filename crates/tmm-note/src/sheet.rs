//! A drawing sheet (лист графической части) as a one-page PDF: the page is
//! the SVG's own size (A1 841 × 594 mm, A2 594 × 420 mm …) and the SVG is
//! placed on it whole as a vector image, by the same linked typst compiler
//! and fonts as the note.

use crate::error::NoteError;
use crate::world::NoteWorld;

/// The largest sheet side accepted, mm (A0 × 4 is 4756 mm).
const MAX_SIDE_MM: f64 = 5000.0;

/// A length attribute of the root `<svg>` in mm: `841mm`, `84.1cm`, or a
/// bare number / `px` (CSS pixels, 96 per inch).
fn length_mm(text: &str) -> Option<f64> {
    let t = text.trim();
    let (num, factor) = if let Some(n) = t.strip_suffix("mm") {
        (n, 1.0)
    } else if let Some(n) = t.strip_suffix("cm") {
        (n, 10.0)
    } else if let Some(n) = t.strip_suffix("in") {
        (n, 25.4)
    } else if let Some(n) = t.strip_suffix("px") {
        (n, 25.4 / 96.0)
    } else {
        (t, 25.4 / 96.0)
    };
    num.trim().parse::<f64>().ok().map(|v| v * factor)
}

/// The value of attribute `name` in the root element's tag `tag`.
fn attribute<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let mut rest = tag;
    while let Some(i) = rest.find(name) {
        let before = rest[..i].chars().last();
        let after = &rest[i + name.len()..];
        if before.is_some_and(char::is_whitespace) {
            let after = after.trim_start();
            if let Some(a) = after.strip_prefix('=') {
                let a = a.trim_start();
                let q = a.chars().next()?;
                if q == '"' || q == '\'' {
                    let body = &a[1..];
                    return body.find(q).map(|end| &body[..end]);
                }
            }
        }
        rest = after;
    }
    None
}

/// The size of an SVG document in mm, from the root's `width` and `height`.
///
/// ```
/// let svg = r#"<?xml version="1.0"?><svg xmlns="http://www.w3.org/2000/svg" width="841mm" height="594mm" viewBox="0 0 841 594"/>"#;
/// assert_eq!(tmm_note::sheet::svg_size_mm(svg).unwrap(), (841.0, 594.0));
/// assert!(tmm_note::sheet::svg_size_mm("<svg/>").is_err());
/// ```
///
/// # Errors
/// [`NoteError::SheetSize`] if there is no `<svg` element, no width or
/// height, or a size outside 1 … 5000 mm.
pub fn svg_size_mm(svg: &str) -> Result<(f64, f64), NoteError> {
    let start = svg.find("<svg").ok_or_else(|| NoteError::SheetSize {
        what: "has no <svg> element".into(),
    })?;
    let tag = &svg[start..];
    let tag = &tag[..tag.find('>').unwrap_or(tag.len())];
    let side = |name: &str| -> Result<f64, NoteError> {
        let v = attribute(tag, name).ok_or_else(|| NoteError::SheetSize {
            what: format!("has no {name}"),
        })?;
        match length_mm(v) {
            Some(x) if x.is_finite() && (1.0..=MAX_SIDE_MM).contains(&x) => Ok(x),
            _ => Err(NoteError::SheetSize {
                what: format!("has {name}=\"{v}\""),
            }),
        }
    };
    Ok((side("width")?, side("height")?))
}

/// The language of a sheet: the root `<svg>`'s `xml:lang`, when it is an
/// ISO 639 code (two or three lowercase letters), so the PDF declares the
/// sheet's language (its `/Lang`), not typst's default English.
///
/// ```
/// use tmm_note::sheet::svg_lang;
/// assert_eq!(svg_lang(r#"<svg xml:lang="uk" width="1mm">"#), Some("uk"));
/// assert_eq!(svg_lang(r#"<svg width="1mm">"#), None);
/// assert_eq!(svg_lang(r#"<svg xml:lang="ru&quot;)">"#), None);
/// ```
pub fn svg_lang(svg: &str) -> Option<&str> {
    let start = svg.find("<svg")?;
    let tag = &svg[start..];
    let tag = &tag[..tag.find('>').unwrap_or(tag.len())];
    attribute(tag, "xml:lang").filter(|l| (2..=3).contains(&l.len()) && l.bytes().all(|b| b.is_ascii_lowercase()))
}

/// Typesets one sheet: a page of the SVG's own size with the SVG on it.
///
/// ```no_run
/// let svg = r#"<svg xmlns="http://www.w3.org/2000/svg" width="594mm" height="420mm" viewBox="0 0 594 420"><rect x="20" y="5" width="569" height="410" fill="none" stroke="black"/></svg>"#;
/// let pdf = tmm_note::sheet_pdf(svg).unwrap();
/// assert!(pdf.starts_with(b"%PDF"));
/// ```
///
/// # Errors
/// [`NoteError::SheetSize`] for an SVG without a usable size,
/// [`NoteError::Typst`] if typst cannot read the SVG, [`NoteError::Pdf`] if
/// the export fails.
pub fn sheet_pdf(svg: &str) -> Result<Vec<u8>, NoteError> {
    let (w, h) = svg_size_mm(svg)?;
    let lang = svg_lang(svg).map_or(String::new(), |l| format!(", lang: \"{l}\""));
    let main = format!(
        "#set page(width: {w}mm, height: {h}mm, margin: 0pt)\n#set text(font: \"New Computer Modern\"{lang})\n#image(\"/sheet.svg\", width: {w}mm, height: {h}mm)\n"
    );
    let world = NoteWorld::new(main, vec![("/sheet.svg".into(), svg.to_string())])?;
    let result = typst::compile::<typst_layout::PagedDocument>(&world);
    typst::comemo::evict(10);
    let document = result.output.map_err(|errors| NoteError::Typst {
        messages: errors.iter().map(|d| d.message.to_string()).collect(),
    })?;
    typst_pdf::pdf(&document, &typst_pdf::PdfOptions::default()).map_err(|errors| NoteError::Pdf {
        messages: errors.iter().map(|d| d.message.to_string()).collect(),
    })
}
