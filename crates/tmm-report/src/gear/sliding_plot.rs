//! The specific-sliding diagram ϑ1, ϑ2 over the active line of action.

use tmm_gears::Pair;

use crate::svg::{Series, plot};

/// The specific-sliding diagram over the active line (ϑ clipped to [−4, 1]).
pub fn sliding_svg(pair: &Pair) -> String {
    let tab = pair.sliding_table(101);
    let clip = |v: f64| if v.is_finite() { v.clamp(-4.0, 1.0) } else { f64::NAN };
    let a: Vec<(f64, f64)> = tab.iter().map(|q| (q.s * 1e3, clip(q.theta1))).collect();
    let b: Vec<(f64, f64)> = tab.iter().map(|q| (q.s * 1e3, clip(q.theta2))).collect();
    plot(
        "Specific sliding along the active line",
        "distance from N1, mm",
        "ϑ",
        &[
            Series {
                name: "ϑ1 (wheel 1)",
                points: &a,
                color: "#c00000",
            },
            Series {
                name: "ϑ2 (wheel 2)",
                points: &b,
                color: "#1f5fbf",
            },
        ],
        200.0,
        130.0,
    )
}
