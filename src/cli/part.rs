//! `ugo solve CASE --part i/n` and `ugo parts FILE…` (issue 36, point 4; `docs/petsc.md`,
//! "Parts"): one part's links written to its own file with its counts (links, bytes, cut
//! links and the ghost values they read per application), and part files joined: refused
//! unless they are every part of one partition of one case, else their table and totals.

use super::options::Discretize;
use super::{Bars, load};
use anyhow::{Result, bail};
use std::path::{Path, PathBuf};
use ugo::io::{read_part, write_part};
use ugo::kernel::hierarchy::Part;
use ugo::model::{Fingerprint, NamedPart, PartLinks, join, link_part};
use ugo::scene::KernelKind;

/// Links part `part` of `case` and writes it to `output` (default
/// `<case>-part-<i>-of-<n>.h5`).
pub fn run(case: &Path, d: &Discretize, part: Part, output: Option<PathBuf>) -> Result<()> {
    let scene = load(case, d)?;
    let KernelKind::Hierarchical(parameters) = scene.discretization.kernel else {
        bail!(
            "--part links the hierarchical kernel's receivers by part: the case's kernel is uniform (--kernel hierarchical)"
        );
    };
    let stem = case.file_stem().unwrap_or_default().to_string_lossy().into_owned();
    let output = output.unwrap_or_else(|| PathBuf::from(format!("{stem}-part-{}-of-{}.h5", part.index, part.count)));
    super::check_writable(&output)?;
    let links = link_part(&scene, parameters, part, &Bars::default())?;
    write_part(&output, &Fingerprint::of(&scene), &links)?;
    let cells = scene.discretization.directions.set().len();
    println!("part {part} of {}: {}", case.display(), summary(&links, cells));
    println!("wrote {}", output.display());
    Ok(())
}

/// One line of counts of `p` (`cells` direction cells a value).
fn summary(p: &PartLinks, cells: usize) -> String {
    format!(
        "{} of {} roots, {} links, {} bytes ({} links and {} tree nodes), {} cut links from {} remote sources ({} bytes of ghost values per application), {} links into clusters spanning other parts, {} rays, {:.3} s",
        p.own_roots.len(),
        p.roots,
        p.links.len(),
        p.bytes,
        p.links.len(),
        p.nodes,
        p.cut,
        p.remote_sources,
        p.remote_sources * cells * 8,
        p.spanning,
        p.rays,
        p.seconds
    )
}

/// Reads the part files `files`, refuses them unless they are every part of one
/// partition of one case, and prints their table.
pub fn join_files(files: &[PathBuf]) -> Result<()> {
    let stored = files.iter().map(|f| read_part(f)).collect::<Result<Vec<_>, _>>()?;
    let named: Vec<NamedPart> = files
        .iter()
        .zip(&stored)
        .map(|(f, s)| NamedPart { name: f.display().to_string(), fingerprint: &s.fingerprint, links: &s.links })
        .collect();
    let parts = join(&named)?;
    println!(
        "{:>5} {:>8} {:>12} {:>14} {:>12} {:>15} {:>10}",
        "part", "roots", "links", "bytes", "cut links", "remote sources", "seconds"
    );
    let (mut links, mut cut) = (0, 0);
    for p in &parts {
        let l = p.links;
        println!(
            "{:>5} {:>8} {:>12} {:>14} {:>12} {:>15} {:>10} {:>10.3}",
            l.part.to_string(),
            l.own_roots.len(),
            l.links.len(),
            l.bytes,
            l.cut,
            l.remote_sources,
            l.spanning,
            l.seconds
        );
        links += l.links.len();
        cut += l.cut;
    }
    println!("{} parts of one case and partition: {links} links, {cut} of them cut", parts.len());
    Ok(())
}
