//! The fixed words of the note in each language, read from
//! `lang/{ru,uk,en}.toml`.
//!
//! The files are embedded in the binary (`include_str!`) and parsed with
//! `toml`; a teacher edits them without touching Rust. Every key of
//! [`KEYS`] is required in every file and no other key is allowed, so a typo
//! is an error, not a silently missing heading.

use std::collections::BTreeMap;

use crate::error::NoteError;
use crate::model::Lang;

/// Every key of a translation file, in the order the files list them.
pub const KEYS: &[&str] = &[
    "note_title",
    "note_subtitle",
    "quote_open",
    "quote_close",
    "variant",
    "performed_by",
    "checked_by",
    "assignment",
    "assignment_attached",
    "contents",
    "sources",
    "appendix",
    "appendix_letters",
    "figure",
    "table",
    "tb_change",
    "tb_sheet",
    "tb_doc_number",
    "tb_signature",
    "tb_date",
    "tb_developed",
    "tb_checked",
    "tb_norm_control",
    "tb_approved",
    "tb_letter",
    "tb_letter_value",
    "tb_sheets",
    "tb_document",
    "table_continued",
];

/// The embedded source of a language's translation file.
pub fn source(lang: Lang) -> &'static str {
    match lang {
        Lang::Ru => include_str!("../lang/ru.toml"),
        Lang::Uk => include_str!("../lang/uk.toml"),
        Lang::En => include_str!("../lang/en.toml"),
    }
}

/// The fixed words of one language: key → text.
#[derive(Debug, Clone, PartialEq)]
pub struct Translation {
    words: BTreeMap<String, String>,
}

impl Translation {
    /// Loads the embedded translation of `lang`.
    ///
    /// ```
    /// let t = tmm_note::Translation::load(tmm_note::Lang::Uk).unwrap();
    /// assert_eq!(t.get("contents"), "Зміст");
    /// ```
    ///
    /// # Errors
    /// [`NoteError::Translation`] if the file is not valid TOML, misses a key
    /// of [`KEYS`], has another key or a value that is not a string.
    pub fn load(lang: Lang) -> Result<Self, NoteError> {
        Self::parse(lang, source(lang))
    }

    /// Parses a translation file's text (used for the embedded files and to
    /// test an edited one).
    ///
    /// # Errors
    /// As [`Translation::load`].
    pub fn parse(lang: Lang, text: &str) -> Result<Self, NoteError> {
        let err = |message: String| NoteError::Translation {
            lang: lang.code(),
            message,
        };
        let table: toml::Table = toml::from_str(text).map_err(|e| err(e.to_string()))?;
        let mut words = BTreeMap::new();
        for (key, value) in table {
            if !KEYS.contains(&key.as_str()) {
                return Err(err(format!("unknown key {key:?}; the keys are {KEYS:?}")));
            }
            let toml::Value::String(s) = value else {
                return Err(err(format!("key {key:?} must be a string")));
            };
            words.insert(key, s);
        }
        if let Some(missing) = KEYS.iter().find(|k| !words.contains_key(**k)) {
            return Err(err(format!("missing key {missing:?}")));
        }
        Ok(Translation { words })
    }

    /// The text of `key` (an empty string for a key not in [`KEYS`]).
    pub fn get(&self, key: &str) -> &str {
        self.words.get(key).map_or("", String::as_str)
    }

    /// The appendix letters, in order.
    pub fn appendix_letters(&self) -> Vec<&str> {
        self.get("appendix_letters").split_whitespace().collect()
    }

    /// All pairs, sorted by key.
    pub fn iter(&self) -> impl Iterator<Item = (&str, &str)> {
        self.words.iter().map(|(k, v)| (k.as_str(), v.as_str()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn all_three_files_have_the_same_keys() {
        let key_set = |lang| {
            let t: toml::Table = toml::from_str(source(lang)).unwrap();
            t.keys().cloned().collect::<std::collections::BTreeSet<_>>()
        };
        let expected: std::collections::BTreeSet<String> = KEYS.iter().map(|s| s.to_string()).collect();
        for lang in Lang::ALL {
            assert_eq!(key_set(lang), expected, "{lang:?}");
            Translation::load(lang).unwrap();
        }
    }

    #[test]
    fn a_missing_or_unknown_key_is_an_error() {
        let text = source(Lang::Ru).replace("contents = ", "contentz = ");
        let e = Translation::parse(Lang::Ru, &text).unwrap_err();
        assert!(e.to_string().contains("contentz"), "{e}");
        let text: String = source(Lang::En)
            .lines()
            .filter(|l| !l.starts_with("tb_date"))
            .collect::<Vec<_>>()
            .join("\n");
        let e = Translation::parse(Lang::En, &text).unwrap_err();
        assert!(e.to_string().contains("tb_date"), "{e}");
    }

    #[test]
    fn the_title_block_words_of_the_brief() {
        let uk = Translation::load(Lang::Uk).unwrap();
        let words: Vec<&str> = [
            "tb_developed",
            "tb_checked",
            "tb_norm_control",
            "tb_approved",
            "tb_letter",
            "tb_sheet",
            "tb_sheets",
        ]
        .iter()
        .map(|k| uk.get(k))
        .collect();
        assert_eq!(words, ["Розроб.", "Перев.", "Н. контр.", "Затв.", "Літ.", "Арк.", "Арків."]);
        let ru = Translation::load(Lang::Ru).unwrap();
        assert_eq!(ru.appendix_letters().len(), 25);
        assert!(!ru.appendix_letters().contains(&"З"));
    }
}
