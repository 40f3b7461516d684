use tmm_cams::{design::{CamTask, FollowerSpec}, mechanism::Rotation, program::Program, spec};
fn main() {
    let program = Program::new(0.013, spec::parse_phases("rise 108 const-accel(u=1/3); dwell 15; return 108 const-accel(u=1/3); dwell 129").unwrap()).unwrap();
    for f in [FollowerSpec::TranslatingRoller { offset: None, roller: None }, FollowerSpec::TranslatingRoller { offset: Some(0.0), roller: None }, FollowerSpec::TranslatingFlat { offset: 0.0 }] {
        for rot in [Rotation::Ccw, Rotation::Cw] {
        let task = CamTask { program: program.clone(), follower: f, rotation: rot, limits: spec::parse_limits("rise 75, return 60", true).unwrap(), min_curvature: None, face_margin: 0.005, omega: 200.0, points: 720 };
        let d = task.solve().unwrap();
        println!("{:?} {:?} r0={:.3} e={:?} roller={:.3} rise={:.3} ret={:.3} rho_p={:?} rho={:.3} face={:?}", f, rot, d.r0*1e3, d.offset().map(|e|e*1e3), d.roller*1e3, d.pressure_max_rise.to_degrees(), d.pressure_max_return.to_degrees(), d.rho_min_pitch.map(|r|r*1e3), d.rho_min*1e3, d.face);
        }
    }
    let prog2 = Program::new(20f64.to_radians(), spec::parse_phases("rise 108 sine; dwell 15; return 108 sine; dwell 129").unwrap()).unwrap();
    for f in [FollowerSpec::OscillatingRoller { arm: 0.1, pivot: None, roller: None }, FollowerSpec::OscillatingRoller { arm: 0.1, pivot: Some(0.12), roller: None }, FollowerSpec::OscillatingFlat { pivot: 0.1 }] {
        let task = CamTask { program: prog2.clone(), follower: f, rotation: Rotation::Ccw, limits: spec::parse_limits("30", false).unwrap(), min_curvature: None, face_margin: 0.005, omega: 200.0, points: 720 };
        match task.solve() { Ok(d) =>
        println!("{:?} r0={:.3} pivot={:?} roller={:.3} rise={:.3} ret={:.3} rho_p={:?} rho={:.3} face={:?} mech={:?}", f, d.r0*1e3, d.pivot_distance().map(|e|e*1e3), d.roller*1e3, d.pressure_max_rise.to_degrees(), d.pressure_max_return.to_degrees(), d.rho_min_pitch.map(|r|r*1e3), d.rho_min*1e3, d.face, d.mechanism), Err(e) => println!("{f:?}: {e}") }
    }
}
