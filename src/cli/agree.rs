//! `ugo agree SOLUTION.h5 REFERENCE`: a deterministic solution against a Monte Carlo
//! reference, in units of the reference's standard error. The reference is either the
//! HDF5 file of `ugo trace --forward` (compared per `(patch, cell)`, on the same mesh and
//! direction set) or the mean image of `ugo trace --camera` (`X.exr`, its standard errors
//! in `X-stderr.exr`; compared per pixel with the solution rendered through the same
//! camera, flat, smooth or with a final gather), and on request the picture of their
//! relative difference per pixel (`--difference`, `ugo::io::write_difference`).

use super::options::ShadingArg;
use super::render::{describe, shading_of};
use super::sibling;
use anyhow::{Result, bail};
use std::path::Path;
use ugo::io::{StoredSolution, read_exr, read_solution, relative_difference, write_difference};
use ugo::luminaire::Source;
use ugo::model::{Fingerprint, Part};
use ugo::placement::{Place, places};
use ugo::render::render;
use ugo::trace::{Agreement, World, agreement, leaf_errors};

/// How the solution is rendered for a comparison with a traced image.
pub struct Rendering<'a> {
    /// The camera of the traced image (default: the one camera of its size).
    pub camera: Option<&'a str>,
    /// Stratified rays per pixel.
    pub samples: usize,
    /// `flat`, `smooth` or `gather`, and the gather's rays per pixel.
    pub shading: ShadingArg,
    pub gather_rays: usize,
}

/// The picture of the relative difference per pixel (`--difference`).
pub struct Difference<'a> {
    /// The PNG written.
    pub path: &'a Path,
    /// Where its colours saturate, ± percent.
    pub scale: f64,
}

pub fn run(
    solution: &Path,
    reference: &Path,
    rendering: &Rendering,
    precise: f64,
    difference: Option<&Difference>,
) -> Result<()> {
    if !(precise > 0.0 && precise < 1.0) {
        bail!("--precise must lie between 0 and 1 (a relative standard error), got {precise}");
    }
    let shading = shading_of(rendering.shading, rendering.gather_rays)?;
    let is_image = reference.extension().is_some_and(|e| e.eq_ignore_ascii_case("exr"));
    if let Some(d) = difference {
        if !is_image {
            bail!(
                "--difference draws a traced image's pixels: give `ugo trace --camera`'s X.exr as the reference, not {}",
                reference.display()
            );
        }
        if !(d.scale.is_finite() && d.scale > 0.0) {
            bail!("--difference-scale must be a positive percentage, got {}", d.scale);
        }
        super::check_writable(d.path)?;
    }
    let stored = read_solution(solution)?;
    if !is_image {
        return against_estimate(solution, reference, &stored, precise);
    }
    let mean = read_exr(reference)?;
    let error_path = sibling(&reference.with_extension(""), "-stderr.exr");
    let error = read_exr(&error_path)?;
    if (error.width, error.height) != (mean.width, mean.height) {
        bail!("{} and {} differ in size", reference.display(), error_path.display());
    }
    let cameras = &stored.scene.cameras;
    let chosen = match rendering.camera {
        Some(name) => cameras.iter().find(|c| c.name == name),
        None => {
            let fitting: Vec<_> = cameras.iter().filter(|c| c.resolution == [mean.width, mean.height]).collect();
            if fitting.len() > 1 {
                bail!("several cameras are {}×{}: name one with --camera", mean.width, mean.height);
            }
            fitting.first().copied()
        }
    };
    let Some(camera) = chosen else {
        bail!(
            "no [[camera]] of the stored scene matches the {}×{} image (name it with --camera)",
            mean.width,
            mean.height
        );
    };
    if camera.resolution != [mean.width, mean.height] {
        bail!("camera \"{}\" is {:?}, the image {}×{}", camera.name, camera.resolution, mean.width, mean.height);
    }
    let mut camera = camera.clone();
    camera.samples = rendering.samples.max(1);
    let mut lit = ugo::study::lit_scene(stored);
    lit.set_shading(shading);
    let image = render(&lit, &camera);
    super::stop::after_stage(|| format!("the render of camera \"{}\"", camera.name), &[])?;
    say!(
        "ugo agree: {} through camera \"{}\" ({} rays/pixel, {} shading) against the traced image {}",
        solution.display(),
        camera.name,
        camera.samples,
        describe(shading),
        reference.display()
    );
    say!("  per pixel: {} × {}", mean.width, mean.height);
    summary(&agreement(&image.luminance, &mean.luminance, &error.luminance));
    if let Some(d) = difference {
        write_difference(d.path, &image, &mean, &error, d.scale)?;
        let beyond: Vec<f64> = (0..image.luminance.len())
            .filter_map(|i| relative_difference(image.luminance[i], mean.luminance[i], error.luminance[i]))
            .collect();
        let share = |keep: fn(&f64) -> bool| {
            100.0 * beyond.iter().filter(|r| keep(r)).count() as f64 / mean.luminance.len() as f64
        };
        say!(
            "  difference image     {}   (±{} %; beyond 2σ: {:.1} % of the pixels above, {:.1} % below)",
            d.path.display(),
            d.scale,
            share(|r| *r > 0.0),
            share(|r| *r < 0.0)
        );
    }
    Ok(())
}

/// Per (patch, cell) against a forward Monte Carlo estimate, as a whole and per surface.
fn against_estimate(solution: &Path, reference: &Path, stored: &StoredSolution, precise: f64) -> Result<()> {
    let mc = read_solution(reference)?;
    let Some(error) = &mc.standard_error else {
        bail!(
            "{} holds no standard errors: it is not a Monte Carlo estimate (ugo trace --forward)",
            reference.display()
        );
    };
    same_scene(solution, stored, reference, &mc)?;
    let (n, k) = (stored.mesh.len(), stored.directions.len());
    if mc.mesh.len() != n || mc.directions.name() != stored.directions.name() {
        bail!(
            "the two files discretize differently: {n} patches × {} cells against {} × {} (bin the photons on \
             the solve's own patches: ugo trace CASE --forward --bins-of {})",
            stored.directions.name(),
            mc.mesh.len(),
            mc.directions.name(),
            solution.display()
        );
    }
    say!("ugo agree: {} against the forward estimate {}", solution.display(), reference.display());
    say!("  per (patch, cell): {n} × {k}");
    summary(&agreement(&stored.luminance, &mc.luminance, error));
    let areas: Vec<f64> = stored.mesh.patches.iter().flat_map(|p| std::iter::repeat_n(p.area, k)).collect();
    match leaf_errors(&stored.luminance, &mc.luminance, error, &areas, precise) {
        Some(e) => {
            let worst = &stored.mesh.patches[e.largest.1 / k];
            let c = worst.centroid;
            say!(
                "  bins precise to {:.1} % {:>8}   ({:.1} % of the area); |x − m|/m over them, area-weighted:",
                100.0 * precise,
                e.bins,
                100.0 * e.area_share
            );
            say!("    mean               {:>11.3} %", 100.0 * e.mean);
            say!("    95th percentile    {:>11.3} %", 100.0 * e.p95);
            say!(
                "    largest            {:>11.3} %   (\"{}\", patch {} at [{:.3}, {:.3}, {:.3}], cell {})",
                100.0 * e.largest.0,
                names_of(stored)[worst.surface as usize],
                e.largest.1 / k,
                c.x,
                c.y,
                c.z,
                e.largest.1 % k
            );
        }
        None => say!("  no bin is precise to {:.1} %: trace more --photons", 100.0 * precise),
    }
    by_place(stored, &mc.luminance, error, &areas, precise);
    let names = names_of(stored);
    say!("  {:<26} {:>8} {:>10} {:>10}", "surface", "rms z", "rel. L1", "noise L2");
    for (s, name) in names.iter().enumerate() {
        let pick = |v: &[f64]| -> Vec<f64> {
            stored
                .mesh
                .patches
                .iter()
                .enumerate()
                .filter(|(_, p)| p.surface as usize == s)
                .flat_map(|(i, _)| v[i * k..(i + 1) * k].to_vec())
                .collect()
        };
        let a = agreement(&pick(&stored.luminance), &pick(&mc.luminance), &pick(error));
        say!("  {:<26} {:>8.3} {:>10.3e} {:>10.3e}", name, a.rms_z, a.relative_l1, a.noise_l2);
    }
    Ok(())
}

/// Refuses two files of different scenes (their fingerprints' geometry, reflectances or
/// luminaires differ) before their discretizations are compared.
fn same_scene(solution: &Path, stored: &StoredSolution, reference: &Path, mc: &StoredSolution) -> Result<()> {
    let scene = [Part::Geometry, Part::Reflectances, Part::Luminaires];
    let changes = Fingerprint::of(&mc.scene).changes_from(&Fingerprint::of(&stored.scene));
    let differ: Vec<&str> = changes.iter().filter(|c| scene.contains(&c.part)).map(|c| c.part.name()).collect();
    if differ.is_empty() {
        return Ok(());
    }
    bail!(
        "the two files hold different scenes ({} differ): {} is \"{}\" ({}), {} is \"{}\" ({}); compare a solution \
         with a trace of the same case",
        differ.join(", "),
        solution.display(),
        stored.scene.name,
        stored.scene.path.display(),
        reference.display(),
        mc.scene.name,
        mc.scene.path.display()
    )
}

/// The leaf-by-leaf errors of each kind of place (`placement::places`: near a contact, near
/// an edge of the room, umbra, penumbra, open), over the bins precise to `precise`.
fn by_place(stored: &StoredSolution, mean: &[f64], error: &[f64], areas: &[f64], precise: f64) {
    let k = stored.directions.len();
    let sources: Vec<Source> = stored.scene.luminaires.iter().map(Source::of).collect();
    let places = places(&World::new(&stored.scene, stored.mesh.clone()), &sources);
    say!(
        "  by place: the error beyond noise over all its leaves (L2, as above); the bins precise to {:.1} %, their \
         share of its area and their |x − m|/m",
        100.0 * precise
    );
    say!(
        "    {:<10} {:>8} {:>10} {:>8} {:>8} {:>10} {:>10} {:>10}",
        "place",
        "leaves",
        "beyond",
        "bins",
        "area %",
        "mean",
        "95th pct",
        "largest"
    );
    for place in Place::ALL {
        let leaves = places.iter().filter(|p| **p == Some(place)).count();
        let bins: Vec<usize> = (0..mean.len()).filter(|b| places[b / k] == Some(place)).collect();
        let pick = |v: &[f64]| -> Vec<f64> { bins.iter().map(|&b| v[b]).collect() };
        let beyond = agreement(&pick(&stored.luminance), &pick(mean), &pick(error)).excess_l2;
        match leaf_errors(&pick(&stored.luminance), &pick(mean), &pick(error), &pick(areas), precise) {
            Some(e) => say!(
                "    {:<10} {:>8} {:>8.3} % {:>8} {:>8.1} {:>8.3} % {:>8.3} % {:>8.3} %",
                place.name(),
                leaves,
                100.0 * beyond,
                e.bins,
                100.0 * e.area_share,
                100.0 * e.mean,
                100.0 * e.p95,
                100.0 * e.largest.0
            ),
            None => say!("    {:<10} {:>8} {:>8.3} % {:>8}", place.name(), leaves, 100.0 * beyond, 0),
        }
    }
}

/// The surfaces' names, by surface index.
fn names_of(stored: &StoredSolution) -> Vec<&str> {
    stored.scene.surfaces.iter().map(|s| s.name.as_str()).collect()
}

fn summary(a: &Agreement) {
    say!("  compared             {:>12}   (values with a standard error)", a.compared);
    if a.unsampled > 0 {
        say!(
            "  no Monte Carlo sample {:>11}   ({} of them differ from the solution)",
            a.unsampled,
            a.unsampled_different
        );
    }
    say!("  mean z               {:>12.4}", a.mean_z);
    say!("  rms z                {:>12.4}   (1 if the solution were the reference's expectation)", a.rms_z);
    say!("  max |z|              {:>12.4}", a.max_abs_z);
    say!("  |z| > 3              {:>11.3} %   (0.27 % expected by chance alone)", 100.0 * a.beyond_3);
    say!("  relative difference  {:>12.4e}   L1, Σ|x − m|/Σ|m|", a.relative_l1);
    say!("                       {:>12.4e}   L2, ‖x − m‖/‖m‖", a.relative_l2);
    say!("  reference noise      {:>12.4e}   L2, ‖σ‖/‖m‖", a.noise_l2);
    say!("  error beyond noise   {:>12.4e}   L2, √(‖x − m‖² − ‖σ‖²)/‖m‖", a.excess_l2);
}
