//! Reading the SVG tmm writes, as text (чтение SVG): a tag's attributes and
//! numbers, the root's `viewBox`, the characters a text shows and the
//! vertices of a `points` list or a path. Enough for the files tmm itself
//! writes (attributes in double quotes, one space before each, straight
//! lines only), not a general SVG reader.

/// The value of the attribute `name` in the tag `tag` (the text from `<`
/// up to its `>`), as written.
///
/// ```
/// use tmm_testkit::svg::attr;
/// let tag = r#"<text x="12.5" y="4" text-anchor="middle""#;
/// assert_eq!(attr(tag, "x"), Some("12.5"));
/// assert_eq!(attr(tag, "text-anchor"), Some("middle"));
/// assert_eq!(attr(tag, "anchor"), None, "a whole name only");
/// ```
pub fn attr<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let key = format!(" {name}=\"");
    let i = tag.find(&key)? + key.len();
    Some(&tag[i..i + tag[i..].find('"')?])
}

/// A number attribute, a trailing `mm` dropped; `None` when it is missing
/// or not a number.
///
/// ```
/// use tmm_testkit::svg::num;
/// let tag = r#"<svg width="210mm" height="x""#;
/// assert_eq!(num(tag, "width"), Some(210.0));
/// assert_eq!(num(tag, "height"), None);
/// assert_eq!(num(tag, "viewBox"), None);
/// ```
pub fn num(tag: &str, name: &str) -> Option<f64> {
    attr(tag, name).and_then(|v| v.trim_end_matches("mm").parse().ok())
}

/// The root element's `viewBox` (x, y, width, height); `None` when the
/// text has no `<svg` tag or its `viewBox` is not four numbers.
///
/// ```
/// use tmm_testkit::svg::view_box;
/// let svg = r#"<?xml version="1.0"?><svg width="100mm" viewBox="0 -5 100 50"><g viewBox="1 2 3 4"/></svg>"#;
/// assert_eq!(view_box(svg), Some([0.0, -5.0, 100.0, 50.0]));
/// assert_eq!(view_box("<svg width=\"1\"></svg>"), None);
/// ```
pub fn view_box(svg: &str) -> Option<[f64; 4]> {
    let root = &svg[svg.find("<svg")?..];
    let root = &root[..root.find('>').unwrap_or(root.len())];
    let v: Vec<f64> = attr(root, "viewBox")?
        .split_whitespace()
        .map(str::parse)
        .collect::<Result<_, _>>()
        .ok()?;
    <[f64; 4]>::try_from(v).ok()
}

/// The five named XML entities of `s` replaced by their characters
/// (`&amp;` last, so `&amp;lt;` stays `&lt;`).
///
/// ```
/// use tmm_testkit::svg::unescape;
/// assert_eq!(unescape("a &lt; b &amp;&amp;lt; &quot;c&quot; &apos;"), "a < b &&lt; \"c\" '");
/// ```
pub fn unescape(s: &str) -> String {
    s.replace("&lt;", "<")
        .replace("&gt;", ">")
        .replace("&quot;", "\"")
        .replace("&apos;", "'")
        .replace("&amp;", "&")
}

/// The characters of a text's content as written, its markup (the
/// `tspan`s of indices) dropped and its entities left as they are.
///
/// ```
/// use tmm_testkit::svg::shown;
/// assert_eq!(shown(r#"ω<tspan dy="1">1</tspan> = 2 &lt;"#), "ω1 = 2 &lt;");
/// ```
pub fn shown(inner: &str) -> String {
    let mut out = String::new();
    let mut in_tag = false;
    for ch in inner.chars() {
        match ch {
            '<' => in_tag = true,
            '>' => in_tag = false,
            c if !in_tag => out.push(c),
            _ => {}
        }
    }
    out
}

/// The vertices of a `points` list or of a path's `d` with the commands
/// M, L, H and V (the drawings write no curves), absolute or relative
/// (m, l, h, v move from the pen); H and V keep the other coordinate of
/// the pen. Numbers may be parted by spaces, commas or a minus sign.
///
/// ```
/// use tmm_testkit::svg::points;
/// assert_eq!(points("M10,20H30V5L1,2"), vec![(10.0, 20.0), (30.0, 20.0), (30.0, 5.0), (1.0, 2.0)]);
/// assert_eq!(points("0,0 4.5,-1e-3 2-3"), vec![(0.0, 0.0), (4.5, -0.001), (2.0, -3.0)]);
/// assert_eq!(points("M1 1l2 3h-1v1"), vec![(1.0, 1.0), (3.0, 4.0), (2.0, 4.0), (2.0, 5.0)]);
/// ```
pub fn points(d: &str) -> Vec<(f64, f64)> {
    let mut out = Vec::new();
    let (mut pen, mut cmd) = ((0.0, 0.0), 'M');
    let mut nums: Vec<f64> = Vec::new();
    let flush = |cmd: char, nums: &mut Vec<f64>, pen: &mut (f64, f64), out: &mut Vec<(f64, f64)>| {
        let rel = cmd.is_ascii_lowercase();
        match cmd.to_ascii_uppercase() {
            'H' => nums.iter().for_each(|&x| {
                pen.0 = if rel { pen.0 + x } else { x };
                out.push(*pen);
            }),
            'V' => nums.iter().for_each(|&y| {
                pen.1 = if rel { pen.1 + y } else { y };
                out.push(*pen);
            }),
            _ => nums.chunks_exact(2).for_each(|c| {
                *pen = if rel { (pen.0 + c[0], pen.1 + c[1]) } else { (c[0], c[1]) };
                out.push(*pen);
            }),
        }
        nums.clear();
    };
    let mut token = String::new();
    for c in d.chars().chain([' ']) {
        if c.is_ascii_alphabetic() && c != 'e' {
            if let Ok(v) = token.parse() {
                nums.push(v);
            }
            token.clear();
            flush(cmd, &mut nums, &mut pen, &mut out);
            cmd = c;
        } else if c == ',' || c.is_whitespace() || (c == '-' && !token.is_empty() && !token.ends_with('e')) {
            if let Ok(v) = token.parse() {
                nums.push(v);
            }
            token.clear();
            if c == '-' {
                token.push(c);
            }
        } else {
            token.push(c);
        }
    }
    flush(cmd, &mut nums, &mut pen, &mut out);
    out
}
