//! `ugo solve CASE --part i/n` and `ugo parts FILE…` (issue 36, point 4; `docs/petsc.md`,
//! "Parts"): one part's links written to its own file with its counts (links, bytes, cut
//! links and the ghost values they read per application), and part files joined: refused
//! unless they are every part of one partition of one case, else their table and totals;
//! and the second round, `ugo solve CASE --part i/n --linked FILE…`: part `i`'s rows of the
//! operator from every part's file (`docs/petsc.md`, "The operator from the part files").

use super::options::Discretize;
use super::{Bars, load};
use anyhow::{Result, bail};
use std::path::{Path, PathBuf};
use ugo::io::{StoredPart, read_part, read_part_for, write_part, write_part_rows};
use ugo::kernel::hierarchy::Part;
use ugo::model::{Fingerprint, NamedPart, PartLinks, join, link_part, part_rows};
use ugo::scene::{Hierarchical, KernelKind, Scene};

/// Links part `part` of `case` and writes it to `output` (default
/// `<case>-part-<i>-of-<n>.h5`).
pub fn run(case: &Path, d: &Discretize, part: Part, output: Option<PathBuf>) -> Result<()> {
    let (scene, parameters, output) = prepare(case, d, part, "part", output)?;
    let links = link_part(&scene, parameters, part, &Bars::default())?;
    write_part(&output, &Fingerprint::of(&scene), &links)?;
    let cells = scene.discretization.directions.set().len();
    say!("part {part} of {}: {}", case.display(), summary(&links, cells));
    say!("wrote {}", output.display());
    Ok(())
}

/// The scene of `case`, its hierarchy's parameters (refused for the uniform kernel) and
/// the writable output (default `<case>-<what>-<i>-of-<n>.h5`).
fn prepare(
    case: &Path,
    d: &Discretize,
    part: Part,
    what: &str,
    output: Option<PathBuf>,
) -> Result<(Scene, Hierarchical, PathBuf)> {
    let scene = load(case, d)?;
    let KernelKind::Hierarchical(parameters) = scene.discretization.kernel else {
        bail!("--part builds the hierarchical kernel by part: the case's kernel is uniform (--kernel hierarchical)");
    };
    let stem = case.file_stem().unwrap_or_default().to_string_lossy().into_owned();
    let output = output.unwrap_or_else(|| PathBuf::from(format!("{stem}-{what}-{}-of-{}.h5", part.index, part.count)));
    super::check_writable(&output)?;
    Ok((scene, parameters, output))
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

/// Forms part `part`'s rows of the operator of `case` from the part files `files` (every
/// part of one partition of this case) and writes them to `output` (default
/// `<case>-rows-<i>-of-<n>.h5`).
pub fn rows(case: &Path, d: &Discretize, part: Part, files: &[PathBuf], output: Option<PathBuf>) -> Result<()> {
    let (scene, parameters, output) = prepare(case, d, part, "rows", output)?;
    let stored = files.iter().map(|f| read_part_for(f, Some(part))).collect::<Result<Vec<_>, _>>()?;
    let joined = joined(files, &stored)?;
    let fingerprint = Fingerprint::of(&scene);
    let first = &stored[0];
    let changes = first.fingerprint.changes_from(&fingerprint);
    if !changes.is_empty() {
        let named: Vec<&str> = changes.iter().map(|c| c.part.name()).collect();
        bail!(
            "{} was linked for another case than {}: {} changed",
            files[0].display(),
            case.display(),
            named.join(", ")
        );
    }
    if joined[0].part.count != part.count {
        bail!("--part {part}: the part files are parts of {}", joined[0].part.count);
    }
    let rows = part_rows(&scene, parameters, part, &joined, &Bars::default())?;
    let projected: Vec<f64> = scene.discretization.directions.set().cells().iter().map(|c| c.projected).collect();
    write_part_rows(&output, &fingerprint, &projected, &rows)?;
    let r = &rows.rows;
    say!(
        "part {part} of {}: leaves {}..{} of {}, {} bundles, {} gather pieces, {} push shares, {} links ({} reaching its leaves), {} rays, {:.3} s",
        case.display(),
        r.own_leaves.start,
        r.own_leaves.end,
        r.leaves.len(),
        r.bundles.len(),
        r.entries.len(),
        r.push.len(),
        r.links,
        rows.reaching,
        rows.rays,
        rows.seconds
    );
    say!("wrote {}", output.display());
    Ok(())
}

/// The links of `stored` (read from `files`), refused unless they are every part of one
/// partition of one case, in part order.
fn joined<'a>(files: &[PathBuf], stored: &'a [StoredPart]) -> Result<Vec<&'a PartLinks>> {
    let named: Vec<NamedPart> = files
        .iter()
        .zip(stored)
        .map(|(f, s)| NamedPart { name: f.display().to_string(), fingerprint: &s.fingerprint, links: &s.links })
        .collect();
    Ok(join(&named)?.into_iter().map(|p| p.links).collect())
}

/// Reads the part files `files`, refuses them unless they are every part of one
/// partition of one case, and prints their table.
pub fn join_files(files: &[PathBuf]) -> Result<()> {
    let stored = files.iter().map(|f| read_part(f)).collect::<Result<Vec<_>, _>>()?;
    let parts = joined(files, &stored)?;
    say!(
        "{:>5} {:>8} {:>12} {:>14} {:>12} {:>15} {:>10}",
        "part",
        "roots",
        "links",
        "bytes",
        "cut links",
        "remote sources",
        "seconds"
    );
    let (mut links, mut cut) = (0, 0);
    for l in &parts {
        say!(
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
    say!("{} parts of one case and partition: {links} links, {cut} of them cut", parts.len());
    Ok(())
}
