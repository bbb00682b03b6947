//! The one way a dataset and a text attribute are written into an HDF5 group
//! (`docs/design.md` §8), shared by the solution, the forecast estimate, the hierarchy's group,
//! the kernel's and the light scenes': numbers, and strings as variable-length UTF-8.

use hdf5::types::VarLenUnicode;

/// Writes `data` as the dataset `name` of `g`.
pub(super) fn dataset<T: hdf5::H5Type, D: ndarray::Dimension>(
    g: &hdf5::Group,
    name: &str,
    data: &ndarray::Array<T, D>,
) -> hdf5::Result<()> {
    g.new_dataset_builder().with_data(data).create(name).map(|_| ())
}

/// Writes the text attribute `name` of `location`.
pub(super) fn text_attr(location: &hdf5::Location, name: &str, value: &str) -> hdf5::Result<()> {
    location.new_attr::<VarLenUnicode>().shape(()).create(name)?.write_scalar(&unicode(value)?)
}

/// Writes `items` as the dataset `name` of `g`, one variable-length UTF-8 string each.
pub(super) fn strings<'a>(g: &hdf5::Group, name: &str, items: impl Iterator<Item = &'a str>) -> hdf5::Result<()> {
    let values: hdf5::Result<Vec<VarLenUnicode>> = items.map(unicode).collect();
    dataset(g, name, &ndarray::Array1::from(values?))
}

pub(super) fn unicode(s: &str) -> hdf5::Result<VarLenUnicode> {
    s.parse::<VarLenUnicode>().map_err(|e| hdf5::Error::from(format!("cannot store {s:?}: {e}")))
}
