//! The words of the composed note's body (текст разделов записки) in each
//! language, read from `lang/body/{ru,uk,en}.toml`.
//!
//! The files are embedded in the binary and are plain `key = "text"` lines a
//! teacher edits without touching Rust. A text may hold the places `{1}`,
//! `{2}` … that [`Words::fill`] replaces with numbers already formatted for the
//! language. Every language must have the same keys (a test checks it), and
//! a key the code asks for but a file lacks is a typed error, never a panic.

use std::collections::BTreeMap;

use crate::error::NoteError;
use crate::model::Lang;

/// The embedded source of a language's body-words file.
pub fn source(lang: Lang) -> &'static str {
    match lang {
        Lang::Ru => include_str!("../../lang/body/ru.toml"),
        Lang::Uk => include_str!("../../lang/body/uk.toml"),
        Lang::En => include_str!("../../lang/body/en.toml"),
    }
}

/// The body words of one language: key → text.
#[derive(Debug, Clone, PartialEq)]
pub struct Words {
    lang: Lang,
    words: BTreeMap<String, String>,
}

impl Words {
    /// Loads the embedded words of `lang`.
    ///
    /// ```
    /// let w = tmm_note::compose::Words::load(tmm_note::Lang::En).unwrap();
    /// assert_eq!(w.get("sub_conclusions").unwrap(), "Conclusions");
    /// ```
    ///
    /// # Errors
    /// [`NoteError::Translation`] if the file is not valid TOML or a value is
    /// not a string.
    pub fn load(lang: Lang) -> Result<Self, NoteError> {
        Self::parse(lang, source(lang))
    }

    /// Parses a body-words file's text.
    ///
    /// # Errors
    /// As [`Words::load`].
    pub fn parse(lang: Lang, text: &str) -> Result<Self, NoteError> {
        let err = |message: String| NoteError::Translation {
            lang: lang.code(),
            message,
        };
        let table: toml::Table = toml::from_str(text).map_err(|e| err(format!("lang/body/{}.toml: {e}", lang.code())))?;
        let mut words = BTreeMap::new();
        for (k, v) in table {
            match v {
                toml::Value::String(s) => {
                    words.insert(k, s);
                }
                _ => return Err(err(format!("lang/body/{}.toml: {k} is not a text", lang.code()))),
            }
        }
        Ok(Words { lang, words })
    }

    /// The keys, sorted.
    pub fn keys(&self) -> impl Iterator<Item = &str> {
        self.words.keys().map(String::as_str)
    }

    /// The text of `key`.
    ///
    /// # Errors
    /// [`NoteError::Translation`] naming the key if the file lacks it.
    pub fn get(&self, key: &str) -> Result<&str, NoteError> {
        self.words.get(key).map(String::as_str).ok_or_else(|| NoteError::Translation {
            lang: self.lang.code(),
            message: format!("lang/body/{}.toml has no key {key}", self.lang.code()),
        })
    }

    /// The text of `key` with `{1}`, `{2}` … replaced by `args`.
    ///
    /// ```
    /// let w = tmm_note::compose::Words::parse(tmm_note::Lang::En, "k = \"a {1} b {2}\"").unwrap();
    /// assert_eq!(w.fill("k", &["1.5".into(), "x".into()]).unwrap(), "a 1.5 b x");
    /// ```
    ///
    /// # Errors
    /// As [`Words::get`].
    pub fn fill(&self, key: &str, args: &[String]) -> Result<String, NoteError> {
        let mut s = self.get(key)?.to_string();
        // from the last place down, so {1} does not eat the start of {10}
        for (i, a) in args.iter().enumerate().rev() {
            s = s.replace(&format!("{{{}}}", i + 1), a);
        }
        Ok(s)
    }
}
