//! Structural analysis (структурный анализ): Chebyshev's mobility, the
//! decomposition into the input mechanism and Assur groups (группы Ассура),
//! each group's class, order and kind, and the structure formula (формула
//! строения).
//!
//! Conventions (Artobolevsky I.I., *Теория механизмов и машин*, 1988, §§ 5–6):
//! - W = 3n − 2p5 − p4 (Chebyshev–Grübler).
//! - The input mechanism is class I: the crank with the frame, `I(0,1)`.
//! - An Assur group has W = 0 and cannot be split into smaller such groups.
//!   A dyad (2 links, 3 pairs) is class II, order 2; its kind is the sequence of
//!   pair types from one outer pair through the inner pair to the other (RRR,
//!   RRP, RPR, PRP, RPP). A 4-link group with a base link of three inner pairs is
//!   class III (triad), order 3; one whose inner pairs close a four-sided contour
//!   is class IV, order 2.
//! - The class of the mechanism is the highest class of its groups.
//!
//! The decomposition here is a search: from the known links (frame and
//! crank), take the smallest set of unknown links that forms a group (2, then
//! 4, then 6 links with 3k/2 pairs among themselves and the known links), make
//! it known, repeat.

use serde::Serialize;

/// Kind of a lower pair.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
pub enum PairKind {
    /// Revolute pair (вращательная пара).
    R,
    /// Prismatic pair (поступательная пара).
    P,
}

/// A pair as structural analysis sees it: two links and a kind.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct PairLink {
    /// One link (0 is the frame).
    pub a: usize,
    /// The other link.
    pub b: usize,
    /// R or P.
    pub kind: PairKind,
}

/// One Assur group.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct GroupInfo {
    /// Class (класс) in Artobolevsky's convention: 2 for a dyad.
    pub class: u32,
    /// Order (порядок): the number of outer pairs.
    pub order: u32,
    /// Kind: `RRR`, `RRP`, `RPR`, `PRP`, `RPP` for dyads; the pair letters of
    /// larger groups, outer pairs first.
    pub kind: String,
    /// Link names in the group, in solving order.
    pub links: Vec<String>,
    /// Indices of the links (internal numbering).
    #[serde(skip)]
    pub link_ids: Vec<usize>,
    /// Indices of the pairs of the group (outer and inner).
    #[serde(skip)]
    pub pair_ids: Vec<usize>,
}

/// The structure of a mechanism.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Structure {
    /// Degree of freedom by Chebyshev.
    pub dof: i64,
    /// Moving links.
    pub n: usize,
    /// Lower (class V) pairs.
    pub p5: usize,
    /// Higher (class IV) pairs (none in lever mechanisms).
    pub p4: usize,
    /// Assur groups in solving order.
    pub groups: Vec<GroupInfo>,
    /// Structure formula, e.g. `I(0,1) → II(2,3) → II(4,5)`.
    pub formula: String,
    /// Class of the mechanism (the highest class of its groups; 1 with none).
    pub class: u32,
    /// Degree of freedom from the rank of the constraint equations.
    pub dof_rank: i64,
    /// Redundant constraints (избыточные связи) q = 2p5 + p4 − rank.
    pub redundant: i64,
    /// Passive freedoms (местные подвижности): motions left with the crank held.
    pub passive: i64,
}

/// Roman numeral for a class.
pub fn roman(n: u32) -> &'static str {
    match n {
        1 => "I",
        2 => "II",
        3 => "III",
        4 => "IV",
        5 => "V",
        6 => "VI",
        _ => "?",
    }
}

/// A group as found: its links and its pairs (indices).
pub type GroupSets = (Vec<usize>, Vec<usize>);

/// Decompose: `n_links` links (0 = frame), `pairs`, `input` the crank link.
/// Returns groups as (links, pairs) in solving order, or the links left over.
///
/// ```
/// use tmm_linkage::structure::{decompose, PairLink, PairKind::*};
/// // four-bar: frame 0, crank 1, coupler 2, rocker 3
/// let pairs = [PairLink { a: 0, b: 1, kind: R }, PairLink { a: 1, b: 2, kind: R },
///              PairLink { a: 2, b: 3, kind: R }, PairLink { a: 3, b: 0, kind: R }];
/// let g = decompose(4, &pairs, 1).unwrap();
/// assert_eq!(g.len(), 1);
/// assert_eq!(g[0].0, vec![2, 3]);
/// ```
pub fn decompose(n_links: usize, pairs: &[PairLink], input: usize) -> Result<Vec<GroupSets>, Vec<usize>> {
    let mut known = vec![false; n_links];
    known[0] = true;
    known[input] = true;
    let mut groups = Vec::new();
    loop {
        let unknown: Vec<usize> = (0..n_links).filter(|&i| !known[i]).collect();
        if unknown.is_empty() {
            return Ok(groups);
        }
        let mut found = None;
        'sizes: for size in [2usize, 4, 6] {
            if size > unknown.len() {
                break;
            }
            let mut comb: Vec<usize> = (0..size).collect();
            loop {
                let set: Vec<usize> = comb.iter().map(|&c| unknown[c]).collect();
                if let Some(pids) = is_group(&set, pairs, &known) {
                    found = Some((set, pids));
                    break 'sizes;
                }
                if !next_comb(&mut comb, unknown.len()) {
                    break;
                }
            }
        }
        match found {
            Some((set, pids)) => {
                for &l in &set {
                    known[l] = true;
                }
                groups.push((set, pids));
            }
            None => return Err(unknown),
        }
    }
}

fn next_comb(c: &mut [usize], n: usize) -> bool {
    let k = c.len();
    let mut i = k;
    while i > 0 {
        i -= 1;
        if c[i] < n - k + i {
            c[i] += 1;
            for j in i + 1..k {
                c[j] = c[j - 1] + 1;
            }
            return true;
        }
    }
    false
}

/// `Some(pairs)` when `set` (unknown links) with its pairs to itself and to the
/// known links is a group: 3k = 2p, every link has at least two such pairs,
/// at least two outer pairs, and the set is connected through inner pairs.
fn is_group(set: &[usize], pairs: &[PairLink], known: &[bool]) -> Option<Vec<usize>> {
    let inset = |l: usize| set.contains(&l);
    let mut pids = Vec::new();
    let mut outer = 0;
    for (i, p) in pairs.iter().enumerate() {
        let (ia, ib) = (inset(p.a), inset(p.b));
        if (ia && (ib || known[p.b])) || (ib && known[p.a]) {
            pids.push(i);
            if !(ia && ib) {
                outer += 1;
            }
        }
    }
    if 3 * set.len() != 2 * pids.len() || outer < 2 {
        return None;
    }
    for &l in set {
        let deg = pids.iter().filter(|&&i| pairs[i].a == l || pairs[i].b == l).count();
        if deg < 2 {
            return None;
        }
    }
    // connected through inner pairs
    let mut seen = vec![set[0]];
    let mut grew = true;
    while grew {
        grew = false;
        for &i in &pids {
            let p = pairs[i];
            if inset(p.a) && inset(p.b) {
                let (sa, sb) = (seen.contains(&p.a), seen.contains(&p.b));
                if sa != sb {
                    seen.push(if sa { p.b } else { p.a });
                    grew = true;
                }
            }
        }
    }
    if seen.len() != set.len() {
        return None;
    }
    Some(pids)
}

/// Class, order and kind of a group (links in `set`, pairs `pids`).
/// For a dyad the links are reordered so that the first carries the first
/// outer pair, and the kind reads outer–inner–outer.
pub fn classify(set: &mut [usize], pids: &mut Vec<usize>, pairs: &[PairLink]) -> (u32, u32, String) {
    let inset = |l: usize| set.contains(&l);
    let letter = |k: PairKind| if k == PairKind::R { 'R' } else { 'P' };
    let outer: Vec<usize> = pids
        .iter()
        .copied()
        .filter(|&i| !(inset(pairs[i].a) && inset(pairs[i].b)))
        .collect();
    let inner: Vec<usize> = pids.iter().copied().filter(|&i| inset(pairs[i].a) && inset(pairs[i].b)).collect();
    let order = outer.len() as u32;
    if set.len() == 2 {
        let on = |l: usize, i: usize| pairs[i].a == l || pairs[i].b == l;
        let (l1, l2) = (set[0], set[1]);
        let e1 = *outer.iter().find(|&&i| on(l1, i)).unwrap_or(&outer[0]);
        let e2 = *outer.iter().find(|&&i| on(l2, i) && i != e1).unwrap_or(&outer[1]);
        let m = inner[0];
        let mut kind: String = [letter(pairs[e1].kind), letter(pairs[m].kind), letter(pairs[e2].kind)]
            .iter()
            .collect();
        // Normalise mirrored kinds: PRR → RRP, PPR → RPP (swap the links).
        if kind == "PRR" || kind == "PPR" {
            set.swap(0, 1);
            *pids = vec![e2, m, e1];
            kind = kind.chars().rev().collect();
        } else {
            *pids = vec![e1, m, e2];
        }
        return (2, order, kind);
    }
    let max_inner_deg = set
        .iter()
        .map(|&l| inner.iter().filter(|&&i| pairs[i].a == l || pairs[i].b == l).count())
        .max()
        .unwrap_or(0) as u32;
    let class = if max_inner_deg >= 3 { max_inner_deg } else { inner.len() as u32 };
    let kind: String = outer.iter().chain(inner.iter()).map(|&i| letter(pairs[i].kind)).collect();
    (class.max(3), order, kind)
}
