//! The one way a dataset is written into an HDF5 group (`design.md` §8), shared by the
//! solution, the forecast estimate and the hierarchy's group.

/// Writes `data` as the dataset `name` of `g`.
pub(super) fn dataset<T: hdf5::H5Type, D: ndarray::Dimension>(
    g: &hdf5::Group,
    name: &str,
    data: &ndarray::Array<T, D>,
) -> hdf5::Result<()> {
    g.new_dataset_builder().with_data(data).create(name).map(|_| ())
}
