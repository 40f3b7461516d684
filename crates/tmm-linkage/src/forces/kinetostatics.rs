//! Kinetostatics of the whole mechanism (кинетостатический расчёт): loads on
//! every link, then the reactions of the Assur groups from the last group back
//! to the input, as the course does, and finally the input link: the reaction
//! at its fixed pivot and the balancing torque M_b that the drive applies to it
//! (уравновешивающий момент), with the equivalent balancing force
//! P_b = M_b / l₁ at the crank pin, perpendicular to the crank
//! (уравновешивающая сила P_ур).
//!
//! Crank equilibrium about its pivot A (seed 001 sheet 3: "ΣM₁(A) = R₂₁·h₂₁ −
//! P_ур·AB = 0"): M_b + Σ M_A(loads on the crank, reactions from its groups) = 0.
//!
//! Solving allocates nothing: [`Kinetostatics::solve`] fills a reusable
//! [`ForceSolution`].

use tmm_geom::{Vec2, cross, perp};

use super::dyads::{RrpDyad, RrrDyad};
use super::error::ForceError;
use super::group::{GroupWork, PairForce, about_origin, is_ordered_dyad, solve_dyad, solve_group};
use super::inertia::inertia_load;
use super::loads::Loads;
use super::slider_load::ActiveSliderLoad;
use super::stroke::{Phase, Stroke, Working};
use crate::mechanism::Pair;
use crate::{Mechanism, Solution};

/// The loads on one link at one position, reduced to its centre of mass S.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct LinkForces {
    /// Centre of mass S, global, m.
    pub s: Vec2,
    /// Inertia force −m·a_S, N (at S).
    pub inertia_force: Vec2,
    /// Inertia torque −J_S·ε, N·m.
    pub inertia_moment: f64,
    /// Weight m·g, N (at S).
    pub weight: Vec2,
    /// External forces and the useful resistance on the link, summed, N.
    pub external_force: Vec2,
    /// Their moment about S plus external couples, N·m.
    pub external_moment: f64,
    /// All loads (inertia, weight, external) summed, N.
    pub force: Vec2,
    /// Their moment about S, N·m, counter-clockwise positive.
    pub moment: f64,
}

/// The reaction in one kinematic pair: the force exerted by link `from` on
/// link `on` (the link `on` is in the later group; inside a group, the pair's
/// first link). The force on `from` is the opposite.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Reaction {
    /// Index into [`Mechanism::pairs`].
    pub pair: usize,
    /// The link exerting the force.
    pub from: usize,
    /// The link the force acts on.
    pub on: usize,
    /// The force on `on`, N.
    pub force: Vec2,
    /// Where it acts, global: the joint centre; for a prismatic pair the
    /// resultant's point on the guide line (the slider's point shifted by `offset`).
    pub at: Vec2,
    /// Component along the axis of link `on` (its local x-axis), N: the seeds' R^n.
    pub normal: f64,
    /// Component perpendicular to that axis (axis turned +90°), N: the seeds' R^τ.
    pub tangential: f64,
    /// Prismatic pair: where the resultant acts along the guide, measured
    /// from the slider's point in the guide's direction, m (0 for a revolute pair).
    pub offset: f64,
    /// `true` for a prismatic pair (the force is normal to the guide).
    pub prismatic: bool,
}

/// Where the reaction of one pair of a group goes: the pair, the link it
/// acts on (inside the group) and the link exerting it, whether the group
/// solve's force (on the pair's first link) must be reversed, whether its
/// opposite loads a link of an earlier group, and for a prismatic pair its
/// guide (the link and the direction on it).
#[derive(Debug, Clone, Copy)]
struct PairPlan {
    pid: usize,
    on: usize,
    from: usize,
    flip: bool,
    carry: bool,
    guide: Option<(usize, Vec2)>,
}

impl PairPlan {
    fn new(m: &Mechanism, pid: usize, on: usize, from: usize, flip: bool, carry: bool) -> Self {
        let guide = match m.pairs[pid] {
            Pair::P { guide, d, .. } => Some((guide, d)),
            Pair::R { .. } => None,
        };
        PairPlan {
            pid,
            on,
            from,
            flip,
            carry,
            guide,
        }
    }
}

/// How a group's reactions are found, chosen once: a dyad written out for
/// its pair kinds, another dyad by the elimination, or the general solve.
#[derive(Debug, Clone)]
enum GroupSolver {
    Rrr(RrrDyad),
    Rrp(RrpDyad),
    Dyad,
    General,
}

/// The result at one crank angle.
#[derive(Debug, Clone, PartialEq)]
pub struct ForceSolution {
    /// Crank angle φ, rad.
    pub phi: f64,
    /// Loads per link (index 0, the frame, stays zero).
    pub links: Vec<LinkForces>,
    /// Reaction per pair, indexed as [`Mechanism::pairs`].
    pub reactions: Vec<Reaction>,
    /// Magnitude of each useful resistance at this position.
    pub resistance: Vec<f64>,
    /// Phase of the cycle (when a resistance law needs the stroke).
    pub phase: Option<Phase>,
    /// Angle of the machine's cycle, rad from its start (see
    /// [`crate::forces::MachineCycle`]).
    pub cycle_angle: f64,
    /// The force of each slider load ([`Loads::sliders`]) at this position, N.
    pub slider_forces: Vec<Vec2>,
    /// Torque the drive applies to the input link, N·m, counter-clockwise positive.
    pub balancing_moment: f64,
    /// The equivalent force at the crank pin perpendicular to the crank,
    /// signed along k × (pin − pivot), N.
    pub balancing_force: f64,
    /// That force as a vector, N.
    pub balancing_force_vec: Vec2,
    /// The crank pin, global, m (where P_b acts).
    pub pin: Vec2,
    /// The frame's reaction on the crank at its pivot when the drive applies
    /// the balancing force P_b at the pin instead of the torque M_b:
    /// `R₀₁(P_b) = R₀₁(M_b) − P_b` (crank equilibrium ΣF = 0, derived in
    /// docs/forces.md). The reaction in [`ForceSolution::reactions`] is the
    /// torque model's. N.
    pub pivot_reaction_with_force: Vec2,
    /// The balancing torque by Zhukovsky's lever (virtual power), N·m.
    pub zhukovsky_moment: f64,
    acc: Vec<(Vec2, f64)>,
    q: Vec<(Vec2, f64)>,
    pf: Vec<PairForce>,
}

impl ForceSolution {
    /// |M_b − M_Zh| / max(|M_b|, |M_Zh|), 0 when both are 0.
    pub fn relative_difference(&self) -> f64 {
        let s = self.balancing_moment.abs().max(self.zhukovsky_moment.abs());
        if s == 0.0 {
            0.0
        } else {
            (self.balancing_moment - self.zhukovsky_moment).abs() / s
        }
    }
}

/// The kinetostatic solver of one mechanism under given loads.
#[derive(Debug, Clone)]
pub struct Kinetostatics<'m> {
    /// The mechanism.
    pub m: &'m Mechanism,
    /// The loads.
    pub loads: Loads,
    /// The output's stroke, when a resistance law needs it.
    pub stroke: Option<Stroke>,
    gpairs: Vec<Vec<&'m Pair>>,
    /// Per group: how its reactions are found.
    solver: Vec<GroupSolver>,
    /// Per group, per pair: where its reaction goes (found once, not per position).
    plan: Vec<Vec<PairPlan>>,
    /// Per link: a useful resistance acts on it.
    resisted: Vec<bool>,
    pivot_pair: usize,
    pivot_plan: PairPlan,
    /// 1 / |pin − pivot| of the crank, 1/m.
    inv_radius: f64,
    work: GroupWork,
    /// Solve every group by the general Jᵀ·λ system (for cross-checks).
    pub general: bool,
    /// The slider loads, prepared.
    pub sliders: Vec<ActiveSliderLoad>,
    /// Absolute crank angle of the start of the machine's cycle, rad.
    pub cycle_start: f64,
    /// The machine cycle's length, rad (2π or 4π).
    pub period: f64,
    /// The cycle angle of the next [`Kinetostatics::solve`], when set by
    /// [`Kinetostatics::solve_at_cycle`].
    next_cycle_angle: Option<f64>,
}

impl<'m> Kinetostatics<'m> {
    /// Prepare: check the loads; find the stroke if a resistance law needs it
    /// (the slower stroke is the working one).
    pub fn new(m: &'m Mechanism, loads: Loads) -> Result<Self, ForceError> {
        Self::with_working(m, loads, Working::Slower)
    }

    /// As [`Kinetostatics::new`], choosing which stroke is the working one.
    pub fn with_working(m: &'m Mechanism, loads: Loads, working: Working) -> Result<Self, ForceError> {
        loads.check(m)?;
        let stroke = if loads.resistance.iter().any(|r| r.law.needs_stroke()) {
            Some(Stroke::find(m, m.output, working)?)
        } else {
            None
        };
        for (k, r) in loads.resistance.iter().enumerate() {
            r.law.check_cover(&format!("resistance[{k}]"), stroke.as_ref(), &|x, ang| {
                if ang {
                    format!("{:.4}°", x.to_degrees())
                } else {
                    format!("{:.6} m", x)
                }
            })?;
        }
        let gpairs: Vec<Vec<&Pair>> = m
            .groups
            .iter()
            .map(|g| g.info.pair_ids.iter().map(|&i| &m.pairs[i]).collect())
            .collect();
        let solver = m
            .groups
            .iter()
            .zip(&gpairs)
            .map(|(g, p)| {
                let links = &g.info.link_ids;
                if let Some(d) = RrrDyad::new(p, links) {
                    GroupSolver::Rrr(d)
                } else if let Some(d) = RrpDyad::new(p, links) {
                    GroupSolver::Rrp(d)
                } else if is_ordered_dyad(p, links) {
                    GroupSolver::Dyad
                } else {
                    GroupSolver::General
                }
            })
            .collect();
        let c = m.crank.link;
        let pivot_pair = m
            .pairs
            .iter()
            .position(|p| matches!(*p, Pair::R { a, b, .. } if (a == 0 && b == c) || (a == c && b == 0)))
            .ok_or_else(|| ForceError::load("input", "the crank has no revolute pair with the frame"))?;
        let plan = m
            .groups
            .iter()
            .map(|g| {
                let links = &g.info.link_ids;
                g.info
                    .pair_ids
                    .iter()
                    .map(|&pid| {
                        let (first, other) = m.pairs[pid].links();
                        let flip = !links.contains(&first);
                        let (on, from) = if flip { (other, first) } else { (first, other) };
                        PairPlan::new(m, pid, on, from, flip, from != 0 && !links.contains(&from))
                    })
                    .collect()
            })
            .collect();
        let max_links = m.groups.iter().map(|g| g.info.link_ids.len()).max().unwrap_or(1);
        let period = loads.cycle.period();
        let sliders = loads
            .sliders
            .iter()
            .enumerate()
            .map(|(k, s)| s.prepare(m, period, &format!("sliders[{k}]")))
            .collect::<Result<Vec<_>, _>>()?;
        let cycle_start = match loads.cycle.start {
            Some(s) => s,
            None => match &stroke {
                Some(s) => s.phi_start,
                None if loads.cycle.turns > 1 || !sliders.is_empty() => Stroke::find(m, m.output, working).map_or(0.0, |s| s.phi_start),
                None => 0.0,
            },
        };
        Ok(Kinetostatics {
            m,
            stroke,
            gpairs,
            solver,
            plan,
            resisted: (0..m.link_names.len())
                .map(|l| loads.resistance.iter().any(|r| r.link == l) || loads.sliders.iter().any(|r| r.link == l))
                .collect(),
            pivot_pair,
            pivot_plan: PairPlan::new(m, pivot_pair, c, 0, false, false),
            inv_radius: 1.0 / (m.crank.dir_local.hypot() * m.crank.radius),
            work: GroupWork::new(max_links),
            loads,
            general: false,
            sliders,
            cycle_start,
            period,
            next_cycle_angle: None,
        })
    }

    /// A fresh result buffer.
    pub fn result(&self) -> ForceSolution {
        let nl = self.m.link_names.len();
        let maxp = self.m.groups.iter().map(|g| g.info.pair_ids.len()).max().unwrap_or(0);
        let maxl = self.m.groups.iter().map(|g| g.info.link_ids.len()).max().unwrap_or(0);
        ForceSolution {
            phi: f64::NAN,
            links: vec![LinkForces::default(); nl],
            reactions: vec![Reaction::default(); self.m.pairs.len()],
            resistance: vec![0.0; self.loads.resistance.len()],
            phase: None,
            cycle_angle: 0.0,
            slider_forces: vec![Vec2::ZERO; self.sliders.len()],
            balancing_moment: 0.0,
            balancing_force: 0.0,
            balancing_force_vec: Vec2::ZERO,
            pin: Vec2::ZERO,
            pivot_reaction_with_force: Vec2::ZERO,
            zhukovsky_moment: 0.0,
            acc: vec![(Vec2::ZERO, 0.0); nl],
            q: vec![(Vec2::ZERO, 0.0); maxl],
            pf: vec![PairForce::default(); maxp],
        }
    }

    /// Solve the kinematics at crank angle `phi` (rad), then the forces.
    pub fn solve_at(&mut self, phi: f64, sol: &mut Solution, out: &mut ForceSolution) -> Result<(), ForceError> {
        self.m.solve(phi, sol)?;
        self.solve(sol, out)
    }

    /// Solve at cycle angle `psi` (rad from the start of the machine's
    /// cycle in the direction of rotation, 0…period): the crank angle follows,
    /// and the processes of the indicator diagrams are those of `psi` (over a
    /// 720° cycle a crank angle alone does not tell which turn it is).
    pub fn solve_at_cycle(&mut self, psi: f64, sol: &mut Solution, out: &mut ForceSolution) -> Result<(), ForceError> {
        let phi = self.cycle_start + self.m.crank.omega.signum() * psi;
        self.m.solve(phi, sol)?;
        self.next_cycle_angle = Some(psi);
        self.solve(sol, out)
    }

    /// Take cycle angle `psi` (rad) for the next [`Kinetostatics::solve`]
    /// (over a 720° cycle a crank angle alone does not tell which turn it is).
    pub fn set_cycle_angle(&mut self, psi: f64) {
        self.next_cycle_angle = Some(psi);
    }

    /// The cycle angle of a crank angle, rad in [0, period): on the first
    /// turn of a 720° cycle.
    #[inline]
    pub fn cycle_angle_of(&self, phi: f64) -> f64 {
        let dir = if self.m.crank.omega < 0.0 { -1.0 } else { 1.0 };
        (dir * (phi - self.cycle_start)).rem_euclid(2.0 * std::f64::consts::PI)
    }

    /// The forces of a solved position. Allocates nothing.
    pub fn solve(&mut self, sol: &Solution, out: &mut ForceSolution) -> Result<(), ForceError> {
        let m = self.m;
        let phi = sol.phi;
        out.phi = phi;
        let psi = match self.next_cycle_angle.take() {
            Some(p) => p,
            None => self.cycle_angle_of(phi),
        };
        out.cycle_angle = psi;
        out.phase = self.stroke.as_ref().map(|s| s.phase(sol));
        let phase = out.phase.unwrap_or_default();
        for (k, r) in self.loads.resistance.iter().enumerate() {
            out.resistance[k] = r.law.value(&phase);
        }
        // 1/ω₁ of the crank depends on the position only: found before the
        // loads, off their path
        let inv_omega = 1.0 / sol.links[m.crank.link].omega;
        // --- loads on every link, reduced to S and to the link's origin
        out.acc[0] = (Vec2::ZERO, 0.0);
        // virtual power of the same raw loads, summed alongside (Zhukovsky's
        // lever, zhukovsky::balancing_moment written inline): no reaction enters it
        let mut power = 0.0;
        for l in 1..m.link_names.len() {
            let ld = &self.loads.links[l];
            let st = &sol.links[l];
            if ld.mass == 0.0 && ld.inertia == 0.0 && ld.moment == 0.0 && ld.forces.is_empty() && !self.resisted[l] {
                // an unloaded link (a balanced crank): nothing to reduce
                out.links[l] = LinkForces {
                    s: st.pos(m.mass_centers[l]),
                    ..LinkForces::default()
                };
                out.acc[l] = (Vec2::ZERO, 0.0);
                continue;
            }
            let (fi, s, mi) = inertia_load(st, m.mass_centers[l], ld.mass, ld.inertia);
            let w = self.loads.gravity * ld.mass;
            power += (fi + w).dot(st.kin_at(s).0) + (mi + ld.moment) * st.omega;
            let (mut fe, mut me) = (Vec2::ZERO, ld.moment);
            for pf in &ld.forces {
                let p = st.pos(pf.local);
                fe += pf.force;
                me += cross(p - s, pf.force);
                power += pf.force.dot(st.kin_at(p).0);
            }
            for (k, r) in self.loads.resistance.iter().enumerate() {
                if self.resisted[l] && r.link == l {
                    let (f, p, c) = r.apply(st, out.resistance[k]);
                    fe += f;
                    me += cross(p - s, f) + c;
                    power += f.dot(st.kin_at(p).0) + c * st.omega;
                }
            }
            for (k, a) in self.sliders.iter().enumerate() {
                if a.load.link == l {
                    let (f, p) = a.force(sol, psi);
                    out.slider_forces[k] = f;
                    fe += f;
                    me += cross(p - s, f);
                    power += f.dot(st.kin_at(p).0);
                }
            }
            let f = fi + w + fe;
            let mo = mi + me;
            out.links[l] = LinkForces {
                s,
                inertia_force: fi,
                inertia_moment: mi,
                weight: w,
                external_force: fe,
                external_moment: me,
                force: f,
                moment: mo,
            };
            out.acc[l] = about_origin(st.o, f, s, mo);
        }
        // --- Assur groups from the last one back to the crank
        for (g, grp) in m.groups.iter().enumerate().rev() {
            let links = &grp.info.link_ids;
            for (i, &l) in links.iter().enumerate() {
                out.q[i] = out.acc[l];
            }
            let prs = &self.gpairs[g];
            let (q, pf) = (&out.q[..links.len()], &mut out.pf[..prs.len()]);
            // direct calls, so that the dyads' eliminations are inlined
            let solved = match (&self.solver[g], self.general) {
                (GroupSolver::Rrr(d), false) => d.solve(&sol.links, q, pf),
                (GroupSolver::Rrp(d), false) => d.solve(&sol.links, q, pf),
                (GroupSolver::Dyad, false) => solve_dyad(prs, links, &sol.links, q, &mut self.work, pf),
                _ => solve_group(prs, links, &sol.links, q, &mut self.work, pf),
            };
            if !solved {
                return Err(ForceError::Singular {
                    phi_deg: phi.to_degrees(),
                    group: grp.label(),
                });
            }
            for (pl, pf) in self.plan[g].iter().zip(out.pf.iter()) {
                let (f, c) = if pl.flip { (-pf.force, -pf.couple) } else { (pf.force, pf.couple) };
                out.reactions[pl.pid] = reaction(pl, f, pf.at, c, sol);
                if pl.carry {
                    let (df, dm) = about_origin(sol.links[pl.from].o, -f, pf.at, -c);
                    out.acc[pl.from].0 += df;
                    out.acc[pl.from].1 += dm;
                }
            }
        }
        // --- the input link: pivot reaction and balancing torque
        let c = m.crank.link;
        let (f, mo) = out.acc[c];
        let o = sol.links[c].o;
        let pivot = m.crank.pivot;
        let m_pivot = mo + cross(o - pivot, f);
        out.balancing_moment = -m_pivot;
        out.reactions[self.pivot_pair] = reaction(&self.pivot_plan, -f, pivot, 0.0, sol);
        // the pin from the crank's own state (pivot + radius along the crank)
        let r = crate::state::rot(sol.links[c].u, m.crank.dir_local) * m.crank.radius;
        // |r| = l₁·|d| (a rotation keeps lengths): fixed, its inverse found once
        out.balancing_force = out.balancing_moment * self.inv_radius;
        out.balancing_force_vec = perp(r) * (out.balancing_moment * self.inv_radius * self.inv_radius);
        out.pin = pivot + r;
        // with P_b at the pin the crank's ΣF = 0 changes: R₀₁ = −(f + P_b)
        out.pivot_reaction_with_force = -f - out.balancing_force_vec;
        out.zhukovsky_moment = -power * inv_omega;
        // --- nothing non-finite leaves
        let bad = |what: &str| ForceError::NonFinite {
            phi_deg: phi.to_degrees(),
            what: what.to_string(),
        };
        if !(out.balancing_moment.is_finite() && out.zhukovsky_moment.is_finite()) {
            return Err(bad("the balancing torque"));
        }
        // a sum is finite when its terms are (inside the ranges of `limits`
        // nothing overflows): one test per reaction, each independent of the
        // others, the search for the culprit only when one fails
        if out
            .reactions
            .iter()
            .all(|r| ((r.force.x + r.force.y) + (r.at.x + r.at.y)).is_finite())
        {
            return Ok(());
        }
        for r in &out.reactions {
            if !(r.force.x.is_finite() && r.force.y.is_finite() && r.at.x.is_finite() && r.at.y.is_finite()) {
                return Err(bad(&format!("the reaction at {}", m.points[m.pairs[r.pair].point()].name)));
            }
        }
        Ok(())
    }
}

/// Build a reaction record: split along the axis of `on`, and for a prismatic
/// pair turn the couple into a shift of the force along the guide.
#[inline(always)]
fn reaction(pl: &PairPlan, force: Vec2, at: Vec2, couple: f64, sol: &Solution) -> Reaction {
    let u = sol.links[pl.on].u;
    let (prismatic, offset, at) = match pl.guide {
        Some((guide, d)) => {
            let dg = crate::state::rot(sol.links[guide].u, d);
            // force ⟂ guide: couple = x·(d × F) ⇒ x = couple / (d × F)
            let k = cross(dg, force);
            let x = if k.abs() > 1e-300 { couple / k } else { 0.0 };
            (true, x, at + dg * x)
        }
        None => (false, 0.0, at),
    };
    Reaction {
        pair: pl.pid,
        from: pl.from,
        on: pl.on,
        force,
        at,
        normal: force.dot(u),
        tangential: force.dot(perp(u)),
        offset,
        prismatic,
    }
}
