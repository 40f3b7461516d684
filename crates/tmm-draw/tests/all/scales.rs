//! GOST 2.302 scales: the series, round trips, captions, fitting.

use tmm_draw::Scale;

#[test]
fn every_scale_round_trips_model_to_paper_and_back() {
    for s in Scale::all() {
        for model in [1.0, 37.5, 250.0, 1234.5] {
            let paper = s.to_paper(model);
            assert!((s.to_model(paper) - model).abs() < 1e-9 * model, "{s:?}");
            // the paper length is the model length times the printed ratio
            let cap = s.caption('.');
            let (a, b) = cap.split_once(':').unwrap();
            let ratio: f64 = a.parse::<f64>().unwrap() / b.parse::<f64>().unwrap();
            assert!((paper - model * ratio).abs() < 1e-9 * paper.max(1.0), "{cap}");
        }
    }
}

#[test]
fn only_gost_ratios_exist() {
    for n in [2.0, 2.5, 4.0, 5.0, 10.0, 15.0, 20.0, 25.0, 40.0, 50.0, 75.0, 100.0] {
        assert!(Scale::reduction(n).is_ok(), "1:{n}");
    }
    for n in [2.0, 2.5, 4.0, 5.0, 10.0, 20.0] {
        assert!(Scale::enlargement(n).is_ok(), "{n}:1");
    }
    for n in [3.0, 6.0, 2.4, 1.5, 0.5, f64::NAN, f64::INFINITY, 15.0 + 1e-6] {
        assert!(Scale::reduction(n).is_err(), "1:{n}");
    }
    assert!(Scale::enlargement(15.0).is_err());
    let msg = Scale::reduction(3.0).unwrap_err().to_string();
    assert!(msg.contains("1:2.5") && msg.contains("GOST 2.302"), "{msg}");
}

#[test]
fn captions_use_the_decimal_separator_asked_for() {
    assert_eq!(Scale::reduction(2.5).unwrap().caption(','), "1:2,5");
    assert_eq!(Scale::enlargement(2.5).unwrap().caption(','), "2,5:1");
    assert_eq!(Scale::NATURAL.caption(','), "1:1");
    assert_eq!(Scale::reduction(1.0).unwrap(), Scale::NATURAL);
}

#[test]
fn fit_picks_the_largest_scale_not_above_the_room() {
    // brute force over the series: the fitted scale is the largest factor ≤ room
    for room in [0.01, 0.05, 0.3, 0.4, 0.41, 0.99, 1.0, 2.4, 2.5, 7.0, 150.0] {
        let want = Scale::all()
            .filter(|s| s.factor() <= room)
            .max_by(|a, b| a.factor().total_cmp(&b.factor()));
        assert_eq!(Scale::fit(room), want, "room {room}");
    }
}
