//! Quality checks of a pair (проверка качества зацепления): undercut,
//! interference, tip pointing, contact ratio, and tip interference of internal pairs.

use crate::{Kind, Pair};

/// Least tip thickness for teeth of uniform (through-hardened) material,
/// sa ≥ 0.3·m: GOST 16532-70 (quoted in seed 001, §IV: "ГОСТ 16532-70
/// рекомендует иметь Sа ≥ 0,3m при однородной структуре материала зубьев").
/// The default: a course pair is through-hardened unless stated otherwise.
pub const SA_MIN_THROUGH_HARDENED: f64 = 0.3;

/// Least tip thickness for surface-hardened (case-hardened, nitrided) teeth,
/// sa ≥ 0.4·m: GOST 16532-70 (same place: "Sа ≥ 0,4m при поверхностном
/// упрочнении зубьев").
pub const SA_MIN_CASE_HARDENED: f64 = 0.4;

/// Least contact ratio of a spur pair, εα ≥ 1.2 (GOST 16532-70; seed 001 §IV).
pub const EPS_MIN: f64 = 1.2;

/// The limits the checks compare with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// Least tip thickness as a fraction of m: [`SA_MIN_THROUGH_HARDENED`]
    /// (0.3, the default) or [`SA_MIN_CASE_HARDENED`] (0.4), GOST 16532-70.
    pub sa_min: f64,
    /// Least contact ratio εα (GOST 16532-70: ≥ 1.2 for spur pairs).
    pub eps_min: f64,
}

impl Default for Limits {
    /// sa ≥ 0.3·m (GOST 16532-70, uniform material), εα ≥ 1.2.
    fn default() -> Self {
        Limits {
            sa_min: SA_MIN_THROUGH_HARDENED,
            eps_min: EPS_MIN,
        }
    }
}

/// Which check.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CheckKind {
    /// No undercut of wheel 1 or 2 by the rack: x ≥ xmin.
    Undercut(u8),
    /// No interference: max(ρl, 0) ≤ ρp (the contact must not pass the
    /// form point, nor N on the line of action).
    Interference(u8),
    /// No interference at a ring: its contact with the pinion tip stays inside
    /// its generated involute, ρp2 ≤ ρl2.
    RingInterference,
    /// No tip pointing: sa ≥ sa_min·m.
    Pointing(u8),
    /// Contact ratio εα ≥ εmin.
    ContactRatio,
    /// Internal pair: tip interference margin ≥ 0.
    TipInterference,
    /// Internal pair: trimming (radial assembly) margin ≥ 0; a pair that fails
    /// runs, but can only be assembled by sliding the pinion in axially.
    Trimming,
}

impl CheckKind {
    /// A stable key for JSON (`undercut1`, `interference2`, `contact_ratio`, …).
    pub fn key(&self) -> String {
        match self {
            CheckKind::Undercut(w) => format!("undercut{w}"),
            CheckKind::Interference(w) => format!("interference{w}"),
            CheckKind::RingInterference => "interference2".into(),
            CheckKind::Pointing(w) => format!("pointing{w}"),
            CheckKind::ContactRatio => "contact_ratio".into(),
            CheckKind::TipInterference => "tip_interference".into(),
            CheckKind::Trimming => "trimming".into(),
        }
    }

    /// What the check says, in words.
    pub fn describe(&self) -> String {
        match self {
            CheckKind::Undercut(w) => format!("no undercut of wheel {w}: x{w} ≥ xmin{w}"),
            CheckKind::Interference(w) => format!("no interference at wheel {w}: max(ρl{w}, 0) ≤ ρp{w}"),
            CheckKind::RingInterference => "no interference at the ring: ρp2 ≤ ρl2".into(),
            CheckKind::Pointing(w) => format!("no tip pointing of wheel {w}: sa{w} ≥ sa_min"),
            CheckKind::ContactRatio => "contact ratio εα ≥ εmin".into(),
            CheckKind::TipInterference => "no tip interference of the internal pair: margin ≥ 0".into(),
            CheckKind::Trimming => "radial assembly without trimming (else the pinion goes in axially only): margin ≥ 0".into(),
        }
    }
}

/// One check: the value, the limit it is compared with, and the verdict.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Check {
    /// Which check.
    pub kind: CheckKind,
    /// The value (SI: m for ρ and sa, plain numbers otherwise).
    pub value: f64,
    /// The limit.
    pub limit: f64,
    /// `true` when the check passes.
    pub pass: bool,
}

/// Up to ten checks, without allocation.
#[derive(Debug, Clone, Copy)]
pub struct Checks {
    items: [Check; 10],
    len: usize,
}

impl Checks {
    fn push(&mut self, c: Check) {
        self.items[self.len] = c;
        self.len += 1;
    }

    /// The checks as a slice.
    pub fn as_slice(&self) -> &[Check] {
        &self.items[..self.len]
    }

    /// `true` when every check passes.
    pub fn all_pass(&self) -> bool {
        self.as_slice().iter().all(|c| c.pass)
    }
}

impl Pair {
    /// Every quality check of the pair against `lim` (GOST 16532-70 §4; seed 001 §IV).
    ///
    /// ```
    /// use tmm_gears::{Pair, PairSpec, Limits};
    /// let p = Pair::new(&PairSpec::external(15, 20, 0.005, 0.2, 0.85)).unwrap();
    /// let c = p.checks(&Limits::default());
    /// assert!(c.all_pass());
    /// ```
    pub fn checks(&self, lim: &Limits) -> Checks {
        let blank = Check {
            kind: CheckKind::ContactRatio,
            value: 0.0,
            limit: 0.0,
            pass: true,
        };
        let mut out = Checks {
            items: [blank; 10],
            len: 0,
        };
        let internal = self.spec.kind == Kind::Internal;
        let m = self.spec.m;
        for (i, w) in [(1u8, &self.w1), (2u8, &self.w2)] {
            if let Some(xm) = w.xmin {
                out.push(Check {
                    kind: CheckKind::Undercut(i),
                    value: w.x,
                    limit: xm,
                    pass: w.x >= xm - 1e-12,
                });
            }
        }
        // Below ρl < 0 (undercut) the involute still ends at the base circle,
        // ρ = 0 (N on the line of action): compare with max(ρl, 0).
        let limit1 = self.w1.rho_l.max(0.0);
        out.push(Check {
            kind: CheckKind::Interference(1),
            value: self.w1.rho_p,
            limit: limit1,
            pass: limit1 <= self.w1.rho_p,
        });
        if internal {
            out.push(Check {
                kind: CheckKind::RingInterference,
                value: self.w2.rho_p,
                limit: self.w2.rho_l,
                pass: self.w2.rho_p <= self.w2.rho_l,
            });
        } else {
            let limit2 = self.w2.rho_l.max(0.0);
            out.push(Check {
                kind: CheckKind::Interference(2),
                value: self.w2.rho_p,
                limit: limit2,
                pass: limit2 <= self.w2.rho_p,
            });
        }
        for (i, w) in [(1u8, &self.w1), (2u8, &self.w2)] {
            let lim_sa = lim.sa_min * m;
            out.push(Check {
                kind: CheckKind::Pointing(i),
                value: w.sa,
                limit: lim_sa,
                pass: w.sa >= lim_sa,
            });
        }
        out.push(Check {
            kind: CheckKind::ContactRatio,
            value: self.eps_alpha,
            limit: lim.eps_min,
            pass: self.eps_alpha >= lim.eps_min,
        });
        if let Some(t) = self.tip_interference {
            out.push(Check {
                kind: CheckKind::TipInterference,
                value: t,
                limit: 0.0,
                pass: t >= 0.0,
            });
        }
        if let Some(t) = self.trimming {
            out.push(Check {
                kind: CheckKind::Trimming,
                value: t,
                limit: 0.0,
                pass: t >= 0.0,
            });
        }
        out
    }
}
