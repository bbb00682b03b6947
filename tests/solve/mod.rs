mod furnace;
mod lambert_cells;
mod material_furnaces;
mod methods;
mod mirror;
mod opal;
mod plates;
mod sphere;
