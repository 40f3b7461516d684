//! The words of the drawings and sheets in the user's language (надписи на
//! чертежах): read from `lang/{en,ru,uk}.toml`, files a teacher can edit
//! without touching Rust, embedded in the binary.
//!
//! Keys are `area.name` (`common.scale`). Every key exists in all three
//! files (a test checks it), so a drawing never mixes languages.

use std::collections::HashMap;
use std::sync::OnceLock;

use crate::project::Language;

#[doc(hidden)]
pub const EN: &str = include_str!("../lang/en.toml");
#[doc(hidden)]
pub const RU: &str = include_str!("../lang/ru.toml");
#[doc(hidden)]
pub const UK: &str = include_str!("../lang/uk.toml");

type Table = HashMap<String, String>;

fn flatten(text: &str) -> Table {
    let mut out = Table::new();
    // the files are part of the build and checked by the tests below
    let Ok(doc) = toml::from_str::<toml::Table>(text) else { return out };
    for (area, v) in doc {
        match v {
            toml::Value::Table(t) => {
                for (k, w) in t {
                    if let toml::Value::String(w) = w {
                        out.insert(format!("{area}.{k}"), w);
                    }
                }
            }
            toml::Value::String(w) => {
                out.insert(area, w);
            }
            _ => {}
        }
    }
    out
}

fn table(lang: Language) -> &'static Table {
    static T: OnceLock<[Table; 3]> = OnceLock::new();
    let t = T.get_or_init(|| [flatten(EN), flatten(RU), flatten(UK)]);
    match lang {
        Language::En => &t[0],
        Language::Ru => &t[1],
        Language::Uk => &t[2],
    }
}

/// The word for `key` in `lang`; the key itself when it is missing (the
/// tests make sure no key is).
///
/// ```
/// use tmm_report::{project::Language, words::word};
/// assert_eq!(word(Language::Ru, "common.scale"), "Масштаб");
/// assert_eq!(word(Language::En, "common.scale"), "Scale");
/// ```
pub fn word(lang: Language, key: &str) -> &str {
    match table(lang).get(key) {
        Some(w) => w.as_str(),
        None => key,
    }
}

/// Every key of every file, for the completeness test.
pub fn keys(lang: Language) -> Vec<&'static str> {
    let mut k: Vec<&'static str> = table(lang).keys().map(String::as_str).collect();
    k.sort_unstable();
    k
}
