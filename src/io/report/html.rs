//! The few pieces of HTML the report is made of: escaped text, numbers with their unit, a
//! table whose every row has its header's number of cells, a section, and a PNG embedded
//! as a `data:` URI (no reference outside the file).

use super::base64::base64;

/// `text` with `&`, `<`, `>` and `"` escaped.
pub(super) fn escape(text: &str) -> String {
    text.replace('&', "&amp;").replace('<', "&lt;").replace('>', "&gt;").replace('"', "&quot;")
}

/// `value` with `decimals` decimals, or a dash where it is not a number.
pub(super) fn number(value: f64, decimals: usize) -> String {
    if value.is_finite() { format!("{value:.decimals$}") } else { "—".to_string() }
}

/// A value and, where it has a finite one, its error bar: "value ± bar".
pub(super) fn with_bar(value: f64, bar: Option<f64>, decimals: usize) -> String {
    match bar.filter(|b| b.is_finite()) {
        Some(bar) if value.is_finite() => format!("{} ± {}", number(value, decimals), number(bar, decimals)),
        _ => number(value, decimals),
    }
}

/// An optional value with `decimals` decimals, a dash where it is absent.
pub(super) fn optional(value: Option<f64>, decimals: usize) -> String {
    value.map_or("—".to_string(), |v| number(v, decimals))
}

/// A check against a requirement: "yes" or "no", coloured, or a dash when there is none.
pub(super) fn verdict(met: Option<bool>) -> String {
    match met {
        Some(true) => "<span class=\"pass\">yes</span>".to_string(),
        Some(false) => "<span class=\"fail\">no</span>".to_string(),
        None => "—".to_string(),
    }
}

/// A table with the header `head` (text, escaped here) and `rows` of cells (HTML), each
/// row as long as the header.
pub(super) fn table(id: &str, head: &[String], rows: &[Vec<String>]) -> String {
    let cells = |tag: &str, row: &[String]| row.iter().map(|c| format!("<{tag}>{c}</{tag}>")).collect::<String>();
    let head: Vec<String> = head.iter().map(|h| escape(h)).collect();
    let mut html = format!("<table id=\"{id}\">\n<thead><tr>{}</tr></thead>\n<tbody>\n", cells("th", &head));
    for row in rows {
        debug_assert_eq!(row.len(), head.len(), "a row of table {id} as long as its header");
        html += &format!("<tr>{}</tr>\n", cells("td", row));
    }
    html + "</tbody>\n</table>\n"
}

/// A section with the heading `title` (text) around `body` (HTML).
pub(super) fn section(id: &str, title: &str, body: &str) -> String {
    format!("<section id=\"{id}\">\n<h2>{}</h2>\n{body}</section>\n", escape(title))
}

/// A paragraph of `text`.
pub(super) fn paragraph(text: &str) -> String {
    format!("<p>{}</p>\n", escape(text))
}

/// The PNG `bytes` as an image in the page, described (and captioned) by `alt`.
pub(super) fn image(bytes: &[u8], alt: &str) -> String {
    let alt = escape(alt);
    format!(
        "<figure><img alt=\"{alt}\" src=\"data:image/png;base64,{}\"><figcaption>{alt}</figcaption></figure>\n",
        base64(bytes)
    )
}
