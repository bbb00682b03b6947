//! `/observers` (`docs/design.md` §8, `docs/photometry.md` "UGR"): the UGR at every
//! `[[observer]]`, one row each (with `grid`, the `[[grid]]` it names, empty for none), and
//! every luminaire counted in it, one row each in `/observers/sources`.

use super::dataset::{dataset, strings};
use crate::readout::ugr::{GlareSource, UgrReading};
use ndarray::{Array1, Array2};

pub(super) fn write_observers(g: &hdf5::Group, readings: &[UgrReading]) -> hdf5::Result<()> {
    let n = readings.len();
    let column = |f: &dyn Fn(&UgrReading) -> f64| Array1::from_iter(readings.iter().map(f));
    strings(g, "name", readings.iter().map(|r| r.observer.name.as_str()))?;
    dataset(g, "position", &Array2::from_shape_fn((n, 3), |(i, c)| readings[i].observer.position[c]))?;
    dataset(g, "look", &Array2::from_shape_fn((n, 3), |(i, c)| readings[i].observer.look[c]))?;
    dataset(g, "ugr", &column(&|r| r.ugr()))?;
    dataset(g, "ugr_limit", &column(&|r| r.observer.ugr_limit.unwrap_or(f64::NAN)))?;
    strings(g, "grid", readings.iter().map(|r| r.observer.grid.as_deref().unwrap_or("")))?;
    dataset(g, "background_luminance", &column(&|r| r.background))?;
    let sources = g.create_group("sources")?;
    let counted: Vec<_> =
        readings.iter().enumerate().flat_map(|(i, r)| r.sources.iter().map(move |s| (i, s))).collect();
    let row = |f: &dyn Fn(&(usize, &GlareSource)) -> f64| Array1::from_iter(counted.iter().map(f));
    dataset(&sources, "observer", &Array1::from_iter(counted.iter().map(|(i, _)| *i as u64)))?;
    strings(&sources, "name", counted.iter().map(|(_, s)| s.name.as_str()))?;
    dataset(&sources, "luminance", &row(&|(_, s)| s.luminance))?;
    dataset(&sources, "solid_angle", &row(&|(_, s)| s.solid_angle))?;
    dataset(&sources, "position_index", &row(&|(_, s)| s.position_index))
}
