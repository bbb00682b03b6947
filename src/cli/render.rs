//! `ugo render OUT.h5`: camera images of a stored solution (or of one of its light scenes,
//! named after it), linear EXR and sRGB PNG, and optionally a false-colour map with a
//! legend in cd/m² and the reflection-order pictures; with `--mode J`, eigenvector J of `K`
//! from the file's `/spectrum` in a signed false colour.

use super::options::{ScaleArg, ShadingArg};
use super::{file_name, sibling};
use anyhow::{Result, bail};
use glam::DVec3;
use std::path::Path;
use std::time::Instant;
use ugo::io::{
    Scale, auto_exposure, read_mode, read_solution, write_exr, write_false_colour, write_png, write_triptych,
};
use ugo::render::{Image, LitScene, Projection, Shading, Sight, render};
use ugo::scene::{Camera, RawCamera};

/// A camera given on the command line (named `cli`), instead of the stored scene's.
#[derive(Debug, clap::Args)]
pub struct CameraOptions {
    /// Eye position `x,y,z`, m: render from this camera (with --look-at).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, requires = "look_at")]
    position: Option<Vec<f64>>,
    /// Point looked at, `x,y,z`, m.
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, requires = "position")]
    look_at: Option<Vec<f64>>,
    /// Up direction `x,y,z` (default 0,1,0).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, requires = "position")]
    up: Option<Vec<f64>>,
    /// Vertical field of view, degrees (default 40).
    #[arg(long, allow_negative_numbers = true, requires = "position")]
    fov_deg: Option<f64>,
    /// Image size `width,height`, pixels, of every camera rendered (default: the camera's
    /// own; 512,512 for --position).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    resolution: Option<Vec<i64>>,
    /// Primary rays per pixel of every camera rendered (default: the camera's own; 4 for
    /// --position).
    #[arg(long, allow_negative_numbers = true)]
    samples: Option<i64>,
}

impl CameraOptions {
    /// The command-line camera, if one was given.
    fn camera(&self) -> Result<Option<Camera>> {
        let (Some(position), Some(look_at)) = (&self.position, &self.look_at) else { return Ok(None) };
        let xyz = |flag: &str, v: &Vec<f64>| match v[..] {
            [x, y, z] => Ok([x, y, z]),
            _ => Err(anyhow::anyhow!("{flag} takes three numbers x,y,z, got {} values", v.len())),
        };
        let keys = RawCamera {
            name: "cli".into(),
            position: xyz("--position", position)?,
            look_at: xyz("--look-at", look_at)?,
            up: self.up.as_ref().map(|v| xyz("--up", v)).transpose()?,
            fov_deg: self.fov_deg,
            resolution: self.resolution()?,
            samples: self.samples,
        };
        Ok(Some(Camera::from_keys(&keys, "the command line")?))
    }

    fn resolution(&self) -> Result<Option<[i64; 2]>> {
        match self.resolution.as_deref() {
            None => Ok(None),
            Some(&[w, h]) => Ok(Some([w, h])),
            Some(other) => bail!("--resolution takes two numbers width,height, got {} values", other.len()),
        }
    }

    /// A stored camera with `--resolution` and `--samples` applied, checked as the case's
    /// keys are.
    fn applied_to(&self, camera: &Camera) -> Result<Camera> {
        if self.resolution.is_none() && self.samples.is_none() {
            return Ok(camera.clone());
        }
        let [w, h] = camera.resolution.map(|n| n as i64);
        let keys = RawCamera {
            name: camera.name.clone(),
            position: camera.position.to_array(),
            look_at: camera.look_at.to_array(),
            up: Some(camera.up.to_array()),
            fov_deg: Some(camera.fov_deg),
            resolution: Some(self.resolution()?.unwrap_or([w, h])),
            samples: Some(self.samples.unwrap_or(camera.samples as i64)),
        };
        Ok(Camera::from_keys(&keys, "the command line")?)
    }
}

/// How the images look and which pictures accompany them.
pub struct Look<'a> {
    /// A camera from the command line (rendered instead of the stored ones).
    pub view: CameraOptions,
    /// Luminance shown as white, cd/m² (default: the 99th percentile).
    pub exposure: Option<f64>,
    /// Also a false-colour map, on this scale.
    pub false_colour: Option<ScaleArg>,
    /// Reflection orders for the side-by-side order pictures.
    pub orders: &'a [usize],
    pub shading: ShadingArg,
    /// Final-gather rays per pixel.
    pub gather_rays: usize,
    /// Draw this eigenvector of `K` (from 1) instead of the field (`--mode J`).
    pub mode: Option<usize>,
    /// The light scene drawn (`[[light_scene]]`), instead of the case's own light.
    pub light_scene: Option<&'a str>,
}

pub fn run(file: &Path, names: &[String], dir: &Path, look: &Look) -> Result<()> {
    let exposure = look.exposure;
    let shading = shading_of(look.shading, look.gather_rays)?;
    let mut scale: Option<Scale> = look.false_colour.map(Scale::from);
    if let Some(l) = exposure
        && !(l.is_finite() && l > 0.0)
    {
        bail!("--exposure must be a positive luminance in cd/m², got {l}");
    }
    let mut stored = read_solution(file)?;
    let mut unit = "cd/m²".to_string();
    let mut case_suffix = String::new();
    if let Some(j) = look.mode {
        if matches!(shading, Shading::Gather { .. }) {
            bail!(
                "--mode draws an eigenvector of K, which has no luminaires' light to gather: use --shading flat or smooth"
            );
        }
        let mode = read_mode(file, j)?;
        say!("ugo render: mode {j} of K, λ = {:.8} {:+.8}i (real part, max |x| = 1)", mode.re, mode.im);
        stored.luminance = mode.vector;
        scale = Some(scale.unwrap_or(Scale::Signed));
        unit = format!("mode {j}");
        case_suffix = format!("-mode-{j}");
    }
    let cameras: Vec<Camera> = match look.view.camera()? {
        Some(camera) if names.is_empty() => vec![camera],
        Some(_) => bail!("give either --camera NAME or a camera by --position and --look-at, not both"),
        None => chosen(&stored.scene.cameras, names, &stored.scene.path)?
            .into_iter()
            .map(|c| look.view.applied_to(c))
            .collect::<Result<_>>()?,
    };
    let case = format!("{}{case_suffix}", stored.scene.path.file_stem().unwrap_or_default().to_string_lossy());
    let orders = chosen_orders(&stored.orders, look.orders)?;
    let (mut lit, case) = match look.light_scene {
        None if look.mode.is_some() => (ugo::study::lit_scene_with(stored, Vec::new()), case),
        None => (ugo::study::lit_scene(stored), case),
        Some(_) if !orders.is_empty() => bail!("--orders draws the case's own light, not a light scene's"),
        Some(name) => (ugo::study::lit_light_scene(file, stored, name)?, format!("{case}-{}", file_name(name))),
    };
    lit.set_shading(shading);
    std::fs::create_dir_all(dir).map_err(|e| anyhow::anyhow!("cannot create {}: {e}", dir.display()))?;
    for camera in &cameras {
        let start = Instant::now();
        let image = render(&lit, camera);
        let seconds = start.elapsed().as_secs_f64();
        let stem = dir.join(format!("{case}-{}-{}", file_name(&camera.name), tag(shading)));
        let (exr, png) = (sibling(&stem, ".exr"), sibling(&stem, ".png"));
        super::stop::after_stage(|| format!("the render of camera \"{}\"", camera.name), &[&exr, &png])?;
        write_exr(&exr, &image)?;
        let white = exposure.unwrap_or_else(|| auto_exposure(&surfaces_seen(&lit, camera, &image)));
        write_png(&png, &image, white)?;
        let (lo, hi) = image.range();
        say!(
            "ugo render: camera \"{}\" {}×{}, {} samples/pixel, {} shading, {seconds:.2} s",
            camera.name,
            image.width,
            image.height,
            camera.samples,
            describe(shading)
        );
        say!("  luminance {lo:.4e} .. {hi:.4e} cd/m², white at {white:.4e} cd/m²");
        say!("  {}\n  {}", exr.display(), png.display());
        if let Some(scale) = scale {
            let map = sibling(&stem, "-false.png");
            write_false_colour(&map, &image, scale, &unit)?;
            say!("  {}", map.display());
        }
        if !orders.is_empty() {
            // A gather from the sum of n orders would show n + 1: the panels are drawn smooth.
            if let Shading::Gather { .. } = shading {
                lit.set_shading(Shading::Smooth);
            }
            let solved = std::mem::take(&mut lit.solved.luminance);
            let mut panels = Vec::with_capacity(orders.len());
            for (n, sum) in &orders {
                lit.solved.luminance = sum.clone();
                let caption = if *n == 1 { "after 1 reflection".to_string() } else { format!("after {n} reflections") };
                panels.push((caption, render(&lit, camera)));
                super::stop::after_stage(
                    || format!("the render of {n} reflections"),
                    &[&sibling(&stem, "-orders.png")],
                )?;
            }
            lit.solved.luminance = solved;
            lit.set_shading(shading);
            let path = sibling(&stem, "-orders.png");
            write_triptych(&path, &panels, white)?;
            say!("  {}", path.display());
        }
    }
    Ok(())
}

/// The pixels of `image` whose samples all see surfaces, none a light source's own
/// luminance (what the automatic exposure is taken from).
fn surfaces_seen(lit: &LitScene, camera: &Camera, image: &Image) -> Vec<f64> {
    let view = Projection::of(camera);
    let light = |d: DVec3| matches!(lit.sight(view.eye, d), Some(Sight::Light(_)));
    let pixels = image.luminance.iter().zip(view.pixels());
    pixels.filter(|(_, p)| !view.any_sample(*p, &light)).map(|(l, _)| *l).collect()
}

/// `--shading` and `--gather-rays` as a [`Shading`]; shared with `ugo agree`.
pub fn shading_of(shading: ShadingArg, gather_rays: usize) -> Result<Shading> {
    Ok(match shading {
        ShadingArg::Flat => Shading::Flat,
        ShadingArg::Smooth => Shading::Smooth,
        ShadingArg::Gather if (1..=65_536).contains(&gather_rays) => Shading::Gather { rays: gather_rays },
        ShadingArg::Gather => bail!("--gather-rays must be from 1 to 65536, got {gather_rays}"),
    })
}

/// The shading's name as printed; shared with `ugo agree`.
pub fn describe(shading: Shading) -> String {
    match shading {
        Shading::Flat => "flat".into(),
        Shading::Smooth => "smooth".into(),
        Shading::Gather { rays } => format!("final-gather ({rays} rays/pixel)"),
    }
}

/// The shading as a part of a file name: `flat`, `smooth`, `gather-64`.
fn tag(shading: Shading) -> String {
    match shading {
        Shading::Flat => "flat".into(),
        Shading::Smooth => "smooth".into(),
        Shading::Gather { rays } => format!("gather-{rays}"),
    }
}

/// The recorded partial sums for the orders asked for.
fn chosen_orders(recorded: &[(usize, Vec<f64>)], wanted: &[usize]) -> Result<Vec<(usize, Vec<f64>)>> {
    wanted
        .iter()
        .map(|n| {
            recorded.iter().find(|(m, _)| m == n).cloned().ok_or_else(|| {
                let known: Vec<String> = recorded.iter().map(|(m, _)| m.to_string()).collect();
                anyhow::anyhow!(
                    "order {n} was not recorded (recorded: {}); solve with --orders to record it",
                    if known.is_empty() { "none".to_string() } else { known.join(", ") }
                )
            })
        })
        .collect()
}

/// The cameras asked for (all when none are named); shared with `ugo trace`.
pub fn chosen<'a>(cameras: &'a [Camera], names: &[String], case: &Path) -> Result<Vec<&'a Camera>> {
    if cameras.is_empty() {
        bail!("the stored scene ({}) has no [[camera]]; add one to the case and solve again", case.display());
    }
    if names.is_empty() {
        return Ok(cameras.iter().collect());
    }
    let known = || cameras.iter().map(|c| format!("\"{}\"", c.name)).collect::<Vec<_>>().join(", ");
    names
        .iter()
        .map(|n| {
            cameras
                .iter()
                .find(|c| &c.name == n)
                .ok_or_else(|| anyhow::anyhow!("unknown camera \"{n}\"; known: {}", known()))
        })
        .collect()
}
