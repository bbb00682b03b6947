//! The one refusal of a model or matrix too large for the memory limit ([`TooLarge`]),
//! with every figure of its estimate and the ways out: a model's [`Forecast`] (before
//! meshing, or counted on the mesh) or a matrix's [`Footprint`] (the hierarchy's links
//! after a pass, the explicit product `B·G`).

use super::forecast::Forecast;
use super::memory::Footprint;

const GIB: f64 = (1u64 << 30) as f64;
/// The share of a model's patches that, once the surfaces' own elements (OBJ and glTF triangles),
/// makes a coarser size no way out.
const FIXED_SHARE: f64 = 0.5;

/// What was over the limit.
#[derive(Debug, Clone, PartialEq)]
pub enum Need {
    /// A whole model, from its forecast.
    Model(Box<Forecast>),
    /// One matrix about to be formed.
    Matrix(Footprint),
}

/// A model or matrix refused before allocation because it would not fit in the limit.
#[derive(Debug, Clone, PartialEq)]
pub struct TooLarge {
    /// What it would need.
    pub need: Need,
    /// The memory limit, bytes.
    pub limit: u64,
}

impl std::error::Error for TooLarge {}

impl Forecast {
    /// `Ok` when the peak fits in `limit` bytes, else the refusal with every figure.
    pub fn check(&self, limit: u64) -> Result<(), TooLarge> {
        match self.peak_bytes() <= limit as f64 {
            true => Ok(()),
            false => Err(TooLarge { need: Need::Model(Box::new(*self)), limit }),
        }
    }
}

impl Footprint {
    /// `Ok` when the footprint fits in `limit` bytes, else the refusal with it.
    pub fn check(self, limit: u64) -> Result<(), TooLarge> {
        match self.bytes <= limit as f64 {
            true => Ok(()),
            false => Err(TooLarge { need: Need::Matrix(self), limit }),
        }
    }
}

impl std::fmt::Display for TooLarge {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match &self.need {
            Need::Model(e) => model(f, e, self.limit),
            Need::Matrix(_) => write!(
                f,
                "{}. Ways out: a coarser patch_size (memory grows as patch_size⁻⁴), fewer direction \
                 cells, the factored operator instead of the explicit product, or a higher --memory-limit if \
                 the machine has the RAM",
                self.figures()
            ),
        }
    }
}

impl TooLarge {
    /// What was over the limit, with its figures, without the ways out (a matrix's; a
    /// model's whole refusal).
    pub fn figures(&self) -> String {
        match &self.need {
            Need::Model(_) => self.to_string(),
            Need::Matrix(m) => format!(
                "the {} would need about {:.2} GiB ({:.3e} non-zeros for {} patches × {} cells), over the limit \
                 of {:.2} GiB",
                m.what,
                m.bytes / GIB,
                m.nonzeros,
                m.patches,
                m.cells,
                self.limit as f64 / GIB
            ),
        }
    }
}

/// A model's refusal: its figures and the ways out for its kernel.
fn model(f: &mut std::fmt::Formatter<'_>, e: &Forecast, limit: u64) -> std::fmt::Result {
    write!(f, "the model would need about {}, over the limit of {}: ", gib(e.peak_bytes()), gib(limit as f64))?;
    write!(f, "{} patches × {} direction cells = {} unknowns", figure(e.patches), e.cells, figure(e.unknowns))?;
    match e.leaves {
        None => write!(
            f,
            ", {} facing pairs, {} non-zeros of G ({} to assemble)",
            figure(e.facing_pairs),
            figure(e.nonzeros),
            gib(e.assembly_bytes.max(e.kernel_bytes))
        )?,
        Some(leaves) => write!(f, " (roots of the hierarchy; at most {} leaves)", figure(leaves))?,
    }
    write!(f, ", the mesh {}, the material blocks (K × K each) {}; ", gib(e.mesh_bytes), gib(e.block_bytes))?;
    let fixed = e.fewest_patches.filter(|&n| n >= FIXED_SHARE * e.patches);
    if let Some(n) = fixed {
        return write!(
            f,
            "{}. {} of the {} patches are the surfaces' own elements (a mesh's triangle, OBJ or glTF, is one patch at any \
             size), so a larger size cannot lower them. Ways out: simplify the models (decimate the mesh \
             files, leave out small parts), {}or a higher --memory-limit if the machine has the RAM",
            provenance(e),
            figure(n),
            figure(e.patches),
            if e.leaves.is_none() { "--kernel hierarchical (no pairs of patches stored), " } else { "" }
        );
    }
    write!(
        f,
        "{}. Ways out: a larger \
         {}, fewer --directions, {}or a higher --memory-limit if the machine has the RAM",
        provenance(e),
        match e.leaves {
            None => "--patch-size (patches grow as patch_size⁻², the uniform kernel as patch_size⁻⁴)",
            Some(_) => "--root-size (the hierarchy's roots grow as root_size⁻²)",
        },
        if e.leaves.is_none() { "--kernel hierarchical, " } else { "" }
    )
}

/// Where the figures come from.
fn provenance(e: &Forecast) -> &'static str {
    if e.counted { "counted on the mesh" } else { "estimated before meshing" }
}

/// Bytes as GiB, in scientific notation past 10⁴ GiB; past the largest number, in words.
fn gib(bytes: f64) -> String {
    match bytes / GIB {
        g if g < 1e4 => format!("{g:.3} GiB"),
        g if g.is_finite() => format!("{g:.3e} GiB"),
        _ => "1e308 bytes or more".to_string(),
    }
}

/// A forecast's count in scientific notation; past the largest number (a patch size of
/// 1e-300 m), in words.
pub fn figure(x: f64) -> String {
    match x.is_finite() {
        true => format!("{x:.3e}"),
        false => "over 1e308".to_string(),
    }
}
