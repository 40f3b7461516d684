//! Zhukovsky's lever of the report (`forces.lever`) carries every load the
//! kinetostatics carries, the gas forces of an engine's pistons included:
//! checked by virtual power against the kinetostatic balancing moment,
//! which comes from the Assur groups' reactions (an independent path):
//! the moment of a force F at the image k = v turned by +90° about the pole
//! is k × F = −F·v, so without P_b the moments sum to M_b·ω1 (M_b·ω1 + ΣF·v
//! = 0, Artobolevsky 1988, § 15), and with P_b to zero. Each gas force's
//! image is the velocity plan's velocity of its slider's pair (the
//! linkage section's plan, at the same position; scaled by the forces'
//! ω1 where the machine's crank speed differs from the plan's).

use serde_json::Value;
use tmm_report::TaskSource;
use tmm_report::run::{DEFAULT_TASK, run_task_in};
use tmm_testkit::examples;

fn report(name: &str, text: &str) -> Value {
    let run = run_task_in(&TaskSource::new(name, text), None).unwrap();
    run.report.clone()
}

fn xy(v: &Value, key: &str) -> (f64, f64) {
    let a = &v[key];
    (a[0].as_f64().unwrap(), a[1].as_f64().unwrap())
}

/// (Σ k × F without P_b, Σ k × F with it, Σ |k|·|F|) and the labels.
fn moments(r: &Value) -> (f64, f64, f64, Vec<String>) {
    let (mut without, mut with, mut scale) = (0.0, 0.0, 0.0);
    let mut labels = Vec::new();
    for e in r["forces"]["lever"].as_array().unwrap() {
        let (kx, ky) = xy(e, "image");
        let (fx, fy) = xy(e, "force");
        let m = kx * fy - ky * fx;
        let label = e["label"].as_str().unwrap().to_string();
        if label != "Pb" {
            without += m;
        }
        with += m;
        scale += kx.hypot(ky) * fx.hypot(fy);
        labels.push(label);
    }
    (without, with, scale, labels)
}

#[test]
fn lever_virtual_power() {
    for (name, text, gas) in [
        ("textbook/p2-engine.toml", examples::text("textbook/p2-engine.toml"), 2),
        ("compressor-two-stage.toml", examples::text("compressor-two-stage.toml"), 2),
        ("default.toml", DEFAULT_TASK.to_string(), 0),
    ] {
        let r = report(name, &text);
        let d = &r["forces"]["detail"];
        let mb = d["balancing_moment"].as_f64().unwrap();
        let w1 = d["omega1"].as_f64().unwrap();
        let (without, with, scale, labels) = moments(&r);
        assert!(
            (without - mb * w1).abs() <= 1e-9 * scale,
            "{name}: Σ k×F = {without}, M_b·ω1 = {}",
            mb * w1
        );
        assert!(with.abs() <= 1e-9 * scale, "{name}: the lever with P_b is off by {with}");
        let fc: Vec<&Value> = r["forces"]["lever"]
            .as_array()
            .unwrap()
            .iter()
            .filter(|e| e["label"].as_str().unwrap().starts_with("Fc"))
            .collect();
        assert_eq!(fc.len(), gas, "{name}: {labels:?}");
        // each gas force at the image of its slider's pair on the velocity plan
        let plan_w = r["linkage"]["input"]["omega"].as_f64().unwrap();
        let same_phi = (r["linkage"]["plans"]["phi"].as_f64().unwrap() - d["phi"].as_f64().unwrap()).abs() < 1e-9;
        for e in fc {
            let link = &e["label"].as_str().unwrap()[2..];
            let pair = r["linkage"]["structure"]["pairs"]
                .as_array()
                .unwrap()
                .iter()
                .find(|p| p["kind"] == "P" && p["links"].as_array().unwrap().iter().any(|l| l == link))
                .unwrap_or_else(|| panic!("{name}: no slider pair of link {link}"));
            let point = pair["point"].as_str().unwrap();
            if !same_phi {
                continue;
            }
            let v = r["linkage"]["plans"]["velocity"]
                .as_array()
                .unwrap()
                .iter()
                .find(|v| v["label"] == format!("V_{point}"))
                .unwrap();
            let (fx0, fy0) = xy(v, "from");
            let (tx, ty) = xy(v, "to");
            let s = w1 / plan_w;
            let (vx, vy) = ((tx - fx0) * s, (ty - fy0) * s);
            let (kx, ky) = xy(e, "image");
            assert!(
                (kx + vy).abs() < 1e-9 * vx.hypot(vy).max(1.0) && (ky - vx).abs() < 1e-9 * vx.hypot(vy).max(1.0),
                "{name}: the image of F_c{link} ({kx}, {ky}) is not v_{point} = ({vx}, {vy}) turned by 90°"
            );
            // the force is the report's slider force
            let (fx, fy) = xy(e, "force");
            assert!(fx.hypot(fy) > 0.0);
        }
    }
}
