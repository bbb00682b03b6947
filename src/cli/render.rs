//! `ugo render OUT.h5`: camera images of a stored solution, linear EXR and sRGB PNG, and
//! optionally a false-colour map with a legend in cd/m² and the reflection-order pictures.

use super::file_name;
use anyhow::{Result, bail};
use std::path::Path;
use std::time::Instant;
use ugo::io::{Scale, auto_exposure, read_solution, write_exr, write_false_colour, write_png, write_triptych};
use ugo::render::{LitScene, render};
use ugo::scene::Camera;

/// The optional pictures beside the camera images.
pub struct Extras<'a> {
    /// `log` or `linear`: also a false-colour map.
    pub false_colour: Option<&'a str>,
    /// Reflection orders for the side-by-side order pictures.
    pub orders: &'a [usize],
}

pub fn run(file: &Path, names: &[String], exposure: Option<f64>, dir: &Path, extras: &Extras) -> Result<()> {
    let scale = match extras.false_colour {
        None => None,
        Some("log") => Some(Scale::Log),
        Some("linear") => Some(Scale::Linear),
        Some(other) => bail!("--false-colour takes `log` or `linear`, got \"{other}\""),
    };
    if let Some(l) = exposure
        && !(l.is_finite() && l > 0.0)
    {
        bail!("--exposure must be a positive luminance in cd/m², got {l}");
    }
    let stored = read_solution(file)?;
    let cameras = chosen(&stored.scene.cameras, names, &stored.scene.path)?;
    let case = stored.scene.path.file_stem().unwrap_or_default().to_string_lossy().into_owned();
    let orders = chosen_orders(&stored.orders, extras.orders)?;
    let mut lit = LitScene::new(stored.mesh, stored.directions, stored.luminance);
    std::fs::create_dir_all(dir).map_err(|e| anyhow::anyhow!("cannot create {}: {e}", dir.display()))?;
    for camera in cameras {
        let start = Instant::now();
        let image = render(&lit, camera);
        let seconds = start.elapsed().as_secs_f64();
        let stem = dir.join(format!("{case}-{}", file_name(&camera.name)));
        let (exr, png) = (stem.with_extension("exr"), stem.with_extension("png"));
        write_exr(&exr, &image)?;
        let white = exposure.unwrap_or_else(|| auto_exposure(&image));
        write_png(&png, &image, white)?;
        let (lo, hi) = image.range();
        println!(
            "ugo render: camera \"{}\" {}×{}, {} samples/pixel, {seconds:.2} s",
            camera.name, image.width, image.height, camera.samples
        );
        println!("  luminance {lo:.4e} .. {hi:.4e} cd/m², white at {white:.4e} cd/m²");
        println!("  {}\n  {}", exr.display(), png.display());
        if let Some(scale) = scale {
            let map = dir.join(format!("{case}-{}-false.png", file_name(&camera.name)));
            write_false_colour(&map, &image, scale, "cd/m²")?;
            println!("  {}", map.display());
        }
        if !orders.is_empty() {
            let solved = std::mem::take(&mut lit.luminance);
            let mut panels = Vec::with_capacity(orders.len());
            for (n, sum) in &orders {
                lit.luminance = sum.clone();
                let caption = if *n == 1 { "after 1 reflection".to_string() } else { format!("after {n} reflections") };
                panels.push((caption, render(&lit, camera)));
            }
            lit.luminance = solved;
            let path = dir.join(format!("{case}-{}-orders.png", file_name(&camera.name)));
            write_triptych(&path, &panels, white)?;
            println!("  {}", path.display());
        }
    }
    Ok(())
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

/// The cameras asked for (all when none are named).
fn chosen<'a>(cameras: &'a [Camera], names: &[String], case: &Path) -> Result<Vec<&'a Camera>> {
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
