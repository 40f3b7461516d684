//! Quality checks of a pair (проверка качества зацепления): undercut,
//! interference, tip pointing, contact ratio, and tip interference of internal pairs.

use crate::{Kind, Pair};

/// The limits the checks compare with.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Limits {
    /// Least tip thickness as a fraction of m (GOST 16532-70 recommends 0.3
    /// for through-hardened teeth and 0.4 for case-hardened; 0.25 is the
    /// usual course minimum).
    pub sa_min: f64,
    /// Least contact ratio εα (GOST 16532-70: ≥ 1.2 for spur pairs).
    pub eps_min: f64,
}

impl Default for Limits {
    /// sa ≥ 0.25·m, εα ≥ 1.2.
    fn default() -> Self {
        Limits {
            sa_min: 0.25,
            eps_min: 1.2,
        }
    }
}

/// Which check.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CheckKind {
    /// No undercut of wheel 1 or 2 by the rack: x ≥ xmin.
    Undercut(u8),
    /// No interference: ρl ≤ ρp.
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
        }
    }

    /// What the check says, in words.
    pub fn describe(&self) -> String {
        match self {
            CheckKind::Undercut(w) => format!("no undercut of wheel {w}: x{w} ≥ xmin{w}"),
            CheckKind::Interference(1) => "no interference at wheel 1: ρl1 ≤ ρp1".into(),
            CheckKind::Interference(w) => format!("no interference at wheel {w}: ρl{w} ≤ ρp{w}"),
            CheckKind::RingInterference => "no interference at the ring: ρp2 ≤ ρl2".into(),
            CheckKind::Pointing(w) => format!("no tip pointing of wheel {w}: sa{w} ≥ sa_min"),
            CheckKind::ContactRatio => "contact ratio εα ≥ εmin".into(),
            CheckKind::TipInterference => "no tip interference of the internal pair: margin ≥ 0".into(),
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

/// Up to eight checks, without allocation.
#[derive(Debug, Clone, Copy)]
pub struct Checks {
    items: [Check; 8],
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
        let mut out = Checks { items: [blank; 8], len: 0 };
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
        out.push(Check {
            kind: CheckKind::Interference(1),
            value: self.w1.rho_p,
            limit: self.w1.rho_l,
            pass: self.w1.rho_l <= self.w1.rho_p,
        });
        if internal {
            out.push(Check {
                kind: CheckKind::RingInterference,
                value: self.w2.rho_p,
                limit: self.w2.rho_l,
                pass: self.w2.rho_p <= self.w2.rho_l,
            });
        } else {
            out.push(Check {
                kind: CheckKind::Interference(2),
                value: self.w2.rho_p,
                limit: self.w2.rho_l,
                pass: self.w2.rho_l <= self.w2.rho_p,
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
        out
    }
}
