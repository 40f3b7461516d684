//! Tests of `tmm_report::sheets`, kept outside the library so that the
//! test command compiles it once.

use tmm_report::project::Language;
use tmm_report::sheets::*;

/// Two ids, one the beginning of the other (`a`, `ab`), defined and
/// referred to by `href="#…"` and `url(#…)`; a colour `#abc` that is no
/// id stays as it is. The expected markup is written out by hand.
#[test]
fn ids_take_the_drawing_prefix() {
    let svg = concat!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="20mm" height="10mm" viewBox="0 0 20 10">"#,
        r#"<defs><marker id="a"><path d="M0 0L1 1"/></marker><clipPath id="ab"><rect width="5" height="5"/></clipPath></defs>"#,
        r##"<path d="M0 0H9" marker-end="url(#a)" clip-path="url(#ab)" fill="#abc"/>"##,
        r##"<use href="#ab"/><use xlink:href="#a"/><text>#a ab a"</text>"##,
        "</svg>\n"
    );
    let expected = concat!(
        r#"<defs><marker id="d7-a"><path d="M0 0L1 1"/></marker><clipPath id="d7-ab"><rect width="5" height="5"/></clipPath></defs>"#,
        r##"<path d="M0 0H9" marker-end="url(#d7-a)" clip-path="url(#d7-ab)" fill="#abc"/>"##,
        r##"<use href="#d7-ab"/><use xlink:href="#d7-a"/><text>#a ab a"</text>"##,
    );
    let d = read_drawing("linkage/positions.svg", svg, Language::En, true, 7).unwrap();
    assert_eq!(d.body, expected);
    assert_eq!((d.w, d.h, d.view_box), (20.0, 10.0, [0.0, 0.0, 20.0, 10.0]));
}
