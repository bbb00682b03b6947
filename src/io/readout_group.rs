//! `/probes` and `/grids/<name>` (`docs/design.md` §8): the readings of the probes and of one
//! grid written as a group, for the solve and for each of its light scenes.

use super::dataset::{dataset, strings};
use crate::readout::grid::GridReading;
use crate::readout::grid_error::GridErrorBars;
use crate::readout::grid_ugr::GlareReadings;
use crate::readout::probe::ProbeReading;
use ndarray::{Array1, Array2, Array3};

pub(super) fn write_probes(g: &hdf5::Group, probes: &[ProbeReading]) -> hdf5::Result<()> {
    let n = probes.len();
    strings(g, "name", probes.iter().map(|p| p.name.as_str()))?;
    strings(g, "kind", probes.iter().map(|p| p.kind.name()))?;
    dataset(g, "position", &Array2::from_shape_fn((n, 3), |(i, c)| probes[i].position[c]))?;
    dataset(g, "normal", &Array2::from_shape_fn((n, 3), |(i, c)| probes[i].normal[c]))?;
    dataset(g, "luminance", &Array1::from_iter(probes.iter().map(|p| p.luminance)))?;
    dataset(g, "illuminance", &Array1::from_iter(probes.iter().map(|p| p.illuminance)))?;
    dataset(g, "direct", &Array1::from_iter(probes.iter().map(|p| p.direct)))?;
    dataset(g, "correction", &Array1::from_iter(probes.iter().map(|p| p.correction)))?;
    dataset(g, "error", &Array1::from_iter(probes.iter().map(|p| p.error.unwrap_or(f64::NAN))))
}

/// `/grids/<name>` for every grid of `grids` in `g`, each with its error bars of `errors`
/// and its UGR from the observers and glare grids of `glare` that name it.
pub(super) fn write_grids(
    g: &hdf5::Group,
    grids: &[GridReading],
    errors: &[GridErrorBars],
    glare: GlareReadings,
) -> hdf5::Result<()> {
    grids
        .iter()
        .zip(errors)
        .try_for_each(|(grid, errors)| write_grid(&g.create_group(&grid.grid.name)?, grid, errors, glare))
}

/// Points, illuminance, its `direct` part and `counted` (1 for a point in the statistics, 0
/// for one left out, `readout::obstructed`) as `nv × nu` arrays (row `b` runs along
/// `edge_u`), and why a point is left out: `obstruction_surface` (the surface over it, −1
/// for a point that counts), `obstruction_inside` (1 inside a solid), `obstruction_distance`
/// (m, NaN for a point that counts), and `error`, the illuminance's error bar (lx, NaN for a
/// point left out; `readout::grid_error`). Attributes: the statistics, their error bars
/// `E_avg_error`, `E_min_error` (lx) and `U0_error`, `UGR` (the largest of the observers
/// and glare grids of `glare` that name the grid, `readout::grid_ugr`) when one does, and the `target`'s
/// `Em_target` (lx), `U0_target` and `UGR_target` when the case gives them.
fn write_grid(g: &hdf5::Group, grid: &GridReading, errors: &GridErrorBars, glare: GlareReadings) -> hdf5::Result<()> {
    let [nu, nv] = grid.grid.resolution;
    let map = |f: &dyn Fn(usize) -> f64| Array2::from_shape_fn((nv, nu), |(b, a)| f(b * nu + a));
    dataset(g, "points", &Array3::from_shape_fn((nv, nu, 3), |(b, a, c)| grid.points[b * nu + a][c]))?;
    dataset(g, "illuminance", &map(&|i| grid.illuminance[i]))?;
    dataset(g, "direct", &map(&|i| grid.direct[i]))?;
    dataset(g, "error", &map(&|i| errors.points[i]))?;
    let o = &grid.obstructed;
    dataset(g, "counted", &Array2::from_shape_fn((nv, nu), |(b, a)| u8::from(o[b * nu + a].is_none())))?;
    let surface = Array2::from_shape_fn((nv, nu), |(b, a)| o[b * nu + a].as_ref().map_or(-1, |x| x.surface as i64));
    dataset(g, "obstruction_surface", &surface)?;
    let inside = Array2::from_shape_fn((nv, nu), |(b, a)| u8::from(o[b * nu + a].as_ref().is_some_and(|x| x.inside)));
    dataset(g, "obstruction_inside", &inside)?;
    dataset(g, "obstruction_distance", &map(&|i| o[i].as_ref().map_or(f64::NAN, |x| x.distance)))?;
    let st = grid.stats();
    let n = grid.grid.normal;
    g.new_attr::<f64>().shape(3).create("normal")?.write_raw(&[n.x, n.y, n.z])?;
    let target = grid.grid.target;
    let ugr = glare.grid_ugr(&grid.grid.name).map(|u| u.ugr);
    let targets = [("Em_target", target.em), ("U0_target", target.u0), ("UGR_target", target.ugr), ("UGR", ugr)];
    let stats = [
        ("E_avg", st.average),
        ("E_min", st.min),
        ("E_max", st.max),
        ("U0", st.u0),
        ("E_avg_error", errors.average),
        ("E_min_error", errors.min),
        ("U0_error", errors.u0),
    ];
    for (name, value) in stats.into_iter().chain(targets.into_iter().filter_map(|(n, v)| Some((n, v?)))) {
        g.new_attr::<f64>().create(name)?.write_scalar(&value)?;
    }
    Ok(())
}
