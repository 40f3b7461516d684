//! The drawings' lettering fonts: osifont (read from the machine) and tmm's
//! GOST supplement (linked in). Checked on the fonts themselves — every
//! letter of Russian and Ukrainian, the Greek, the digits and the signs the
//! drawings print has a real glyph (not osifont's filled boxes) in the face
//! the SVG sets it in, the supplement sits on osifont's metrics — and on
//! the default project's PDFs, whose font resources must name both faces
//! and, on the sheets, no other (a substitute face would mean a character
//! fell out of both).

use pdf_extract::{Document, Object};
use tmm_report::TaskSource;
use tmm_report::run::{DEFAULT_TASK, run_task};

/// Russian and Ukrainian, both cases.
const CYRILLIC: &str = "АБВГДЕЁЖЗИЙКЛМНОПРСТУФХЦЧШЩЪЫЬЭЮЯабвгдеёжзийклмнопрстуфхцчшщъыьэюяІіЇїЄєҐґ";
/// Greek, both cases, with the symbol forms the drawings use (ϑ).
const GREEK: &str = "ΑΒΓΔΕΖΗΘΙΚΛΜΝΞΟΠΡΣΤΥΦΧΨΩαβγδεζηθικλμνξοπρστυφχψωϑ";
/// Digits and Latin.
const LATIN: &str = "0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz";
/// The signs in the drawings' text (the default project, the examples'
/// sections): punctuation, operators, indices, units.
const SIGNS: &str = "()[]*+,-./:;=<>%«»°²³⁻·–—…′″₀№→−≈±×";

/// The outline of glyph `c` in `face`: contours and points (line and
/// curve ends), or `None` when the face has no glyph for it.
fn outline(face: &ttf_parser::Face<'_>, c: char) -> Option<(usize, usize)> {
    struct Count(usize, usize);
    impl ttf_parser::OutlineBuilder for Count {
        fn move_to(&mut self, _: f32, _: f32) {
            self.0 += 1;
            self.1 += 1;
        }
        fn line_to(&mut self, _: f32, _: f32) {
            self.1 += 1;
        }
        fn quad_to(&mut self, _: f32, _: f32, _: f32, _: f32) {
            self.1 += 2;
        }
        fn curve_to(&mut self, _: f32, _: f32, _: f32, _: f32, _: f32, _: f32) {
            self.1 += 3;
        }
        fn close(&mut self) {}
    }
    let id = face.glyph_index(c)?;
    let mut n = Count(0, 0);
    face.outline_glyph(id, &mut n);
    Some((n.0, n.1))
}

/// A filled box: one contour of four straight corners (the closing point
/// may repeat the first).
fn is_box(o: (usize, usize)) -> bool {
    o.0 == 1 && o.1 <= 5
}

fn osifont() -> Option<Vec<u8>> {
    let path = tmm_note::fonts::gost_font()?;
    Some(std::fs::read(path).expect("the found font reads"))
}

#[test]
fn every_letter_and_sign_has_a_real_glyph_in_its_face() {
    let sup = ttf_parser::Face::parse(tmm_note::fonts::SUPPLEMENT, 0).expect("the supplement parses");
    // the supplement draws every character the SVG sets in it, with real
    // strokes (each a round-ended outline: curves, many points)
    for c in tmm_draw::svg::SUPPLEMENT_CHARS.chars() {
        let o = outline(&sup, c).unwrap_or_else(|| panic!("{c} not in the supplement"));
        assert!(o.0 >= 1 && !is_box(o) && o.1 > 16, "{c}: {o:?}");
    }
    let Some(data) = osifont() else {
        eprintln!("skipped the osifont half: osifont is not installed (apt install fonts-osifont, or TMM_FONT_PATH)");
        return;
    };
    let osi = ttf_parser::Face::parse(&data, 0).expect("osifont parses");
    let mut boxed = Vec::new();
    for c in CYRILLIC.chars().chain(GREEK.chars()).chain(LATIN.chars()).chain(SIGNS.chars()) {
        let (face, name) = if tmm_draw::svg::in_supplement(c) {
            (&sup, "supplement")
        } else {
            (&osi, "osifont")
        };
        let o = outline(face, c).unwrap_or_else(|| panic!("{c} (U+{:04X}) has no glyph in {name}", c as u32));
        assert!(o.0 >= 1, "{c} is empty in {name}");
        // a letter or digit drawn as one 4-corner contour is a box; signs
        // such as the hyphen may be straight bars, but never one in osifont
        // that is a letter's box
        if c.is_alphanumeric() {
            assert!(!is_box(o), "{c} (U+{:04X}) is a box in {name}: {o:?}", c as u32);
        }
        if is_box(outline(&osi, c).unwrap_or((0, 0))) && c.is_alphanumeric() {
            boxed.push(c);
        }
    }
    // what the supplement is for: the boxes found in osifont are set in it
    assert!(boxed.iter().all(|&c| tmm_draw::svg::in_supplement(c)), "{boxed:?}");
    eprintln!("osifont's boxes, set in the supplement: {}", boxed.iter().collect::<String>());
}

#[test]
fn the_supplement_sits_on_osifonts_metrics() {
    let sup = ttf_parser::Face::parse(tmm_note::fonts::SUPPLEMENT, 0).unwrap();
    // GOST 2.304 type B on osifont's em: capital height 1510 of 2048, the
    // stroke h/10
    assert_eq!(sup.units_per_em(), 2048);
    assert_eq!(sup.capital_height(), Some(1510));
    let bbox = |c: char| sup.glyph_bounding_box(sup.glyph_index(c).unwrap()).unwrap();
    for c in ['Э', 'Ё'] {
        let b = bbox(c);
        assert_eq!(b.y_min, 0, "{c} stands on the baseline");
    }
    let e = bbox('Э');
    assert!((i32::from(e.y_max) - 1510).abs() <= 1, "Э is a capital's height: {e:?}");
    let e = bbox('э');
    assert!(
        (i32::from(e.y_max) - i32::from(sup.x_height().unwrap())).abs() <= 1,
        "э is x-high: {e:?}"
    );
    // the mark that keeps usvg's fallback off the supplement's letters: in
    // the supplement, empty and of no width, and in none of the linked faces
    let mark = sup.glyph_index(tmm_draw::svg::RUN_MARK).expect("the mark is in the supplement");
    assert_eq!(sup.glyph_hor_advance(mark), Some(0));
    for data in typst_assets::fonts() {
        let f = ttf_parser::Face::parse(data, 0).unwrap();
        assert!(f.glyph_index(tmm_draw::svg::RUN_MARK).is_none());
    }
    let Some(data) = osifont() else {
        eprintln!("skipped the comparison with osifont: not installed");
        return;
    };
    let osi = ttf_parser::Face::parse(&data, 0).unwrap();
    assert_eq!(osi.units_per_em(), sup.units_per_em());
    let adv = |f: &ttf_parser::Face<'_>, c: char| f.glyph_hor_advance(f.glyph_index(c).unwrap()).unwrap();
    // each letter as wide as osifont's own (so text fitted by osifont's
    // widths still fits), and each capital as tall as osifont's
    for c in ['Э', 'э', 'Ё', 'ё'] {
        assert_eq!(adv(&sup, c), adv(&osi, c), "{c}");
    }
    let top = |f: &ttf_parser::Face<'_>, c: char| i32::from(f.glyph_bounding_box(f.glyph_index(c).unwrap()).unwrap().y_max);
    assert!((top(&sup, 'Э') - top(&osi, 'Е')).abs() <= 6, "Э as tall as Е");
    assert!((top(&sup, 'э') - top(&osi, 'е')).abs() <= 6, "э as tall as е");
    // the stroke: osifont's I is one stem, h/10 wide as GOST's type B
    let i = osi.glyph_bounding_box(osi.glyph_index('I').unwrap()).unwrap();
    assert!((i32::from(i.x_max - i.x_min) - 151).abs() <= 2, "{i:?}");
}

/// The `/BaseFont` names of every font in a PDF, without the subset tag.
fn font_names(pdf: &[u8]) -> Vec<String> {
    let doc = Document::load_mem(pdf).expect("the PDF loads");
    let mut out: Vec<String> = doc
        .objects
        .values()
        .filter_map(|o| match o {
            Object::Dictionary(d) => Some(d),
            _ => None,
        })
        .filter(|d| d.get(b"Type").ok().and_then(|t| t.as_name().ok()) == Some(b"Font".as_slice()))
        .filter_map(|d| d.get(b"BaseFont").ok().and_then(|n| n.as_name().ok()))
        .map(|n| {
            let n = String::from_utf8_lossy(n).into_owned();
            n.split_once('+').map_or(n.clone(), |(_, b)| b.to_string())
        })
        .collect();
    out.sort();
    out.dedup();
    out
}

#[test]
fn the_default_projects_pdfs_embed_the_gost_fonts() {
    if tmm_note::fonts::gost_font().is_none() {
        eprintln!("skipped: osifont is not installed (apt install fonts-osifont, or TMM_FONT_PATH)");
        return;
    }
    let task = TaskSource::new("default.toml", DEFAULT_TASK);
    let run = run_task(&task).expect("the default project runs");
    let docs = tmm_note::documents::pdf_documents(&run, &task, |_| {}).expect("the PDFs typeset");
    let supplement = "tmmGOSTsupplement";
    let mut sheets = 0;
    let mut with_supplement = 0;
    for d in docs.iter() {
        let fonts = font_names(&d.bytes);
        if d.path == "note.pdf" {
            for f in ["osifont", supplement] {
                assert!(fonts.iter().any(|n| n == f), "note.pdf lacks {f}: {fonts:?}");
            }
        } else {
            // a sheet's text is all drawings: set in osifont and the
            // supplement only, no character left to a substitute face
            sheets += 1;
            assert!(fonts.iter().any(|n| n == "osifont"), "{}: {fonts:?}", d.path);
            assert!(fonts.iter().all(|n| n == "osifont" || n == supplement), "{}: {fonts:?}", d.path);
            with_supplement += usize::from(fonts.iter().any(|n| n == supplement));
        }
    }
    assert_eq!(sheets, 4);
    // sheet 1 prints "коэффициенту", minus signs and primes
    assert!(with_supplement >= 1);
}

/// A sheet of one line of lettering, named as the drawings name their
/// font (osifont first).
fn lettering_sheet() -> String {
    format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"80mm\" height=\"20mm\" viewBox=\"0 0 80 20\">\
         <text x=\"5\" y=\"12\" font-family=\"{}\" font-size=\"5\">Шарнир B, звено 2</text></svg>",
        tmm_draw::svg::FONT_FAMILY
    )
}

#[test]
fn osifont_given_as_bytes_is_embedded_in_the_pdf() {
    // the browser page's way: no disk, the unaltered file's bytes given to
    // the typesetter (the bytes read here from the machine's osifont, or
    // from Debian's place when TMM_FONT_PATH turned the lookup off)
    let debian = "/usr/share/fonts/truetype/osifont/osifont.ttf";
    let Some(data) = osifont().or_else(|| std::fs::read(debian).ok()) else {
        eprintln!("skipped: osifont is not installed (apt install fonts-osifont, or TMM_FONT_PATH)");
        return;
    };
    tmm_note::fonts::with_gost_font(data).expect("osifont's own file is accepted");
    assert!(tmm_note::fonts::current().has_gost_font());
    let pdf = tmm_note::sheet_pdf(&lettering_sheet()).expect("the sheet typesets");
    let fonts = font_names(&pdf);
    assert_eq!(fonts, ["osifont"], "the lettering is set in osifont alone");
}

#[test]
fn bytes_that_are_not_osifont_are_refused_and_the_pdf_falls_back() {
    use tmm_note::fonts::{GostFontError, current, with_gost_font};
    let had = current().has_gost_font();
    let before = font_names(&tmm_note::sheet_pdf(&lettering_sheet()).expect("the sheet typesets"));
    // no font at all: empty, text, a truncated TrueType header
    for bytes in [&b""[..], b"not a font", b"\x00\x01\x00\x00\x00\x0a\x00\x80"] {
        assert_eq!(with_gost_font(bytes.to_vec()), Err(GostFontError::NotAFont(bytes.len())));
    }
    // a font, but not the one the drawings name
    let other = with_gost_font(tmm_note::fonts::SUPPLEMENT.to_vec());
    assert_eq!(other, Err(GostFontError::NotOsifont("tmm GOST supplement".into())));
    assert!(other.unwrap_err().to_string().contains("fallback"));
    // the set in use is kept, and the PDF is made as before: in osifont
    // when the machine has it, else in the fallback faces, never failing
    assert_eq!(current().has_gost_font(), had);
    let after = font_names(&tmm_note::sheet_pdf(&lettering_sheet()).expect("the sheet still typesets"));
    assert_eq!(after, before);
    assert_eq!(after.iter().any(|n| n == "osifont"), had, "{after:?}");
    assert!(!after.is_empty());
}
