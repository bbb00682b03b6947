//! A part file (issue 36, point 4; `docs/kernel-file.md`, "Part files"): the links one part
//! owns (`model::link_part`), each end by its address, with the fingerprint of the case and
//! the hash of the partition, so that parts of other cases or partitions are refused when
//! joined. `/part` holds the attributes `part`, `parts`, `roots`, `partition` (hex),
//! `format`, `cut_links`, `remote_sources`, `spanning_links`, `nodes`, `bytes`, `rays`, `seconds`; the
//! dataset `roots` (the part's roots, u32); `links/{receiver,source}/{top (u32), depth
//! (u8), path (u64: the child positions, 2 bits each, the first step in the lowest bits)}`,
//! `links/factor` (f64), `links/visible` (f32), `links/pieces/{indptr (u64), d, m (u16),
//! f (f64)}`; `splits/{top, depth, path}` (the elements its linking split); and
//! `/part/fingerprint` as `/kernel/fingerprint`.

use super::IoError;
use super::dataset::{dataset, text_attr};
use super::kernel_file::{fingerprint, write_fingerprint};
use super::read::{File, Why, open, text};
use crate::kernel::hierarchy::{Address, Part, Piece};
use crate::model::{Fingerprint, PartLink, PartLinks};
use ndarray::Array1;
use std::path::Path;

/// The layout of `/part`.
const PART_FORMAT: u32 = 2;

/// Deepest address a part file holds (2 bits a level in 64).
const DEEPEST: usize = 32;

/// A part file as read: the case's fingerprint and the part's links.
pub struct StoredPart {
    /// The fingerprint of the case that linked it.
    pub fingerprint: Fingerprint,
    /// The part, its links and counts.
    pub links: PartLinks,
}

/// Writes the links of one part, with the case's `fingerprint`, to `path` (through a
/// temporary file).
pub fn write_part(path: &Path, fingerprint: &Fingerprint, part: &PartLinks) -> Result<(), IoError> {
    super::atomic(path, |tmp| write_to(tmp, fingerprint, part).map_err(|e| e.to_string()))
}

fn write_to(path: &Path, fingerprint: &Fingerprint, p: &PartLinks) -> hdf5::Result<()> {
    let file = hdf5::File::create(path)?;
    let g = file.create_group("part")?;
    let attr = |name: &str, v: u64| g.new_attr::<u64>().create(name)?.write_scalar(&v);
    attr("part", u64::from(p.part.index))?;
    attr("parts", u64::from(p.part.count))?;
    attr("roots", p.roots as u64)?;
    attr("format", u64::from(PART_FORMAT))?;
    attr("cut_links", p.cut as u64)?;
    attr("remote_sources", p.remote_sources as u64)?;
    attr("spanning_links", p.spanning as u64)?;
    attr("nodes", p.nodes as u64)?;
    attr("bytes", p.bytes as u64)?;
    attr("rays", p.rays as u64)?;
    g.new_attr::<f64>().create("seconds")?.write_scalar(&p.seconds)?;
    text_attr(&g, "partition", &format!("{:016x}", p.partition))?;
    dataset(&g, "roots", &Array1::from(p.own_roots.clone()))?;
    let links = g.create_group("links")?;
    write_ends(&links.create_group("receiver")?, p.links.iter().map(|l| &l.receiver))?;
    write_ends(&links.create_group("source")?, p.links.iter().map(|l| &l.source))?;
    dataset(&links, "factor", &Array1::from_iter(p.links.iter().map(|l| l.factor)))?;
    dataset(&links, "visible", &Array1::from_iter(p.links.iter().map(|l| l.visible)))?;
    let pieces = links.create_group("pieces")?;
    let indptr = std::iter::once(0).chain(p.links.iter().scan(0u64, |n, l| {
        *n += l.pieces.len() as u64;
        Some(*n)
    }));
    dataset(&pieces, "indptr", &Array1::from_iter(indptr))?;
    let all = || p.links.iter().flat_map(|l| l.pieces.iter());
    dataset(&pieces, "d", &Array1::from_iter(all().map(|x| x.0)))?;
    dataset(&pieces, "m", &Array1::from_iter(all().map(|x| x.1)))?;
    dataset(&pieces, "f", &Array1::from_iter(all().map(|x| x.2)))?;
    write_ends(&g.create_group("splits")?, p.splits.iter())?;
    write_fingerprint(&g.create_group("fingerprint")?, fingerprint)
}

/// The addresses `ends` as `top`, `depth` and packed `path`.
fn write_ends<'a>(g: &hdf5::Group, ends: impl Iterator<Item = &'a Address> + Clone) -> hdf5::Result<()> {
    if ends.clone().any(|a| a.path.len() > DEEPEST) {
        return Err(format!("a node more than {DEEPEST} levels below its root").into());
    }
    let packed = |a: &Address| a.path.iter().rev().fold(0u64, |p, &c| (p << 2) | u64::from(c));
    dataset(g, "top", &Array1::from_iter(ends.clone().map(|a| a.top)))?;
    dataset(g, "depth", &Array1::from_iter(ends.clone().map(|a| a.path.len() as u8)))?;
    dataset(g, "path", &Array1::from_iter(ends.map(packed)))
}

/// Reads the part file `path` whole, checking its sizes.
pub fn read_part(path: &Path) -> Result<StoredPart, IoError> {
    read_part_for(path, None)
}

/// Reads the part file `path` for part `reader`'s rows: whole if it is `reader`'s own file;
/// of another part's, only the links into clusters. A part owns the links whose receivers
/// are its own: elements under its roots, under which no other part's leaf lies, and
/// clusters, which may span other parts (`model::part_rows`).
pub fn read_part_for(path: &Path, reader: Option<Part>) -> Result<StoredPart, IoError> {
    let (h5, bytes) = open(path)?;
    let not_a_part = |why: String| IoError::Read { path: path.to_path_buf(), why };
    if h5.group("part").is_err() {
        return Err(not_a_part("no /part group: not a part file (`ugo solve CASE --part i/n` writes one)".into()));
    }
    read_from(&File { h5: &h5, bytes }, reader).map_err(|Why(why)| not_a_part(why))
}

fn read_from(file: &File, reader: Option<Part>) -> Result<StoredPart, Why> {
    let g = file.h5.group("part")?;
    let attr = |name: &str| -> Result<u64, Why> { Ok(g.attr(name)?.read_scalar::<u64>()?) };
    if attr("format")? != u64::from(PART_FORMAT) {
        let format = attr("format")?;
        return Err(Why(format!("/part is of format {format}, this ugo reads {PART_FORMAT}: link the part again")));
    }
    let (index, count) = (attr("part")? as u32, attr("parts")? as u32);
    let part = format!("{index}/{count}").parse::<Part>().map_err(|e| Why(format!("/part: {e}")))?;
    let partition =
        u64::from_str_radix(&text(&g, "partition")?, 16).map_err(|e| Why(format!("/part partition: {e}")))?;
    let roots = attr("roots")? as usize;
    let whole = reader.is_none_or(|r| r.index == part.index);
    let links = read_links(file, |top| whole || top as usize >= roots)?;
    let links = PartLinks {
        part,
        roots,
        own_roots: file.raw::<u32>("part/roots")?,
        partition,
        links,
        splits: Ends::read(file, "part/splits")?.all(),
        cut: attr("cut_links")? as usize,
        remote_sources: attr("remote_sources")? as usize,
        spanning: attr("spanning_links")? as usize,
        nodes: attr("nodes")? as usize,
        bytes: attr("bytes")? as usize,
        rays: attr("rays")? as usize,
        seconds: g.attr("seconds")?.read_scalar::<f64>()?,
    };
    Ok(StoredPart { fingerprint: fingerprint(&g.group("fingerprint")?)?, links })
}

/// The links whose receiver's `top` `kept` accepts (the others' addresses are not unpacked).
fn read_links(file: &File, kept: impl Fn(u32) -> bool) -> Result<Vec<PartLink>, Why> {
    let receivers = Ends::read(file, "part/links/receiver")?;
    let sources = Ends::read(file, "part/links/source")?;
    let factor = file.raw::<f64>("part/links/factor")?;
    let visible = file.raw::<f32>("part/links/visible")?;
    let indptr = file.raw::<u64>("part/links/pieces/indptr")?;
    let (d, m, f) = (
        file.raw::<u16>("part/links/pieces/d")?,
        file.raw::<u16>("part/links/pieces/m")?,
        file.raw::<f64>("part/links/pieces/f")?,
    );
    let n = receivers.top.len();
    let sizes_agree =
        [sources.top.len(), factor.len(), visible.len(), indptr.len().saturating_sub(1)].iter().all(|&l| l == n);
    let pieces_agree = indptr.windows(2).all(|w| w[0] <= w[1]) && [m.len(), f.len()].iter().all(|&l| l == d.len());
    if indptr.is_empty() || !sizes_agree || !pieces_agree || indptr[n] as usize != d.len() {
        return Err(Why("/part/links: datasets of disagreeing sizes".into()));
    }
    let piece = |i: usize| -> Piece { (d[i], m[i], f[i]) };
    let link = |l: usize| PartLink {
        receiver: receivers.at(l),
        source: sources.at(l),
        factor: factor[l],
        visible: visible[l],
        pieces: (indptr[l] as usize..indptr[l + 1] as usize).map(piece).collect(),
    };
    Ok((0..n).filter(|&l| kept(receivers.top[l])).map(link).collect())
}

/// The addresses in a group (`top`, `depth`, `path`), packed as stored.
struct Ends {
    top: Vec<u32>,
    depth: Vec<u8>,
    path: Vec<u64>,
}

impl Ends {
    /// The addresses of the group `group`, checked.
    fn read(file: &File, group: &str) -> Result<Ends, Why> {
        let top = file.raw::<u32>(&format!("{group}/top"))?;
        let depth = file.raw::<u8>(&format!("{group}/depth"))?;
        let path = file.raw::<u64>(&format!("{group}/path"))?;
        if depth.len() != top.len() || path.len() != top.len() || depth.iter().any(|&d| d as usize > DEEPEST) {
            return Err(Why(format!("/{group}: datasets of disagreeing sizes or depths")));
        }
        Ok(Ends { top, depth, path })
    }

    /// The `i`-th address.
    fn at(&self, i: usize) -> Address {
        let (d, p) = (self.depth[i], self.path[i]);
        Address { top: self.top[i], path: (0..d).map(|k| ((p >> (2 * k)) & 3) as u8).collect() }
    }

    /// Every address.
    fn all(&self) -> Vec<Address> {
        (0..self.top.len()).map(|i| self.at(i)).collect()
    }
}
