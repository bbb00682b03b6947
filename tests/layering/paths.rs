//! The paths a Rust file names: the full paths of its `use` trees and the `crate::…` and
//! `super::…` paths written inline, with comments removed first.

/// A path as written, split at `::` (`["crate", "kernel", "Kernel"]`).
pub type Path = Vec<String>;

/// The text without `//` comments (string literals holding `//` are kept).
pub fn strip_comments(text: &str) -> String {
    text.lines().map(code_of_line).collect::<Vec<_>>().join("\n")
}

fn code_of_line(line: &str) -> &str {
    let mut in_string = false;
    let bytes = line.as_bytes();
    for i in 0..bytes.len() {
        match bytes[i] {
            b'"' if i == 0 || bytes[i - 1] != b'\\' => in_string = !in_string,
            b'/' if !in_string && bytes.get(i + 1) == Some(&b'/') => return &line[..i],
            _ => {}
        }
    }
    line
}

/// Every `use` statement (one that starts a line, as rustfmt writes them): whether it is
/// `pub`, and the full paths of its tree.
pub fn use_statements(code: &str) -> Vec<(bool, Vec<Path>)> {
    split_uses(code).0
}

/// The code with its `use` statements removed.
pub fn without_uses(code: &str) -> String {
    split_uses(code).1
}

fn split_uses(code: &str) -> (Vec<(bool, Vec<Path>)>, String) {
    let (mut uses, mut rest) = (Vec::new(), String::new());
    let mut lines = code.lines();
    while let Some(line) = lines.next() {
        let trimmed = line.trim_start();
        let public = trimmed.starts_with("pub");
        let body = trimmed.strip_prefix("use ").or_else(|| {
            let after_pub = trimmed.strip_prefix("pub")?;
            let after_scope =
                if after_pub.starts_with('(') { &after_pub[after_pub.find(')')? + 1..] } else { after_pub };
            after_scope.trim_start().strip_prefix("use ")
        });
        let Some(body) = body else {
            rest.push_str(line);
            rest.push('\n');
            continue;
        };
        let mut statement = body.to_string();
        while !statement.contains(';') {
            let Some(more) = lines.next() else { break };
            statement.push_str(more);
        }
        let tree = statement.split(';').next().unwrap_or_default();
        uses.push((public, expand(tree.trim())));
    }
    (uses, rest)
}

/// `crate::…`, `super::…` and `child::…` paths (for the modules `children` the file
/// declares) written outside `use` statements.
pub fn inline_paths(code: &str, children: &std::collections::BTreeSet<String>) -> Vec<Path> {
    let code = without_uses(code);
    let mut out = Vec::new();
    let roots = ["crate", "super"].into_iter().map(String::from).chain(children.iter().cloned());
    for root in roots.map(|r| r + "::") {
        let root = root.as_str();
        let mut from = 0;
        while let Some(i) = code[from..].find(root) {
            let start = from + i;
            from = start + root.len();
            if start > 0 && (is_ident(code.as_bytes()[start - 1]) || code.as_bytes()[start - 1] == b':') {
                continue;
            }
            let len = code[start..].bytes().take_while(|&b| is_ident(b) || b == b':').count();
            let path: Path = code[start..start + len].split("::").filter(|s| !s.is_empty()).map(String::from).collect();
            out.push(path);
        }
    }
    out
}

fn is_ident(b: u8) -> bool {
    b.is_ascii_alphanumeric() || b == b'_'
}

/// The full paths of a use tree: `a::{b, c::{d, e as f}}` → `a::b`, `a::c::d`, `a::c::e`.
pub fn expand(tree: &str) -> Vec<Path> {
    let words: Vec<&str> = tree.split_whitespace().collect();
    let mut kept = Vec::new();
    let mut i = 0;
    while i < words.len() {
        if words[i] == "as" {
            i += 2; // drop the alias: the path names the item by its own name
            continue;
        }
        kept.push(words[i]);
        i += 1;
    }
    let tree: String = kept.concat();
    let mut out = Vec::new();
    expand_into(&[], &tree, &mut out);
    out
}

fn expand_into(prefix: &[String], tree: &str, out: &mut Vec<Path>) {
    let (head, group) = match tree.find('{') {
        Some(i) if tree.ends_with('}') => (&tree[..i], Some(&tree[i + 1..tree.len() - 1])),
        _ => (tree, None),
    };
    let mut path = prefix.to_vec();
    for segment in head.split("::").filter(|s| !s.is_empty()) {
        if segment != "self" && segment != "*" {
            path.push(segment.to_string());
        }
    }
    match group {
        None => out.push(path),
        Some(items) => split_top_level(items).into_iter().for_each(|item| expand_into(&path, item, out)),
    }
}

/// `a, b::{c, d}, e` → `["a", "b::{c, d}", "e"]`.
fn split_top_level(items: &str) -> Vec<&str> {
    let (mut depth, mut start, mut out) = (0, 0, Vec::new());
    for (i, c) in items.char_indices() {
        match c {
            '{' => depth += 1,
            '}' => depth -= 1,
            ',' if depth == 0 => {
                out.push(&items[start..i]);
                start = i + 1;
            }
            _ => {}
        }
    }
    out.push(&items[start..]);
    out.into_iter().filter(|s| !s.is_empty()).collect()
}
