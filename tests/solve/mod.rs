mod furnace;
mod methods;
mod plates;
mod sphere;
