mod furnace;
mod lambert_cells;
mod material_furnaces;
mod methods;
mod mirror;
pub mod opal;
mod plates;
mod sphere;
mod warnings;
