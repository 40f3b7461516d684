//! A small XML reader for the tests, for the SVG tmm writes (разбор SVG):
//! start, end and empty tags with quoted attributes, text with the five
//! named entities and numeric character references; the prolog, comments,
//! doctype and processing instructions are skipped. Enough for SVG that
//! tmm itself writes; anything it cannot read is a typed error.

/// One piece of an XML document.
#[derive(Debug, Clone, PartialEq)]
pub enum Token<'a> {
    /// `<name a="v" …>` or `<name … />` (`empty`), with its byte range in the text.
    Start {
        /// Element name.
        name: &'a str,
        /// Attributes, values unescaped, in document order.
        attrs: Vec<(&'a str, String)>,
        /// `<… />`.
        empty: bool,
        /// Byte offset of `<`.
        from: usize,
        /// Byte offset just past `>`.
        to: usize,
    },
    /// `</name>`, with the byte offset of its `<`.
    End {
        /// Element name.
        name: &'a str,
        /// Byte offset of `<`.
        from: usize,
    },
    /// Character data between tags, unescaped (whitespace kept).
    Text(String),
}

impl Token<'_> {
    /// The value of attribute `key` of a start tag.
    pub fn attr(&self, key: &str) -> Option<&str> {
        match self {
            Token::Start { attrs, .. } => attrs.iter().find(|(k, _)| *k == key).map(|(_, v)| v.as_str()),
            _ => None,
        }
    }
}

/// Replace the XML entities of `s` by their characters.
///
/// ```text
/// use tmm_report::sheets::xml::unescape;
/// assert_eq!(unescape("a &lt; b &amp;&#x3C9;&#969;"), "a < b &ωω");
/// ```
pub fn unescape(s: &str) -> String {
    if !s.contains('&') {
        return s.to_string();
    }
    let mut out = String::with_capacity(s.len());
    let mut rest = s;
    while let Some(i) = rest.find('&') {
        out.push_str(&rest[..i]);
        let tail = &rest[i..];
        let Some(j) = tail.find(';').filter(|&j| j <= 10) else {
            out.push('&');
            rest = &tail[1..];
            continue;
        };
        let ent = &tail[1..j];
        let ch = match ent {
            "amp" => Some('&'),
            "lt" => Some('<'),
            "gt" => Some('>'),
            "quot" => Some('"'),
            "apos" => Some('\''),
            _ if ent.starts_with("#x") || ent.starts_with("#X") => u32::from_str_radix(&ent[2..], 16).ok().and_then(char::from_u32),
            _ if ent.starts_with('#') => ent[1..].parse::<u32>().ok().and_then(char::from_u32),
            _ => None,
        };
        match ch {
            Some(c) => {
                out.push(c);
                rest = &tail[j + 1..];
            }
            None => {
                out.push('&');
                rest = &tail[1..];
            }
        }
    }
    out.push_str(rest);
    out
}

/// The tokens of an XML text.
///
/// ```text
/// use tmm_report::sheets::xml::{tokens, Token};
/// let t = tokens("<?xml version=\"1.0\"?><svg w='2'><!-- c --><text>a&amp;b</text><g/></svg>").unwrap();
/// assert_eq!(t.len(), 6);
/// assert_eq!(t[0].attr("w"), Some("2"));
/// assert_eq!(t[2], Token::Text("a&b".into()));
/// assert!(matches!(t[4], Token::Start { name: "g", empty: true, .. }));
/// assert!(tokens("<svg a=\"1></svg>").is_err());
/// ```
pub fn tokens(s: &str) -> Result<Vec<Token<'_>>, String> {
    let b = s.as_bytes();
    let mut out = Vec::new();
    let mut i = 0;
    while i < b.len() {
        if b[i] != b'<' {
            let j = s[i..].find('<').map_or(b.len(), |k| i + k);
            out.push(Token::Text(unescape(&s[i..j])));
            i = j;
            continue;
        }
        let rest = &s[i..];
        let skip_to = |end: &str| {
            rest.find(end)
                .map(|k| i + k + end.len())
                .ok_or_else(|| format!("unclosed markup at byte {i}"))
        };
        if rest.starts_with("<?") {
            i = skip_to("?>")?;
        } else if rest.starts_with("<!--") {
            i = skip_to("-->")?;
        } else if rest.starts_with("<![CDATA[") {
            let j = skip_to("]]>")?;
            out.push(Token::Text(s[i + 9..j - 3].to_string()));
            i = j;
        } else if rest.starts_with("<!") {
            i = skip_to(">")?;
        } else if let Some(r) = rest.strip_prefix("</") {
            let k = r.find('>').ok_or_else(|| format!("unclosed end tag at byte {i}"))?;
            out.push(Token::End {
                name: r[..k].trim(),
                from: i,
            });
            i += 2 + k + 1;
        } else {
            let (tok, next) = start_tag(s, i)?;
            out.push(tok);
            i = next;
        }
    }
    Ok(out)
}

fn start_tag(s: &str, from: usize) -> Result<(Token<'_>, usize), String> {
    let b = s.as_bytes();
    let mut i = from + 1;
    let name_end = |i: usize| {
        (i..b.len())
            .find(|&k| b[k].is_ascii_whitespace() || b[k] == b'>' || b[k] == b'/')
            .unwrap_or(b.len())
    };
    let e = name_end(i);
    let name = &s[i..e];
    if name.is_empty() {
        return Err(format!("a tag without a name at byte {from}"));
    }
    i = e;
    let mut attrs = Vec::new();
    loop {
        while i < b.len() && b[i].is_ascii_whitespace() {
            i += 1;
        }
        if i >= b.len() {
            return Err(format!("unclosed tag <{name}> at byte {from}"));
        }
        if b[i] == b'>' {
            return Ok((
                Token::Start {
                    name,
                    attrs,
                    empty: false,
                    from,
                    to: i + 1,
                },
                i + 1,
            ));
        }
        if b[i] == b'/' {
            if b.get(i + 1) == Some(&b'>') {
                return Ok((
                    Token::Start {
                        name,
                        attrs,
                        empty: true,
                        from,
                        to: i + 2,
                    },
                    i + 2,
                ));
            }
            return Err(format!("stray '/' in <{name}> at byte {i}"));
        }
        let k0 = i;
        while i < b.len() && b[i] != b'=' && !b[i].is_ascii_whitespace() && b[i] != b'>' {
            i += 1;
        }
        let key = &s[k0..i];
        while i < b.len() && b[i].is_ascii_whitespace() {
            i += 1;
        }
        if b.get(i) != Some(&b'=') {
            return Err(format!("attribute {key} of <{name}> has no value (byte {i})"));
        }
        i += 1;
        while i < b.len() && b[i].is_ascii_whitespace() {
            i += 1;
        }
        let q = *b.get(i).ok_or_else(|| format!("unclosed tag <{name}> at byte {from}"))?;
        if q != b'"' && q != b'\'' {
            return Err(format!("attribute {key} of <{name}> is not quoted (byte {i})"));
        }
        let v0 = i + 1;
        let v1 = (v0..b.len())
            .find(|&k| b[k] == q || b[k] == b'<')
            .filter(|&k| b[k] == q)
            .ok_or_else(|| format!("unclosed value of {key} in <{name}> at byte {from}"))?;
        attrs.push((key, unescape(&s[v0..v1])));
        i = v1 + 1;
    }
}
