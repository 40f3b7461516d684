//! Numbers in messages: long ones are shortened, all else is kept.

use tmm_report::message_numbers::tidy;

#[test]
fn long_numbers_are_shortened_and_the_rest_is_kept() {
    // written by Rust's `{}` and `{:.4}`: the digits counted here by hand
    let full = format!("{}", 1e300);
    assert_eq!(full.len(), 301);
    assert_eq!(tidy(&format!("ω = {full} рад/с")), "ω = 1e300 рад/с");
    assert_eq!(tidy(&format!("{:.4} mm", -1e-300)), "-0.0000 mm"); // 5 digits: kept
    assert_eq!(tidy(&format!("{} mm", 1e-300)), "1e-300 mm");
    assert_eq!(tidy("1.0471975511965977e8 rad/s"), "1.0472e8 rad/s");
    // short numbers, field names and places are not touched
    for keep in [
        "task.toml:12:9: gear.z1: z1 = 4294967295 is too many",
        "x2 = -1.25, αw = 20.0000°, 123456789012",
        "v1.2.3, sheet-1.svg, 0.3",
        "значение 1e300 вне диапазона",
        "",
    ] {
        assert_eq!(tidy(keep), keep);
    }
    // a 13-digit number is the first to change
    assert_eq!(tidy("1234567890123"), "1.23457e12");
    // numbers glued to a word are part of the word
    assert_eq!(tidy("id_12345678901234567890"), "id_12345678901234567890");
}
