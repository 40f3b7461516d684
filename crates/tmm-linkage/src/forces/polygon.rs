//! Force polygons (планы сил): for every Assur group and for the input link,
//! the ordered list of the forces on it — the resultant load of each link at
//! its centre of mass, then the reactions from the links outside — whose
//! vector sum is zero because the body is in equilibrium (kinetostatics:
//! d'Alembert's principle, Artobolevsky 1988, § 40). Drawing them tip to tail
//! closes the polygon; the closure gap is a check of the solve.
//!
//! The input link is drawn with the balancing force P_b at the crank pin
//! (уравновешивающая сила) in place of the balancing torque M_b. With a force
//! at the pin the frame's reaction at the pivot is not the one of the torque
//! model: the crank's equilibrium ΣF = 0 gives
//! `R₀₁(P_b) = −(F₁ + Σ R_k1 + P_b) = R₀₁(M_b) − P_b` (derived here; see
//! docs/forces.md), which is [`ForceSolution::pivot_reaction_with_force`].
//! Both models have the same moment about the pivot, since
//! `(pin − pivot) × P_b = M_b`.

use tmm_geom::Vec2;

use super::kinetostatics::ForceSolution;
use crate::Mechanism;

/// What one force of a polygon is.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum PolygonForceKind {
    /// The resultant load (inertia, weight, external) of a link, at its
    /// centre of mass.
    Load {
        /// The link.
        link: usize,
    },
    /// The reaction in a pair on a link of the body from a link outside it.
    Reaction {
        /// Index into [`Mechanism::pairs`].
        pair: usize,
        /// The link exerting it (outside the body).
        from: usize,
        /// The link of the body it acts on.
        on: usize,
    },
    /// The balancing force P_b at the crank pin.
    BalancingForce,
}

/// One force of a polygon.
#[derive(Debug, Clone, PartialEq)]
pub struct PolygonForce {
    /// What it is.
    pub kind: PolygonForceKind,
    /// The course's label: `F2` (load of link 2), `R12` (on 2 from 1), `Pb`.
    pub label: String,
    /// Its point of application, global, m.
    pub at: Vec2,
    /// The force, N.
    pub force: Vec2,
}

/// The force polygon of one body: a group, or the input link.
#[derive(Debug, Clone, PartialEq)]
pub struct ForcePolygon {
    /// The links of the body.
    pub links: Vec<usize>,
    /// The group index in [`Mechanism::groups`], `None` for the input link.
    pub group: Option<usize>,
    /// The forces in drawing order: loads, then reactions (and P_b with the
    /// frame's reaction for the input link). Their sum is zero.
    pub forces: Vec<PolygonForce>,
}

impl ForcePolygon {
    /// The vector sum of the forces (zero up to round-off), N.
    pub fn closure(&self) -> Vec2 {
        self.forces.iter().fold(Vec2::ZERO, |s, f| s + f.force)
    }

    /// The largest force's magnitude, N.
    pub fn largest(&self) -> f64 {
        self.forces.iter().map(|f| f.force.hypot()).fold(0.0, f64::max)
    }
}

impl ForceSolution {
    /// The force polygons of every group (in solving order) and, last, of the
    /// input link with the balancing force P_b and the frame's reaction for
    /// that model ([`ForceSolution::pivot_reaction_with_force`]). Loads that
    /// are exactly zero are left out.
    ///
    /// ```
    /// use tmm_linkage::{LinkDef, MechanismDef, InputDef, Mechanism};
    /// use tmm_linkage::forces::{Loads, Kinetostatics};
    /// use tmm_geom::Vec2;
    /// let def = MechanismDef {
    ///     fixed: vec![("O".into(), Vec2::ZERO), ("C".into(), Vec2::new(0.3, 0.0))],
    ///     links: vec![LinkDef::bar("1", "O", "A", 0.1), LinkDef::bar("2", "A", "B", 0.3), LinkDef::bar("3", "C", "B", 0.25)],
    ///     input: Some(InputDef { link: "1".into(), pivot: "O".into(), pin: "A".into(), omega: 10.0, epsilon: 0.0 }),
    ///     ..Default::default()
    /// };
    /// let m = Mechanism::new(&def).unwrap();
    /// let mut loads = Loads::new(&m);
    /// loads.links[2].mass = 2.0;
    /// loads.links[3].mass = 1.5;
    /// let mut k = Kinetostatics::new(&m, loads).unwrap();
    /// let (mut sol, mut f) = (m.solution(), k.result());
    /// k.solve_at(0.7, &mut sol, &mut f).unwrap();
    /// let polys = f.polygons(&m);
    /// assert_eq!(polys.len(), 2);
    /// for p in &polys {
    ///     assert!(p.closure().hypot() <= 1e-12 * p.largest());
    /// }
    /// assert!(polys[1].forces.iter().any(|x| x.label == "Pb"));
    /// ```
    pub fn polygons(&self, m: &Mechanism) -> Vec<ForcePolygon> {
        let mut out: Vec<ForcePolygon> = m
            .groups
            .iter()
            .enumerate()
            .map(|(g, grp)| self.polygon(m, &grp.info.link_ids, Some(g)))
            .collect();
        out.push(self.polygon(m, &[m.crank.link], None));
        out
    }

    fn polygon(&self, m: &Mechanism, links: &[usize], group: Option<usize>) -> ForcePolygon {
        let name = |l: usize| m.link_names[l].as_str();
        let mut forces = Vec::new();
        for &l in links {
            let lf = &self.links[l];
            if lf.force != Vec2::ZERO {
                forces.push(PolygonForce {
                    kind: PolygonForceKind::Load { link: l },
                    label: format!("F{}", name(l)),
                    at: lf.s,
                    force: lf.force,
                });
            }
        }
        let crank = group.is_none();
        let mut frame = None;
        for r in &self.reactions {
            let (on_in, from_in) = (links.contains(&r.on), links.contains(&r.from));
            let (from, on, f) = if on_in && !from_in {
                (r.from, r.on, r.force)
            } else if from_in && !on_in {
                (r.on, r.from, -r.force)
            } else {
                continue;
            };
            let force = if crank && from == 0 { self.pivot_reaction_with_force } else { f };
            let pf = PolygonForce {
                kind: PolygonForceKind::Reaction { pair: r.pair, from, on },
                label: format!("R{}{}", name(from), name(on)),
                at: r.at,
                force,
            };
            if crank && from == 0 {
                frame = Some(pf);
            } else {
                forces.push(pf);
            }
        }
        if crank {
            forces.push(PolygonForce {
                kind: PolygonForceKind::BalancingForce,
                label: "Pb".into(),
                at: self.pin,
                force: self.balancing_force_vec,
            });
            forces.extend(frame);
        }
        ForcePolygon {
            links: links.to_vec(),
            group,
            forces,
        }
    }
}
