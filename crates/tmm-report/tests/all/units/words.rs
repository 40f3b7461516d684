//! Tests of `tmm_report::words`, kept outside the library so that the
//! test command compiles it once.

use tmm_report::project::Language;
use tmm_report::words::*;

#[test]
fn the_files_parse_and_have_the_same_keys() {
    for text in [EN, RU, UK] {
        assert!(toml::from_str::<toml::Table>(text).is_ok());
    }
    let en = keys(Language::En);
    assert!(!en.is_empty());
    for l in [Language::Ru, Language::Uk] {
        assert_eq!(keys(l), en, "{} differs from en", l.code());
        for k in &en {
            assert!(!word(l, k).trim().is_empty(), "{k} empty in {}", l.code());
        }
    }
}
