//! `/spectrum` of a solution file (`ugo norms --spectrum N`, `solve/arnoldi.rs`): the
//! leading eigenvalues of `K` and their eigenvectors as fields, and the reading of one of
//! them back for `ugo render --mode J`.
//!
//! Layout: `eigenvalues_re`, `eigenvalues_im`, `residuals` (`‖K x − λ x‖₂ / ‖x‖₂`), each of
//! length `count`, largest magnitude first; `vectors` and `vectors_im` (`N × K × count`, the
//! real and imaginary parts, scaled so that `max |x_i| = 1` at a real positive entry, the
//! same layout as `/petsc/spectrum/vectors`); attributes `spectral_radius`, `restarts`,
//! `applications`, `converged` (1 or 0), `tolerance`, `seconds`.

use super::IoError;
use super::dataset::dataset;
use super::read::{File, Why, open};
use crate::solve::Spectrum;
use ndarray::{Array1, Array3};
use std::path::Path;

/// Writes `spectrum` (of an operator on `k` cells per patch) into the group `g`.
pub(super) fn write_spectrum(g: &hdf5::Group, spectrum: &Spectrum, k: usize) -> hdf5::Result<()> {
    let pairs = &spectrum.pairs;
    let column = |f: fn(&crate::solve::Eigenpair) -> f64| Array1::from_iter(pairs.iter().map(f));
    dataset(g, "eigenvalues_re", &column(|p| p.re))?;
    dataset(g, "eigenvalues_im", &column(|p| p.im))?;
    dataset(g, "residuals", &column(|p| p.residual))?;
    let n = pairs.first().map_or(0, |p| p.vector_re.len() / k);
    dataset(g, "vectors", &Array3::from_shape_fn((n, k, pairs.len()), |(i, c, j)| pairs[j].vector_re[i * k + c]))?;
    dataset(g, "vectors_im", &Array3::from_shape_fn((n, k, pairs.len()), |(i, c, j)| pairs[j].vector_im[i * k + c]))?;
    let rho = pairs.first().map_or(f64::NAN, |p| p.magnitude());
    for (name, value) in [("spectral_radius", rho), ("tolerance", spectrum.tolerance), ("seconds", spectrum.seconds)] {
        g.new_attr::<f64>().create(name)?.write_scalar(&value)?;
    }
    for (name, value) in [("restarts", spectrum.restarts), ("applications", spectrum.applications)] {
        g.new_attr::<u64>().create(name)?.write_scalar(&(value as u64))?;
    }
    g.new_attr::<u8>().create("converged")?.write_scalar(&u8::from(spectrum.converged))
}

/// Eigenvector `J` of a stored spectrum, as a field.
#[derive(Debug, Clone, PartialEq)]
pub struct Mode {
    /// 1 for the eigenvalue of largest magnitude.
    pub index: usize,
    /// Real part of its eigenvalue.
    pub re: f64,
    /// Imaginary part of its eigenvalue.
    pub im: f64,
    /// The real part of the eigenvector at `i·K + k` (`max |x| = 1`).
    pub vector: Vec<f64>,
}

/// Reads eigenvector `index` (from 1) of `/spectrum` in `path`.
pub fn read_mode(path: &Path, index: usize) -> Result<Mode, IoError> {
    let (h5, bytes) = open(path)?;
    let file = File { h5: &h5, bytes };
    let why = |Why(why)| IoError::NoMode { path: path.to_path_buf(), why };
    if h5.group("spectrum").is_err() {
        return Err(why(Why("it has no /spectrum (written by `ugo norms CASE --spectrum N`)".to_string())));
    }
    mode_of(&file, index).map_err(why)
}

fn mode_of(file: &File, index: usize) -> Result<Mode, Why> {
    let vectors = file.f64s("spectrum/vectors")?;
    let (re, im) = (file.f64s("spectrum/eigenvalues_re")?, file.f64s("spectrum/eigenvalues_im")?);
    let shape = vectors.shape().to_vec();
    let count = re.len();
    if shape.len() != 3 || shape[2] != count || im.len() != count {
        return Err(Why(format!(
            "/spectrum/vectors has shape {shape:?} for {count} eigenvalues, expected N×K×{count}"
        )));
    }
    if index == 0 || index > count {
        return Err(Why(format!("--mode {index}: /spectrum holds modes 1 to {count}")));
    }
    let j = index - 1;
    let vector: Vec<f64> =
        (0..shape[0]).flat_map(|i| (0..shape[1]).map(move |c| (i, c))).map(|(i, c)| vectors[[i, c, j]]).collect();
    if let Some(v) = vector.iter().find(|v| !v.is_finite()) {
        return Err(Why(format!("/spectrum/vectors of mode {index} holds {v}, not a finite value")));
    }
    Ok(Mode { index, re: re[[j]], im: im[[j]], vector })
}
