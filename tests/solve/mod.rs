mod furnace;
mod plates;
mod sphere;
