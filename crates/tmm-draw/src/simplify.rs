//! Polyline simplification (упрощение ломаной) by Douglas–Peucker: the
//! vertices of a densely sampled curve that lie within a tolerance of the
//! chord of their neighbours kept are dropped, so a drawing carries the
//! points its print needs and no more. The drawings use
//! [`TOLERANCE_MM`] = 0.01 mm on paper: under a tenth of the thinnest line
//! GOST 2.303 allows (a thin line is s/3 … s/2, at least 0.17 mm at
//! s = 0.5 mm) and a quarter of a 600 dpi printer's dot (0.042 mm), so the
//! line drawn through the kept vertices covers the same dots as the one
//! through all of them. The first and the last vertex are always kept, so a closed curve
//! stays closed and a curve's ends (a diagram's cycle, a profile's ends)
//! stay exact; every kept vertex is one of the input's, unmoved.
//!
//! Source: D. H. Douglas, T. K. Peucker, "Algorithms for the reduction of
//! the number of points required to represent a digitized line or its
//! caricature", The Canadian Cartographer 10 (2), 1973, pp. 112–122.

use kurbo::Point;

/// The tolerance the drawings are simplified with, mm on paper: no
/// dropped vertex is farther than this from the line drawn instead.
pub const TOLERANCE_MM: f64 = 0.01;

/// The distance from `p` to the segment `a`–`b` (to `a` when the segment
/// has no length).
fn distance_to_segment(p: Point, a: Point, b: Point) -> f64 {
    let ab = b - a;
    let len2 = ab.hypot2();
    if len2 <= f64::MIN_POSITIVE {
        return (p - a).hypot();
    }
    let t = ((p - a).dot(ab) / len2).clamp(0.0, 1.0);
    (p - (a + ab * t)).hypot()
}

/// Marks in `keep` the vertices of `points[first..=last]` that
/// Douglas–Peucker keeps at `tolerance` (the ends are marked by the caller).
fn mark(points: &[Point], first: usize, last: usize, tolerance: f64, keep: &mut [bool], stack: &mut Vec<(usize, usize)>) {
    stack.push((first, last));
    while let Some((i, j)) = stack.pop() {
        if j <= i + 1 {
            continue;
        }
        let (a, b) = (points[i], points[j]);
        let mut far = (0.0, i);
        for (k, &p) in points.iter().enumerate().take(j).skip(i + 1) {
            let d = distance_to_segment(p, a, b);
            if d > far.0 {
                far = (d, k);
            }
        }
        if far.0 > tolerance {
            keep[far.1] = true;
            stack.push((i, far.1));
            stack.push((far.1, j));
        }
    }
}

/// The vertices of the open polyline `points` Douglas–Peucker keeps at
/// `tolerance` (mm): every dropped vertex lies within `tolerance` of the
/// segment between the kept vertices around it; the first and last are
/// kept. A non-finite or non-positive tolerance keeps every vertex.
///
/// ```
/// use kurbo::Point;
/// use tmm_draw::simplify::simplify;
/// // 101 points on a straight line and one corner: the ends and the corner stay
/// let mut pts: Vec<Point> = (0..=100).map(|i| Point::new(i as f64, 0.0)).collect();
/// pts.push(Point::new(100.0, 50.0));
/// let s = simplify(&pts, 0.01);
/// assert_eq!(s, vec![Point::new(0.0, 0.0), Point::new(100.0, 0.0), Point::new(100.0, 50.0)]);
/// // a quarter circle of radius 50 sampled every 0.05°: the chord error
/// // r(1 − cos(Δ/2)) ≤ 0.01 mm needs a step Δ ≤ 2 acos(1 − 0.01/50) ≈ 2.29°
/// let arc: Vec<Point> = (0..=1800).map(|i| {
///     let t = (i as f64 * 0.05).to_radians();
///     Point::new(50.0 * t.cos(), 50.0 * t.sin())
/// }).collect();
/// let s = simplify(&arc, 0.01);
/// assert!(s.len() as f64 > 90.0 / 2.29 && s.len() < 2 * 40 + 2, "{}", s.len());
/// assert_eq!((s[0], s[s.len() - 1]), (arc[0], arc[1800]));
/// ```
pub fn simplify(points: &[Point], tolerance: f64) -> Vec<Point> {
    let n = points.len();
    if n < 3 || !(tolerance.is_finite() && tolerance > 0.0) {
        return points.to_vec();
    }
    let mut keep = vec![false; n];
    keep[0] = true;
    keep[n - 1] = true;
    let mut stack = Vec::new();
    mark(points, 0, n - 1, tolerance, &mut keep, &mut stack);
    points.iter().zip(&keep).filter(|(_, k)| **k).map(|(p, _)| *p).collect()
}

/// The vertices of the closed polyline `points` (the last joins the
/// first; the first is not repeated) Douglas–Peucker keeps at
/// `tolerance`: the ring is cut at the first vertex and the vertex
/// farthest from it, and each half simplified as an open polyline, so
/// both stay.
///
/// ```
/// use kurbo::Point;
/// use tmm_draw::simplify::simplify_closed;
/// // a 10 × 10 square with every side sampled each millimetre: its corners remain
/// let mut sq = Vec::new();
/// for i in 0..10 { sq.push(Point::new(i as f64, 0.0)); }
/// for i in 0..10 { sq.push(Point::new(10.0, i as f64)); }
/// for i in 0..10 { sq.push(Point::new(10.0 - i as f64, 10.0)); }
/// for i in 0..10 { sq.push(Point::new(0.0, 10.0 - i as f64)); }
/// let s = simplify_closed(&sq, 0.01);
/// assert_eq!(s, vec![Point::new(0.0, 0.0), Point::new(10.0, 0.0), Point::new(10.0, 10.0), Point::new(0.0, 10.0)]);
/// ```
pub fn simplify_closed(points: &[Point], tolerance: f64) -> Vec<Point> {
    let n = points.len();
    if n < 4 || !(tolerance.is_finite() && tolerance > 0.0) {
        return points.to_vec();
    }
    let p0 = points[0];
    let (mut far, mut k) = (0.0, 0);
    for (i, p) in points.iter().enumerate().skip(1) {
        let d = (*p - p0).hypot2();
        if d > far {
            far = d;
            k = i;
        }
    }
    if k == 0 {
        return points.to_vec();
    }
    let mut keep = vec![false; n];
    keep[0] = true;
    keep[k] = true;
    let mut stack = Vec::new();
    mark(points, 0, k, tolerance, &mut keep, &mut stack);
    // the second half runs k … n−1 and back to the first vertex
    let mut ring: Vec<Point> = points[k..].to_vec();
    ring.push(p0);
    let mut keep_ring = vec![false; ring.len()];
    let last = ring.len() - 1;
    mark(&ring, 0, last, tolerance, &mut keep_ring, &mut stack);
    for (i, kept) in keep_ring.iter().enumerate().take(last).skip(1) {
        keep[k + i] = *kept;
    }
    points.iter().zip(&keep).filter(|(_, k)| **k).map(|(p, _)| *p).collect()
}
