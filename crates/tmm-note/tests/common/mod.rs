//! A hand-made sample note with every block kind, in each language, shared by
//! the tests and the benchmark.

#![allow(dead_code)]

use tmm_note::{Block, Cell, Lang, Note, ProjectInfo, Section, Span, Text};

/// A student's name with every character that means something in typst
/// markup; it must come out literally.
pub const TRICKY_NAME: &str = "O'Brien #1 *bold* $x$ _u_ @me <tag> [b] \\n";

/// Words of the sample in one language.
struct Words {
    university: &'static str,
    department: &'static str,
    title: &'static str,
    teacher: &'static str,
    city: &'static str,
    structure: &'static str,
    kinematics: &'static str,
    velocities: &'static str,
    forces: &'static str,
    para: &'static str,
    velocity_of_b: &'static str,
    see_formula: &'static str,
    table_caption: &'static str,
    position: &'static str,
    speed: &'static str,
    figure_caption: &'static str,
    svg_label: &'static str,
    item1: &'static str,
    item2: &'static str,
    source1: &'static str,
    source2: &'static str,
    appendix: &'static str,
    pangram: &'static str,
}

fn words(lang: Lang) -> Words {
    match lang {
        Lang::Ru => Words {
            university: "Национальный технический университет",
            department: "Кафедра теории механизмов и машин",
            title: "Механизм поперечно-строгального станка",
            teacher: "Петров П. П.",
            city: "Харьков",
            structure: "Структурный анализ механизма",
            kinematics: "Кинематический анализ механизма",
            velocities: "План скоростей",
            forces: "Силовой анализ",
            para: "Число степеней свободы механизма определяем по формуле Чебышёва; механизм состоит из кривошипа, шатуна и ползуна. ",
            velocity_of_b: "Скорость точки B равна ",
            see_formula: ", см. формулу ",
            table_caption: "Скорости точек механизма",
            position: "Положение",
            speed: "Скорость",
            figure_caption: "Схема механизма",
            svg_label: "Кривошип OA, шатун AB",
            item1: "кривошип вращается равномерно;",
            item2: "трение в кинематических парах не учитываем.",
            source1: "Артоболевский И. И. Теория механизмов и машин. – М.: Наука, 1988. – 640 с.",
            source2: "Попов С. А. Курсовое проектирование по теории механизмов и машин. – М.: Высшая школа, 1986.",
            appendix: "Распечатка результатов расчёта",
            pangram: "Съешь же ещё этих мягких французских булок, да выпей чаю. Ёж.",
        },
        Lang::Uk => Words {
            university: "Національний технічний університет",
            department: "Кафедра теорії механізмів і машин",
            title: "Механізм поперечно-стругального верстата",
            teacher: "Петренко П. П.",
            city: "Харків",
            structure: "Структурний аналіз механізму",
            kinematics: "Кінематичний аналіз механізму",
            velocities: "План швидкостей",
            forces: "Силовий аналіз",
            para: "Ступінь вільності механізму визначаємо за формулою Чебишова; механізм складається з кривошипа, шатуна і повзуна. ",
            velocity_of_b: "Швидкість точки B дорівнює ",
            see_formula: ", див. формулу ",
            table_caption: "Швидкості точок механізму",
            position: "Положення",
            speed: "Швидкість",
            figure_caption: "Схема механізму",
            svg_label: "Кривошип OA, ґ є і ї",
            item1: "кривошип обертається рівномірно;",
            item2: "тертя в кінематичних парах не враховуємо.",
            source1: "Кіницький Я. Т. Теорія механізмів і машин. – К.: Наукова думка, 2002. – 660 с.",
            source2: "Кореняко О. С. Курсове проектування з теорії механізмів і машин. – К.: Вища школа, 1970.",
            appendix: "Роздруківка результатів розрахунку",
            pangram: "Чуєш їх, доцю, га? Кумедна ж ти, прощайся без ґольфів! Ґедзь, єнот, їжак, ірис.",
        },
        Lang::En => Words {
            university: "National Technical University",
            department: "Department of Theory of Mechanisms and Machines",
            title: "Mechanism of a shaping machine",
            teacher: "Peters P. P.",
            city: "Kharkiv",
            structure: "Structural analysis of the mechanism",
            kinematics: "Kinematic analysis of the mechanism",
            velocities: "Velocity diagram",
            forces: "Force analysis",
            para: "The degree of freedom of the mechanism follows from Chebyshev's formula; the mechanism consists of a crank, a connecting rod and a slider. ",
            velocity_of_b: "The velocity of point B is ",
            see_formula: ", see formula ",
            table_caption: "Velocities of the points",
            position: "Position",
            speed: "Velocity",
            figure_caption: "Kinematic diagram of the mechanism",
            svg_label: "Crank OA, rod AB",
            item1: "the crank rotates uniformly;",
            item2: "friction in the joints is neglected.",
            source1: "Uicker J. J., Pennock G. R., Shigley J. E. Theory of Machines and Mechanisms. – Oxford University Press, 2017.",
            source2: "Norton R. L. Design of Machinery. – McGraw-Hill, 2019.",
            appendix: "Printout of the results",
            pangram: "The quick brown fox jumps over the lazy dog.",
        },
    }
}

/// An SVG drawing with Cyrillic (or Latin) text, as the tool's drawings are.
pub fn sample_svg(label: &str) -> String {
    format!(
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="120mm" height="60mm" viewBox="0 0 120 60">
<line x1="10" y1="50" x2="40" y2="15" stroke="black" stroke-width="0.7"/>
<line x1="40" y1="15" x2="105" y2="50" stroke="black" stroke-width="0.7"/>
<circle cx="10" cy="50" r="2" fill="white" stroke="black" stroke-width="0.35"/>
<circle cx="40" cy="15" r="2" fill="white" stroke="black" stroke-width="0.35"/>
<rect x="98" y="46" width="14" height="8" fill="none" stroke="black" stroke-width="0.5"/>
<text x="60" y="8" font-size="4" font-family="DejaVu Sans, Arial, sans-serif" text-anchor="middle">{label}</text>
</svg>"#
    )
}

/// The technical assignment's data table.
fn assignment(lang: Lang) -> Vec<Block> {
    let (param, value) = match lang {
        Lang::Ru => ("Параметр", "Значение"),
        Lang::Uk => ("Параметр", "Значення"),
        Lang::En => ("Parameter", "Value"),
    };
    vec![Block::Table {
        caption: match lang {
            Lang::Ru => "Исходные данные".into(),
            Lang::Uk => "Вихідні дані".into(),
            Lang::En => "Initial data".into(),
        },
        header: vec![param.into(), value.into()],
        rows: vec![
            vec![
                Cell::Text(Text::plain("").with(Span::Math("l_(O A)".into()))),
                Cell::Text(Text(vec![Span::Number {
                    value: 0.125,
                    digits: 3,
                    unit: "м".into(),
                }])),
            ],
            vec![
                Cell::Text(Text::plain("").with(Span::Math("n_1".into()))),
                Cell::Text(Text(vec![Span::Number {
                    value: 95.0,
                    digits: 2,
                    unit: "об/мин".into(),
                }])),
            ],
        ],
        units: vec![],
        label: None,
    }]
}

/// The structural, kinematic and force sections, numbered from `first`.
fn body_sections(lang: Lang, w: &Words, copies: usize) -> Vec<Section> {
    let mut sections = Vec::new();
    for copy in 0..copies {
        let tag = |s: &str| if copy == 0 { s.to_owned() } else { format!("{s}-{copy}") };
        let mut s1 = Section::new(w.structure);
        s1.blocks.push(Block::Paragraph(
            Text::plain(w.para)
                .with(Span::Strong(w.pangram.into()))
                .with(Span::Plain(" ".into()))
                .with(Span::Emph(w.pangram.into()))
                .with(Span::Cite(1)),
        ));
        s1.blocks.push(Block::Formula {
            typst_math: "W = 3 n - 2 p_5 - p_4 = 3 dot 3 - 2 dot 4 - 0 = 1".into(),
            label: Some(tag("eq-dof")),
        });
        s1.blocks.push(Block::List(vec![Text::plain(w.item1), Text::plain(w.item2)]));
        s1.blocks.push(Block::Figure {
            caption: w.figure_caption.into(),
            svg: sample_svg(w.svg_label),
            width_mm: 120.0,
            label: Some(tag("fig-scheme")),
        });
        for _ in 0..3 {
            s1.blocks
                .push(Block::Paragraph(Text::plain(w.para).with(Span::Plain(w.para.into()))));
        }
        let mut s2 = Section::new(w.kinematics);
        let mut s21 = Section::new(w.velocities);
        let vb = tmm_note::number::math_number(12.3456, 4, lang).expect("a finite number");
        s21.blocks.push(Block::Formula {
            typst_math: format!("v_B = omega_1 l_(O A) = {vb} \"м/с\""),
            label: Some(tag("eq-vb")),
        });
        s21.blocks.push(Block::Paragraph(
            Text::plain(w.velocity_of_b)
                .with(Span::Number {
                    value: 12.3456,
                    digits: 4,
                    unit: "м/с".into(),
                })
                .with(Span::Plain(w.see_formula.into()))
                .with(Span::Ref(tag("eq-vb")))
                .with(Span::Plain("; ".into()))
                .with(Span::Ref(tag("eq-dof")))
                .with(Span::Plain(", ".into()))
                .with(Span::Ref(tag("fig-scheme")))
                .with(Span::Plain(", ".into()))
                .with(Span::Ref(tag("tab-v")))
                .with(Span::Plain(". ".into()))
                .with(Span::Math("omega_1 = (pi n_1) / 30".into()))
                .with(Span::Plain(" = ".into()))
                .with(Span::Number {
                    value: 9.948_376_736,
                    digits: 3,
                    unit: "рад/с".into(),
                })
                .with(Span::Plain("; ".into()))
                .with(Span::Number {
                    value: 1.5e-7,
                    digits: 2,
                    unit: "м".into(),
                })
                .with(Span::Cite(2)),
        ));
        let rows = (0..13)
            .map(|i| {
                let phi = f64::from(i) * 30.0_f64.to_radians();
                vec![
                    Cell::Text(Text::plain(i.to_string())),
                    Cell::Number {
                        value: f64::from(i) * 30.0,
                        digits: 3,
                    },
                    Cell::Number {
                        value: 1.25 * phi.sin() - 0.5,
                        digits: 3,
                    },
                    if i == 6 {
                        Cell::Empty
                    } else {
                        Cell::Number {
                            value: 12.3456 + f64::from(i),
                            digits: 4,
                        }
                    },
                ]
            })
            .collect();
        s21.blocks.push(Block::Table {
            caption: w.table_caption.into(),
            header: vec![w.position.into(), "φ".into(), "x".into(), w.speed.into()],
            rows,
            units: vec!["".into(), "°".into(), "м".into(), "м/с".into()],
            label: Some(tag("tab-v")),
        });
        s2.subsections.push(s21);
        let mut s22 = Section::new(w.forces);
        for _ in 0..4 {
            s22.blocks.push(Block::Paragraph(
                Text::plain(w.para)
                    .with(Span::Plain(w.para.into()))
                    .with(Span::Plain(w.pangram.into())),
            ));
        }
        s2.subsections.push(s22);
        sections.push(s1);
        sections.push(s2);
    }
    sections
}

/// The sample note in `lang`; `copies` repeats the body sections (1 gives
/// 8 pages, 8 about 30).
pub fn sample_note(lang: Lang, frame: bool, copies: usize) -> Note {
    let w = words(lang);
    let mut appendix = Section::new(w.appendix);
    appendix.blocks.push(Block::Paragraph(Text::plain(w.pangram)));
    appendix.blocks.push(Block::Formula {
        typst_math: "F_(\"ин\") = -m a_S".into(),
        label: Some("eq-app".into()),
    });
    appendix.blocks.push(Block::Figure {
        caption: w.figure_caption.into(),
        svg: sample_svg(w.svg_label),
        width_mm: 300.0,
        label: None,
    });
    Note {
        lang,
        project: ProjectInfo {
            university: w.university.into(),
            department: w.department.into(),
            student: TRICKY_NAME.into(),
            group: "ТМ-21а".into(),
            teacher: w.teacher.into(),
            variant: "12".into(),
            city: w.city.into(),
            year: "2026".into(),
            title: w.title.into(),
            designation: "ТММ.КП.012.00.000 ПЗ".into(),
        },
        frame,
        assignment: assignment(lang),
        introduction: None,
        sections: body_sections(lang, &w, copies),
        conclusion: None,
        sources: vec![w.source1.into(), w.source2.into()],
        appendices: vec![appendix],
    }
}
