//! The page's own words (надписи страницы) in Russian, Ukrainian and
//! English: the `[web]` area of the word files the drawings and sheets use
//! (`crates/tmm-report/lang/{ru,uk,en}.toml`, read by
//! [`tmm_report::words`]), so a teacher edits the page's words in the same
//! files, and every key exists in all three languages (their test checks
//! it).

use tmm_report::project::Language;
use tmm_report::words::{keys, word};

/// The `[web]` words in `lang` (`ru`, `uk`, `en`; anything else: English)
/// as JSON `{"lang": code, "words": {key: text}}`, keys without the `web.`
/// prefix.
///
/// ```
/// let v: serde_json::Value = serde_json::from_str(&tmm_web::ui_words::json("ru")).unwrap();
/// assert_eq!(v["lang"], "ru");
/// assert_eq!(v["words"]["tab_mechanism"], "Механизм");
/// let e: serde_json::Value = serde_json::from_str(&tmm_web::ui_words::json("xx")).unwrap();
/// assert_eq!(e["words"]["tab_mechanism"], "Mechanism");
/// ```
pub fn json(lang: &str) -> String {
    let l = Language::from_code(lang).unwrap_or(Language::En);
    let mut words = serde_json::Map::new();
    for k in keys(l) {
        if let Some(short) = k.strip_prefix("web.") {
            words.insert(short.to_string(), word(l, k).into());
        }
    }
    serde_json::json!({ "lang": l.code(), "words": words }).to_string()
}
