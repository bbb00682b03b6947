//! Files as nodes, the paths they name as edges to the files that define them (through
//! `pub use` re-exports), and the two faults: an edge up a floor, and a circle of files.

use super::paths::{Path, inline_paths, strip_comments, use_statements};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt;

#[derive(Debug, PartialEq)]
pub enum Fault {
    /// `from` (a file) names module `to`, which stands on a higher floor.
    Up { from: String, to: String, floors: (usize, usize) },
    /// These files import each other round a loop.
    Circle(Vec<String>),
    /// These top-level modules of one floor import each other round a loop (through
    /// different files, so no file circle shows it).
    ModuleCircle(Vec<String>),
    /// A top-level module of `lib.rs` that the floor list does not place.
    NoFloor(String),
}

impl fmt::Display for Fault {
    fn fmt(&self, f: &mut fmt::Formatter) -> fmt::Result {
        match self {
            Fault::Up { from, to, floors } => {
                write!(f, "{from} (floor {}) imports `{to}` from floor {} above it", floors.0, floors.1)
            }
            Fault::Circle(files) => write!(f, "these files import each other: {}", files.join(" → ")),
            Fault::ModuleCircle(m) => write!(f, "these modules import each other: {}", m.join(" → ")),
            Fault::NoFloor(m) => write!(f, "module `{m}` is on no floor of the list in lib.rs"),
        }
    }
}

/// One source file: its crate root, its module path and its code without comments.
struct File {
    path: String,
    root: &'static str,
    module: Vec<String>,
    is_mod: bool,
    /// Modules the file declares (`mod x;`): paths may start from them.
    children: BTreeSet<String>,
    code: String,
}

/// All faults of the files `(path relative to src/, text)`.
pub fn analyse(sources: &[(String, String)]) -> Vec<Fault> {
    let binary = binary_modules(sources);
    let files: Vec<File> = sources.iter().map(|(p, t)| file(p, t, &binary)).collect();
    let floors = floors(sources);
    let mut faults = no_floor(sources, &floors);
    let edges = edges(&files);
    for (from, targets) in &edges {
        faults.extend(targets.iter().filter_map(|to| up(&files[*from], &files[*to], &floors)));
    }
    let paths: Vec<String> = files.iter().map(|f| f.path.clone()).collect();
    faults.extend(circles(&paths, &edges).into_iter().map(Fault::Circle));
    let (modules, module_edges) = module_graph(&files, &edges);
    faults.extend(circles(&modules, &module_edges).into_iter().map(Fault::ModuleCircle));
    faults
}

/// The library's top-level modules and, for each, the others its files import.
fn module_graph(
    files: &[File],
    edges: &BTreeMap<usize, BTreeSet<usize>>,
) -> (Vec<String>, BTreeMap<usize, BTreeSet<usize>>) {
    let top = |f: &File| (f.root == "lib" && f.module.len() > 1).then(|| f.module[0].clone());
    let modules: Vec<String> = files.iter().filter_map(top).collect::<BTreeSet<_>>().into_iter().collect();
    let index = |f: &File| top(f).and_then(|m| modules.iter().position(|x| *x == m));
    let mut out: BTreeMap<usize, BTreeSet<usize>> = BTreeMap::new();
    for (from, targets) in edges {
        let Some(a) = index(&files[*from]) else { continue };
        out.entry(a).or_default().extend(targets.iter().filter_map(|t| index(&files[*t])).filter(|&b| b != a));
    }
    (modules, out)
}

/// Every import between two files, as (importing file, imported file), paths relative to
/// `src/`.
pub fn imports(sources: &[(String, String)]) -> Vec<(String, String)> {
    let binary = binary_modules(sources);
    let files: Vec<File> = sources.iter().map(|(p, t)| file(p, t, &binary)).collect();
    let edges = edges(&files);
    edges.iter().flat_map(|(from, to)| to.iter().map(|t| (files[*from].path.clone(), files[*t].path.clone()))).collect()
}

/// The top-level modules of the binary (`mod x;` in `main.rs`).
fn binary_modules(sources: &[(String, String)]) -> BTreeSet<String> {
    let main = sources.iter().find(|(p, _)| p == "main.rs").map_or("", |(_, t)| t.as_str());
    declared_modules(main)
}

fn declared_modules(code: &str) -> BTreeSet<String> {
    strip_comments(code)
        .lines()
        .filter_map(|l| l.trim().trim_start_matches("pub ").strip_prefix("mod ")?.strip_suffix(';').map(String::from))
        .collect()
}

fn file(path: &str, text: &str, binary: &BTreeSet<String>) -> File {
    let stem = path.trim_end_matches(".rs");
    let mut module: Vec<String> = stem.split('/').map(String::from).collect();
    let is_mod = matches!(module.last().map(String::as_str), Some("mod" | "lib" | "main"));
    if is_mod {
        module.pop();
    }
    let in_binary = path == "main.rs" || module.first().is_some_and(|m| binary.contains(m));
    let root = if in_binary { "bin" } else { "lib" };
    File { path: path.into(), root, module, is_mod, children: declared_modules(text), code: strip_comments(text) }
}

/// Module name → floor, from the lines `//! N. label: [`a`], [`b`]` of `lib.rs`.
fn floors(sources: &[(String, String)]) -> BTreeMap<String, usize> {
    let lib = sources.iter().find(|(p, _)| p == "lib.rs").map_or("", |(_, t)| t.as_str());
    let mut out = BTreeMap::new();
    for line in lib.lines().filter_map(|l| l.strip_prefix("//! ")) {
        let Some((number, rest)) = line.split_once(". ") else { continue };
        let Ok(floor) = number.trim().parse::<usize>() else { continue };
        for name in rest.split("[`").skip(1).filter_map(|s| s.split("`]").next()) {
            out.insert(name.to_string(), floor);
        }
    }
    out
}

fn no_floor(sources: &[(String, String)], floors: &BTreeMap<String, usize>) -> Vec<Fault> {
    let lib = sources.iter().find(|(p, _)| p == "lib.rs").map_or("", |(_, t)| t.as_str());
    declared_modules(lib).into_iter().filter(|m| !floors.contains_key(m)).map(Fault::NoFloor).collect()
}

/// For every file, the files it names (never itself; a module file's re-exports of its
/// children do not count).
fn edges(files: &[File]) -> BTreeMap<usize, BTreeSet<usize>> {
    let mut out = BTreeMap::new();
    for (i, f) in files.iter().enumerate() {
        // A module file's `pub use` of its own children re-exports them: not an import.
        let reexport = |public: bool, p: &Path| public && f.is_mod && p.first().is_some_and(|s| f.children.contains(s));
        let mut paths: Vec<Path> = use_statements(&f.code)
            .into_iter()
            .flat_map(|(public, paths)| paths.into_iter().filter(move |p| !reexport(public, p)))
            .collect();
        paths.extend(inline_paths(&f.code, &f.children));
        let targets: BTreeSet<usize> = paths
            .iter()
            .filter_map(|p| absolute(f, p))
            .filter_map(|m| resolve(files, f.root, &m))
            .filter(|&t| t != i)
            .collect();
        out.insert(i, targets);
    }
    out
}

/// The path from its crate root (`crate::a::b` → `a::b`; `super::` resolved), or `None`
/// for a path into another crate.
fn absolute(f: &File, path: &Path) -> Option<Vec<String>> {
    let mut base = f.module.clone();
    let mut rest = path.as_slice();
    match rest.first().map(String::as_str) {
        Some("crate") => {
            base.clear();
            rest = &rest[1..];
        }
        Some("super") => {
            while rest.first().is_some_and(|s| s == "super") {
                base.pop();
                rest = &rest[1..];
            }
        }
        Some(first) if f.children.contains(first) => {}
        _ => return None,
    }
    base.extend(rest.iter().cloned());
    Some(base)
}

/// The file that defines the item at `path`: the deepest module on the path, then through
/// that module's `pub use` re-exports of the next name.
fn resolve(files: &[File], root: &str, path: &[String]) -> Option<usize> {
    resolve_within(files, root, path, 8)
}

/// [`resolve`], following at most `hops` re-exports.
fn resolve_within(files: &[File], root: &str, path: &[String], hops: usize) -> Option<usize> {
    let (index, depth) = (0..=path.len())
        .rev()
        .find_map(|d| files.iter().position(|f| f.root == root && f.module == path[..d]).map(|i| (i, d)))?;
    let Some(name) = path.get(depth) else { return Some(index) };
    let module = &files[index];
    if !module.is_mod || hops == 0 {
        return Some(index);
    }
    for (public, paths) in use_statements(&module.code) {
        for p in paths.iter().filter(|p| public && p.last() == Some(name) && p.first().is_some_and(|s| s != "crate")) {
            let mut target = module.module.clone();
            target.extend(p.iter().cloned());
            if let Some(found) = resolve_within(files, root, &target, hops - 1).filter(|&t| t != index) {
                return Some(found);
            }
        }
    }
    Some(index)
}

/// An edge that points up a floor (library files only; the binary stands on top).
fn up(from: &File, to: &File, floors: &BTreeMap<String, usize>) -> Option<Fault> {
    if from.root != "lib" || to.root != "lib" {
        return None;
    }
    let floor = |f: &File| f.module.first().and_then(|m| floors.get(m)).copied();
    let (a, b) = (floor(from)?, floor(to)?);
    (b > a).then(|| Fault::Up { from: from.path.clone(), to: to.module[0].clone(), floors: (a, b) })
}

/// Strongly connected components of more than one node (Tarjan), as sorted names.
fn circles(names: &[String], edges: &BTreeMap<usize, BTreeSet<usize>>) -> Vec<Vec<String>> {
    struct State<'a> {
        edges: &'a BTreeMap<usize, BTreeSet<usize>>,
        index: Vec<Option<usize>>,
        low: Vec<usize>,
        stack: Vec<usize>,
        on_stack: Vec<bool>,
        next: usize,
        found: Vec<Vec<usize>>,
    }
    fn visit(s: &mut State, v: usize) {
        s.index[v] = Some(s.next);
        s.low[v] = s.next;
        s.next += 1;
        s.stack.push(v);
        s.on_stack[v] = true;
        for &w in s.edges.get(&v).into_iter().flatten() {
            match s.index[w] {
                None => {
                    visit(s, w);
                    s.low[v] = s.low[v].min(s.low[w]);
                }
                Some(iw) if s.on_stack[w] => s.low[v] = s.low[v].min(iw),
                _ => {}
            }
        }
        if Some(s.low[v]) == s.index[v] {
            let mut component = Vec::new();
            while let Some(w) = s.stack.pop() {
                s.on_stack[w] = false;
                component.push(w);
                if w == v {
                    break;
                }
            }
            if component.len() > 1 {
                s.found.push(component);
            }
        }
    }
    let n = names.len();
    let mut s = State {
        edges,
        index: vec![None; n],
        low: vec![0; n],
        stack: Vec::new(),
        on_stack: vec![false; n],
        next: 0,
        found: Vec::new(),
    };
    for v in 0..n {
        if s.index[v].is_none() {
            visit(&mut s, v);
        }
    }
    s.found
        .into_iter()
        .map(|c| {
            let mut circle: Vec<String> = c.into_iter().map(|i| names[i].clone()).collect();
            circle.sort();
            circle
        })
        .collect()
}
