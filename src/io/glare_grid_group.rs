//! `/glare_grids` (`docs/design.md` §8, `docs/photometry.md` "UGR on a grid of
//! observers"): per `[[glare_grid]]` a group `/glare_grids/<name>` with its eye positions
//! `positions` (nv × nu × 3, m), its views `turn_deg` (degrees) and `look` (views × 3),
//! the UGR `ugr` and the background luminance `background_luminance` (cd/m²) per position
//! and view (nv × nu × views; `−∞` where no luminaire is seen), the luminaires counted
//! `sources` likewise, and the attributes `UGR_max` (the largest), `UGR_max_position`
//! (`[u, v]`), `UGR_max_turn_deg`, `ugr_limit` (when the case gives one) and `grid` (the
//! `[[grid]]` whose UGR it counts towards, when it names one).

use super::dataset::{dataset, text_attr};
use crate::readout::glare_grid::GlareGridReading;
use crate::readout::ugr::UgrReading;
use ndarray::{Array1, Array2, Array3};

pub(super) fn write_glare_grids(g: &hdf5::Group, grids: &[GlareGridReading]) -> hdf5::Result<()> {
    grids.iter().try_for_each(|grid| write_glare_grid(&g.create_group(&grid.grid.name)?, grid))
}

fn write_glare_grid(g: &hdf5::Group, r: &GlareGridReading) -> hdf5::Result<()> {
    let grid = &r.grid;
    let ([nu, nv], views) = (grid.resolution, grid.views.len());
    let positions = grid.positions();
    dataset(g, "positions", &Array3::from_shape_fn((nv, nu, 3), |(b, a, c)| positions[b * nu + a][c]))?;
    dataset(g, "turn_deg", &Array1::from_iter(grid.views.iter().map(|v| v.turn_deg)))?;
    dataset(g, "look", &Array2::from_shape_fn((views, 3), |(j, c)| grid.views[j].look[c]))?;
    let per = |f: &dyn Fn(&UgrReading) -> f64| {
        Array3::from_shape_fn((nv, nu, views), |(b, a, j)| f(&r.readings[(b * nu + a) * views + j]))
    };
    dataset(g, "ugr", &per(&UgrReading::ugr))?;
    dataset(g, "background_luminance", &per(&|x| x.background))?;
    let sources =
        Array3::from_shape_fn((nv, nu, views), |(b, a, j)| r.readings[(b * nu + a) * views + j].sources.len() as u64);
    dataset(g, "sources", &sources)?;
    let largest = r.largest();
    let scalar = |name: &str, value: f64| g.new_attr::<f64>().create(name)?.write_scalar(&value);
    scalar("UGR_max", largest.ugr)?;
    scalar("UGR_max_turn_deg", grid.views[largest.view].turn_deg)?;
    let at = [(largest.position % nu) as u64, (largest.position / nu) as u64];
    g.new_attr::<u64>().shape(2).create("UGR_max_position")?.write_raw(&at)?;
    grid.ugr_limit.map(|limit| scalar("ugr_limit", limit)).transpose()?;
    grid.grid.as_ref().map(|name| text_attr(g, "grid", name)).transpose()?;
    Ok(())
}
