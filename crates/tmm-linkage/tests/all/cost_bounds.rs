//! Bounded cost of choosing the assembly: a crank driving many independent
//! RRR dyads, each with a side hint of its own, assembles on the hinted
//! branch of every dyad (checked by the side of the line, computed here);
//! hints that tie more dyads together than the search allows are refused
//! with a message naming the limit.

use tmm_geom::Vec2;
use tmm_linkage::{AssemblyHint, HintKind, InputDef, LinkDef, MAX_COUPLED, Mechanism, MechanismDef};

/// Crank A–B (0.1 m) driving `n` dyads B–Ck (1 m), Dk–Ck (1 m), Dk fixed at
/// (1.2 + 0.0005·k, 0.5) m; dyad k's hint puts Ck below the line B–Dk when
/// `below(k)`, above it otherwise.
fn fan(n: usize, below: impl Fn(usize) -> bool) -> MechanismDef {
    let mut fixed = vec![("A".to_string(), Vec2::ZERO)];
    let mut links = vec![LinkDef::bar("1", "A", "B", 0.1)];
    let mut hints = Vec::new();
    for k in 0..n {
        fixed.push((format!("D{k}"), Vec2::new(1.2 + 0.0005 * k as f64, 0.5)));
        links.push(LinkDef::bar(&format!("c{k}"), "B", &format!("C{k}"), 1.0));
        links.push(LinkDef::bar(&format!("r{k}"), &format!("D{k}"), &format!("C{k}"), 1.0));
        let line = (String::from("B"), format!("D{k}"));
        hints.push(AssemblyHint {
            point: format!("C{k}"),
            kind: if below(k) {
                HintKind::Below(line.0, line.1)
            } else {
                HintKind::Above(line.0, line.1)
            },
        });
    }
    MechanismDef {
        fixed,
        links,
        input: Some(InputDef {
            link: "1".into(),
            pivot: "A".into(),
            pin: "B".into(),
            omega: 10.0,
            epsilon: 0.0,
        }),
        hints,
        ..Default::default()
    }
}

/// Assemble the fan and check every dyad against its hint and its lengths.
fn check_fan(n: usize) {
    let below = |k: usize| k % 3 != 1;
    let def = fan(n, below);
    let m = Mechanism::new(&def).unwrap_or_else(|e| panic!("{n} dyads: {e}"));
    assert_eq!(m.groups.len(), n);
    let mut s = m.solution();
    m.solve(m.assembly_angle, &mut s).unwrap();
    let p = |name: &str| s.points[m.point(name).unwrap()].p;
    let b = p("B");
    for k in 0..n {
        let (c, d) = (p(&format!("C{k}")), p(&format!("D{k}")));
        assert!(((c - b).hypot() - 1.0).abs() < 1e-9 && ((c - d).hypot() - 1.0).abs() < 1e-9);
        // D is to the right of B, so "below B→D" is the clockwise side: cross < 0
        let t = d - b;
        let cross = t.x * (c.y - b.y) - t.y * (c.x - b.x);
        assert!(t.x > 0.0);
        assert_eq!(cross < 0.0, below(k), "dyad {k}: C{k} = {c:?}");
    }
}

#[test]
fn sixty_four_dyads_assemble_on_their_hinted_branches() {
    // the exhaustive search wrapped at 64 dyads (2^64 as 1) and refused this
    check_fan(64);
}

#[test]
fn seventy_four_dyads_assemble_on_their_hinted_branches() {
    // 1 + 2·74 = 149 links, the most a mechanism may have
    check_fan(74);
}

#[test]
fn hints_coupling_too_many_dyads_are_refused_naming_the_limit() {
    // a chain: dyad k hangs from C(k−1) (C(−1) = B) and the fixed Ek; one
    // hint on the last point depends on every dyad's branch
    let n = MAX_COUPLED + 1;
    let mut fixed = vec![("A".to_string(), Vec2::ZERO)];
    let mut links = vec![LinkDef::bar("1", "A", "B", 0.1)];
    for k in 0..n {
        let prev = if k == 0 { "B".to_string() } else { format!("C{}", k - 1) };
        fixed.push((format!("E{k}"), Vec2::new(0.3 * (k + 1) as f64, 0.4)));
        links.push(LinkDef::bar(&format!("c{k}"), &prev, &format!("C{k}"), 0.5));
        links.push(LinkDef::bar(&format!("r{k}"), &format!("E{k}"), &format!("C{k}"), 0.4));
    }
    let def = MechanismDef {
        fixed,
        links,
        input: Some(InputDef {
            link: "1".into(),
            pivot: "A".into(),
            pin: "B".into(),
            omega: 10.0,
            epsilon: 0.0,
        }),
        hints: vec![AssemblyHint {
            point: format!("C{}", n - 1),
            kind: HintKind::Near(Vec2::new(4.0, 1.0)),
        }],
        ..Default::default()
    };
    let e = Mechanism::new(&def).unwrap_err().to_string();
    assert!(e.contains(&format!("2^{n} ")) && e.contains(&format!("2^{MAX_COUPLED}")), "{e}");
    assert!(e.contains("assembly"), "{e}");
}

#[test]
fn more_links_than_the_cap_are_refused_naming_the_limit() {
    // 1 + 2·75 = 151 links: the rank check costs their cube (999 links took
    // 300 s) and a whole run grows with them
    assert_eq!(tmm_linkage::limits::MAX_LINKS, 150);
    let e = Mechanism::new(&fan(75, |_| true)).unwrap_err().to_string();
    assert!(
        e.contains("links") && e.contains("151") && e.contains(&tmm_linkage::limits::MAX_LINKS.to_string()),
        "{e}"
    );
}
