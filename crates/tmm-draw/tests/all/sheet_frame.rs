//! The ESKD sheet as a scene: the frame, graph 26 and title block form 1
//! with every text inside its cell at an allowed size.

use tmm_draw::eskd::{Format, TitleBlock, sheet};
use tmm_draw::{Geom, LineType, Rich, Shape, svg};

fn block() -> TitleBlock {
    TitleBlock {
        designation: "ТММ.КП.017.00.000".into(),
        title: "Кинематический и силовой анализ рычажного механизма".into(),
        scale: "1:2,5".into(),
        sheet: 1,
        sheets: 4,
        student: "Иванов И. И.".into(),
        teacher: "Петров П. П.".into(),
        organisation: "Национальный технический университет «ХПИ», каф. ТММ, гр. МШ-21".into(),
        ..TitleBlock::default()
    }
}

#[test]
fn frame_lies_twenty_and_five_mm_inside_the_edges() {
    let (scene, _) = sheet(Format::A1, &block()).unwrap();
    let frame = scene.items().iter().find_map(|i| match &i.shape {
        Shape::Stroke {
            line: LineType::Main,
            geom: Geom::Polyline { points, closed: true },
        } => Some(points.clone()),
        _ => None,
    });
    let f = frame.expect("the inner frame");
    assert_eq!((f[0].x, f[0].y, f[2].x, f[2].y), (20.0, 5.0, 836.0, 589.0));
}

#[test]
fn every_title_block_text_fits_its_cell_at_an_allowed_size() {
    let (scene, cut) = sheet(Format::A1, &block()).unwrap();
    assert!(cut.is_empty(), "{cut:?}");
    // the title block spans x 651 … 836, y 5 … 60 on A1
    let texts: Vec<_> = scene
        .items()
        .iter()
        .filter_map(|i| match &i.shape {
            Shape::Text(t) if t.rotation_deg == 0.0 => Some(t.clone()),
            _ => None,
        })
        .collect();
    assert!(texts.len() > 20);
    for t in &texts {
        assert!(t.height.mm() >= 2.5);
        let w = t.rich.width(t.height);
        let (x0, x1) = match t.anchor {
            tmm_draw::Anchor::Start => (t.at.x, t.at.x + w),
            tmm_draw::Anchor::Middle => (t.at.x - w / 2.0, t.at.x + w / 2.0),
            tmm_draw::Anchor::End => (t.at.x - w, t.at.x),
        };
        assert!(
            x0 >= 651.0 && x1 <= 836.0 && t.at.y >= 5.0 && t.at.y + t.height.mm() <= 60.0,
            "{:?}",
            t.rich.plain()
        );
    }
    // the long university name wraps into several lines rather than shrinking below 2.5 mm
    let org: Vec<_> = texts.iter().filter(|t| t.at.x > 786.0 && t.at.y < 20.0).collect();
    assert!(org.len() >= 2, "{org:?}");
    // the scale field is filled
    assert!(texts.iter().any(|t| t.rich == Rich::plain_text("1:2,5") && t.height.mm() == 5.0));
}

#[test]
fn a_text_too_long_for_its_cell_is_cut_and_reported_not_narrowed() {
    let mut b = block();
    b.organisation = "очень ".repeat(60);
    let (_, cut) = sheet(Format::A1, &b).unwrap();
    assert_eq!(cut.len(), 1);
}

/// With `TMM_DRAW_DUMP=DIR`, the A1 frame is written there as SVG and DXF.
#[test]
fn dump_the_frame_when_asked() {
    let Ok(dir) = std::env::var("TMM_DRAW_DUMP") else { return };
    let (scene, _) = sheet(Format::A1, &block()).unwrap();
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(format!("{dir}/frame-a1.svg"), svg::render(&scene)).unwrap();
    std::fs::write(format!("{dir}/frame-a1.dxf"), tmm_draw::dxf::render(&scene)).unwrap();
}
