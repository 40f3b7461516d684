//! Tests of `tmm_report::sheets`, kept outside the library so that the
//! test command compiles it once.

use tmm_report::project::Language;
use tmm_report::sheets::*;

/// A drawing placed on a sheet keeps its size and scale, and its group
/// ids take the drawing's prefix (unique ids when drawings share a sheet);
/// the expected markup is written out by hand.
#[test]
fn ids_take_the_drawing_prefix() {
    use tmm_report::output::Documents;
    use tmm_report::picture::{Element, Picture};
    let pic = Picture::new(
        20.0,
        10.0,
        vec![("data-scale".into(), "1:2".into())],
        vec![
            Element::GroupOpen {
                id: Some("a".into()),
                class: None,
                data: Vec::new(),
            },
            Element::GroupClose,
        ],
    );
    let mut docs = Documents::new();
    docs.add_text("linkage/positions.svg", pic).unwrap();
    let d = drawing_of(&docs, "linkage/positions.svg", Language::En, true, 7).unwrap();
    assert_eq!(d.pic.body(&format!("d{}-", d.id)), "<g id=\"d7-a\">\n</g>\n");
    assert_eq!((d.w, d.h, d.scale.as_deref()), (20.0, 10.0, Some("1:2")));
    assert!(drawing_of(&docs, "linkage/other.svg", Language::En, true, 8).is_none());
}
